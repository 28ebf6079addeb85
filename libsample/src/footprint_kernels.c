/*
 * Radial kernels for the elliptical filter (footprint_kernels.h): the
 * windowed sinc of Lanczos (Duchon 1979; Turkowski 1990, "Filters for
 * common resampling tasks") and the Mitchell–Netravali cubic (Mitchell &
 * Netravali 1988, B = C = ⅓), as functions of the radius — the EWA form of
 * a separable kernel (Heckbert 1989 §3.5.8 allows any radial weight; the
 * same construction as ImageMagick's "EWA" resampling).
 * doc/footprint-filters.md, "Radial kernels".
 */
#include "footprint_kernels.h"

#include "portable_math.h"

/* sinc(x) = sin(πx)/(πx) and its derivative, with sample_sinpi (the same
 * bits on any machine); cos(πx) = sin(π(x + ½)). Near 0 the series
 * 1 − (πx)²/6, whose error there is below 2^−60. */
static double sinc(double x, double *d)
{
    const double px = 3.14159265358979323846 * x;
    double s, c;
    if (fabs(x) < 1e-5) {
        if (d) *d = -3.14159265358979323846 * px / 3.0;
        return 1.0 - px * px / 6.0;
    }
    s = sample_sinpi(x);
    c = sample_sinpi(x + 0.5);
    if (d) *d = (c * px - s) / (px * x);
    return s / px;
}

static double lanczos(double x, double a, double *dk)
{
    double d1, d2, s1 = sinc(x, dk ? &d1 : NULL), s2 = sinc(x / a, dk ? &d2 : NULL);
    if (dk) *dk = d1 * s2 + s1 * d2 / a;
    return s1 * s2;
}

static double lanczos2(double x, double *dk) { return lanczos(x, 2.0, dk); }
static double lanczos3(double x, double *dk) { return lanczos(x, 3.0, dk); }

/* Mitchell & Netravali's piecewise cubic with B = C = ⅓, times 6:
 * 7x³ − 12x² + 16/3 on [0, 1), −(7/3)x³ + 12x² − 20x + 32/3 on [1, 2). */
static double mitchell(double x, double *dk)
{
    double w;
    if (x < 1.0) {
        w = (7.0 * x - 12.0) * x * x + 16.0 / 3.0;
        if (dk) *dk = (21.0 * x - 24.0) * x / 6.0;
    } else {
        w = ((-7.0 / 3.0 * x + 12.0) * x - 20.0) * x + 32.0 / 3.0;
        if (dk) *dk = ((-7.0 * x + 24.0) * x - 20.0) / 6.0;
    }
    return w / 6.0;
}

/* minor_texels: see doc/footprint-filters.md, "Radial kernels" for the
 * measurements behind them. */
static const fp_radial kernels[SAMPLE_EWA_KERNEL_COUNT] = {
    [SAMPLE_EWA_LANCZOS2] = {2.0, 2.0, lanczos2},
    [SAMPLE_EWA_LANCZOS3] = {3.0, 2.0, lanczos3},
    [SAMPLE_EWA_MITCHELL] = {2.0, 2.0, mitchell},
};

const fp_radial *ls_fp_radial(sample_ewa_kernel k)
{
    if (k <= SAMPLE_EWA_GAUSSIAN || k >= SAMPLE_EWA_KERNEL_COUNT) return NULL;
    return &kernels[k];
}

double ls_fp_radial_at(const fp_radial *k, double q, double *dq)
{
    const double a = k->support, x = a * sqrt(q > 0.0 ? q : 0.0);
    double dk, w = k->weight(x, dq ? &dk : NULL);
    /* dK/dq = K′(x)·a²/(2x); K′(x)/x tends to K″(0) at 0 (every kernel
     * here is smooth there), taken at a tiny x. */
    if (dq) {
        const double xm = x > 1e-4 ? x : 1e-4;
        if (!(x > 1e-4)) k->weight(xm, &dk);
        *dq = dk * a * a / (2.0 * xm);
    }
    return w;
}

/* Texels of the support on both levels of the blend with the finer one's
 * minor semi-axis t (ellipse semi-axes a·√(t² + 1) and a·√((e·t)² + 1)
 * with the unit reconstruction term, the coarser level's half those
 * before it), plus a row of texels round each ellipse. */
static double support_texels(double a, double e, double t)
{
    const double pi = 3.14159265358979323846;
    double n = 0.0;
    int l;
    for (l = 0; l < 2; ++l, t *= 0.5) {
        double r0 = a * sqrt(t * t + 1.0), r1 = a * sqrt(e * e * t * t + 1.0);
        n += pi * r0 * r1 + 2.0 * (r0 + r1) + 2.0;
    }
    return n;
}

double ls_fp_radial_minor(const fp_radial *k, double ecc)
{
    /* Below the cap with room for rounding of the rows (the cap's own
     * escalation stays the safety net). The top of the blend is twice the
     * low end, hence 2t on the finer level. */
    const double budget = 0.85 * (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    double lo = 1.0 / 64.0, hi = k->minor_texels;
    int i;
    if (!(ecc >= 1.0)) ecc = 1.0;
    if (support_texels(k->support, ecc, 2.0 * hi) <= budget) return hi;
    /* Bisection on a fixed number of steps: the same t for the same
     * footprint on any machine, continuous to 2^−30 of the range. */
    for (i = 0; i < 30; ++i) {
        double mid = 0.5 * (lo + hi);
        if (support_texels(k->support, ecc, 2.0 * mid) <= budget) lo = mid;
        else hi = mid;
    }
    return lo;
}
