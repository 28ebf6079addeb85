/*
 * Stochastic filtering (stochastic.h): what the filters share — the
 * uniform input, the choice between two blended levels, the anisotropic
 * filter's one-probe estimate and the weighted texel draws of the
 * footprint filters' level loop (ls_fp_run_draw).
 *
 * Every estimate is unbiased by construction: a choice made with
 * probability equal to its weight in the deterministic sum, the chosen
 * term's value not reweighted; with signed weights (the EWA kernels'
 * negative lobes) a texel is drawn with probability |w|/Σ|w| and counted
 * with sign(w)·Σ|w|/Σw (importance sampling). Stratifying the k draws of
 * one query over [0, 1) keeps that expectation and lowers the variance.
 */
#include "stochastic.h"

#include "aniso.h"
#include "footprint.h"
#include "kernels.h"

double ls_stochastic_u(const sample_batch_args *a, size_t i)
{
    double u = a->u[i];
    if (!(fabs(u) < INFINITY)) return 0.0;
    u -= floor(u);
    return u >= 0.0 && u < 1.0 ? u : 0.0; /* floor's rounding at −tiny */
}

int ls_stochastic_pick2(double f, double *u)
{
    double v;
    int second;
    if (!(f > 0.0)) return 0;
    if (!(f < 1.0)) return 1;
    second = *u < f;
    v = second ? *u / f : (*u - f) / (1.0 - f);
    *u = v >= 0.0 && v < 1.0 ? v : 0.0;
    return second;
}

uint32_t ls_fp_aniso_draw(const sample_ctx *c, const sample_query *q, float call_bias, double u, float out[4],
                          sample_stats *st)
{
    double rho2[2], lr = lod_log2_rho(c, q, rho2), x;
    fp_aniso_setup a;
    float s, t;
    int i;
    ls_fp_aniso_setup_of(c, q, rho2, lr, call_bias, &a);
    /* Probe i + 1 for u in [i/N, (i + 1)/N); the rest of u picks its
     * level. */
    x = u * a.n;
    i = (int)x;
    if (i > a.n - 1) i = a.n - 1;
    u = x - i;
    if (!(u >= 0.0 && u < 1.0)) u = 0.0;
    fp_aniso_probe(q, &a, i + 1, &s, &t);
    if (st) fp_aniso_stats(&a, st);
    return ctx_readers(c)->bilinear(c, a.l1 != a.l0 && ls_stochastic_pick2(a.f, &u) ? a.l1 : a.l0, s, t, out,
                                    NULL, NULL);
}

uint32_t ls_fp_run_draw(const sample_ctx *c, const fp_run_state *rs, double u, int draws, float out[4],
                        sample_stats *st)
{
    double at[64], scale;
    fp_accum a, d;
    int lv, k, j;
    uint32_t n;
    if (!rs->ok) return ls_fp_run_read(c, rs, out, NULL, NULL, st); /* the deterministic fallback */
    if (draws < 1) draws = 1;
    if (draws > 64) draws = 64;
    lv = rs->l1 != rs->l0 && ls_stochastic_pick2(rs->f, &u) ? rs->l1 : rs->l0;
    /* Σw and Σ|w| of the level, then the draws at (j + u)/k of Σ|w|. */
    ls_fp_accum_init(&a);
    n = (uint32_t)rs->level(c, rs->geom, lv, &a, 0);
    if (st) {
        st->level0 = (int16_t)lv;
        st->level1 = -1;
        st->level_frac = 0.0f;
        st->lod = rs->lam;
    }
    if (!(a.sw > 0.0)) return n + ls_fp_run_read(c, rs, out, NULL, NULL, st);
    for (j = 0; j < draws; ++j) at[j] = (j + u) / draws * a.sabs;
    ls_fp_accum_init(&d);
    d.draw = 1;
    d.at = at;
    d.draws = draws;
    n += (uint32_t)rs->level(c, rs->geom, lv, &d, 0);
    /* Targets the rounding of the running sum left past its end. */
    for (; d.drawn < draws; d.drawn++)
        for (k = 0; k < 4; ++k) d.sD[k] += d.lastsign * d.lastT[k];
    scale = a.sabs / a.sw / draws;
    for (k = 0; k < 4; ++k) out[k] = (float)(d.sD[k] * scale);
    return n;
}
