/*
 * The radial kernels of the elliptical filter (footprint_ewa.c) other than
 * its Gaussian: each a profile K(x) of the distance x from the centre in
 * pixels with support x < `support`, and the level rule that goes with it
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
    /* K(x) for 0 ≤ x < support, and dK/dx in *dk if dk is not NULL. */
    double (*weight)(double x, double *dk);
} fp_radial;

/* The kernel of a sample_ewa_kernel other than SAMPLE_EWA_GAUSSIAN; NULL
 * for the Gaussian (footprint_ewa.c's table) and for values out of range. */
const fp_radial *ls_fp_radial(sample_ewa_kernel k);

/* The weight as the elliptical filter uses it: K at x = support·√q, q the
 * texel's r² in the ellipse scaled to the support (q < 1), and dK/dq in
 * *dq if dq is not NULL. */
double ls_fp_radial_at(const fp_radial *k, double q, double *dq);

/* The minor semi-axis, in texels of the finer level at the low end of the
 * blend, for a footprint of eccentricity ecc (≥ 1): the kernel's
 * minor_texels, lowered where the support's texels on the two levels
 * would not fit in SAMPLE_MAX_FOOTPRINT_TEXELS (continuous in ecc, so the
 * level moves smoothly with the footprint). */
double ls_fp_radial_minor(const fp_radial *k, double ecc);

#endif /* SAMPLE_FOOTPRINT_KERNELS_H */
