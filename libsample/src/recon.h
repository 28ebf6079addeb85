/*
 * Reconstruction on one level (reconstruct.c): NEAREST, LINEAR (GL 4.6
 * §8.14.2, eq. 8.13) and bicubic (DESIGN §4), and the arithmetic the fast
 * path shares with it (recon_bilerp, recon_blend, ls_recon_cubic_combine), so
 * that both round identically.
 */
#ifndef SAMPLE_RECON_H
#define SAMPLE_RECON_H

#include "ctx.h"

/* kind is SAMPLE_NEAREST, SAMPLE_LINEAR or SAMPLE_CUBIC. (s, t) normalized.
 * dds/ddt (may be NULL) receive ∂/∂s and ∂/∂t of the result. Returns the
 * number of texels read. */
uint32_t ls_recon_level(const sample_ctx *c, int lv, sample_filter kind, float s, float t,
                     float out[4], float dds[4], float ddt[4]);

/* The bilinear combination of the 2 × 2 texels T[0] = (i0, j0), T[1] =
 * (i0+1, j0), T[2] = (i0, j0+1), T[3] = (i0+1, j0+1) with fractions α, β
 * (GL 4.6 eq. 8.13), and its derivatives d/du, d/dv (may be NULL). The one
 * copy of this arithmetic: the general and the fast path both call it, so
 * they round identically. */
SAMPLE_FORCE_INLINE void recon_bilerp(const v4f T[4], float al, float be, float out[4], float ddu[4],
                                float ddv[4])
{
    v4f a1 = v4_set1(1.0f - al), b1 = v4_set1(1.0f - be), a = v4_set1(al), b = v4_set1(be);
    /* (1−α)(1−β)·T00 + α(1−β)·T10 + (1−α)β·T01 + αβ·T11, left to right. */
    v4f r = v4_add(v4_add(v4_add(v4_mul(v4_mul(a1, b1), T[0]), v4_mul(v4_mul(a, b1), T[1])),
                          v4_mul(v4_mul(a1, b), T[2])),
                   v4_mul(v4_mul(a, b), T[3]));
    v4_store(out, r);
    if (ddu) v4_store(ddu, v4_add(v4_mul(b1, v4_sub(T[1], T[0])), v4_mul(b, v4_sub(T[3], T[2]))));
    if (ddv) v4_store(ddv, v4_add(v4_mul(a1, v4_sub(T[2], T[0])), v4_mul(a, v4_sub(T[3], T[1]))));
}

/* a ← (1 − f)·a + f·b: the blend of two mip levels (GL 4.6 eq. 8.18). */
SAMPLE_FORCE_INLINE void recon_blend(float a[4], const float b[4], float f)
{
    v4_store(a, v4_add(v4_mul(v4_set1(1.0f - f), v4_load(a)), v4_mul(v4_set1(f), v4_load(b))));
}

/* The texel coordinate u = s'·n of a query on an axis of n texels, after the
 * wraps that transform s (ls_wrap_coord). s·n may overflow to ±inf for finite s
 * near FLT_MAX; it is kept finite so that the fractional weights stay
 * defined (α = u − ⌊u⌋ would be inf − inf). */
static inline float recon_texel_coord(sample_wrap mode, float s, int n)
{
    float u = (wrap_transforms_coord(mode) ? ls_wrap_coord(mode, s, n) : s) * (float)n;
    return u > FLT_MAX ? FLT_MAX : (u < -FLT_MAX ? -FLT_MAX : u);
}

/* The block a LINEAR or CUBIC read at texel coordinate u starts from (GL
 * 4.6 §8.14.2, eq. 8.13): returns i0 = ⌊u − ½⌋ and sets *alpha = frac(u −
 * ½), in float as the specification's reference implementations compute
 * them. The one copy of this addressing: the reference reconstruction and
 * the fast path's planner (plan_level) both call it; the anisotropic fast
 * path's probes, which it addresses only when every block lies inside the
 * level (u − ½ ≥ 0), take the same floor as a truncation in vector lanes
 * (fast_gl.c, aniso_address). */
SAMPLE_FORCE_INLINE float recon_linear_origin(float u, float *alpha)
{
    const float a = u - 0.5f, i0 = floorf(a);
    *alpha = a - i0;
    return i0;
}

/* The Mitchell–Netravali combination of a 4 × 4 block T[y][x] (taps −1 … 2
 * around (i0, j0)) with weights wx, wy and their derivatives, accumulated
 * in double (16 float products would lose the exact reproduction of
 * constants and ramps); `clamp` is SAMPLE_OPT_CUBIC_CLAMP. Shared by the
 * general and the fast path. Texels as plain floats, not v4f: v4f is a
 * different type in each instruction-set build of the fast path (isa.c),
 * and this function is compiled once. T is only read (not const-qualified
 * because C before C23 does not convert float (*)[4] to that implicitly). */
void ls_recon_cubic_combine(float T[16][4], const double wx[4], const double wy[4],
                         const double dwx[4], const double dwy[4], int clamp, float out[4],
                         float ddu[4], float ddv[4]);

/* Cubic kernel weights for fractional offset f ∈ [0, 1): taps at −1, 0, 1, 2,
 * and their derivatives d/df (dw may be NULL). */
void ls_cubic_weights(sample_cubic kind, float f, double w[4], double dw[4]);

#endif /* SAMPLE_RECON_H */
