/*
 * libsample — texture filtering and mipmap sampling.
 *
 * This header is the manual. Read it top to bottom.
 *
 * 1. QUICK START
 *
 *     sample_image img = { .width = w, .height = h, .channels = 4,
 *                          .format = SAMPLE_FORMAT_F32, .data = pixels };
 *     sample_mip_params mip;  sample_mip_params_init(&mip);
 *     sample_texture *tex;
 *     sample_error err;
 *     if (sample_texture_create(&img, &mip, &tex, &err) != SAMPLE_OK)
 *         fprintf(stderr, "%s\n", err.message);
 *     sample_sampler s;  sample_sampler_init(&s);     // OpenGL defaults
 *     s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;     // trilinear
 *     float rgba[4];
 *     sample_one(tex, &s, &(sample_query){ u, v, dsdx, dtdx, dsdy, dtdy }, rgba);
 *     sample_texture_destroy(tex);
 *
 * 2. COORDINATES (doc/semantics.md, DESIGN §2)
 *
 *   Normalized (s, t): texel (i, j) of a w × h level has its centre at
 *   ((i + ½)/w, (j + ½)/h). Row 0 in memory is at t = 0. A query carries the
 *   screen-space Jacobian in GLSL textureGrad order: dPdx = (dsdx, dtdx),
 *   dPdy = (dsdy, dtdy). A zero Jacobian means "no footprint" (magnification
 *   of the base level). Filtering is always done on linear values; 8-bit sRGB
 *   texels are decoded with the exact sRGB EOTF first. Output is float RGBA:
 *   1 channel reads as (r, 0, 0, 1), 2 as (r, g, 0, 1), 3 as (r, g, b, 1),
 *   as OpenGL's R, RG and RGB formats do.
 *
 * 3. API LEVELS
 *
 *   sample_batch() is the primary entry point: one sampler state, an array of
 *   queries, arrays of results. It validates and specializes once per call.
 *   sample_one() is a thin wrapper over it.
 *
 * 4. MEMORY AND THREADS
 *
 *   A texture is immutable after creation: every function taking a
 *   `const sample_texture *` may be called from any number of threads at once.
 *   Nothing is allocated while sampling. The only global state is which
 *   instruction set sampling runs on (section 6), decided once, thread-safe.
 *   sample_texture_destroy() must not race with readers of the same texture.
 *
 * 5. BAD INPUT (DESIGN §10, doc/guarantees.md)
 *
 *   Creation validates everything and returns a status plus a message;
 *   nothing half-built is ever returned. A query whose (s, t) or Jacobian
 *   holds NaN or ±inf returns the sampler's border colour. Coordinates far
 *   outside [0, 1] wrap as specified and never index out of bounds. Every
 *   footprint filter reads at most SAMPLE_MAX_FOOTPRINT_TEXELS texels.
 *
 * 6. INSTRUCTION SETS (doc/performance.md)
 *
 *   The sampling loops are built for several instruction sets — portable
 *   C ("scalar"), SSE2 and AVX2 on x86-64, and AVX-512 where the build is
 *   asked for it (doc/performance.md) — and the best one this CPU supports
 *   is picked on first use. Every one returns the same bits,
 *   on every machine: they do the same IEEE operations in the same order,
 *   never fused, and call no C math library (whose last bits vary between
 *   libraries). The environment variable LIBSAMPLE_ISA=scalar|sse2|avx2|
 *   avx512, read once, caps the choice (a level the CPU or the build lacks
 *   falls back to the best below it); sample_isa_name() says what runs.
 */
#ifndef SAMPLE_SAMPLE_H
#define SAMPLE_SAMPLE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

/* SAMPLE_API marks every public function. The library is compiled with
 * -fvisibility=hidden, so these are the only symbols libsample.so exports;
 * its build defines SAMPLE_BUILDING_SHARED. Empty for the static library,
 * for programs using either, and for compilers other than GCC and Clang. */
