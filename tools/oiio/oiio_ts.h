/*
 * oiio_ts: a thin C wrapper around OpenImageIO 2.4's TextureSystem, so that
 * the C tools (bench, compare, freq) and tests can put libsample beside the
 * renderer-industry reference at matching settings (doc/benchmarks.md).
 *
 * Conventions (checked against OIIO 2.4's texture.h and texturesys.cpp, and
 * asserted by tests/oiio_shim.c):
 *   - (s, t) are normalized with texel centres at (i + ½)/w, as libsample;
 *     t = 0 is the first stored row of the file (OIIO's "top"), which is
 *     what libsample calls row 0 — so the two agree without any flip.
 *   - The derivatives are full-pixel derivatives (OIIO: "the derivatives
 *     span the whole pixel"), in the same dPdx = (dsdx, dtdx),
 *     dPdy = (dsdy, dtdy) order as sample_query; queries pass through as is.
 *   - OIIO does not decode sRGB: an 8-bit file is read as code/255. Where a
 *     comparison of values (not speed) matters, give it float or half data.
 *
 * Threads: one oiio_ts may be sampled from many threads at once; the shim
 * uses OIIO's thread-specific Perthread record of the calling thread.
 */
#ifndef TEXSAMPLE_OIIO_TS_H
#define TEXSAMPLE_OIIO_TS_H

#include "sample/sample.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct oiio_ts oiio_ts;         /* a private TextureSystem and its cache */
typedef struct oiio_ts_tex oiio_ts_tex; /* an opened texture file; owned by its oiio_ts */

/* Storage type of a texture file written by oiio_ts_make_texture. */
typedef enum oiio_ts_format {
    OIIO_TS_FLOAT = 0, /* 32-bit float */
    OIIO_TS_HALF = 1,  /* IEEE half */
    OIIO_TS_UINT8 = 2, /* 8-bit, value·255 rounded; read back as code/255 */
    OIIO_TS_FORMAT_COUNT
} oiio_ts_format;

/* Filtering, as TextureOpt (interpmode, mipmode) pairs that match
 * libsample's filters:
 *   CLOSEST   InterpClosest,  MipModeNoMIP      ~ NEAREST on the base level
 *   BILINEAR  InterpBilinear, MipModeNoMIP      ~ LINEAR on the base level
 *   BICUBIC   InterpBicubic,  MipModeNoMIP      ~ CUBIC with the B-spline
 *   TRILINEAR InterpBilinear, MipModeTrilinear  ~ LINEAR_MIPMAP_LINEAR
 *   ANISO     InterpBilinear, MipModeAniso      ~ anisotropic footprint  */
typedef enum oiio_ts_mode {
    OIIO_TS_CLOSEST = 0,
    OIIO_TS_BILINEAR = 1,
    OIIO_TS_BICUBIC = 2,
    OIIO_TS_TRILINEAR = 3,
    OIIO_TS_ANISO = 4,
    OIIO_TS_MODE_COUNT
} oiio_ts_mode;

/* Per-lookup options. */
typedef struct oiio_ts_opts {
    oiio_ts_mode mode;         /* default TRILINEAR */
    sample_wrap wrap_s, wrap_t; /* default REPEAT; see oiio_ts_wrap_supported */
    int max_aniso;             /* TextureOpt::anisotropic; default 16 */
    int conservative;          /* TextureOpt::conservative_filter; default 1 (OIIO's) */
} oiio_ts_opts;

void oiio_ts_opts_init(oiio_ts_opts *o);

/* Does OIIO have an equivalent of this wrap mode? REPEAT → periodic,
 * MIRRORED_REPEAT → mirror, CLAMP_TO_EDGE → clamp, CLAMP_TO_BORDER → black
 * (so only with a border colour of 0). The others have none. */
int oiio_ts_wrap_supported(sample_wrap wrap);

/* Names as the command line spells them ("closest", "trilinear"); parse
 * returns −1 for an unknown name. */
const char *oiio_ts_mode_name(oiio_ts_mode mode);
int oiio_ts_mode_parse(const char *name);

