/*
 * libsample_io internal header: where the C orchestration meets the thin
 * C++ files that talk to the libraries.
 *
 *   io_error.c      options defaults (errors: sample_error_set)
 *   io_read.c       file → texture: levels, storage format, colour (C)
 *   io_write.c      pictures out: colour, quantization, temp + rename (C)
 *   io_tmp.c        temporary names and the final rename
 *   oiio_read.cpp   OpenImageIO: open a file or memory, read levels
 *   oiio_write.cpp  OpenImageIO: write one picture / named channels
 *   ocio.cpp        OpenColorIO: config, name resolution, conversions
 *   exr_mip.cpp     OpenEXR: tiled mip-mapped writer
 *   exr_read.cpp    OpenEXR: direct reader of tiled mip-mapped files
 *   io_volume.c, oiio_volume.cpp  volume images (3D textures)
 *   io_env.c        environment maps: layouts, files in and out
 *   io_env_convert.c  environment maps: resampling between layouts
 */
#ifndef SAMPLE_IO_INTERNAL_H
#define SAMPLE_IO_INTERNAL_H

#include "sample/sample_io.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Volumes (oiio_volume.cpp) ------------------------------------------- */

/* A volume image's texels as float, slice after slice (x fastest, then y,
 * then z), its first `channels` (≤ 4) channels; data malloc'd (free it). */
typedef struct io_volume {
    int width, height, depth, channels;
    float *data;
} io_volume;
sample_status io_oiio_read_volume(const char *path, io_volume *v, sample_error *err);

/* ---- Reader (oiio_read.cpp) --------------------------------------------- */

/* Pixel types a level is read as. */
typedef enum io_ptype { IO_U8 = 0, IO_U16 = 1, IO_HALF = 2, IO_FLOAT = 3 } io_ptype;

typedef struct io_reader io_reader;

typedef struct io_reader_info {
    int width, height;  /* level 0 data window */
    int channels;       /* as stored (may be > 4) */
    int nlevels;        /* mip levels in the file (1: none) */
    int alpha_channel;  /* index of alpha, −1 if none */
    io_ptype native;    /* the type the level should be read as */
    char colorspace[64];/* oiio:ColorSpace metadata, "" if none */
    char wrapmodes[64]; /* "wrapmodes" metadata ("periodic,clamp"), "" if none */
    int straight_alpha; /* 1: colour is not multiplied by alpha (PNG, TGA, some TIFF) */
    /* What the file says, for sample_io_describe (io_describe.c); the
     * direct OpenEXR reader leaves them as its layout implies. */
    char format[32], pixel_type[16], compression[32];
    int tile_w, tile_h; /* 0: scanlines */
    char channel_names[SAMPLE_IO_NAMED_CHANNELS][32];
    /* OIIO's "textureformat" ("LatLong Environment", …); "" if none. */
    char textureformat[32];
} io_reader_info;

/* io_wrapmodes.c: the words of the "wrapmodes" attribute (maketx, OIIO's
 * TextureSystem) for libsample's wrap modes, both ways. Modes without a
 * word of their own are written "clamp". io_wrapmodes_parse reads "S,T"
 * (or one word for both); 0 if it names no mode libsample has. */
const char *io_wrap_word(sample_wrap w);
int io_wrapmodes_parse(const char *s, sample_wrap *wrap_s, sample_wrap *wrap_t);

/* Exactly one of path or (data, size) is given. format_hint may be NULL. */
sample_status io_reader_open(const char *path, const void *data, size_t size,
                             const char *format_hint, io_reader **out, sample_error *err);
void io_reader_info_get(const io_reader *r, io_reader_info *info);
/* Size of file level k (data window). */
sample_status io_reader_level_size(io_reader *r, int k, int *w, int *h, sample_error *err);
/* Read channels [0, nchan) of level k as `type`, tightly packed, w × h. */
sample_status io_reader_read(io_reader *r, int k, io_ptype type, int nchan, void *dst,
                             sample_error *err);
/* Read the tiles covering [x0, x1) × [y0, y1) of level k (x0, y0 on tile
 * corners; x1, y1 on tile corners or the level's edge), channels
 * [0, nchan) as `type`, tightly packed rows of x1 − x0 pixels
 * (texsys.c's tile loads). */
sample_status io_reader_read_tiles(io_reader *r, int k, int x0, int y0, int x1, int y1, io_ptype type, int nchan,
                                   void *dst, sample_error *err);
