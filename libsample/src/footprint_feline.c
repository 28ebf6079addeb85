/*
 * Feline (footprint_feline.h): EWA quality at the cost of a bounded set of
 * trilinear probes. McCormack et al. 1999 place probes along the major
 * axis of the footprint ellipse, each a trilinear lookup whose level
 * matches the minor axis, weighted by a Gaussian of their distance from
 * the centre; Mavridis & Papaioannou 2011 ("High quality elliptical
 * texture filtering on GPU") take the weights from the EWA ellipse and,
 * for quality near round footprints, probe a finer level so that the sum
 * of the bilinear probes approximates the Gaussian. Here, with the ellipse
 * of footprint_ewa.c (singular values σ0 ≥ σ1 in base texels, σ1 ≥ σ0/16,
 * the major axis u and minor axis v):
 *
 *   the filter aimed at has variance V_a = KV·σ_a² + KE·σ1² along each
 *        axis a (base texels²);
 *   λ' = log2 σ1 − DELTA (+ biases, clamps), split into two levels: each
 *        trilinear probe has variance vp = ¼·((1 − f)·4^l0 + f·4^l1)
 *        (a bilinear tent on a box-filtered level: ¼ level texel²);
 *   the probes make up the rest, V_a − vp, as EWA's own truncated
 *        Gaussian (fp_ewa_weight, e^(−2r²) − e^(−2) on r < 1, marginal
 *        variance 0.136·R² for radius R): R_a = √((V_a − vp)/0.136);
 *   probes on the lattice i·h0·u + j·h1·v inside that ellipse (r < 1),
 *        spacing h = RHO·2^λ' (a probe's width: no aliasing between them),
 *        widened on an axis where more than 2·M_a + 1 probes would not fit;
 *   w = fp_ewa_weight(r²) at each probe, normalised.
 *
 * Every quantity is continuous in the footprint and a probe enters or
 * leaves the lattice at r = 1, where its weight is 0. The probes are
 * float GL bilinear reads, summed in double (fp_aniso_probes).
 */
#include "footprint_feline.h"

#include <stdlib.h>

#include "footprint.h"
#include "kernels.h"
#include "stochastic.h"

static double par(const char *n, double d)
{
    const char *e = getenv(n);
    return e ? atof(e) : d;
}

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

/* Lattice steps m on one axis (|i| ≤ m) and its spacing *h: the probes
 * i·h with i·h < R, at most 2·mmax + 1 (the spacing widened to R/(mmax + 1)
 * where they would not fit). R = 0 or not finite: the centre alone. */
static int axis_steps(double R, double *h, int mmax)
{
    double x;
    if (!(R > 0.0) || !(R < INFINITY) || !(*h > 0.0)) return 0;
    if (*h < R / (mmax + 1)) *h = R / (mmax + 1);
    x = R / *h;
    return x >= mmax + 1 ? mmax : (int)fp_ceil(x) - 1;
}

