/*
 * Feline (footprint_feline.h): EWA quality from a bounded set of bilinear
 * probes. McCormack et al. 1999 place probes along the major axis of the
 * footprint ellipse, weighted by a Gaussian of their distance from the
 * centre; Mavridis & Papaioannou 2011 ("High quality elliptical texture
 * filtering on GPU") take the weights from the EWA ellipse and, for
 * quality near round footprints, probe a finer level so that the sum of
 * the bilinear probes approximates the Gaussian. Here, with the ellipse of
 * footprint_ewa.c (singular values σ0 ≥ σ1 in base texels, σ1 ≥ σ0/16,
 * major axis u, minor axis v):
 *
 *   aimed at: variance V_a = σ_a²/6 along each axis a (base texels²), that
 *        of DESIGN §8's 2 × 2-pixel pyramid;
 *   level: ⌊λ'⌋, λ' = log2 σ1 − ½ (+ biases, clamps), one level (texel
 *        size z base texels): its bilinear probe has variance z²/4 (a tent
 *        on a box-filtered level);
 *   the probes make up the rest, V_a − z²/4, as EWA's own truncated
 *        Gaussian (fp_ewa_weight, e^(−2r²) − e^(−2) on r < 1, whose
 *        marginal variance is FELINE_VAR·R² for radius R):
 *        R_a = √((V_a − z²/4)/FELINE_VAR);
 *   lattice: i·h0·u + j·h1·v, |i| ≤ m0, |j| ≤ m1, inside that ellipse
 *        (r < 1): m_a = ⌈R_a/z⌉ − 1 (spacing about a probe's width, so the
 *        tents sum to a smooth kernel), at least 1, at most FELINE_M0
 *        along u and FELINE_M1 across; h_a = R_a/(m_a + ½);
 *   w = fp_ewa_weight(r²) at each probe, normalised.
 *
 * Measured against EWA and the anisotropic filter (error and cost) in
 * doc/footprint-filters.md, "Feline". The probes are float GL bilinear
 * reads, summed in double (fp_aniso_probes; the fast path reads them as the
 * anisotropic filter's, fast_gl.c).
 */
#include "footprint_feline.h"

#include "footprint.h"
#include "kernels.h"

/* Lattice steps along the major and the minor axis at most: (2·15 + 1) ×
 * (2·1 + 1) probes bound the set. */
#define FELINE_M0 15
#define FELINE_M1 1
_Static_assert((2 * FELINE_M0 + 1) * (2 * FELINE_M1 + 1) <= FP_PROBES_MAX, "the lattice fits a probe set");
/* The marginal variance of e^(−2r²) − e^(−2) on the unit disc:
 * ½·∫r³w dr / ∫r·w dr (numerical integration). */
#define FELINE_VAR 0.13608

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

/* Lattice steps m (|i| ≤ m) on an axis of radius R for probes of width z,
 * and the spacing *h: 0 (the centre alone) where R is 0 or not finite. */
static int axis_steps(double R, double z, int mmax, double *h)
{
    double x = R / z;
    int m;
    *h = 0.0;
    if (!(R > 0.0) || !(R < INFINITY)) return 0;
    m = x >= mmax + 1 ? mmax : (int)fp_ceil(x) - 1;
    if (m < 1) m = 1;
    *h = R / (m + 0.5);
    return m;
}

void ls_fp_feline_setup(const sample_ctx *c, const sample_query *q, float call_bias, fp_aniso_setup *a,
                        fp_probe_set *set)
{
    const struct sample_level *B = &c->tex->level[c->base];
    double J[2][2], ux, uy, s0, s1, lb, z, vp, R0, R1, h0, h1;
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
    lb = sample_log2(s1) - 0.5;
    a->lam = lod_lambda(c, lb < -1e4 ? -1e4f : (lb > 1e4 ? 1e4f : (float)lb), call_bias);
    ls_lod_split(c, a->lam, &a->l0, &a->l1, &a->f);
    a->l1 = a->l0; /* one level: the probes' spread makes up its width */
    a->f = 0.0f;
    a->ms = a->mt = 0.0;
    a->set = set;
    z = exp2((double)(a->l0 - c->base));
    vp = 0.25 * z * z;
    R0 = sqrt(fp_pos(s0 * s0 / 6.0 - vp) / FELINE_VAR);
    R1 = sqrt(fp_pos(s1 * s1 / 6.0 - vp) / FELINE_VAR);
    m0 = axis_steps(R0, z, FELINE_M0, &h0);
    m1 = axis_steps(R1, z, FELINE_M1, &h1);
    set->sw = 0.0;
    for (j = -m1; j <= m1; ++j)
        for (i = -m0; i <= m0; ++i) {
            const double x = m0 ? i * h0 / R0 : 0.0, y = m1 ? j * h1 / R1 : 0.0, r2 = x * x + y * y;
            const double du = i * h0 * ux - j * h1 * uy, dv = i * h0 * uy + j * h1 * ux;
            if (!(r2 < 1.0)) continue;
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
        /* One probe, drawn with probability w_k/Σw: one bilinear read
         * (the probes share one level). */
        const double v = *u * set.sw;
        double cum = 0.0;
        int k;
        for (k = 0; k < a.n - 1; ++k) {
            if (v < cum + set.w[k]) break;
            cum += set.w[k];
        }
        texels = bilinear(c, a.l0, set.s[k], set.t[k], out, NULL, NULL);
    } else
        texels = fp_aniso_probes(c, q, &a, bilinear, out, dds, ddt);
    if (st) fp_aniso_stats(&a, st);
    return texels;
}