void io_reader_close(io_reader *r); /* accepts NULL */

/* ---- The reader's decisions (io_read.c) ---------------------------------- */

typedef struct io_colour io_colour;

/* What the reader decided for one file. */
typedef struct io_plan {
    int nchan;              /* channels kept (≤ 4) */
    io_ptype read_as;       /* type asked of the reader */
    sample_format format;   /* texture storage */
    int convert;            /* 1: OCIO conversion to scene_linear */
    int premultiply;        /* 1: colour × alpha after the conversion */
    int alpha;              /* alpha's index among the kept channels, −1 */
    const char *colorspace; /* resolved source space */
    int colorspace_from_rule; /* 1: chosen by the rule (no usable name) */
    int colorspace_unknown;   /* 1: the file names a space the config does
                                 not know (OIIO's generic names aside) */
} io_plan;

sample_status io_read_plan(const io_colour *col, const io_reader_info *inf, const sample_io_options *o, io_plan *p,
                           sample_error *err);
/* n pixels read as p->read_as (packed, p->nchan channels) into the
 * texture's storage format, in place: the colour conversion, the
 * premultiplication and the narrowing to half the plan asks for. Whole
 * levels (io_read.c) and single tiles (texsys.c) go through it alike. */
sample_status io_plan_apply(const io_colour *col, const io_plan *p, void *buf, size_t n, sample_error *err);
/* sample_io_read_texture with an OCIO config already loaded (the
 * texture system reads files whole with its own); o->ocio_config is not
 * used. */
sample_status io_read_texture_col(const char *path, const io_colour *col, const sample_io_options *o,
                                  const sample_mip_params *mip, sample_texture **out, sample_error *err);
/* io_describe.c: what the file says (inf) and what the plan made of it,
 * into info; the level sizes are left 0 and texture_file_levels 1. */
void io_file_info_fill(const io_reader_info *inf, const io_plan *p, sample_io_file_info *info);
/* The header pre-flights, each a no-op on other formats, on a file (path)
 * or bytes. */
sample_status io_preflight(const char *path, const void *data, size_t size, sample_error *err);

/* ---- Direct OpenEXR reader (exr_read.cpp) -------------------------------- */

/* The same interface as io_reader, for tiled MIPMAP_LEVELS ROUND_DOWN
 * single-part files with half or float channels R[, G[, B[, A]]]. */
typedef struct io_exr_tiled io_exr_tiled;

/* Exactly one of path or (data, size). *out stays NULL (status SAMPLE_OK)
 * when the file is not such a file or Imf cannot parse its header: the
 * caller then uses io_reader. data must outlive the reader. */
sample_status io_exr_tiled_open(const char *path, const void *data, size_t size, io_exr_tiled **out,
                                sample_error *err);
void io_exr_tiled_info_get(const io_exr_tiled *x, io_reader_info *info);
sample_status io_exr_tiled_level_size(io_exr_tiled *x, int k, int *w, int *h, sample_error *err);
/* type must be info.native (linear data is stored as read). */
sample_status io_exr_tiled_read(io_exr_tiled *x, int k, io_ptype type, int nchan, void *dst, sample_error *err);
void io_exr_tiled_close(io_exr_tiled *x); /* accepts NULL */
/* Textures built through the direct reader since load (tests use it to
 * see which path a read took); io_exr_direct_count adds one. */
void io_exr_direct_count(void);
unsigned long io_exr_direct_reads(void);

/* ---- Colour (ocio.cpp) --------------------------------------------------- */

/* Load the config: `path`, else $OCIO, else the shipped config. */
sample_status io_colour_open(const char *path, io_colour **out, sample_error *err);
void io_colour_close(io_colour *c); /* accepts NULL */
/* Does the config know this colour space (name, role or alias)? */
int io_colour_known(const io_colour *c, const char *name);
/* SAMPLE_OK if the config knows `name`, else SAMPLE_E_COLOR with a
 * message naming it and listing the config's colour spaces. */
sample_status io_colour_require(const io_colour *c, const char *name, sample_error *err);
/* What a file written in colour space `name` is labelled with: the space's
 * own name (a role or alias such as scene_linear resolved: "ACEScg" under
 * an ACES config) and, where the config ties it to ACES2065-1 without a
 * change of white, its chromaticities (OpenEXR's order: CIE xy of red,
 * green, blue, white). */
