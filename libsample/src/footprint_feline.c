/*
 * Feline (footprint_feline.h): EWA quality at the cost of a few trilinear
 * probes. McCormack et al. 1999 place probes along the major axis of the
 * footprint ellipse, each a trilinear lookup whose level matches the minor
 * axis, weighted by a Gaussian of their distance from the centre; Mavridis
 * & Papaioannou 2011 ("High quality elliptical texture filtering on GPU")
 * take the weights and spacing from the EWA ellipse itself. Here, with the
 * ellipse of footprint_ewa.c (conjugate semi-axes dPdx, dPdy, singular
 * values σ0 ≥ σ1 in base texels, σ1 ≥ σ0/16):
 *
 *   λ  = log2 σ1 (+ biases): a trilinear probe there blurs about as EWA's
 *        Gaussian does across the minor axis (standard deviation ≈ σ1/2);
 *   the probes' spread along the major axis makes up the rest of EWA's
 *        variance along it: s = ½·√(σ0² − σ1²) (EWA's e^(−2r²) has
 *        standard deviation ½ in r);
 *   N  = 2h + 1 probes at d_k = 2s·k/(h + 1), k = −h … h, spaced at most
 *        σ1 (a probe's own width, so the probes do not alias along the
 *        axis): h = ⌈2s/σ1⌉ − 1, at most 15 (the eccentricity clamp);
 *   w_k = EWA's weight at r = k/(h + 1) (fp_ewa_weight: the truncated
 *        Gaussian e^(−2r²) − e^(−2)), the sum normalised.
 *
 * A round footprint is one trilinear probe. The probes are float GL
 * bilinear reads, summed in double.
 */
#include "footprint_feline.h"

#include "aniso.h"
#include "footprint.h"
#include "kernels.h"
#include "stochastic.h"

/* The unit vector (in base texels) of the ellipse's major axis: the
 * eigenvector of M = J·Jᵀ for its larger eigenvalue e (J in base texels),
 * from whichever of M's two rows gives the longer vector (the other may
 * vanish). (1, 0) for a round or degenerate M. */
static void major_axis(double J[2][2], double e, double *ux, double *uy)
{
    const double m00 = J[0][0] * J[0][0] + J[0][1] * J[0][1], m01 = J[0][0] * J[1][0] + J[0][1] * J[1][1],
                 m11 = J[1][0] * J[1][0] + J[1][1] * J[1][1];
    double ax = m01, ay = e - m00, bx = e - m11, by = m01, la = ax * ax + ay * ay, lb = bx * bx + by * by, n;
    if (lb > la) ax = bx, ay = by, la = lb;
    n = sqrt(la);
    if (!(n > 0.0) || !(n < INFINITY)) {
        *ux = 1.0, *uy = 0.0;
        return;
    }
    *ux = ax / n;
    *uy = ay / n;
}

static void weighted_add(double acc[4], double w, double f, const float a[4], const float b[4])
{
    int k;
    for (k = 0; k < 4; ++k) acc[k] += w * ((1.0 - f) * a[k] + f * b[k]);
}

static void store_mean(float *dst, const double acc[4], double sw)
{
    int k;
    if (dst)
        for (k = 0; k < 4; ++k) dst[k] = (float)(acc[k] / sw);
}

/* The probe d base texels along the major axis (ux, uy) from the centre,
 * in normalized coordinates. */
static void probe_at(const sample_query *q, const struct sample_level *B, double d, double ux, double uy, float *s,
                     float *t)
{
    *s = (float)(q->s + d * ux / B->w);
    *t = (float)(q->t + d * uy / B->h);
}

