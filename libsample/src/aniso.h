/*
 * The anisotropic filter (footprint_aniso.c; EXT_texture_filter_anisotropic
 * as GL 4.6 §8.14.1 allows, DESIGN §7): N trilinear probes along the
 * major axis of the footprint.
 */
#ifndef SAMPLE_ANISO_H
#define SAMPLE_ANISO_H

#include "lod.h"

/* Each returns texels read, fills out (and dds/ddt if non-NULL) and stats
 * (if non-NULL: level0/level1/level_frac). `lambda_base` is lod_lambda_base
 * of q; the filter applies sampler/per-call bias itself via lod_lambda. Each
 * reads at most SAMPLE_MAX_FOOTPRINT_TEXELS texels. */
uint32_t ls_fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st);

/* At most this many weighted probes in an fp_probe_set (8 texels each on
 * two levels: within SAMPLE_MAX_FOOTPRINT_TEXELS); a multiple of the fast
 * path's ANISO_LANES. */
#define FP_PROBES_MAX 96

/* Probes at explicit positions with their own weights (Feline,
 * footprint_feline.c): probe i at (s[i], t[i]) (normalized) weighs
 * w[i] / sw. */
typedef struct fp_probe_set {
    float s[FP_PROBES_MAX], t[FP_PROBES_MAX];
    double w[FP_PROBES_MAX], sw;
} fp_probe_set;

/* What the anisotropic filter decides per query before reading a texel
 * (footprint_aniso.c): N probes along the major column, λ' and its two
 * levels. The fast path computes it when it plans a query and runs the
 * probes later with its own bilinear; ls_fp_anisotropic does both at once.
 * With `set` the n probes are that set's, weighted (Feline); without, N
 * equal probes along the major column (the anisotropic filter). */
typedef struct fp_aniso_setup {
    int n, l0, l1;  /* probe count; levels (l1 == l0: a single level) */
    float lam, f;   /* λ' after biases and clamps; the weight of level l1 */
    double ms, mt;  /* the major column (normalized): the probes' axis */
    const fp_probe_set *set; /* NULL: the anisotropic filter's probes */
} fp_aniso_setup;

/* From lod_log2_rho's ρx², ρy² and log2 ρ of the query. */
void ls_fp_aniso_setup_of(const sample_ctx *c, const sample_query *q, const double rho2[2],
                       double log2_rho, float call_bias, fp_aniso_setup *a);
/* A prefetch of every probe's rows (a hint), from positions stepped in
 * float: the fast path's planning step for the queries whose probes it does
 * not address exactly ahead (fast_gl.c, aniso_address). */
void ls_fp_aniso_prefetch(const sample_ctx *c, const sample_query *q, const fp_aniso_setup *a);

/* Probe i (1 … N) of a query: offsets i/(N + 1) − ½ of the major column. */
SAMPLE_FORCE_INLINE void fp_aniso_probe(const sample_query *q, const fp_aniso_setup *a, int i, float *s,
                                        float *t)
{
    double off = (double)i / (a->n + 1) - 0.5;
    *s = (float)(q->s + off * a->ms);
    *t = (float)(q->t + off * a->mt);
}

/* One probe's trilinear value (1 − f)·a + f·b added to the sums: equal
 * weights, summed in double so that the mean of N equal probes is that
 * probe exactly. */
SAMPLE_FORCE_INLINE void fp_aniso_add(double acc[4], double f, const float a[4], const float b[4])
{
    /* acc + ((1 − f)·a + f·b) on each channel (simd.h's v4d, so that the
     * four channels are one or two vector operations, not eight scalar
     * ones). */
    v4d p = v4d_add(v4d_mul(v4d_set1(1.0 - f), v4d_of(v4_load(a))), v4d_mul(v4d_set1(f), v4d_of(v4_load(b))));
    v4d_store(acc, v4d_add(v4d_load(acc), p));
}

/* One weighted probe's trilinear value w·((1 − f)·a + f·b) added to the
 * sums (an fp_probe_set's probe). */
SAMPLE_FORCE_INLINE void fp_probe_add(double acc[4], double w, double f, const float a[4], const float b[4])
{
    v4d p = v4d_add(v4d_mul(v4d_set1(1.0 - f), v4d_of(v4_load(a))), v4d_mul(v4d_set1(f), v4d_of(v4_load(b))));
    v4d_store(acc, v4d_add(v4d_load(acc), v4d_mul(v4d_set1(w), p)));
}

