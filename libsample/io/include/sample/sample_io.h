/*
 * libsample_io — images and colour for libsample (doc/io-and-colour.md).
 *
 * A separate library with a C API: images in and out through OpenImageIO,
 * colour spaces through OpenColorIO, tiled mip-mapped OpenEXR through the
 * OpenEXR library. The core library (sample.h) never depends on it.
 *
 * 1. READING
 *
 *     sample_io_options o;  sample_io_options_init(&o);
 *     sample_texture *tex;  sample_error err;
 *     if (sample_io_read_texture("wood.png", &o, NULL, &tex, &err) != SAMPLE_OK)
 *         fprintf(stderr, "%s\n", err.message);
 *
 *   Any file OpenImageIO reads. The first stored row (usually the top) is
 *   row 0, t = 0 (as OpenImageIO's TextureSystem). Storage keeps the file's
 *   precision: 8-bit stays 8-bit (SRGB8 when the colour space decodes like
 *   sRGB, UNORM8 when it is the working space or data), half stays half,
 *   16-bit integers and float become float (options can ask for float and
 *   for premultiplied alpha). At most 4 channels are kept (the first four).
 *   Only regular files are read, and headers claiming more than the file
 *   holds are refused before pixels are allocated. Files that hold mip levels (maketx .tx/.exr, our
 *   `texsample mip`) give their levels as stored, unless use_file_levels is
 *   0; otherwise `mip` builds the pyramid (NULL: base level only).
 *
 * 2. COLOUR
 *
 *   Texels are converted at load from the texture's colour space to the
 *   config's scene_linear role. The colour space is, in this order: the
 *   options' `colorspace`, the file's metadata (oiio:ColorSpace) when the
 *   config knows that name, else the rule "8- and 16-bit integer data is
 *   sRGB, half/float is linear". The config is options.ocio_config, else
 *   $OCIO, else the one shipped with libsample (share/libsample/ocio).
 *   Only RGB is converted; alpha and channels past the third never are.
 *
 * 3. WRITING
 *
 *   Every writer writes a temporary file beside the target and renames it
 *   into place, so a failed write leaves no file behind. The temporary has
 *   no name while it is written where the file system allows (Linux
 *   O_TMPFILE), so even SIGKILL leaves nothing; elsewhere a handler for
 *   SIGINT, SIGTERM and SIGHUP, installed on the first write for those of
 *   the three still at SIG_DFL, removes it before the process dies.
 *
 * 4. THREADS
 *
 *   Every function may be called from several threads. The only
 *   process-wide state is that signal handler and its table of named
 *   temporaries.
 */
#ifndef SAMPLE_SAMPLE_IO_H
#define SAMPLE_SAMPLE_IO_H

#include "sample/sample.h"

#include <stddef.h>

/* SAMPLE_IO_API marks every public function of libsample_io, as SAMPLE_API
 * does libsample's (sample.h): the only symbols libsample_io.so exports;
 * its build defines SAMPLE_IO_BUILDING_SHARED. */
#ifndef SAMPLE_IO_API
#if defined(SAMPLE_IO_BUILDING_SHARED) && (defined(__GNUC__) || defined(__clang__))
#define SAMPLE_IO_API __attribute__((visibility("default")))
#else
#define SAMPLE_IO_API
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Reading ------------------------------------------------------------ */

/* What a file holds and what the reader makes of it (below, "Describing a
 * file"). */
typedef struct sample_io_file_info sample_io_file_info;

