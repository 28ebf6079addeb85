/*
 * Sampler state, validation and the batch dispatch: the state is checked and
 * the per-batch context built once; each query then takes one path.
 */
#include "internal.h"

void sample_sampler_init(sample_sampler *s)
{
    /* OpenGL 4.6 table 23.18 (sampler object state) initial values. */
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->wrap_s = s->wrap_t = SAMPLE_WRAP_REPEAT;
    s->min_filter = SAMPLE_NEAREST_MIPMAP_LINEAR;
    s->mag_filter = SAMPLE_LINEAR;
    s->min_lod = -1000.0f;
    s->max_lod = 1000.0f;
    s->base_level = 0;
    s->max_level = 1000;
    s->max_anisotropy = 1.0f;
    /* MAX_TEXTURE_LOD_BIAS: the minimum an implementation must support is
     * 2; 16 is what desktop drivers report. */
    s->max_lod_bias = 16.0f;
    s->footprint = SAMPLE_FOOTPRINT_NONE;
    s->cubic = SAMPLE_CUBIC_CATMULL_ROM;
}

void sample_mip_params_init(sample_mip_params *p)
{
    if (!p) return;
    p->filter = SAMPLE_MIPGEN_BOX;
    p->wrap_s = p->wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    p->max_levels = 0;
}

sample_status sample_sampler_validate(const sample_sampler *s)
{
    if (!s) return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->wrap_s >= SAMPLE_WRAP_COUNT || (unsigned)s->wrap_t >= SAMPLE_WRAP_COUNT)
        return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->min_filter >= SAMPLE_FILTER_COUNT) return SAMPLE_E_INVALID_ARGUMENT;
    if (s->mag_filter != SAMPLE_NEAREST && s->mag_filter != SAMPLE_LINEAR && s->mag_filter != SAMPLE_CUBIC)
        return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->footprint >= SAMPLE_FOOTPRINT_COUNT || (unsigned)s->cubic >= SAMPLE_CUBIC_COUNT)
        return SAMPLE_E_INVALID_ARGUMENT;
    /* NaN fails every comparison below, so it is rejected too. */
    if (!(s->max_anisotropy >= 1.0f) || !isfinite(s->max_anisotropy)) return SAMPLE_E_INVALID_ARGUMENT;
    if (!isfinite(s->lod_bias) || !(s->max_lod_bias >= 0.0f)) return SAMPLE_E_INVALID_ARGUMENT;
    if (isnan(s->min_lod) || isnan(s->max_lod) || s->min_lod > s->max_lod) return SAMPLE_E_INVALID_ARGUMENT;
    if (s->base_level < 0 || s->max_level < s->base_level) return SAMPLE_E_INVALID_ARGUMENT;
    return SAMPLE_OK;
}

/* Reconstruct and blend the levels an OpenGL filter chose for λ. */
static uint32_t gl_apply(const sample_ctx *c, const sample_query *q, float lam, const lod_choice *ch,
                         float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    uint32_t n = recon_level(c, ch->level0, ch->kind, q->s, q->t, out, dds, ddt);
    if (ch->level1 >= 0) {
        float o1[4], ds1[4], dt1[4];
        n += recon_level(c, ch->level1, ch->kind, q->s, q->t, o1, dds ? ds1 : NULL, ddt ? dt1 : NULL);
        recon_blend(out, o1, ch->frac);
        if (dds) recon_blend(dds, ds1, ch->frac);
        if (ddt) recon_blend(ddt, dt1, ch->frac);
    }
    if (st) {
        st->level0 = (int16_t)ch->level0;
        st->level1 = (int16_t)ch->level1;
        st->level_frac = ch->frac;
        st->lod = lam;
    }
    return n;
}

uint32_t sample_gl(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                   float dds[4], float ddt[4], sample_stats *st)
{
    float lam = lod_lambda(c, lod_lambda_base(c, q), call_bias);
    lod_choice ch = lod_select(c, lam);
    return gl_apply(c, q, lam, &ch, out, dds, ddt, st);
}

/* What a query will do, decided for a block of queries before any texel is
 * read, so that the texel rows can be prefetched: random queries into a
 * large texture are bound by memory latency, and overlapping the misses of
 * several queries is worth more than any arithmetic saving. */
typedef struct query_plan {
    enum { PLAN_BORDER, PLAN_GL, PLAN_FOOTPRINT } kind;
    float lam;
    lod_choice ch;
} query_plan;

enum { PLAN_BLOCK = 16 };

static void plan_query(const sample_ctx *c, const sample_batch_args *a, size_t i, query_plan *pl)
{
    const sample_query *q = &a->queries[i];
    float bias = a->lod_bias ? a->lod_bias[i] : 0.0f;
    if (!batch_query_finite(a, i)) {
        pl->kind = PLAN_BORDER;
        return;
    }
    pl->lam = lod_lambda(c, lod_lambda_base(c, q), bias);
    if (c->smp->footprint != SAMPLE_FOOTPRINT_NONE && pl->lam > 0.0f) {
        pl->kind = PLAN_FOOTPRINT;
        return;
    }
    pl->kind = PLAN_GL;
    pl->ch = lod_select(c, pl->lam);
    ctx_prefetch_bilinear(c, pl->ch.level0, q->s, q->t);
    if (pl->ch.level1 >= 0) ctx_prefetch_bilinear(c, pl->ch.level1, q->s, q->t);
}