/* The weighted mean of a probe set's sums. */
SAMPLE_FORCE_INLINE void fp_probe_mean(const double acc[4], double sw, float out[4])
{
    int k;
    for (k = 0; k < 4; ++k) out[k] = (float)(acc[k] / sw);
}

/* The mean of n probes' sums. */
SAMPLE_FORCE_INLINE void fp_aniso_mean(const double acc[4], int n, float out[4])
{
    int k;
    for (k = 0; k < 4; ++k) out[k] = (float)(acc[k] / n);
}

/* One level's bilinear value at (s, t), as ls_recon_level computes it; the
 * per-format tex_readers.bilinear, or the fast path's inline copy of it. */
typedef uint32_t (*fp_bilinear_fn)(const sample_ctx *c, int lv, float s, float t, float out[4],
                                   float dds[4], float ddt[4]);

/* The N trilinear probes and their mean (weighted where a->set). Generic
 * over the bilinear reader so that the fast path's instantiation inlines
 * it (zstd style) while ls_fp_anisotropic and ls_fp_feline call the reader
 * table: one loop, the same bits. */
SAMPLE_FORCE_INLINE uint32_t fp_aniso_probes(const sample_ctx *c, const sample_query *q,
                                             const fp_aniso_setup *a, fp_bilinear_fn bilinear,
                                             float out[4], float dds[4], float ddt[4])
{
    double acc[4] = {0, 0, 0, 0}, as[4] = {0, 0, 0, 0}, at[4] = {0, 0, 0, 0};
    double f = (double)a->f;
    uint32_t texels = 0;
    int i;
    for (i = 1; i <= a->n; ++i) {
        float s, t, o0[4], s0[4], t0[4], o1[4], s1[4], t1[4];
        if (a->set)
            s = a->set->s[i - 1], t = a->set->t[i - 1];
        else
            fp_aniso_probe(q, a, i, &s, &t);
        /* Derivatives only where asked for: they do not touch the value. */
        texels += bilinear(c, a->l0, s, t, o0, dds ? s0 : NULL, ddt ? t0 : NULL);
        if (a->l1 != a->l0) {
            texels += bilinear(c, a->l1, s, t, o1, dds ? s1 : NULL, ddt ? t1 : NULL);
        } else {
            memcpy(o1, o0, sizeof o1);
            if (dds) memcpy(s1, s0, sizeof s1);
            if (ddt) memcpy(t1, t0, sizeof t1);
        }
        if (a->set) {
            const double w = a->set->w[i - 1];
            fp_probe_add(acc, w, f, o0, o1);
            if (dds) fp_probe_add(as, w, f, s0, s1);
            if (ddt) fp_probe_add(at, w, f, t0, t1);
        } else {
            fp_aniso_add(acc, f, o0, o1);
            if (dds) fp_aniso_add(as, f, s0, s1);
            if (ddt) fp_aniso_add(at, f, t0, t1);
        }
    }
    if (a->set) {
        fp_probe_mean(acc, a->set->sw, out);
        if (dds) fp_probe_mean(as, a->set->sw, dds);
        if (ddt) fp_probe_mean(at, a->set->sw, ddt);
    } else {
        fp_aniso_mean(acc, a->n, out);
        if (dds) fp_aniso_mean(as, a->n, dds);
        if (ddt) fp_aniso_mean(at, a->n, ddt);
    }
    return texels;
}

/* The levels and λ' of an anisotropic query, as sample_stats reports them. */
static inline void fp_aniso_stats(const fp_aniso_setup *a, sample_stats *st)
{
    st->level0 = (int16_t)a->l0;
    st->level1 = (int16_t)(a->l1 != a->l0 ? a->l1 : -1);
    st->level_frac = a->l1 != a->l0 ? a->f : 0.0f;
    st->lod = a->lam;
}
/* Anisotropic probe count N for Pmax ≥ Pmin (base texels) under the
 * sampler's max_anisotropy and SAMPLE_OPT_ANISO_POW2 (footprint_aniso.c). */
int ls_fp_aniso_count(const sample_sampler *smp, double pmax, double pmin);

#endif /* SAMPLE_ANISO_H */