void ls_fp_feline_setup(const sample_ctx *c, const sample_query *q, float call_bias, fp_aniso_setup *a,
                        fp_probe_set *set)
{
    const struct sample_level *B = &c->tex->level[c->base];
    const double KV = par("FEL_KV", 1.0 / 6.0), KE = par("FEL_KE", 0.0), DELTA = par("FEL_DELTA", 1.0),
                 RHO = par("FEL_RHO", 1.0);
    const int M0 = (int)par("FEL_M0", 7), M1 = (int)par("FEL_M1", 2);
    double J[2][2], ux, uy, s0, s1, lb, vp, sz0, sz1, R0, R1, h0, h1;
    fp_shape sh;
    int m0, m1, i, j, n = 0;

    J[0][0] = (double)q->dsdx * B->w;
    J[0][1] = (double)q->dsdy * B->w;
    J[1][0] = (double)q->dtdx * B->h;
    J[1][1] = (double)q->dtdy * B->h;
    ls_fp_shape_of(J, &sh); /* σ1 raised to σ0/16 where it was below */
    s0 = sh.s[0];
    s1 = sh.s[1];
    major_axis(J, s0 * s0, &ux, &uy);
    lb = sample_log2(s1) - DELTA;
    a->lam = lod_lambda(c, lb < -1e4 ? -1e4f : (lb > 1e4 ? 1e4f : (float)lb), call_bias);
    ls_lod_split(c, a->lam, &a->l0, &a->l1, &a->f);
    if (a->f == 0.0f) a->l1 = a->l0;
    if (par("FEL_ONE", 0) != 0) {
        if (par("FEL_ONE", 0) == 2 && a->f >= 0.5f) a->l0 = a->l1;
        a->l1 = a->l0, a->f = 0.0f;
    }
    a->ms = a->mt = 0.0;
    a->set = set;
    sz0 = exp2((double)(a->l0 - c->base));
    sz1 = exp2((double)(a->l1 - c->base));
    vp = 0.25 * ((1.0 - a->f) * sz0 * sz0 + a->f * sz1 * sz1);
    R0 = sqrt(fp_pos(KV * s0 * s0 + KE * s1 * s1 - vp) / 0.136);
    R1 = sqrt(fp_pos((KV + KE) * s1 * s1 - vp) / 0.136);
    h0 = h1 = RHO * (par("FEL_ONE", 0) != 0 ? sz0 : exp2(a->lam > 0.0f ? (double)a->lam : 0.0));
    if (par("FEL_ONE", 0) == 3) {
        m0 = R0 > 0.0 && R0 < INFINITY ? (int)fp_ceil(R0 / sz0) - 1 : 0;
        m1 = R1 > 0.0 && R1 < INFINITY ? (int)fp_ceil(R1 / sz0) - 1 : 0;
        if (R0 > 0.0 && m0 < 1) m0 = 1;
        if (R1 > 0.0 && m1 < 1) m1 = 1;
        if (m0 > M0) m0 = M0;
        if (m1 > M1) m1 = M1;
        h0 = R0 / (m0 + par("FEL_EPS", 0.5));
        h1 = R1 / (m1 + par("FEL_EPS", 0.5));
    } else {
    m0 = axis_steps(R0, &h0, M0);
    m1 = axis_steps(R1, &h1, M1);
    }
    set->sw = 0.0;
    for (j = -m1; j <= m1; ++j)
        for (i = -m0; i <= m0; ++i) {
            const double x = m0 ? i * h0 / R0 : 0.0, y = m1 ? j * h1 / R1 : 0.0, r2 = x * x + y * y;
            const double du = i * h0 * ux - j * h1 * uy, dv = i * h0 * uy + j * h1 * ux;
            if (!(r2 < 1.0) || n == FP_PROBES_MAX) continue;
            set->w[n] = fp_ewa_weight(r2, NULL);
            set->s[n] = (float)(q->s + du / B->w);
            set->t[n] = (float)(q->t + dv / B->h);
            set->sw += set->w[n];
            ++n;
        }
    a->n = n;
}

uint32_t ls_fp_feline(const sample_ctx *c, const sample_query *q, float call_bias, const double *u, float out[4],
                      float dds[4], float ddt[4], sample_stats *st)
{
    const fp_bilinear_fn bilinear = ctx_readers(c)->bilinear;
    fp_aniso_setup a;
    fp_probe_set set;
    uint32_t texels;
    ls_fp_feline_setup(c, q, call_bias, &a, &set);
    if (u) {
        /* One probe, drawn with probability w_k/Σw (stratified in u), its
         * level with its blend weight: one bilinear read. */
        double v = *u * set.sw, cum = 0.0;
        int k, l0 = a.l0;
        for (k = 0; k < a.n - 1; ++k) {
            if (v < cum + set.w[k]) break;
            cum += set.w[k];
        }
        v = (v - cum) / set.w[k];
        if (!(v >= 0.0 && v < 1.0)) v = 0.0;
        if (a.l1 != a.l0 && ls_stochastic_pick2((double)a.f, &v)) l0 = a.l1;
        a.l0 = a.l1 = l0;
        texels = bilinear(c, l0, set.s[k], set.t[k], out, NULL, NULL);
    } else
        texels = fp_aniso_probes(c, q, &a, bilinear, out, dds, ddt);
    if (st) fp_aniso_stats(&a, st);
    return texels;
}
