/*
 * Level of detail and level selection (DESIGN §5; OpenGL 4.6 core
 * §8.14.1 "Scale Factor and Level of Detail", §8.14.2, §8.14.3 "Mipmapping").
 */
#include "internal.h"

float lod_lambda_base(const sample_ctx *c, const sample_query *q)
{
    /* ρ = max{ √((∂u/∂x)² + (∂v/∂x)²), √((∂u/∂y)² + (∂v/∂y)²) } (eq. 8.9),
     * u = s·w_t, v = t·h_t with w_t × h_t the size of level_base. In double:
     * a 1e20 Jacobian squared overflows float, and λ must still be right. */
    const struct sample_level *L = &c->tex->level[c->base];
    double ux = (double)q->dsdx * L->w, vx = (double)q->dtdx * L->h;
    double uy = (double)q->dsdy * L->w, vy = (double)q->dtdy * L->h;
    double px = ux * ux + vx * vx, py = uy * uy + vy * vy;
    double p = px > py ? px : py;
    /* log2 ρ = ½ log2 ρ²; p = 0 gives −inf (magnification). */
    return (float)(0.5 * log2(p));
}

float lod_lambda(const sample_ctx *c, float lambda_base, float call_bias)
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

static sample_filter level_kind(sample_filter f)
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

lod_choice lod_select(const sample_ctx *c, float lambda)
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
        r.kind = level_kind(s->mag_filter);
        r.level0 = base;
        return r;
    }
    r.magnify = 0;
    r.kind = level_kind(s->min_filter);
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

void lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac)
{
    double p = (double)c->base + (lambda > 0.0f ? (double)lambda : 0.0);
    if (p >= (double)c->maxlev) {
        *l0 = *l1 = c->maxlev;
        *frac = 0.0f;
        return;
    }
    *l0 = (int)floor(p);
    *l1 = *l0 + 1;
    *frac = (float)(p - floor(p));
}
