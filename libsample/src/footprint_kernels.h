/*
 * The radial kernels of the elliptical filter (footprint_ewa.c) other than
 * its Gaussian: each a profile K(x) of the distance x from the centre in
 * pixels with support x < `support` (tabulated), and the level rule that
 * goes with it
 * (doc/footprint-filters.md, "Radial kernels"; DESIGN §7).
 */
#ifndef SAMPLE_FOOTPRINT_KERNELS_H
#define SAMPLE_FOOTPRINT_KERNELS_H

#include "sample/sample.h"

typedef struct fp_radial {
    double support; /* K(x) = 0 for x ≥ support (pixels) */
    /* The minor semi-axis of the footprint in texels of the finer level at
     * the low end of the level blend (Gaussian: FP_MINOR_TEXELS). */
    double minor_texels;
    /* Texel² added to the ellipse's JJᵀ at minor_texels (Heckbert's
     * reconstruction term; the Gaussian's is 1); ls_fp_radial_recon. */
    double recon;
    /* K(support·√q) at q = k/FP_RADIAL_LUT, k = 0 … FP_RADIAL_LUT
     * (footprint_kernel_luts.c). */
    const double *lut;
} fp_radial;

#define FP_RADIAL_LUT 512
extern const double ls_fp_lut_lanczos2[FP_RADIAL_LUT + 1], ls_fp_lut_lanczos3[FP_RADIAL_LUT + 1],
    ls_fp_lut_mitchell[FP_RADIAL_LUT + 1];

/* The kernel of a sample_ewa_kernel other than SAMPLE_EWA_GAUSSIAN; NULL
 * for the Gaussian (footprint_ewa.c's table) and for values out of range. */
const fp_radial *ls_fp_radial(sample_ewa_kernel k);

/* The weight as the elliptical filter uses it: K at x = support·√q, q the
 * texel's r² in the ellipse scaled to the support (0 ≤ q < 1), linear
 * between the table's entries, and its slope dK/dq in *dq if dq is not
 * NULL (as fp_ewa_weight). */
static inline double ls_fp_radial_at(const fp_radial *k, double q, double *dq)
{
    const double x = q * FP_RADIAL_LUT;
    int e = (int)x;
    if (e > FP_RADIAL_LUT - 1) e = FP_RADIAL_LUT - 1;
    if (dq) *dq = (k->lut[e + 1] - k->lut[e]) * FP_RADIAL_LUT;
    return k->lut[e] + (x - e) * (k->lut[e + 1] - k->lut[e]);
}

/* The minor semi-axis, in texels of the finer level at the low end of the
 * blend, for a footprint of eccentricity ecc (≥ 1): the kernel's
 * minor_texels, lowered where the support's texels on the two levels
 * would not fit in SAMPLE_MAX_FOOTPRINT_TEXELS (continuous in ecc, so the
 * level moves smoothly with the footprint). */
double ls_fp_radial_minor(const fp_radial *k, double ecc);

/* The reconstruction term (texel²) to use with minor semi-axis t
 * (ls_fp_radial_minor's). */
double ls_fp_radial_recon(const fp_radial *k, double t);

#endif /* SAMPLE_FOOTPRINT_KERNELS_H */
