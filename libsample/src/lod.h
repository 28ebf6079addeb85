/*
 * Level of detail (lod.c): λ from the Jacobian (GL 4.6 §8.14.1), biases
 * and clamps, and the level choice of the OpenGL filters (§8.14.2–8.14.3,
 * DESIGN §5). Inline: the fast path calls these for every query.
 */
#ifndef SAMPLE_LOD_H
#define SAMPLE_LOD_H

#include "ctx.h"

/* log2 ρ in double for a Jacobian in normalized coordinates, on level
 * `base` (GL 4.6 §8.14.1 eq. 8.9, ρ = max of the two column lengths), and
 * the squared column lengths ρx², ρy² in base texels (the anisotropic
 * filter's Px², Py²). In double: a 1e20 Jacobian squared overflows float,
 * and λ must still be right; float inputs times a level size squared stay
 * far inside double's range, so no hypot is needed. −inf for a zero
 * Jacobian. */
static inline double lod_log2_rho(const sample_ctx *c, const sample_query *q, double rho2[2])
{
    const struct sample_level *L = &c->tex->level[c->base];
    double ux = (double)q->dsdx * L->w, vx = (double)q->dtdx * L->h;
    double uy = (double)q->dsdy * L->w, vy = (double)q->dtdy * L->h;
    rho2[0] = ux * ux + vx * vx;
    rho2[1] = uy * uy + vy * vy;
    /* log2 ρ = ½ log2 ρ² (sample_log2: the same bits on any machine). */
    return 0.5 * sample_log2(rho2[0] > rho2[1] ? rho2[0] : rho2[1]);
}

/* λ_base = log2 ρ (eq. 8.7 before bias and clamps), as a float. */
static inline float lod_lambda_base(const sample_ctx *c, const sample_query *q)
{
    double rho2[2];
    return (float)lod_log2_rho(c, q, rho2);
}

typedef struct lod_choice {
    int magnify;      /* 1: use mag_filter on level base */
    sample_filter kind; /* per-level reconstruction: NEAREST, LINEAR or CUBIC */
    int level0, level1; /* level1 = −1 unless two levels are blended */
    float frac;       /* weight of level1 */
} lod_choice;

/* λ after sampler bias, per-call bias (clamped to ±max_lod_bias) and the
 * min/max lod clamp (GL 4.6 §8.14.1). Inline (with lod_select): the fast
 * path calls both for every query. */
static inline float lod_lambda(const sample_ctx *c, float lambda_base, float call_bias)
{
    /* λ' = λ_base + clamp(bias_texobj + bias_shader, ±MAX_TEXTURE_LOD_BIAS)
     * (eq. 8.6); λ = clamp(λ', lod_min, lod_max) (eq. 8.7). */
    const sample_sampler *s = c->smp;
    float bias = s->lod_bias + call_bias;
    float lam;
    if (bias > s->max_lod_bias) bias = s->max_lod_bias;
    if (bias < -s->max_lod_bias) bias = -s->max_lod_bias;
    lam = lambda_base + bias;
    if (lam > s->max_lod) lam = s->max_lod;
    if (lam < s->min_lod) lam = s->min_lod;
    return lam;
}

/* The per-level reconstruction of a filter. */
static inline sample_filter lod_level_kind(sample_filter f)
{
    switch (f) {
    case SAMPLE_NEAREST:
    case SAMPLE_NEAREST_MIPMAP_NEAREST:
    case SAMPLE_NEAREST_MIPMAP_LINEAR:
        return SAMPLE_NEAREST;
    case SAMPLE_CUBIC:
    case SAMPLE_CUBIC_MIPMAP_NEAREST:
    case SAMPLE_CUBIC_MIPMAP_LINEAR:
        return SAMPLE_CUBIC;
    default:
        return SAMPLE_LINEAR;
    }
}

/* Level selection for the OpenGL filters (GL 4.6 §8.14.2–8.14.3). */
SAMPLE_FORCE_INLINE lod_choice lod_select(const sample_ctx *c, float lambda)
{
    const sample_sampler *s = c->smp;
    lod_choice r;
    float cswitch = 0.0f;
    int base = c->base, q = c->maxlev;
    r.level1 = -1;
    r.frac = 0.0f;
    /* §8.14.3: λ ≤ c selects magnification. Since GL 4.5 c = 0; the older
     * c = 0.5 for (mag LINEAR, min NEAREST_MIPMAP_*) is an option. */
    if ((s->options & SAMPLE_OPT_LEGACY_SWITCHOVER) && s->mag_filter == SAMPLE_LINEAR &&
        (s->min_filter == SAMPLE_NEAREST_MIPMAP_NEAREST || s->min_filter == SAMPLE_NEAREST_MIPMAP_LINEAR))
        cswitch = 0.5f;
    if (lambda <= cswitch) {
        r.magnify = 1;
        r.kind = lod_level_kind(s->mag_filter);
        r.level0 = base;
        return r;
    }
    r.magnify = 0;
    r.kind = lod_level_kind(s->min_filter);
    switch (s->min_filter) {
    case SAMPLE_NEAREST_MIPMAP_NEAREST:
    case SAMPLE_LINEAR_MIPMAP_NEAREST:
    case SAMPLE_CUBIC_MIPMAP_NEAREST: {
        /* d = level_base                     if λ ≤ ½
         *     ⌈level_base + λ + ½⌉ − 1       if λ > ½ and level_base + λ ≤ q + ½
         *     q                              if λ > ½ and level_base + λ > q + ½
         * (eq. 8.16; ⌊level_base + λ + ½⌋ is the permitted alternative). */
        double p = (double)base + (double)lambda;
        if (lambda <= 0.5f)
            r.level0 = base;
        else if (p > (double)q + 0.5)
            r.level0 = q;
        else if (s->options & SAMPLE_OPT_NEAREST_LEVEL_FLOOR)
            r.level0 = (int)floor(p + 0.5);
        else
            r.level0 = (int)ceil(p + 0.5) - 1;
        if (r.level0 > q) r.level0 = q;
        return r;
    }
    case SAMPLE_NEAREST_MIPMAP_LINEAR:
    case SAMPLE_LINEAR_MIPMAP_LINEAR:
    case SAMPLE_CUBIC_MIPMAP_LINEAR: {
        /* d1 = q if level_base + λ ≥ q, else ⌊level_base + λ⌋; d2 = d1 + 1
         * (or q); τ = (1 − frac(λ)) τ1 + frac(λ) τ2 (eqs. 8.17–8.18). */
        double p = (double)base + (double)lambda;
        if (p >= (double)q) {
            r.level0 = q;
        } else {
            r.level0 = (int)floor(p);
            r.level1 = r.level0 + 1;
            r.frac = (float)(p - floor(p));
            if (r.frac == 0.0f) r.level1 = -1;
        }
        return r;
    }
    default:
        /* NEAREST, LINEAR, CUBIC: level_base only. */
        r.level0 = base;
        return r;
    }
}

/* For footprint filters: continuous level position for λ (clamped to the
 * usable range), split into two adjacent levels and the weight of the upper. */
void ls_lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac);

#endif /* SAMPLE_LOD_H */
