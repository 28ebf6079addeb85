/*
 * Anisotropic filtering, GPU style (DESIGN §7; OpenGL 4.6 §8.14.1 with
 * ARB/EXT_texture_filter_anisotropic, whose reference implementation this
 * follows):
 *
 *   Px = |dP/dx|, Py = |dP/dy| in base-level texels
 *   N  = min(⌈Pmax / Pmin⌉, maxAniso)       λ = log2(Pmax / N)
 *   τ  = 1/N · Σ_{i=1..N} τ_trilinear(P + (i/(N + 1) − ½)·dP_major, λ)
 *
 * so the probes are spread over one pixel step along the major column
 * (offsets from −½ + 1/(N + 1) to ½ − 1/(N + 1)), not over the 2 × 2 region.
 */
#include "internal.h"

/* At most this many probes: 8 texels each (two bilinear levels) stay within
 * SAMPLE_MAX_FOOTPRINT_TEXELS whatever max_anisotropy says. */
#define ANISO_MAX_PROBES (SAMPLE_MAX_FOOTPRINT_TEXELS / 8)

/* N for a footprint (exposed to the tests through fp_aniso_count). */
int fp_aniso_count(const sample_sampler *smp, double pmax, double pmin)
{
    /* maxAniso is a float state; probes are whole, so its integer part. */
    double maxa = floor((double)smp->max_anisotropy), ratio;
    int n, p2;
    if (maxa > ANISO_MAX_PROBES) maxa = ANISO_MAX_PROBES;
    if (maxa < 1.0) maxa = 1.0;
    /* Pmin = 0 (a rank-one footprint) is the limit of an unbounded ratio. */
    ratio = pmin > 0.0 ? ceil(pmax / pmin) : maxa;
    n = (int)(ratio < maxa ? (ratio < 1.0 ? 1.0 : ratio) : maxa);
    if (smp->options & SAMPLE_OPT_ANISO_POW2) {
        /* Round up, as hardware with power-of-two probe counts does; this
         * may exceed maxAniso (by less than 2×) but never the texel cap. */
        for (p2 = 1; p2 < n; p2 <<= 1) {
        }
        n = p2 > ANISO_MAX_PROBES ? ANISO_MAX_PROBES : p2;
    }
    return n;
}

/* Probe count, major column, λ and the two levels of a query. */
typedef struct aniso_setup {
    int n, l0, l1;
    float lam, f;
    double ms, mt;
} aniso_setup;

static void aniso_setup_of(const sample_ctx *c, const sample_query *q, float call_bias, aniso_setup *a)
{
    const struct sample_level *B = &c->tex->level[c->base];
    /* In double: the squares of a 1e20 Jacobian overflow float. */
    double px = hypot((double)q->dsdx * B->w, (double)q->dtdx * B->h);
    double py = hypot((double)q->dsdy * B->w, (double)q->dtdy * B->h);
    double pmax = px >= py ? px : py, pmin = px >= py ? py : px, lb;
    a->ms = px >= py ? q->dsdx : q->dsdy;
    a->mt = px >= py ? q->dtdx : q->dtdy;
    a->n = fp_aniso_count(c->smp, pmax, pmin);
    lb = log2(pmax / a->n);
    a->lam = lod_lambda(c, lb < -1e4 ? -1e4f : (float)lb, call_bias);
    /* Each probe is trilinear (LINEAR_MIPMAP_LINEAR, eqs. 8.17–8.18) at λ;
     * λ ≤ 0 reads the base level bilinearly. */
    lod_split(c, a->lam, &a->l0, &a->l1, &a->f);
    if (a->f == 0.0f) a->l1 = a->l0;
}

/* Ask for every probe's rows, so that their misses overlap. */
SAMPLE_FORCE_INLINE void aniso_prefetch(const sample_ctx *c, const sample_query *q, const aniso_setup *a)
{
    int i;
    for (i = 1; i <= a->n; ++i) {
        double off = (double)i / (a->n + 1) - 0.5;
        float s = (float)(q->s + off * a->ms), t = (float)(q->t + off * a->mt);
        ctx_prefetch_bilinear(c, a->l0, s, t);
        if (a->l1 != a->l0) ctx_prefetch_bilinear(c, a->l1, s, t);
    }
}

void fp_anisotropic_prefetch(const sample_ctx *c, const sample_query *q, float call_bias)
{
    aniso_setup a;
    aniso_setup_of(c, q, call_bias, &a);
    aniso_prefetch(c, q, &a);
}

uint32_t fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    double acc[4] = {0, 0, 0, 0}, as[4] = {0, 0, 0, 0}, at[4] = {0, 0, 0, 0};
    aniso_setup a;
    int n, i, k, l0, l1;
    double ms, mt;
    float lam, f;
    uint32_t texels = 0;
    /* recon_level's bilinear, the fast path's way (same bits). */
    const tex_readers *rd = tex_readers_of(c->tex);

    aniso_setup_of(c, q, call_bias, &a);
    n = a.n;
    l0 = a.l0;
    l1 = a.l1;
    lam = a.lam;
    f = a.f;
    ms = a.ms;
    mt = a.mt;
    aniso_prefetch(c, q, &a);
    for (i = 1; i <= n; ++i) {
        double off = (double)i / (n + 1) - 0.5;
        float s = (float)(q->s + off * ms), t = (float)(q->t + off * mt);
        float o0[4], s0[4], t0[4], o1[4], s1[4], t1[4];
        /* Derivatives only where asked for: they do not touch the value. */
        texels += rd->bilinear(c, l0, s, t, o0, dds ? s0 : NULL, ddt ? t0 : NULL);
        if (l1 != l0) {
            texels += rd->bilinear(c, l1, s, t, o1, dds ? s1 : NULL, ddt ? t1 : NULL);
        } else {
            memcpy(o1, o0, sizeof o1);
            if (dds) memcpy(s1, s0, sizeof s1);
            if (ddt) memcpy(t1, t0, sizeof t1);
        }
        /* Equal weights, summed in double so the mean of N equal probes is
         * that probe exactly. */
        for (k = 0; k < 4; ++k) acc[k] += (1.0 - f) * o0[k] + (double)f * o1[k];
        if (dds)
            for (k = 0; k < 4; ++k) as[k] += (1.0 - f) * s0[k] + (double)f * s1[k];
        if (ddt)
            for (k = 0; k < 4; ++k) at[k] += (1.0 - f) * t0[k] + (double)f * t1[k];
    }
    for (k = 0; k < 4; ++k) {
        out[k] = (float)(acc[k] / n);
        if (dds) dds[k] = (float)(as[k] / n);
        if (ddt) ddt[k] = (float)(at[k] / n);
    }
    if (st) {
        st->level0 = (int16_t)l0;
        st->level1 = (int16_t)(l1 != l0 ? l1 : -1);
        st->level_frac = l1 != l0 ? f : 0.0f;
        st->lod = lam;
    }
    return texels;
}
