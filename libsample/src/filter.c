/*
 * The filters of one query (filter.h): the OpenGL filters' levels
 * reconstructed and blended, and the footprint filters, each registered
 * once in footprint_filters below.
 */
#include "filter.h"
#include "footprint_feline.h"
#include "stochastic.h"

uint32_t ls_filter_gl_levels(const sample_ctx *c, const sample_query *q, float lam, const lod_choice *ch,
                          float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    uint32_t n = ls_recon_level(c, ch->level0, ch->kind, q->s, q->t, out, dds, ddt);
    if (ch->level1 >= 0) {
        float o1[4], ds1[4], dt1[4];
        n += ls_recon_level(c, ch->level1, ch->kind, q->s, q->t, o1, dds ? ds1 : NULL, ddt ? dt1 : NULL);
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

/* The footprint filters by sample_footprint value, in one signature:
 * (context, query, corners or NULL, per-call bias, result, ∂/∂s, ∂/∂t,
 * stats). NONE has no entry: min_filter applies (lod_select). */
typedef uint32_t (*footprint_fn)(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                                 float call_bias, float out[4], float dds[4], float ddt[4], sample_stats *st);

static uint32_t footprint_aniso(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                                float call_bias, float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    (void)corners; /* the probes follow the Jacobian */
    return ls_fp_anisotropic(c, q, call_bias, out, dds, ddt, st);
}

static uint32_t footprint_ewa(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                              float call_bias, float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    (void)corners; /* the ellipse is the Jacobian's */
    return ls_fp_ewa(c, q, call_bias, out, dds, ddt, st);
}

static uint32_t footprint_feline(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                                 float call_bias, float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    (void)corners; /* the ellipse is the Jacobian's */
    return ls_fp_feline(c, q, call_bias, NULL, out, dds, ddt, st);
}

static const footprint_fn footprint_filters[] = {
    [SAMPLE_FOOTPRINT_NONE] = NULL,
    [SAMPLE_FOOTPRINT_ANISOTROPIC] = footprint_aniso,
    [SAMPLE_FOOTPRINT_BLINN_NEWELL] = ls_fp_blinn_newell,
    [SAMPLE_FOOTPRINT_EWA] = footprint_ewa,
    [SAMPLE_FOOTPRINT_FELINE] = footprint_feline,
};
_Static_assert(sizeof footprint_filters / sizeof footprint_filters[0] == SAMPLE_FOOTPRINT_COUNT,
               "one entry per footprint filter");

/* A footprint filter's stochastic estimate (sample_batch_args.u): one
 * probe (anisotropic, Feline) or `draws` texels (Blinn–Newell, EWA). */
static void footprint_draw(const sample_ctx *c, const sample_batch_args *a, size_t i, float out[4], sample_stats *st)
{
    const sample_query *q = &a->queries[i];
    const float bias = a->lod_bias ? a->lod_bias[i] : 0.0f;
    double u = ls_stochastic_u(a, i);
    fp_plan pl;
    switch (c->smp->footprint) {
    case SAMPLE_FOOTPRINT_ANISOTROPIC: st->texels = ls_fp_aniso_draw(c, q, bias, u, out, st); break;
    case SAMPLE_FOOTPRINT_FELINE: st->texels = ls_fp_feline(c, q, bias, &u, out, NULL, NULL, st); break;
    default:
        ls_fp_footprint_plan(c, q, a->corners ? &a->corners[i] : NULL, bias, &pl);
        st->texels = ls_fp_run_draw(c, &pl.rs, u, a->draws ? (int)(a->draws < 64 ? a->draws : 64) : 1, out, st);
        break;
    }
}

void ls_filter_footprint_query(const sample_ctx *c, const sample_batch_args *a, size_t i, const fp_plan *pl)
{
    const sample_query *q = &a->queries[i];
    float *out = a->rgba + 4 * i;
    float *dds = a->drgba_ds ? a->drgba_ds + 4 * i : NULL;
    float *ddt = a->drgba_dt ? a->drgba_dt + 4 * i : NULL;
    sample_stats local, *st = a->stats ? &a->stats[i] : &local;
    footprint_fn f = footprint_filters[c->smp->footprint];

    stats_clear(st);
    if (a->u && f) {
        footprint_draw(c, a, i, out, st);
        /* Derivatives are the deterministic filter's (sample.h). */
        if (dds || ddt) {
            float o[4];
            f(c, q, a->corners ? &a->corners[i] : NULL, a->lod_bias ? a->lod_bias[i] : 0.0f, o, dds, ddt, NULL);
        }
    } else if (pl) {
        st->texels = ls_fp_footprint_run(c, pl, out, dds, ddt, st);
    } else if (f) {
        st->texels = f(c, q, a->corners ? &a->corners[i] : NULL, a->lod_bias ? a->lod_bias[i] : 0.0f, out, dds,
                       ddt, st);
    } else {
        /* NONE is never handed here (the batch loops send its queries to
         * lod_select); should it be, the result is still defined. */
        st->texels = ls_filter_gl_levels(c, q, 0.0f, &(lod_choice){.magnify = 1, .kind = SAMPLE_LINEAR, .level0 = c->base,
                                                              .level1 = -1}, out, dds, ddt, st);
    }
}