typedef struct sample_io_options {
    /* Source colour space (an OCIO name, role or alias). NULL: from the file
     * metadata, else the rule in section 2. */
    const char *colorspace;
    /* OCIO config file. NULL: $OCIO if set, else the shipped config. */
    const char *ocio_config;
    /* 1 (default): take mip levels stored in the file; 0: read the base
     * level only and build the pyramid from `mip`. */
    int use_file_levels;
    /* Largest decoded size (bytes, as float) of every level the texture
     * will hold: the file's, or the base and the levels `mip` builds from
     * it. A file claiming more gives SAMPLE_E_TOO_LARGE before any pixel
     * is read. 0 means the default, SAMPLE_IO_DEFAULT_MAX_BYTES. */
    size_t max_bytes;
    /* 1: store every level as float (SAMPLE_FORMAT_F32) whatever the
     * file's precision, so that a pyramid built from it is built in float
     * (what `texsample mip` does). 0 (default): keep the file's precision
     * (section 1); a pyramid is then built in the texture's format, as
     * glGenerateMipmap builds it (an SRGB8 level from the SRGB8 level
     * above). */
    int float_storage;
    /* 1: when the file stores straight alpha (PNG, Targa, TIFF marked
     * unassociated), multiply colour by alpha once it is linear, so the
     * texture holds premultiplied colour as OpenEXR defines it and a
     * pyramid built from it is filtered premultiplied (no colour bleeds
     * from transparent texels). The texture is then half or float. 0
     * (default): alpha as stored, never applied. */
    int premultiply;
    /* NULL, or filled by sample_io_read_texture / _memory with what the
     * file says and what was made of it, as sample_io_describe fills it
     * (below). */
    sample_io_file_info *file_info;
    /* 1: a pyramid built here (the file holds no levels) takes its edges
     * from the file's wrap modes where it stores them, rather than from
     * `mip`; 0 (default): from `mip`. */
    int mip_wrap_from_file;
} sample_io_options;

#define SAMPLE_IO_DEFAULT_MAX_BYTES ((size_t)1 << 32) /* 4 GiB */

SAMPLE_IO_API void sample_io_options_init(sample_io_options *o);

/* Read an image file into a new texture. `o` may be NULL (defaults).
 * `mip` is used when the file has no levels (or use_file_levels is 0);
 * NULL keeps the base level only. */
SAMPLE_IO_API sample_status sample_io_read_texture(const char *path, const sample_io_options *o,
                                     const sample_mip_params *mip, sample_texture **out,
                                     sample_error *err);

/* The same from a file held in memory. `format_hint` is a file name or an
 * extension ("png", ".exr", "x.tif") naming the format; NULL lets
 * OpenImageIO guess from the bytes. Formats whose OpenImageIO reader cannot
 * read from memory give SAMPLE_E_UNSUPPORTED. */
SAMPLE_IO_API sample_status sample_io_read_memory(const void *data, size_t size, const char *format_hint,
                                    const sample_io_options *o, const sample_mip_params *mip,
                                    sample_texture **out, sample_error *err);

/* Read a volume image into a new 3D texture (doc/volumes.md): the
 * subimages of a multi-page TIFF or a multi-part OpenEXR, all of one size,
 * are its slices (subimage k is slice k, at r = (k + ½)/d), or an image
 * with a depth of its own (a volumetric TIFF) its z extent. Its first four
 * channels are read as float32 as stored — volumes hold data (densities,
 * noise, baked solid textures), so no colour conversion is made; 8- and
 * 16-bit files read as value / (2^n − 1). `mip` builds the pyramid (NULL:
 * the base level only). */
SAMPLE_IO_API sample_status sample_io_read_volume(const char *path, const sample_mip_params *mip,
                                                  sample_texture **out, sample_error *err);

/* Is `path` a regular file that can be opened for reading? SAMPLE_OK, or
 * SAMPLE_E_IO with a message naming `what` ("image", "scene", "OCIO
 * config"; NULL: "file"), the path and what it is instead (a directory, a
 * FIFO, a device). It never blocks: a FIFO is opened with O_NONBLOCK and
 * judged by fstat. Every reader of libsample_io calls it before any library
 * sees the path; programs call it for the other files they read. */
SAMPLE_IO_API sample_status sample_io_check_regular_file(const char *path, const char *what, sample_error *err);

/* ---- Describing a file -------------------------------------------------- */

/* Channel names sample_io_file_info keeps (a file may have more channels). */
#define SAMPLE_IO_NAMED_CHANNELS 16