typedef struct io_colour_label {
    char name[128];
    int has_chromaticities;
    float chromaticities[8];
} io_colour_label;
void io_colour_label_get(const io_colour *c, const char *name, io_colour_label *out);
/* io_read.c: the config's name for sRGB (the first of the names common
 * configs use that it knows), NULL if it has none. */
const char *io_colour_srgb_name(const io_colour *col);
/* Is the space data (no conversion) or the scene_linear space itself? */
int io_colour_is_linear(const io_colour *c, const char *name);
/* Does src → scene_linear equal the sRGB EOTF on every 8-bit code? Then
 * 8-bit data can stay SRGB8 and the core decodes it exactly. */
int io_colour_is_srgb(const io_colour *c, const char *name);
/* Convert n RGBA-strided pixels (stride floats apart, RGB of channels
 * [0, min(3, nchan))) in place; to_linear selects src → scene_linear,
 * else scene_linear → src. 1- and 2-channel pixels convert as grey. */
sample_status io_colour_apply(const io_colour *c, const char *name, int to_linear, float *px,
                              size_t n, int nchan, sample_error *err);

/* ---- Writing (oiio_write.cpp, exr_mip.cpp, io_tmp.c) --------------------- */

/* Write w × h × nchan pixels of `type` to tmp_path in the format of
 * final_path's extension; names may be NULL (R, G, B, A). The spec carries
 * the label's name as oiio:ColorSpace and its chromaticities, when label is
 * non-NULL. */
sample_status io_oiio_write(const char *final_path, const char *tmp_path, const void *px,
                            io_ptype type, int w, int h, int nchan, const char *const *names,
                            const io_colour_label *label, sample_error *err);

/* The file carries the label's name (oiio:ColorSpace) and chromaticities.
 * env: IO_ENV_NONE, or the environment layout tex holds (its envmap and
 * textureformat attributes; a lat-long map also oiio:updirection "y" and
 * wrapmodes "periodic,clamp" in place of o's). */
typedef enum io_env { IO_ENV_NONE = 0, IO_ENV_LATLONG = 1, IO_ENV_CUBE = 2 } io_env;
sample_status io_exr_write_mip(const char *tmp_path, const sample_texture *tex,
                               const sample_io_exr_options *o, const io_colour_label *label, io_env env,
                               size_t *overflows, sample_error *err);
/* io_env.c: `mip` with a lat-long map's wrap modes (periodic across the
 * seam, clamped at the poles, as maketx --envlatl records them) in *copy;
 * NULL stays NULL. */
const sample_mip_params *io_env_latlong_mip(const sample_mip_params *mip, sample_mip_params *copy);
/* io_mip_write.c: sample_io_write_mip_exr with the environment attributes. */
sample_status io_write_mip_env(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                               io_env env, sample_error *err);

/* A temporary file beside a target (io_tmp.c): unnamed (O_TMPFILE) where
 * the file system allows, else named PATH.tmpPID-N and removed on SIGINT,
 * SIGTERM or SIGHUP. Writers write to write_path. */
#define IO_TMP_NAME_MAX 4096
typedef struct io_tmp {
    char write_path[IO_TMP_NAME_MAX]; /* what writers open: /proc/self/fd/N or name */
    char name[IO_TMP_NAME_MAX];       /* the named temporary, once there is one */
    int fd;                           /* the O_TMPFILE descriptor, −1 when named */
    int slot;                         /* its entry in the signal handler's table, −1 */
} io_tmp;
sample_status io_tmp_create(const char *path, io_tmp *t, sample_error *err);
/* st == SAMPLE_OK: name the file and rename it over path; otherwise (or if
 * that fails) remove it. Returns the final status. */
sample_status io_tmp_finish(sample_status st, io_tmp *t, const char *path, sample_error *err);
/* Tests: 0 forces the named protocol (to test the signal handler where
 * O_TMPFILE works); 1 (the default) allows O_TMPFILE. */
void io_tmp_set_unnamed(int on);

/* In place: n floats → `type` (U8, U16: clamped to [0, 1], rounded; HALF;
 * FLOAT unchanged), packed at the start of buf (each output element is no
 * wider than the float it replaces). Returns how many finite values became
 * ±inf in half (±65504 instead when half_clamp). */
size_t io_quantize(float *buf, size_t n, sample_io_type type, int half_clamp);

