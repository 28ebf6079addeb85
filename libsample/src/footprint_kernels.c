/*
 * Radial kernels for the elliptical filter (footprint_kernels.h): the
 * windowed sinc of Lanczos (Duchon 1979; Turkowski 1990, "Filters for
 * common resampling tasks") and the Mitchell–Netravali cubic (Mitchell &
 * Netravali 1988, B = C = ⅓), as functions of the radius — the EWA form of
 * a separable kernel (Heckbert 1989 §3.5.8 allows any radial weight; the
 * same construction as ImageMagick's "EWA" resampling). Their weights are
 * tables (footprint_kernel_luts.c); here the kernels' parameters and the
 * level rule.
 * doc/footprint-filters.md, "Radial kernels".
 */
#include "footprint_kernels.h"

#include <math.h>

/* minor_texels: see doc/footprint-filters.md, "Radial kernels" for the
 * measurements behind them. */
static const fp_radial kernels[SAMPLE_EWA_KERNEL_COUNT] = {
    [SAMPLE_EWA_LANCZOS2] = {2.0, 2.0, 2.0, ls_fp_lut_lanczos2},
    [SAMPLE_EWA_LANCZOS3] = {3.0, 2.0, 1.0, ls_fp_lut_lanczos3},
    [SAMPLE_EWA_MITCHELL] = {2.0, 2.0, 1.0, ls_fp_lut_mitchell},
};

const fp_radial *ls_fp_radial(sample_ewa_kernel k)
{
    if (k <= SAMPLE_EWA_GAUSSIAN || k >= SAMPLE_EWA_KERNEL_COUNT) return NULL;
    return &kernels[k];
}

/* The reconstruction term that goes with minor semi-axis t: the kernel's
 * own at its minor_texels, scaled with t² so that the widening is the same
 * fraction of the footprint wherever the cap lowers t. */
double ls_fp_radial_recon(const fp_radial *k, double t)
{
    const double f = t / k->minor_texels;
    return k->recon * f * f;
}

/* Texels of the support on both levels of the blend, the finer one's
 * minor semi-axis 2t (the top of the blend; ellipse semi-axes a·√(σ² + rc)
 * with the reconstruction term rc, the coarser level's σ half those), plus
 * a row of texels round each ellipse. */
static double support_texels(const fp_radial *k, double e, double t)
{
    const double pi = 3.14159265358979323846, a = k->support, rc = ls_fp_radial_recon(k, t);
    double n = 0.0, m = 2.0 * t;
    int l;
    for (l = 0; l < 2; ++l, m *= 0.5) {
        double r0 = a * sqrt(m * m + rc), r1 = a * sqrt(e * e * m * m + rc);
        n += pi * r0 * r1 + 2.0 * (r0 + r1) + 2.0;
    }
    return n;
}

double ls_fp_radial_minor(const fp_radial *k, double ecc)
{
    /* Below the cap with room for the rounding of the rows (the cap's own
     * escalation stays the safety net). */
    const double budget = 0.85 * (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    double lo = 1.0 / 64.0, hi = k->minor_texels;
    int i;
    if (!(ecc >= 1.0)) ecc = 1.0;
    if (support_texels(k, ecc, hi) <= budget) return hi;
    /* Bisection on a fixed number of steps: the same t for the same
     * footprint on any machine, continuous to 2^−30 of the range. */
    for (i = 0; i < 30; ++i) {
        double mid = 0.5 * (lo + hi);
        if (support_texels(k, ecc, mid) <= budget) lo = mid;
        else hi = mid;
    }
    return lo;
}