struct sample_io_file_info {
    /* What the file holds (subimage 0), as OpenImageIO reports it; strings
     * are "" where the file says nothing. */
    char format[32];     /* reader: "png", "openexr", "tiff", ... */
    char pixel_type[16]; /* "uint8", "uint16", "half", "float", ... */
    int width, height;   /* level 0, data window */
    int channels;        /* every channel of the file */
    char channel_names[SAMPLE_IO_NAMED_CHANNELS][32];
    int alpha_channel;   /* −1: none */
    int straight_alpha;  /* 1: colour is not multiplied by alpha */
    int levels;          /* mip levels stored (1: none) */
    int level_width[SAMPLE_MAX_LEVELS], level_height[SAMPLE_MAX_LEVELS];
    int tile_width, tile_height; /* 0: scanlines */
    char compression[32];
    /* The "wrapmodes" attribute as stored (maketx, OIIO's TextureSystem and
     * sample_io_write_mip write it: black, clamp, periodic, mirror), and
     * has_wrap = 1 where it names modes libsample has, in wrap_s, wrap_t. */
    char wrapmodes[64];
    int has_wrap;
    sample_wrap wrap_s, wrap_t;
    char colorspace[64]; /* the file's oiio:ColorSpace */
    /* What sample_io_read_texture makes of it with the same options. */
    char colorspace_used[64]; /* the space decoded from (an OCIO name or role) */
    int colorspace_from_rule; /* 1: no usable name (none, or one the config
                                 does not know): section 2's rule chose */
    int colorspace_unknown;   /* 1: the file names a space the config does
                                 not know (OpenImageIO's generic "sRGB",
                                 "Linear", which the rule reads alike, aside) */
    sample_format texture_format;
    int texture_channels;
    int texture_file_levels;  /* levels taken from the file (1: built) */
    /* OpenImageIO's "textureformat" ("Plain Texture", "LatLong
     * Environment", "CubeFace Environment", …; OpenEXR's envmap attribute
     * reads as the latter two), "" where the file says nothing. */
    char textureformat[32];
};

/* Describe an image file from its headers, without reading its pixels:
 * the memory used is that of the headers (doc/io-and-colour.md,
 * "Describing"). The same checks as sample_io_read_texture run first (a
 * regular file, the header pre-flights), so a file refused there is
 * refused here. `o` may be NULL. */
SAMPLE_IO_API sample_status sample_io_describe(const char *path, const sample_io_options *o,
                                               sample_io_file_info *info, sample_error *err);

/* ---- Writing pictures --------------------------------------------------- */

typedef enum sample_io_type {
    SAMPLE_IO_TYPE_AUTO = 0,  /* by extension: .exr half, .hdr float, else 8-bit */
    SAMPLE_IO_TYPE_U8 = 1,
    SAMPLE_IO_TYPE_U16 = 2,
    SAMPLE_IO_TYPE_HALF = 3,
    SAMPLE_IO_TYPE_FLOAT = 4,
    SAMPLE_IO_TYPE_COUNT
} sample_io_type;

typedef struct sample_io_write_options {
    /* Colour space of the file (OCIO name). NULL: linear (scene_linear) for
     * half/float, "srgb" for 8/16-bit integers. */
    const char *colorspace;
    sample_io_type type;     /* default AUTO */
    const char *ocio_config; /* as in sample_io_options */
} sample_io_write_options;

SAMPLE_IO_API void sample_io_write_options_init(sample_io_write_options *o);

/* Write w × h linear RGBA floats (rgba[4·(y·w + x)], row 0 = t = 0 = the
 * file's first stored row) as a picture with 3 or 4 channels. colorspace
 * NULL chooses by extension: .exr linear half, .png/.jpg/... sRGB 8-bit.
 * Integer types are clamped to [0, 1] and rounded to nearest; NaN → 0. */
SAMPLE_IO_API sample_status sample_io_write_image(const char *path, const float *rgba, int w, int h,
                                    int channels_to_write, const char *colorspace,
                                    sample_error *err);
SAMPLE_IO_API sample_status sample_io_write_image_ex(const char *path, const float *rgba, int w, int h,
                                       int channels_to_write, const sample_io_write_options *o,
                                       sample_error *err);