#ifndef SAMPLE_API
#if defined(SAMPLE_BUILDING_SHARED) && (defined(__GNUC__) || defined(__clang__))
#define SAMPLE_API __attribute__((visibility("default")))
#else
#define SAMPLE_API
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define SAMPLE_VERSION_MAJOR 0
#define SAMPLE_VERSION_MINOR 1
#define SAMPLE_VERSION_PATCH 0
#define SAMPLE_VERSION_STRING "0.1.0"

/* Largest texture side accepted, and the number of levels that implies. */
#define SAMPLE_MAX_SIZE 65536
#define SAMPLE_MAX_LEVELS 17
/* Texel budget of one footprint-filtered query (anisotropic, Blinn–Newell,
 * EWA), summed over the levels it reads. A degenerate or huge footprint is
 * clamped to stay within it, so no query can stall a renderer. */
#define SAMPLE_MAX_FOOTPRINT_TEXELS 1024

/* ---- Errors ----------------------------------------------------------- */

typedef enum sample_status {
    SAMPLE_OK = 0,
    SAMPLE_E_INVALID_ARGUMENT = 1, /* NULL where an object is needed, bad enum */
    SAMPLE_E_BAD_SIZE = 2,         /* zero, negative or inconsistent sizes */
    SAMPLE_E_TOO_LARGE = 3,        /* over SAMPLE_MAX_SIZE or bytes overflow */
    SAMPLE_E_OUT_OF_MEMORY = 4,    /* an allocation failed; nothing was kept */
    SAMPLE_E_UNSUPPORTED = 5,      /* valid request this build cannot serve */
    SAMPLE_E_IO = 6,               /* libsample_io: file could not be read/written */
    SAMPLE_E_CORRUPT = 7,          /* libsample_io: file is malformed */
    SAMPLE_E_COLOR = 8,            /* libsample_io: colour-space conversion failed */
    SAMPLE_STATUS_COUNT
} sample_status;

/* A short, static, English name of a status ("invalid argument"). */
SAMPLE_API const char *sample_strerror(sample_status status);

/* Optional detail for creation calls: pass NULL if not wanted. */
typedef struct sample_error {
    sample_status status;
    char message[256]; /* what was wrong, with the offending values */
} sample_error;

/* Fill `err` (if not NULL) with a status and a printf-style message, and
 * return the status: how libsample and libraries built on it (libsample_io)
 * report errors in one way. */