/* The TextureOpt that oiio_ts_sample builds from `o`, spelled as OIIO
 * spells it (enum names "InterpBilinear", "MipModeTrilinear"; wrap names
 * as TextureOpt::decode_wrapmode reads them), so that a record of a run
 * (bench --save) states what OIIO was given, not what we meant. */
typedef struct oiio_ts_textureopt {
    const char *interpmode, *mipmode;
    const char *swrap, *twrap;
    int anisotropic;
    int conservative_filter;
} oiio_ts_textureopt;

/* Returns 0, or −1 (bad mode, or a wrap mode OIIO has no equivalent of). */
int oiio_ts_describe(const oiio_ts_opts *o, oiio_ts_textureopt *out);

/* Write `rgba` (w × h float RGBA, row 0 = first stored row) as a tiled
 * (64 × 64), uncompressed, mip-mapped texture file, as maketx does
 * (ImageBufAlgo::make_texture with its default 2 × 2 box down-sampling),
 * with the wrap modes recorded in the file. The extension picks the file
 * format: .tx/.tif (TIFF) hold float and uint8, .exr holds float and half
 * (OIIO 2.4's TIFF writer stores half as float; that is reported as an
 * error). Returns 0, or −1 with a message in err. */
int oiio_ts_make_texture(const float *rgba, int w, int h, oiio_ts_format format,
                         sample_wrap wrap_s, sample_wrap wrap_t, const char *out_path,
                         char *err, size_t errlen);

/* A private (unshared) TextureSystem whose cache holds `cache_mb` megabytes
 * (0: 4096, enough that the benchmark textures are never evicted).
 * Returns NULL on failure. */
oiio_ts *oiio_ts_create(double cache_mb);
void oiio_ts_destroy(oiio_ts *ts); /* accepts NULL */

/* The ImageCache's counts so far (OIIO 2.4's imagecache.h, "stat:"
 * attributes): tiles read from files (stat:tiles_created), their
 * uncompressed bytes (stat:bytes_read), the cache's memory now
 * (stat:cache_memory_used) and its most tiles at once (stat:tiles_peak).
 * Every field is −1 where OIIO does not answer. */
typedef struct oiio_ts_stats {
    long long tiles_read, bytes_read, memory, peak_tiles;
} oiio_ts_stats;
void oiio_ts_stats_get(oiio_ts *ts, oiio_ts_stats *out);

/* Open a texture file; the handle lives as long as ts. Reports into err and
 * returns NULL if the file cannot be read. */
oiio_ts_tex *oiio_ts_open(oiio_ts *ts, const char *path, char *err, size_t errlen);

/* Sample `count` queries into count × 4 floats (RGBA; a file with fewer
 * channels reads 0 for the missing ones, TextureOpt::fill). Returns 0, or −1 (unsupported wrap mode,
 * bad argument, or a lookup OIIO reported as failed) with a message in err
 * (err may be NULL). */
int oiio_ts_sample(oiio_ts *ts, oiio_ts_tex *tex, const oiio_ts_opts *opts,
                   const sample_query *queries, size_t count, float *rgba, char *err,
                   size_t errlen);

/* Environment lookups, TextureSystem::environment(R, dRdx, dRdy): each
 * query is sample_query3's direction and its full-pixel derivatives. OIIO
 * 2.4 samples lat-long maps only (its environment() sets LayoutLatLong
 * whatever the file's textureformat), in the file's convention: y up where
 * the file says oiio:updirection "y" (sample_io_write_env writes it),
 * texel centres at (i + ½)/w unless oiio:sampleborder is 1. The wrap modes
 * of `opts` are not used (environment() sets periodic in s, clamp in t);
 * mode and max_aniso are. Returns as oiio_ts_sample. */
int oiio_ts_environment(oiio_ts *ts, oiio_ts_tex *tex, const oiio_ts_opts *opts,
                        const sample_query3 *queries, size_t count, float *rgba, char *err,
                        size_t errlen);

#ifdef __cplusplus
}
#endif
#endif /* TEXSAMPLE_OIIO_TS_H */