/* Write a float OpenEXR with `nchannels` named channels (any names, e.g.
 * "ds", "dt", "lod"), data[(y·w + x)·nchannels + c]; no colour conversion. */
SAMPLE_IO_API sample_status sample_io_write_channels(const char *path, const float *data, int w, int h,
                                       int nchannels, const char *const *names,
                                       sample_error *err);

/* ---- Tiled mip-mapped files -------------------------------------------- */

/* Options of the mip-mapped writers (the name is historical: OpenEXR was
 * the first). */
typedef struct sample_io_exr_options {
    int tile_w, tile_h;         /* default 64 × 64 */
    int use_float;              /* type AUTO: 0 (default) half, 1 float */
    sample_wrap wrap_s, wrap_t; /* stored as the "wrapmodes" attribute; default CLAMP_TO_EDGE */
    /* Called after each tile row is written (may be NULL). */
    void (*progress)(void *user, size_t done, size_t total);
    void *progress_user;
    /* AUTO (default): half or float by use_float. HALF and FLOAT store the
     * texture's linear values; U8 and U16 (TIFF only: OpenEXR has no such
     * type) store them sRGB-encoded, as maketx's `-d uint8` does, clamped
     * to [0, 1] and rounded to nearest. */
    sample_io_type type;
    /* Names of the texture's channels (as many as it has); NULL: R, G, B, A.
     * A grey + alpha texture read from a PNG is Y, A. */
    const char *const *channel_names;
    /* Index of the alpha channel, −1 (default) for none. */
    int alpha_channel;
    /* 1: the colour channels are premultiplied by alpha (OpenEXR's rule,
     * and what sample_io_options.premultiply reads). Recorded in the file:
     * the "libsample:alpha" attribute in OpenEXR, the ExtraSamples tag
     * (associated / unassociated alpha) in TIFF. */
    int premultiplied;
    /* Half output: a finite value beyond ±65504 becomes ±inf (0, default)
     * or ±65504 (1). Where half_overflows is not NULL it receives how many
     * values were that large, so a caller can say so. */
    int half_clamp;
    size_t *half_overflows;
    /* The OCIO config whose scene_linear space the texels are in: named in
     * the file (oiio:ColorSpace, chromaticities where known), and the
     * source of U8 / U16's sRGB encoding. NULL: $OCIO if set, else the
     * shipped config (as in sample_io_options). */
    const char *ocio_config;
} sample_io_exr_options;

SAMPLE_IO_API void sample_io_exr_options_init(sample_io_exr_options *o);

/* Write every level of `tex` (decoded to linear values) as a tiled OpenEXR:
 * MIPMAP_LEVELS with ROUND_DOWN sizes when the texture has its full chain,
 * ONE_LEVEL when it has only its base; a partial chain is refused.
 * `o` may be NULL. */
SAMPLE_IO_API sample_status sample_io_write_mip_exr(const char *path, const sample_texture *tex,
                                      const sample_io_exr_options *o, sample_error *err);

/* The same, in the format the path's extension names: .exr as
 * sample_io_write_mip_exr; .tx, .tif, .tiff a tiled TIFF holding every
 * level (maketx's .tx layout, read back by OpenImageIO and by this
 * library). Any other extension, or U8/U16 for OpenEXR, is
 * SAMPLE_E_INVALID_ARGUMENT: such formats hold no mip levels. */
SAMPLE_IO_API sample_status sample_io_write_mip(const char *path, const sample_texture *tex,
                                  const sample_io_exr_options *o, sample_error *err);

/* An image file in, a tiled mip-mapped file out (what maketx does and
 * `texsample mip` calls): the input is read in float (ro's colour space
 * and config; its own levels ignored), straight alpha multiplied into the
 * colour, every level built from the base with `mip`'s kernel and wrap
 * modes (NULL: box, clamp to edge), and the levels written by
 * sample_io_write_mip with wo's tiles, type and half overflow handling
 * (NULL: defaults), the input's channel names, its alpha channel marked
 * premultiplied, and the wrap modes as `wrapmodes`. An output whose
 * extension names a format without levels (or without wo's type) is
 * SAMPLE_E_INVALID_ARGUMENT before the input is read; an input with more
 * than 4 channels is SAMPLE_E_UNSUPPORTED. Nothing is written then. */