SAMPLE_API sample_status sample_error_set(sample_error *err, sample_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
SAMPLE_API sample_status sample_error_vset(sample_error *err, sample_status status, const char *fmt, va_list ap);

/* ---- Textures ---------------------------------------------------------- */

typedef enum sample_format {
    SAMPLE_FORMAT_F32 = 0,    /* 32-bit float per channel */
    SAMPLE_FORMAT_F16 = 1,    /* IEEE half per channel */
    SAMPLE_FORMAT_UNORM8 = 2, /* 8-bit, value/255 */
    SAMPLE_FORMAT_SRGB8 = 3,  /* 8-bit sRGB-encoded colour; alpha (4th) is linear */
    SAMPLE_FORMAT_COUNT
} sample_format;

/* Bytes of one channel of a format (4, 2, 1, 1). */
SAMPLE_API size_t sample_format_bytes(sample_format format);

/* A caller-owned image: the library copies what it needs. */
typedef struct sample_image {
    int width, height;
    int channels;         /* 1 to 4 */
    sample_format format;
    const void *data;     /* row 0 first (t = 0), channels interleaved */
    size_t row_stride;    /* bytes between rows; 0 means tightly packed */
} sample_image;

typedef enum sample_wrap {
    SAMPLE_WRAP_REPEAT = 0,                 /* i mod n */
    SAMPLE_WRAP_MIRRORED_REPEAT = 1,        /* mirror every other period */
    SAMPLE_WRAP_CLAMP_TO_EDGE = 2,          /* clamp(i, 0, n−1) */
    SAMPLE_WRAP_CLAMP_TO_BORDER = 3,        /* outside reads the border colour */
    SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE = 4,   /* mirror once, then clamp to edge */
    SAMPLE_WRAP_CLAMP = 5,                  /* legacy GL_CLAMP: LINEAR blends border */
    SAMPLE_WRAP_MIRROR_CLAMP = 6,           /* GL_MIRROR_CLAMP_EXT */
    SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER = 7, /* GL_MIRROR_CLAMP_TO_BORDER_EXT */
    SAMPLE_WRAP_COUNT
} sample_wrap;

typedef enum sample_mipgen {
    SAMPLE_MIPGEN_NONE = 0,     /* base level only */
    SAMPLE_MIPGEN_BOX = 1,      /* 2-tap box, 3-tap polyphase box on odd axes */
    SAMPLE_MIPGEN_LANCZOS3 = 2, /* windowed sinc, a = 3 */
    SAMPLE_MIPGEN_KAISER = 3,   /* Kaiser-windowed sinc (alpha 4, width 3) */
    SAMPLE_MIPGEN_COUNT
} sample_mipgen;

/* How a pyramid is built at creation (DESIGN §6). Down-sampling is done on
 * linear values; kernels that reach past an edge read as the wrap modes say
 * (a texture meant to tile should be built with REPEAT). */
typedef struct sample_mip_params {
    sample_mipgen filter; /* default SAMPLE_MIPGEN_BOX */
    sample_wrap wrap_s, wrap_t; /* default CLAMP_TO_EDGE */
    int max_levels;       /* 0 = all the way to 1×1 (1×1×1 for a volume) */
    sample_wrap wrap_r;   /* across a volume's slices; default CLAMP_TO_EDGE */
} sample_mip_params;

SAMPLE_API void sample_mip_params_init(sample_mip_params *params);

/* What a texture is, as OpenGL's texture targets say it (GL 4.6 §8.1):
 * the shape of its levels and the coordinates a query gives. A 2D texture
 * (GL_TEXTURE_2D: levels of w × h texels) takes queries (s, t) with a
 * 2 × 2 Jacobian (sample_batch). A cube map (GL_TEXTURE_CUBE_MAP: six
 * square faces per level) and a 3D texture (GL_TEXTURE_3D: w × h × d
 * texels per level) take 9-float queries (sample_query3) through their
 * own batch entry points; the filters and the texel addressing below them
 * are shared. */
typedef enum sample_texture_kind {
    SAMPLE_TEXTURE_2D = 0,
    SAMPLE_TEXTURE_CUBE = 1,
    SAMPLE_TEXTURE_3D = 2,
    SAMPLE_TEXTURE_KIND_COUNT
} sample_texture_kind;

typedef struct sample_texture sample_texture;

/* Copy `image` into a new texture and, unless mip is NULL or mip->filter is
 * SAMPLE_MIPGEN_NONE, build its pyramid. */
SAMPLE_API sample_status sample_texture_create(const sample_image *image,
                                    const sample_mip_params *mip,
                                    sample_texture **out, sample_error *err);

/* Create from caller-supplied levels (e.g. read from a mip-mapped file).
 * levels[k] must be max(1, ⌊w/2^k⌋) × max(1, ⌊h/2^k⌋) with the same channel
 * count and format as levels[0]. A partial chain (count < full) is allowed. */
SAMPLE_API sample_status sample_texture_create_levels(const sample_image *levels, int count,
                                           sample_texture **out, sample_error *err);

/* A cube map (GL_TEXTURE_CUBE_MAP, GL 4.6 §8.13) from its six faces in
 * OpenGL's order +X, −X, +Y, −Y, +Z, −Z, each a square N × N image of the
 * same size, channel count and format, row 0 at t = 0 as glTexImage2D
 * takes a face (so a face's (s, t) is table 8.19's). Unless mip is NULL or
 * mip->filter is SAMPLE_MIPGEN_NONE the pyramid is built face by face, the
 * kernels reading across face edges from the adjacent faces (seamless, as
 * sampling reads them) so that every level is continuous across edges;
 * mip->wrap_s/wrap_t are not used. Sampled by direction with
 * sample_batch_cube(); doc/environment-maps.md. */
SAMPLE_API sample_status sample_texture_create_cube(const sample_image faces[6], const sample_mip_params *mip,
                                                    sample_texture **out, sample_error *err);

/* A cube map from caller-supplied levels: count × 6 images, level-major
 * (faces[6k + f] is face f of level k), level k's faces max(1, ⌊N/2^k⌋)
 * square. A partial chain is allowed, as sample_texture_create_levels. */
SAMPLE_API sample_status sample_texture_create_cube_levels(const sample_image *faces, int count,
                                                           sample_texture **out, sample_error *err);

SAMPLE_API void sample_texture_destroy(sample_texture *tex); /* accepts NULL */

typedef struct sample_texture_info {
    int width, height, channels, levels;
    sample_format format;
    size_t bytes; /* texel memory held, all levels */
    sample_texture_kind kind;
    int depth; /* layers of level 0: a 3D texture's slices, a cube map's 6 faces, 1 for 2D */
} sample_texture_info;

SAMPLE_API void sample_texture_info_get(const sample_texture *tex, sample_texture_info *info);
/* Size of level k (0 ≤ k < levels); returns 0 and zeros if k is out of range. */
SAMPLE_API int sample_texture_level_size(const sample_texture *tex, int level, int *w, int *h);
/* Decoded linear RGBA float of texel (i, j) of a level, no wrapping: for
 * tests and tools, not for sampling loops. Out-of-range gives 0. */
SAMPLE_API void sample_texture_texel(const sample_texture *tex, int level, int i, int j, float rgba[4]);
/* The same for layer `layer` of a level: the face of a cube map (0 … 5,
 * GL order). Out-of-range gives 0. */
SAMPLE_API void sample_texture_texel_layer(const sample_texture *tex, int level, int layer, int i, int j,
                                           float rgba[4]);

/* ---- Sampler state (mirrors an OpenGL sampler object) ------------------- */

typedef enum sample_filter {
    SAMPLE_NEAREST = 0,
    SAMPLE_LINEAR = 1,
    SAMPLE_NEAREST_MIPMAP_NEAREST = 2,
    SAMPLE_LINEAR_MIPMAP_NEAREST = 3,
    SAMPLE_NEAREST_MIPMAP_LINEAR = 4,
    SAMPLE_LINEAR_MIPMAP_LINEAR = 5, /* trilinear */
    /* Engine extensions: Catmull–Rom/B-spline/Mitchell (see `cubic`) per level. */
    SAMPLE_CUBIC = 6,                /* mag or min: one level (the base) */
    SAMPLE_CUBIC_MIPMAP_NEAREST = 7,
    SAMPLE_CUBIC_MIPMAP_LINEAR = 8,
    SAMPLE_FILTER_COUNT
} sample_filter;

typedef enum sample_cubic {
    SAMPLE_CUBIC_CATMULL_ROM = 0, /* B = 0, C = ½: interpolating (VK_EXT_filter_cubic) */
    SAMPLE_CUBIC_BSPLINE = 1,     /* B = 1, C = 0: smoothing, non-negative */
    SAMPLE_CUBIC_MITCHELL = 2,    /* B = C = ⅓ */
    SAMPLE_CUBIC_COUNT
} sample_cubic;

/* Minification beyond the OpenGL filters (DESIGN §7). When not NONE it
 * replaces min_filter whenever λ > 0; magnification still uses mag_filter. */
typedef enum sample_footprint {
    SAMPLE_FOOTPRINT_NONE = 0,         /* min_filter, as OpenGL */
    SAMPLE_FOOTPRINT_ANISOTROPIC = 1,  /* GPU-style probes (EXT_texture_filter_anisotropic) */
    SAMPLE_FOOTPRINT_BLINN_NEWELL = 2, /* pyramid-weighted quadrilateral (1976) */
    SAMPLE_FOOTPRINT_EWA = 3,          /* elliptical Gaussian (Heckbert 1989, pbrt-v4) */
    SAMPLE_FOOTPRINT_FELINE = 4,       /* EWA's ellipse by weighted trilinear probes (McCormack 1999) */
    SAMPLE_FOOTPRINT_COUNT
} sample_footprint;

/* The radial weight of the EWA footprint filter (doc/footprint-filters.md,
 * "Radial kernels"), as a function of the distance r from the centre in
 * pixels (r = 1 on the ellipse of conjugate semi-axes dPdx, dPdy, widened by
 * Heckbert's reconstruction term), normalised by the weights' sum. The
 * sharp kernels have negative lobes (SAMPLE_OPT_EWA_CLAMP bounds their
 * ringing) and run on the reference path's per-texel walk. */
typedef enum sample_ewa_kernel {
    SAMPLE_EWA_GAUSSIAN = 0, /* e^(−2r²) − e^(−2), r < 1 (Heckbert, pbrt-v4) */
    SAMPLE_EWA_LANCZOS2 = 1, /* sinc(r)·sinc(r/2), r < 2 */
    SAMPLE_EWA_LANCZOS3 = 2, /* sinc(r)·sinc(r/3), r < 3 */
    SAMPLE_EWA_MITCHELL = 3, /* Mitchell–Netravali cubic, B = C = ⅓, r < 2 */
    SAMPLE_EWA_KERNEL_COUNT
} sample_ewa_kernel;

/* Options that change a specified behaviour; all off by default. */
enum {
    /* Pre-4.5 rule: switch-over c = 0.5 when mag is LINEAR and min is
     * NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR (GL 4.6 §8.14.3 note). */
    SAMPLE_OPT_LEGACY_SWITCHOVER = 1u << 0,
    /* NEAREST_MIPMAP_*: d = ⌊base + λ + ½⌋ (allowed alternative, Mesa's)
     * instead of the preferred ⌈base + λ + ½⌉ − 1. */
    SAMPLE_OPT_NEAREST_LEVEL_FLOOR = 1u << 1,
    /* Clamp Catmull–Rom / Mitchell overshoot to the 2×2 neighbourhood range. */
    SAMPLE_OPT_CUBIC_CLAMP = 1u << 2,
    /* Anisotropic: round the probe count up to a power of two. */
    SAMPLE_OPT_ANISO_POW2 = 1u << 3,
    /* 1u << 4 is reserved. */
    /* Blinn–Newell corners: texel weight pyramid / |det| of the quad map (screen-space integral). */
    SAMPLE_OPT_BN_AREA_WEIGHT = 1u << 5,
    /* EWA with a kernel that has negative lobes: clamp each channel to the
     * range of the texels in the kernel's support, level by level. */
    SAMPLE_OPT_EWA_CLAMP = 1u << 6,
};

typedef struct sample_sampler {
    sample_wrap wrap_s, wrap_t;   /* default REPEAT */
    sample_wrap wrap_r;           /* third coordinate of a 3D texture; default REPEAT */
    sample_filter min_filter;     /* default NEAREST_MIPMAP_LINEAR (GL default) */
    sample_filter mag_filter;     /* NEAREST, LINEAR or CUBIC; default LINEAR */
    float border_color[4];        /* linear RGBA; default 0,0,0,0 */
    float lod_bias;               /* GL_TEXTURE_LOD_BIAS; default 0 */
    float min_lod, max_lod;       /* default −1000, 1000 */
    int base_level, max_level;    /* default 0, 1000 */
    float max_anisotropy;         /* ≥ 1; default 1. Used by ANISOTROPIC */
    float max_lod_bias;           /* |sampler + per-call bias| limit; default 16 */
    sample_footprint footprint;   /* default NONE */
    sample_cubic cubic;           /* default CATMULL_ROM */
    unsigned options;             /* SAMPLE_OPT_* */
    sample_ewa_kernel ewa_kernel; /* EWA's radial weight; default GAUSSIAN */
} sample_sampler;

/* OpenGL's initial sampler-object state (GL 4.6 table 23.18). */
SAMPLE_API void sample_sampler_init(sample_sampler *sampler);
/* Checks enums and ranges; sample_batch() calls it too. */
SAMPLE_API sample_status sample_sampler_validate(const sample_sampler *sampler);

/* ---- Queries ----------------------------------------------------------- */

/* 6 floats, the order of the `lookup` query file. */
typedef struct sample_query {
    float s, t;
    float dsdx, dtdx; /* dPdx */
    float dsdy, dtdy; /* dPdy */
} sample_query;

/* The exact texture-space images of the corners of the 2 × 2-pixel region
 * centred on the pixel, screen offsets (−1,−1), (+1,−1), (+1,+1), (−1,+1) in
 * that order, as (s, t) pairs. Used by Blinn–Newell; other filters ignore it. */
typedef struct sample_quad {
    float st[4][2];
} sample_quad;

/* What one query did; for benchmarks and tests. */
typedef struct sample_stats {
    uint32_t texels;   /* texel reads (a footprint filter's visited texels) */
    int16_t level0;    /* first level read (−1: none, e.g. NaN input) */
    int16_t level1;    /* second level blended, or −1 */
    float level_frac;  /* weight of level1 */
    float lod;         /* λ after bias and clamps */
} sample_stats;

typedef struct sample_batch_args {
    size_t count;
    const sample_query *queries; /* count entries; required */
    const sample_quad *corners;  /* optional: exact footprint corners */
    const float *lod_bias;       /* optional: per-query bias (GLSL `bias`) */
    float *rgba;                 /* count × 4 results; required */
    float *drgba_ds;             /* optional: count × 4, ∂result/∂s */
    float *drgba_dt;             /* optional: count × 4, ∂result/∂t */
    sample_stats *stats;         /* optional: count entries */
    /* optional: count entries, each a uniform random number in [0, 1):
     * stochastic filtering (doc/footprint-filters.md, "Stochastic
     * filtering"). Each query then returns one random estimate whose
     * expectation over u is the deterministic filter's result: trilinear
     * reads one level (chosen with its blend weight), anisotropic one
     * probe, Feline one probe, EWA and Blinn–Newell `draws` texels drawn
     * in proportion to |weight|. A value outside [0, 1) is reduced to its
     * fractional part (NaN reads as 0). Runs the reference path;
     * derivatives, when asked for, are the deterministic filter's. */
    const float *u;
    unsigned draws; /* texels per EWA / Blinn–Newell estimate; 0 reads as 1 */
} sample_batch_args;

/* Sample `count` queries. Results are bit-for-bit independent of how a job is
 * split into batches or threads. Derivatives are of the filtered result with
 * respect to (s, t) at fixed footprint; NEAREST gives 0. */
SAMPLE_API sample_status sample_batch(const sample_texture *tex, const sample_sampler *sampler,
                           const sample_batch_args *args);

/* A query of a cube map or a 3D texture: 9 floats, GLSL textureGrad's
 * order. For a cube map p is the direction R (any length but zero) and
 * dpdx, dpdy its screen derivatives; for a 3D texture p is (s, t, r) and
 * dpdx, dpdy the columns of its 3 × 2 Jacobian. */
typedef struct sample_query3 {
    float p[3];
    float dpdx[3];
    float dpdy[3];
} sample_query3;

/* A batch of sample_query3 queries, as sample_batch_args. */
typedef struct sample_batch3_args {
    size_t count;
    const sample_query3 *queries; /* count entries; required */
    const float *lod_bias;        /* optional: per-query bias (GLSL `bias`) */
    float *rgba;                  /* count × 4 results; required */
    sample_stats *stats;          /* optional: count entries */
} sample_batch3_args;

/* Sample a cube map (sample_texture_create_cube) by direction, as GLSL's
 * textureGrad(samplerCube, R, dRdx, dRdy) with GL_TEXTURE_CUBE_MAP_SEAMLESS
 * (doc/environment-maps.md). Query p is the direction R (any length),
 * dpdx and dpdy its screen derivatives. The face and its (s, t) are GL 4.6
 * table 8.19's; λ comes from the derivatives of the face coordinates
 * (the quotient rule of §8.13, with the ma term), then bias, clamps and
 * base/max level as for 2D. Every filter reads texels past a face edge
 * from the adjacent face, and a corner texel is the mean of the three
 * texels beside it (§8.13.1). The sampler's wrap modes are ignored, as
 * GL ignores them for seamless cube maps. A NaN, infinite or zero
 * direction, or a non-finite derivative or bias, gives the border colour.
 * Cube maps run the reference path (one query at a time). Refuses a
 * texture of another kind (SAMPLE_E_INVALID_ARGUMENT). */
SAMPLE_API sample_status sample_batch_cube(const sample_texture *tex, const sample_sampler *sampler,
                                           const sample_batch3_args *args);

/* Sample a 2D texture as a lat-long (equirectangular) environment map by
 * direction (doc/environment-maps.md), with OpenImageIO's convention for
 * lat-long maps whose up direction is +y:
 *   s = atan2(−x, z)/2π + ½,  t = ½ − atan2(y, √(x² + z²))/π
 * (+y is row 0, +z the middle column, the seam s = 0 = 1 towards −z).
 * Texels past s = 0 or 1 wrap (REPEAT); a row past t = 0 or t = 1 is read
 * over the pole, from the other half of the map (s + ½, the row mirrored),
 * so no filter shows the seam or the poles. λ and the footprint filters
 * take the Jacobian of (s, t) from the exact derivatives of the two
 * angles, strongly anisotropic near the poles (where it is held finite).
 * The sampler's wrap modes are not used. Bad input as sample_batch_cube. */
SAMPLE_API sample_status sample_batch_latlong(const sample_texture *tex, const sample_sampler *sampler,
                                              const sample_batch3_args *args);

/* An environment lookup as OpenImageIO's environment(R, dRdx, dRdy): a
 * cube map through sample_batch_cube, a 2D texture as a lat-long map
 * through sample_batch_latlong. */
SAMPLE_API sample_status sample_batch_env(const sample_texture *tex, const sample_sampler *sampler,
                                          const sample_batch3_args *args);
/* ---- 3D textures (doc/volumes.md) --------------------------------------
 *
 * A 3D texture (SAMPLE_TEXTURE_3D, GL_TEXTURE_3D) is w × h × d texels:
 * texel (i, j, k) has its centre at ((i + ½)/w, (j + ½)/h, (k + ½)/d) in
 * (s, t, r); slice k = 0 is at r = 0. Level k is max(1, ⌊w/2^k⌋) ×
 * max(1, ⌊h/2^k⌋) × max(1, ⌊d/2^k⌋), down to 1 × 1 × 1, built on linear
 * values as 2D pyramids are (box; polyphase box on odd axes; the sinc
 * kernels), mip->wrap_r deciding what a kernel reads past r's edges.
 *
 * Queries are sample_query3: p = (s, t, r), dpdx and dpdy the columns of
 * the 3 × 2 Jacobian (GLSL textureGrad(sampler3D, P, dPdx, dPdy)). λ uses
 * ρ over all three components (GL 4.6 §8.14.1: the longer of the
 * texel-space columns (w·ds, h·dt, d·dr)); every min and mag filter,
 * bias, clamp, base/max level and border colour is the sampler's, with
 * wrap_r on r. LINEAR is trilinear within a level (eq. 8.11), CUBIC
 * tricubic (4 × 4 × 4 texels). The footprint filters integrate over the
 * flat patch a pixel's footprint is inside the volume (the parallelogram
 * spanned by dpdx and dpdy). 3D textures are sampled one query at a time
 * (no vector fast path); results are deterministic as in section 6. */

/* A caller-owned volume: `depth` slices of width × height texels. */
typedef struct sample_volume {
    int width, height, depth;
    int channels;          /* 1 to 4 */
    sample_format format;
    const void *data;      /* slice 0 (r = 0) first, each slice row 0 first */
    size_t row_stride;     /* bytes between rows; 0 means tightly packed */
    size_t slice_stride;   /* bytes between slices; 0 means row_stride × height */
} sample_volume;

/* Copy `volume` into a new 3D texture and, unless mip is NULL or
 * mip->filter is SAMPLE_MIPGEN_NONE, build its pyramid. */
SAMPLE_API sample_status sample_texture_create_3d(const sample_volume *volume, const sample_mip_params *mip,
                                                  sample_texture **out, sample_error *err);
/* A 3D texture from caller-supplied levels: levels[k] must be
 * max(1, ⌊w/2^k⌋) × max(1, ⌊h/2^k⌋) × max(1, ⌊d/2^k⌋), the channel count
 * and format of levels[0]; a partial chain is allowed. */
SAMPLE_API sample_status sample_texture_create_3d_levels(const sample_volume *levels, int count,
                                                         sample_texture **out, sample_error *err);
/* Size of level k of any texture (d is 1 for 2D); 0 and zeros if k is out
 * of range. */
SAMPLE_API int sample_texture_level_size3(const sample_texture *tex, int level, int *w, int *h, int *d);
/* A volume's texel (i, j) of slice k is sample_texture_texel_layer's
 * layer k. */

/* Sample `count` queries of a 3D texture (SAMPLE_E_INVALID_ARGUMENT for
 * another kind). A query whose p, dpdx, dpdy or bias holds NaN or ±inf
 * returns the border colour; footprint filters read at most
 * SAMPLE_MAX_FOOTPRINT_TEXELS texels. */
SAMPLE_API sample_status sample_batch_3d(const sample_texture *tex, const sample_sampler *sampler,
                                         const sample_batch3_args *args);

/* One query; a thin wrapper over sample_batch(). */
SAMPLE_API sample_status sample_one(const sample_texture *tex, const sample_sampler *sampler,
                         const sample_query *query, float rgba[4]);

/* The instruction set sampling runs on in this process (section 6):
 * "scalar", "sse2", "avx2" or "avx512". Static string; decides the choice
 * if no sampling has yet. For tools to print what ran; results do not
 * depend on it. */
SAMPLE_API const char *sample_isa_name(void);

/* ---- Names ------------------------------------------------------------- */

/* Lower-case names as the command line spells them ("clamp_to_edge",
 * "linear_mipmap_linear", "catmull-rom", "blinn-newell"). Parsing returns −1
 * for an unknown name. */
SAMPLE_API const char *sample_wrap_name(sample_wrap wrap);
SAMPLE_API int sample_wrap_parse(const char *name);
SAMPLE_API const char *sample_filter_name(sample_filter filter);
SAMPLE_API int sample_filter_parse(const char *name);
SAMPLE_API const char *sample_cubic_name(sample_cubic cubic);
SAMPLE_API int sample_cubic_parse(const char *name);
SAMPLE_API const char *sample_footprint_name(sample_footprint footprint);
SAMPLE_API int sample_footprint_parse(const char *name);
SAMPLE_API const char *sample_ewa_kernel_name(sample_ewa_kernel kernel); /* "gaussian", "lanczos2", … */
SAMPLE_API int sample_ewa_kernel_parse(const char *name);
SAMPLE_API const char *sample_mipgen_name(sample_mipgen mipgen);
SAMPLE_API int sample_mipgen_parse(const char *name);
SAMPLE_API const char *sample_format_name(sample_format format);
SAMPLE_API const char *sample_texture_kind_name(sample_texture_kind kind); /* "2d", "cube", "3d" */

/* ---- Colour helpers ---------------------------------------------------- */

SAMPLE_API float sample_srgb_to_linear(float v); /* exact sRGB EOTF (IEC 61966-2-1) */
SAMPLE_API float sample_linear_to_srgb(float v); /* its inverse */
SAMPLE_API float sample_half_to_float(uint16_t h);
SAMPLE_API uint16_t sample_float_to_half(float f); /* round to nearest even */

#ifdef __cplusplus
}
#endif
#endif /* SAMPLE_SAMPLE_H */