uint32_t ls_fp_feline(const sample_ctx *c, const sample_query *q, float call_bias, const double *u, float out[4],
                      float dds[4], float ddt[4], sample_stats *st)
{
    const struct sample_level *B = &c->tex->level[c->base];
    const fp_bilinear_fn bilinear = ctx_readers(c)->bilinear;
    double J[2][2], ux, uy, s0, s1, spread, lb, f, sw = 0.0, w[FP_FELINE_MAX_PROBES];
    double acc[4] = {0, 0, 0, 0}, as[4] = {0, 0, 0, 0}, at[4] = {0, 0, 0, 0};
    fp_shape sh;
    float lam, ff;
    int h, k, l0, l1;
    uint32_t texels = 0;

    J[0][0] = (double)q->dsdx * B->w;
    J[0][1] = (double)q->dsdy * B->w;
    J[1][0] = (double)q->dtdx * B->h;
    J[1][1] = (double)q->dtdy * B->h;
    ls_fp_shape_of(J, &sh); /* σ1 raised to σ0/16 where it was below */
    s0 = sh.s[0];
    s1 = sh.s[1];
    major_axis(J, s0 * s0, &ux, &uy);
    spread = 0.5 * sqrt(fp_pos(s0 * s0 - s1 * s1));
    /* h = ⌈2s/σ1⌉ − 1 in [0, 15]; a NaN, infinite or zero footprint is one
     * probe (its value then decided by the level clamps, as trilinear's). */
    h = 0;
    if (s1 > 0.0 && 2.0 * spread / s1 < (FP_FELINE_MAX_PROBES + 1) / 2) h = (int)fp_ceil(2.0 * spread / s1) - 1;
    else if (s1 > 0.0 && spread < INFINITY) h = (FP_FELINE_MAX_PROBES - 1) / 2;
    if (h < 0) h = 0;
    lb = sample_log2(s1);
    lam = lod_lambda(c, lb < -1e4 ? -1e4f : (lb > 1e4 ? 1e4f : (float)lb), call_bias);
    ls_lod_split(c, lam, &l0, &l1, &ff);
    if (ff == 0.0f) l1 = l0;
    f = ff;
    for (k = -h; k <= h; ++k) {
        const double r = (double)k / (h + 1);
        w[k + h] = fp_ewa_weight(r * r, NULL);
        sw += w[k + h];
    }
    if (u) {
        /* One probe, drawn with probability w_k/Σw (stratified in u), its
         * level with its blend weight: one bilinear read. */
        double v = *u * sw, cum = 0.0;
        float ps, pt;
        for (k = 0; k < 2 * h; ++k) {
            if (v < cum + w[k]) break;
            cum += w[k];
        }
        v = (v - cum) / w[k];
        if (!(v >= 0.0 && v < 1.0)) v = 0.0;
        probe_at(q, B, 2.0 * spread * (double)(k - h) / (h + 1), ux, uy, &ps, &pt);
        if (l1 != l0 && ls_stochastic_pick2(f, &v)) l0 = l1;
        l1 = l0;
        texels = bilinear(c, l0, ps, pt, out, NULL, NULL);
    } else
        for (k = -h; k <= h; ++k) {
            const double d = 2.0 * spread * (double)k / (h + 1);
            float ps, pt, o0[4], ds0[4], dt0[4], o1[4], ds1[4], dt1[4];
            probe_at(q, B, d, ux, uy, &ps, &pt);
            texels += bilinear(c, l0, ps, pt, o0, dds ? ds0 : NULL, ddt ? dt0 : NULL);
            if (l1 != l0) {
                texels += bilinear(c, l1, ps, pt, o1, dds ? ds1 : NULL, ddt ? dt1 : NULL);
            } else {
                memcpy(o1, o0, sizeof o1);
                if (dds) memcpy(ds1, ds0, sizeof ds1);
                if (ddt) memcpy(dt1, dt0, sizeof dt1);
            }
            weighted_add(acc, w[k + h], f, o0, o1);
            if (dds) weighted_add(as, w[k + h], f, ds0, ds1);
            if (ddt) weighted_add(at, w[k + h], f, dt0, dt1);
        }
    if (!u) {
        store_mean(out, acc, sw);
        store_mean(dds, as, sw);
        store_mean(ddt, at, sw);
    }
    if (st) {
        st->level0 = (int16_t)l0;
        st->level1 = (int16_t)(l1 != l0 ? l1 : -1);
        st->level_frac = l1 != l0 ? ff : 0.0f;
        st->lod = lam;
    }
    return texels;
}
