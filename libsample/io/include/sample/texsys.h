/*
 * libsample_io's texture system: textures by name, held as tiles in a cache
 * of bounded memory (doc/texture-system.md) — what OpenImageIO's
 * TextureSystem gives a renderer, with libsample's filters.
 *
 * 1. USE
 *
 *     sample_texsys_options o;  sample_texsys_options_init(&o);
 *     o.max_memory_mb = 256;
 *     sample_texsys *sys;  const sample_texture *tex;  sample_error err;
 *     sample_texsys_create(&o, &sys, &err);
 *     sample_texsys_open(sys, "wood.tx", &tex, &err);    // header only
 *     sample_texsys_batch(sys, tex, &sampler, &args);     // tiles load here
 *     sample_texsys_destroy(sys);                         // every texture too
 *
 *   The texture a name opens is an ordinary sample_texture whose texels
 *   come from the cache: sample_batch, sample_one and every filter take it
 *   unchanged, and give the results an in-memory texture of the same
 *   levels gives, bit for bit. It belongs to the system (never pass it to
 *   sample_texture_destroy); opening the same name again returns it.
 *
 * 2. FILES
 *
 *   A tiled file whose tiles are square, a power of two from 4 to 4096
 *   texels a side, and whose levels follow libsample's size rule (tiled
 *   OpenEXR, maketx .tx, tiled TIFF, `texsample mip` output) is read one
 *   tile at a time, when a filter first touches it (OpenImageIO's
 *   ImageInput::read_tiles). Any other file (scanlines, one level, odd
 *   tiles) is tiled and mip-mapped on first use, as OpenImageIO's autotile
 *   and automip do: the whole file is read as sample_io_read_texture reads
 *   it, a pyramid built with the box filter (sample_mip_params_init's
 *   defaults, edges from the file's wrap modes), and cut into 64 × 64
 *   tiles; a tile of such a file evicted and needed again reads the file
 *   again. Texels are stored as sample_io_read_texture stores them:
 *   the same format, colour conversion and premultiplication.
 *
 *   A cube map (a file that says so, textureformat "CubeFace Environment",
 *   in OpenEXR's N × 6N layout, as sample_io_read_env reads it) opens as
 *   a SAMPLE_TEXTURE_CUBE texture and a volume (as sample_io_read_volume
 *   reads one) as a SAMPLE_TEXTURE_3D texture: read whole by that reader
 *   when opened, with the default pyramid, and held until the system is
 *   destroyed, outside the memory limit (doc/texture-system.md, "Cube maps
 *   and volumes"). A lat-long map is a 2D texture, read tile by tile.
 *
 * 3. UDIM
 *
 *   A name holding <UDIM>, <u>, <v>, <U>, <V> or <uvtile> names a set of
 *   files: tile (u, v) (0-based, u and v below 10) has <UDIM> = 1001 + u +
 *   10 v, <u> = "u" u and <v> = "v" v (0-based), <U> = "u" (u + 1) and
 *   <V> = "v" (v + 1) (1-based), <uvtile> = <U>_<V>. sample_texsys_batch
 *   resolves each query's tile from floor(s), floor(t) (OpenImageIO's
 *   rule): the set is one virtual texture of its tiles side by side, so a
 *   footprint that crosses a tile's edge continues into the neighbouring
 *   tile, and a tile the set lacks reads the fill colour.
 *
 * 4. FAILURES
 *
 *   A tile that cannot be read (a truncated or corrupt file, a file gone
 *   or unreadable since it was opened, memory refused) reads as the fill
 *   colour; the error is recorded on the texture and the system
 *   (sample_texsys_texture_error, sample_texsys_stats_get) and the tile is
 *   not tried again. Nothing crashes; sampling never fails for it.
 *
 * 5. MEMORY AND THREADS
 *
 *   Tiles held never exceed max_memory_mb; above it lie only tiles evicted
 *   while a batch that may still read them runs (doc/texture-system.md,
 *   "Memory": sample_texsys_batch keeps them few). Every function may be
 *   called from any thread at once, except sample_texsys_destroy, which
 *   must run alone. Two systems share nothing.
 */
#ifndef SAMPLE_TEXSYS_H
#define SAMPLE_TEXSYS_H

#include "sample/sample_io.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sample_texsys sample_texsys;

typedef struct sample_texsys_options {
    /* The most memory tiles may hold, in MiB (fractions allowed); default
     * 1024, OpenImageIO's max_memory_MB default. The cache evicts the
     * least recently used tiles (the clock approximation) to stay under
     * it; doc/texture-system.md, "Memory", says what lies above it. */
    double max_memory_mb;
    /* The most files open at once; default 100 (OpenImageIO's
     * max_open_files). The least recently used is closed, and reopened
     * when needed again. */
    int max_open_files;
    /* What texels that cannot be read return (linear RGBA); default 0. */
    float fill[4];
    /* As sample_io_options: the OCIO config (NULL: $OCIO, else the shipped
     * one) and a colour space that overrides every file's (NULL: each
     * file's own, else the rule of sample_io.h section 2). */
    const char *ocio_config;
    const char *colorspace;
} sample_texsys_options;