void sample_run_footprint(const sample_ctx *c, const sample_batch_args *a, size_t i,
                          const struct fp_plan *pl)
{
    const sample_query *q = &a->queries[i];
    float *out = a->rgba + 4 * i;
    float *dds = a->drgba_ds ? a->drgba_ds + 4 * i : NULL;
    float *ddt = a->drgba_dt ? a->drgba_dt + 4 * i : NULL;
    sample_stats local, *st = a->stats ? &a->stats[i] : &local;
    float bias = a->lod_bias ? a->lod_bias[i] : 0.0f;
    const sample_quad *corners = a->corners ? &a->corners[i] : NULL;
    uint32_t n;

    st->level0 = st->level1 = -1;
    st->level_frac = 0.0f;
    st->lod = 0.0f;
    if (pl) {
        n = fp_footprint_run(c, pl, out, dds, ddt, st);
    } else {
        switch (c->smp->footprint) {
        case SAMPLE_FOOTPRINT_ANISOTROPIC:
            n = fp_anisotropic(c, q, bias, out, dds, ddt, st);
            break;
        case SAMPLE_FOOTPRINT_BLINN_NEWELL:
            n = fp_blinn_newell(c, q, corners, bias, out, dds, ddt, st);
            break;
        case SAMPLE_FOOTPRINT_EWA:
        default:
            n = fp_ewa(c, q, bias, out, dds, ddt, st);
            break;
        }
    }
    st->texels = n;
}

static void run_query(const sample_ctx *c, const sample_batch_args *a, size_t i, const query_plan *pl)
{
    const sample_query *q = &a->queries[i];
    float *out = a->rgba + 4 * i;
    float *dds = a->drgba_ds ? a->drgba_ds + 4 * i : NULL;
    float *ddt = a->drgba_dt ? a->drgba_dt + 4 * i : NULL;
    sample_stats local, *st = a->stats ? &a->stats[i] : &local;
    uint32_t n = 0;

    if (pl->kind == PLAN_FOOTPRINT) {
        sample_run_footprint(c, a, i, NULL);
        return;
    }
    st->level0 = st->level1 = -1;
    st->level_frac = 0.0f;
    st->lod = 0.0f;
    switch (pl->kind) {
    case PLAN_BORDER:
        memcpy(out, c->border, sizeof c->border);
        if (dds) memset(dds, 0, 4 * sizeof(float));
        if (ddt) memset(ddt, 0, 4 * sizeof(float));
        break;
    case PLAN_GL:
        n = gl_apply(c, q, pl->lam, &pl->ch, out, dds, ddt, st);
        break;
    case PLAN_FOOTPRINT: /* above */
        break;
    }
    st->texels = n;
}

sample_status sample_batch(const sample_texture *tex, const sample_sampler *smp,
                           const sample_batch_args *a)
{
    sample_ctx c;
    sample_status st;
    fast_gl_fn fast;
    size_t i;
    if (!tex || !a) return SAMPLE_E_INVALID_ARGUMENT;
    if ((st = sample_sampler_validate(smp)) != SAMPLE_OK) return st;
    if (a->count == 0) return SAMPLE_OK;
    if (!a->queries || !a->rgba) return SAMPLE_E_INVALID_ARGUMENT;
    c.tex = tex;
    c.smp = smp;
    memcpy(c.border, smp->border_color, sizeof c.border);
    /* level_base and q (§8.14.3): base clamped to the levels present (an
     * OpenGL texture would be incomplete; we read the last level instead),
     * q = min(level_max, last level). */
    c.base = smp->base_level < tex->nlevels ? smp->base_level : tex->nlevels - 1;
    c.maxlev = smp->max_level < tex->nlevels - 1 ? smp->max_level : tex->nlevels - 1;
    if (c.maxlev < c.base) c.maxlev = c.base;
    /* The specialized loop where one applies; the general one below is the
     * reference it must match bit for bit. */
    if (!(smp->options & SAMPLE_OPT_SCALAR_PATH) && (fast = fast_gl_select(&c, a)) != NULL) {
        fast(&c, a);
        return SAMPLE_OK;
    }
    for (i = 0; i < a->count; i += PLAN_BLOCK) {
        query_plan plan[PLAN_BLOCK];
        size_t k, m = a->count - i < PLAN_BLOCK ? a->count - i : PLAN_BLOCK;
        for (k = 0; k < m; ++k) plan_query(&c, a, i + k, &plan[k]);
        for (k = 0; k < m; ++k) run_query(&c, a, i + k, &plan[k]);
    }
    return SAMPLE_OK;
}

sample_status sample_one(const sample_texture *tex, const sample_sampler *smp,
                         const sample_query *query, float rgba[4])
{
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = query;
    a.rgba = rgba;
    return sample_batch(tex, smp, &a);
}