SAMPLE_IO_API sample_status sample_io_make_mip(const char *in, const char *out, const sample_io_options *ro,
                                               const sample_mip_params *mip, const sample_io_exr_options *wo,
                                               sample_error *err);

/* ---- Environment maps (doc/environment-maps.md, "Files") --------------- */

/* Read an environment map: a lat-long map into a 2D texture for
 * sample_batch_latlong, a cube map into a cube texture (kind
 * SAMPLE_TEXTURE_CUBE) for sample_batch_cube. A 1:6 image is a cube
 * (OpenEXR's layout: faces +X, −X, +Y, −Y, +Z, −Z stacked from the top,
 * each oriented as OpenEXR's ImfEnvmap.h draws it, which is OpenGL's face
 * mirrored; the faces are turned into GL's orientation), a 2:1 image is
 * lat-long, whatever their attributes say (exrenvmap copies its input's).
 * An image of another shape is lat-long if it says "LatLong Environment"
 * (OpenEXR's "envmap" attribute, OpenImageIO's "textureformat"), else
 * SAMPLE_E_UNSUPPORTED. A lat-long map keeps the file's
 * levels as sample_io_read_texture does; a cube map is read in float and its
 * pyramid built with `mip` across face edges (sample_texture_create_cube):
 * levels stored in a cube file were filtered as one flat image, mixing
 * faces where they meet in the stack. mip NULL: base level only. */
SAMPLE_IO_API sample_status sample_io_read_env(const char *path, const sample_io_options *o,
                                               const sample_mip_params *mip, sample_texture **out,
                                               sample_error *err);

/* Resample an environment map into the other layout (or the same at another
 * size): `to` is SAMPLE_TEXTURE_CUBE (size: the face's side; 0 chooses the
 * lat-long width / 4) or SAMPLE_TEXTURE_2D for lat-long (size: its height,
 * the width twice that; 0 chooses 2 × the face's side). src is a cube
 * texture, or a 2D texture read as lat-long. Each new texel is src
 * filtered by EWA over the footprint of that texel: its centre direction
 * and the derivatives of the direction along the new map's two texel
 * axes, through sample_batch_cube / sample_batch_latlong. The result gets
 * its pyramid from `mip` (NULL: base level only). */
SAMPLE_IO_API sample_status sample_io_env_convert(const sample_texture *src, sample_texture_kind to, int size,
                                                  const sample_mip_params *mip, sample_texture **out,
                                                  sample_error *err);

/* Write an environment map as a tiled OpenEXR (.exr only: the envmap
 * attribute is OpenEXR's) that OpenImageIO reads as an environment: a cube
 * texture in OpenEXR's cube layout (above) with envmap = cube and
 * textureformat "CubeFace Environment"; a 2D texture as a lat-long map,
 * envmap = latlong, textureformat "LatLong Environment", oiio:updirection
 * "y" and wrapmodes "periodic,clamp", as maketx --envlatl writes. Texel
 * (i, j) is at ((i + ½)/w, (j + ½)/h), OpenImageIO's default (no
 * oiio:sampleborder). A cube's levels are written when its side is a power
 * of two and it holds the full chain (the stacked image's levels are then
 * the faces' levels stacked; the two 1 × 3 and 1 × 1 levels below are the
 * 1 × 6 level boxed), otherwise its base only. `o` as for
 * sample_io_write_mip_exr (tile size, type); its wrap modes are not used. */
SAMPLE_IO_API sample_status sample_io_write_env(const char *path, const sample_texture *tex,
                                                const sample_io_exr_options *o, sample_error *err);

#ifdef __cplusplus
}
#endif
#endif /* SAMPLE_SAMPLE_IO_H */