SAMPLE_IO_API void sample_texsys_options_init(sample_texsys_options *o);

/* A new, empty system. `o` may be NULL (defaults). */
SAMPLE_IO_API sample_status sample_texsys_create(const sample_texsys_options *o, sample_texsys **out,
                                                 sample_error *err);

/* Frees every texture and tile of the system. No other call on it, or on
 * its textures, may run meanwhile. Accepts NULL. */
SAMPLE_IO_API void sample_texsys_destroy(sample_texsys *sys);

/* The texture `filename` names (section 2, and section 3 for UDIM): its
 * header is read now, its texels when sampled. SAMPLE_E_IO for a file
 * that cannot be opened, SAMPLE_E_CORRUPT for one that is not an image. */
SAMPLE_IO_API sample_status sample_texsys_open(sample_texsys *sys, const char *filename, const sample_texture **tex,
                                               sample_error *err);

/* sample_texsys_open with the colour space the file's texels are decoded
 * from (an OCIO name or role, e.g. "data" for a bump or normal map: as
 * sample_io_options.colorspace). It overrides the system's `colorspace`
 * option for this texture; NULL opens as sample_texsys_open does. The same
 * file opened with two colour spaces is two textures, each with its own
 * tiles. SAMPLE_E_COLOR for a name the OCIO config lacks. */
SAMPLE_IO_API sample_status sample_texsys_open_colorspace(sample_texsys *sys, const char *filename,
                                                          const char *colorspace, const sample_texture **tex,
                                                          sample_error *err);

typedef struct sample_texsys_info {
    /* Size, levels, channels, format, kind (sample_texture_info_get); of
     * a UDIM set, the virtual texture's (section 3). */
    sample_texture_info texture;
    int tile_size;   /* texels a side of the cache's tiles */
    int file_tiled;  /* 1: tiles read from the file; 0: tiled on first use */
    int has_wrap;    /* 1: the file's "wrapmodes" named wrap_s, wrap_t */
    sample_wrap wrap_s, wrap_t;
    char colorspace[64]; /* the space decoded from (an OCIO name or role) */
    int udim;            /* 1: a UDIM set of udim_cols × udim_rows tiles */
    int udim_cols, udim_rows;
} sample_texsys_info;

/* What a texture of this system is. SAMPLE_E_INVALID_ARGUMENT if `tex` is
 * not one of its textures. */
SAMPLE_IO_API sample_status sample_texsys_texture_info(sample_texsys *sys, const sample_texture *tex,
                                                       sample_texsys_info *info, sample_error *err);

/* sample_sampler_init, then the file's wrap modes where it stores them
 * (UDIM sets: clamp to border, the tiles' outside being the fill). */
SAMPLE_IO_API void sample_texsys_sampler_init(sample_texsys *sys, const sample_texture *tex, sample_sampler *s);

/* sample_batch for a texture of this system; UDIM sets are sampled only
 * through it (section 3). */
SAMPLE_IO_API sample_status sample_texsys_batch(sample_texsys *sys, const sample_texture *tex,
                                                const sample_sampler *s, const sample_batch_args *args);

/* How many tiles of `tex` failed to load (0: none), the first failure's
 * message in *first (may be NULL). */
SAMPLE_IO_API unsigned long sample_texsys_texture_error(sample_texsys *sys, const sample_texture *tex,
                                                        sample_error *first);

typedef struct sample_texsys_stats {
    uint64_t tiles_read;    /* tiles loaded from files */
    uint64_t bytes_read;    /* texel bytes those tiles hold */
    uint64_t misses;        /* texel reads that found their tile absent */
    uint64_t evictions;     /* tiles evicted */
    uint64_t errors;        /* tiles that failed to load */
    uint64_t files_opened;  /* file opens, reopens after closing included */
    size_t memory;          /* bytes of tiles held now */
    size_t peak_memory;     /* most bytes of tiles ever held at once */
    int open_files, peak_open_files;
    /* Bytes of the cube maps and volumes held whole (section 2), outside
     * max_memory_mb and not in `memory`. */
    size_t held_memory;
    /* Of tiles_read, those the direct OpenEXR tile reader decoded (the
     * others came through OpenImageIO or a whole-file read;
     * doc/texture-system.md, "Files"). */
    uint64_t tiles_direct;
} sample_texsys_stats;

SAMPLE_IO_API void sample_texsys_stats_get(sample_texsys *sys, sample_texsys_stats *stats);

#ifdef __cplusplus
}
#endif

#endif /* SAMPLE_TEXSYS_H */