/* io_mip_write.c: level k of tex as packed pixels of `type`, malloc'ed in
 * *out: half/float linear, U8/U16 encoded to `cs` through col; half
 * overflows are added to *overflows. */
sample_status io_level_pixels(const sample_texture *tex, int k, sample_io_type type, const io_colour *col,
                              const char *cs, int half_clamp, size_t *overflows, void **out, sample_error *err);
/* oiio_write.cpp: every level of tex as a tiled TIFF (maketx's .tx layout),
 * its texels in colour space `cs`, labelled with `label` (oiio:ColorSpace). */
sample_status io_oiio_write_mip(const char *final_path, const char *tmp_path, const sample_texture *tex,
                                const sample_io_exr_options *o, sample_io_type type, const io_colour *col,
                                const char *cs, const io_colour_label *label, size_t *overflows,
                                sample_error *err);
/* Which mip-mapped writer path's extension names (*tiff: 1 TIFF, 0
 * OpenEXR), or SAMPLE_E_INVALID_ARGUMENT where it names a format without
 * levels or one without `type`. */
sample_status io_mip_target(const char *path, sample_io_type type, int *tiff, sample_error *err);

/* Lower-case extension of a path without the dot ("" if none), into ext. */
void io_extension(const char *path, char *ext, size_t ext_size);

/* io_src.c: the pre-flights' byte source, a buffer or a file (pos bytes
 * read of size). io_src_byte and io_src_skip return 0 at the end. */
typedef struct io_src {
    const unsigned char *mem;
    FILE *f;
    uint64_t size, pos;
} io_src;
int io_src_byte(io_src *s, int *c);
int io_src_skip(io_src *s, uint64_t n);
int io_src_file(io_src *s, FILE *f); /* 0 if its size cannot be found */
int io_src_seek(io_src *s, uint64_t pos); /* 0 past the end */
/* An unsigned integer of nbytes (1 to 4) bytes; 0 at the end. */
int io_src_uint(io_src *s, int nbytes, int big_endian, uint32_t *v);
void io_src_memory(io_src *s, const void *data, size_t size);
/* A pre-flight over the file at path (or, with path NULL, the buffer):
 * nothing unless its first nmagic bytes are the format's (is_format),
 * then check() from byte `start` on, named by the path or "image in
 * memory". An unreadable file passes: the reader reports it. */
sample_status io_src_preflight(const char *path, const void *data, size_t size, size_t nmagic,
                               int (*is_format)(const unsigned char *p, size_t n), uint64_t start,
                               sample_status (*check)(io_src *s, const char *what, sample_error *err),
                               sample_error *err);

/* exr_guard.c: reject OpenEXR headers whose attribute sizes exceed the data
 * (before OpenEXR allocates them); other formats pass through untouched. */
sample_status io_exr_guard_memory(const void *data, size_t size, sample_error *err);
sample_status io_exr_guard_file(const char *path, sample_error *err);

/* jpeg_guard.c: reject JPEG files whose APP13 (Photoshop IPTC) segment
 * claims more bytes than it holds (before OpenImageIO's JPEG reader reads
 * past it); other files pass through untouched. */
sample_status io_jpeg_guard_memory(const void *data, size_t size, sample_error *err);
sample_status io_jpeg_guard_file(const char *path, sample_error *err);

/* tiff_guard.c: reject TIFF files whose strip or tile tables are shorter
 * than the image, point past the end of the file, or (uncompressed) hold
 * fewer bytes than the image needs: OpenImageIO would allocate the whole
 * image and fill what is missing with zeros. Other files pass untouched. */
sample_status io_tiff_guard_memory(const void *data, size_t size, sample_error *err);
sample_status io_tiff_guard_file(const char *path, sample_error *err);

/* tga_guard.c: reject Targa files whose RLE packets run past the image or
 * whose colour-map indices lie outside the map: OpenImageIO drops the rest
 * of the packet, or reads whatever is there, without a word. */
sample_status io_tga_guard_memory(const void *data, size_t size, sample_error *err);
sample_status io_tga_guard_file(const char *path, sample_error *err);

#ifdef __cplusplus
}
#endif

/* A copy of s in memory of its own (malloc; NULL for NULL or when memory
 * is refused): the C11 library has no strdup. */
static inline char *io_strdup(const char *s)
{
    char *d;
    if (!s) return NULL;
    d = (char *)malloc(strlen(s) + 1);
    if (d) memcpy(d, s, strlen(s) + 1);
    return d;
}

#endif
