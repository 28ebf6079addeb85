/*
 * libsample internal header: the one place the library's pieces meet.
 *
 *   texture.c      storage, formats, texel decode, creation/validation
 *   color.c        sRGB EOTF table, half <-> float
 *   wrap.c         the single texel-addressing function (DESIGN §3)
 *   reconstruct.c  nearest / bilinear / bicubic on one level (DESIGN §4)
 *   lod.c          λ and level selection (DESIGN §5, GL 4.6 §8.14)
 *   mip.c          pyramid building (DESIGN §6)
 *   footprint_*.c  anisotropic, Blinn–Newell, EWA (DESIGN §7)
 *   sampler.c      validation and per-batch dispatch
 *   names.c        enum <-> string, strerror
 */
#ifndef SAMPLE_INTERNAL_H
#define SAMPLE_INTERNAL_H

#include "sample/sample.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* Record an error with a formatted message when the caller asked for one. */
sample_status sample_fail(sample_error *err, sample_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
#define RETURN_ERROR_IF(cond, err, status, ...)                                \
    do {                                                                       \
        if (cond) return sample_fail((err), (status), __VA_ARGS__);            \
    } while (0)

/* ---- Storage ------------------------------------------------------------ */

struct sample_level {
    int w, h;
    size_t stride;       /* bytes per row */
    unsigned char *data; /* owned */
};

struct sample_texture {
    int width, height, channels, nlevels;
    sample_format format;
    size_t texel_bytes; /* channels × format bytes */
    size_t bytes;       /* all levels */
    struct sample_level level[SAMPLE_MAX_LEVELS];
};

/* The exact sRGB EOTF for each 8-bit code (color.c). */
extern const float sample_srgb_table[256];

/* Decode texel (i, j) (both in range) of a level to linear RGBA with the
 * OpenGL channel expansion (missing G, B → 0, missing A → 1). */
static inline void tex_decode(const sample_texture *tex, const struct sample_level *lv,
                              int i, int j, float out[4])
{
    const unsigned char *p = lv->data + (size_t)j * lv->stride + (size_t)i * tex->texel_bytes;
    float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    int c, nc = tex->channels;
    switch (tex->format) {
    case SAMPLE_FORMAT_F32:
        memcpy(v, p, (size_t)nc * sizeof(float));
        break;
    case SAMPLE_FORMAT_F16:
        for (c = 0; c < nc; ++c) {
            uint16_t h;
            memcpy(&h, p + 2 * c, 2);
            v[c] = sample_half_to_float(h);
        }
        break;
    case SAMPLE_FORMAT_UNORM8:
        /* c / 255 correctly rounded (GL 4.6 eq. 2.1); a multiply by the
         * rounded reciprocal is off by an ulp for some codes. */
        for (c = 0; c < nc; ++c) v[c] = (float)p[c] / 255.0f;
        break;
    case SAMPLE_FORMAT_SRGB8:
        /* Alpha of an sRGB format is linear (GL 4.6 §8.24). */
        for (c = 0; c < nc; ++c)
            v[c] = (c < 3) ? sample_srgb_table[p[c]] : (float)p[c] / 255.0f;
        break;
    default:
        break;
    }
    out[0] = v[0]; out[1] = v[1]; out[2] = v[2]; out[3] = v[3];
}

/* Encode linear RGBA (first `channels` values) into one texel of the
 * texture's format; used by the pyramid builder. */
void tex_encode(const sample_texture *tex, const float in[4], unsigned char *dst);

/* Allocate level k's storage (size from the level rule); tex->bytes updated. */
sample_status tex_alloc_level(sample_texture *tex, int k, sample_error *err);

/* ---- Wrapping (wrap.c) -------------------------------------------------- */

/* Wrap modes that transform the coordinate before indexing (GL_CLAMP and the
 * EXT mirror-clamps) do it here: s → s', normalized, for an axis of n texels.
 * Other modes return s unchanged. NaN must be rejected before. */
float wrap_coord(sample_wrap mode, float s, int n);

/* The single addressing function (DESIGN §3): integral index i (a double so
 * that any float coordinate's floor is exact) on an axis of n texels → a
 * texel index in [0, n), or −1 for "border colour". `linear` selects the
 * LINEAR/footprint rule of legacy CLAMP (clamp to [−1, n]) instead of the
 * NEAREST rule (clamp to [0, n−1]). */
int wrap_index(sample_wrap mode, double i, int n, int linear);

/* ---- Per-batch context --------------------------------------------------- */

typedef struct sample_ctx {
    const sample_texture *tex;
    const sample_sampler *smp;
    float border[4];
    int base;      /* effective base level */
    int maxlev;    /* q: last level that may be used (GL 4.6 §8.14.3) */
} sample_ctx;

/* Read texel (i, j) of level `lv` through the wrap modes; border colour where
 * the wrap says so. Every filter reads texels through this. */
static inline void ctx_texel(const sample_ctx *c, int lv, double i, double j, int linear,
                             float out[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    int x = wrap_index(c->smp->wrap_s, i, L->w, linear);
    int y = wrap_index(c->smp->wrap_t, j, L->h, linear);
    if (x < 0 || y < 0) {
        out[0] = c->border[0]; out[1] = c->border[1];
        out[2] = c->border[2]; out[3] = c->border[3];
        return;
    }
    tex_decode(c->tex, L, x, y, out);
}

/* ---- Reconstruction on one level (reconstruct.c) ------------------------ */

/* kind is SAMPLE_NEAREST, SAMPLE_LINEAR or SAMPLE_CUBIC. (s, t) normalized.
 * dds/ddt (may be NULL) receive ∂/∂s and ∂/∂t of the result. Returns the
 * number of texels read. */
uint32_t recon_level(const sample_ctx *c, int lv, sample_filter kind, float s, float t,
                     float out[4], float dds[4], float ddt[4]);

/* Cubic kernel weights for fractional offset f ∈ [0, 1): taps at −1, 0, 1, 2,
 * and their derivatives d/df (dw may be NULL). */
void cubic_weights(sample_cubic kind, float f, double w[4], double dw[4]);

/* ---- Level of detail (lod.c) --------------------------------------------- */

/* λ_base = log2 ρ for a Jacobian in normalized coordinates, on level `base`
 * (GL 4.6 §8.14.1 eq. 8.7, ρ = max of the two column lengths). Returns
 * −inf for a zero Jacobian. */
float lod_lambda_base(const sample_ctx *c, const sample_query *q);

/* λ after sampler bias, per-call bias (clamped to ±max_lod_bias) and the
 * min/max lod clamp (GL 4.6 §8.14.1). */
float lod_lambda(const sample_ctx *c, float lambda_base, float call_bias);

typedef struct lod_choice {
    int magnify;      /* 1: use mag_filter on level base */
    sample_filter kind; /* per-level reconstruction: NEAREST, LINEAR or CUBIC */
    int level0, level1; /* level1 = −1 unless two levels are blended */
    float frac;       /* weight of level1 */
} lod_choice;

/* Level selection for the OpenGL filters (GL 4.6 §8.14.2–8.14.3). */
lod_choice lod_select(const sample_ctx *c, float lambda);

/* For footprint filters: continuous level position for λ (clamped to the
 * usable range), split into two adjacent levels and the weight of the upper. */
void lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac);

/* ---- Pyramid (mip.c) ----------------------------------------------------- */

/* Fill levels 1 … of a texture whose level 0 is loaded (DESIGN §6).
 * On failure the extra levels are freed and tex->nlevels is back to 1. */
sample_status mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err);

/* ---- Footprint filters --------------------------------------------------- */

/* Each returns texels read, fills out (and dds/ddt if non-NULL) and stats
 * (if non-NULL: level0/level1/level_frac). `lambda_base` is lod_lambda_base
 * of q; the filter applies sampler/per-call bias itself via lod_lambda. Each
 * reads at most SAMPLE_MAX_FOOTPRINT_TEXELS texels. */
uint32_t fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st);
uint32_t fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st);
uint32_t fp_ewa(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                float dds[4], float ddt[4], sample_stats *st);

/* One OpenGL-filtered query (LOD + level selection + reconstruction +
 * blend); the anisotropic probes use it. Returns texels read. */
uint32_t sample_gl(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                   float dds[4], float ddt[4], sample_stats *st);

#endif /* SAMPLE_INTERNAL_H */
