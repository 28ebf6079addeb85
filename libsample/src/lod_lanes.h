/*
 * λ_base (GL 4.6 §8.14.1 eqs. 8.7–8.9: log2 ρ, ρ the longer Jacobian
 * column in base texels) of four queries at once, one query per lane of
 * 256-bit double vectors: lod_lambda_base (internal.h) four times over, to
 * the bit. For the fast path's block passes (fast_gl.c, gl_blocks), where
 * λ was a fifth of a trilinear query's instructions, most of it
 * sample_log2 (measured: doc/history/performance-passes.md).
 *
 * Same bits, by construction: each lane runs lod_log2_rho's and
 * sample_log2's operations in their order — the widening, the products
 * and sums of ρx² and ρy², the larger of the two, the exponent and the
 * table index from the bits, (m − c)·(1/c), SAMPLE_LOG2_POLY, the final
 * sum, ½·, the rounding to float — and IEEE rounds a lane as it rounds the
 * scalar (no FMA: -ffp-contract=off). Lanes outside sample_log2's main
 * case are taken from it: ρ² = 0 (−inf), a power of two (exactly its
 * exponent); anything else (subnormal, inf, NaN: not reached from finite
 * floats, whose squares times a level size stay normal, but possible in
 * principle) is recomputed by lod_lambda_base itself. tests/test_fastpath.c
 * compares with the general path on every instruction set, in its
 * all-finite query sets and in test_lambda_lanes (Jacobians at each of
 * those cases, λ read back through the stats).
 *
 * Built where the fast path has AVX2 (64-bit integer lanes and gathers,
 * SAMPLE_VEC_AVX2); elsewhere the caller runs lod_lambda_base per query.
 */
#ifndef SAMPLE_LOD_LANES_H
#define SAMPLE_LOD_LANES_H

#include "lod.h"

#if SAMPLE_VEC_AVX2
/* q[0 … 3]'s λ_base into out[0 … 3]. */
SAMPLE_FORCE_INLINE void lod_lambda_base4(const sample_ctx *c, const sample_query *q, float out[4])
{
    const struct sample_level *L = &c->tex->level[c->base];
    const d4 w = {(double)L->w, (double)L->w, (double)L->w, (double)L->w};
    const d4 h = {(double)L->h, (double)L->h, (double)L->h, (double)L->h};
    /* dsdx, dtdx, dsdy, dtdy of each query (16 contiguous bytes), as rows
     * of a 4 × 4 matrix; transposed, a row per derivative. */
    __m128 j0 = _mm_loadu_ps(&q[0].dsdx), j1 = _mm_loadu_ps(&q[1].dsdx), j2 = _mm_loadu_ps(&q[2].dsdx),
           j3 = _mm_loadu_ps(&q[3].dsdx);
    d4 ux, vx, uy, vy, x, m, ci, t0, t1, r, r2, y, e;
    l4 b, fr, ix, ok;
    int k;
    _MM_TRANSPOSE4_PS(j0, j1, j2, j3);
    ux = (d4)_mm256_cvtps_pd(j0) * w;
    vx = (d4)_mm256_cvtps_pd(j1) * h;
    uy = (d4)_mm256_cvtps_pd(j2) * w;
    vy = (d4)_mm256_cvtps_pd(j3) * h;
    /* MAXPD(a, b) is a > b ? a : b, lod_log2_rho's choice. */
    x = (d4)_mm256_max_pd((__m256d)(ux * ux + vx * vx), (__m256d)(uy * uy + vy * vy));

    b = (l4)x;
    fr = b & (int64_t)SAMPLE_LOG2_FRAC;
    ix = fr >> SAMPLE_LOG2_TOP7;
    /* The exponent as a double, exactly: 2^52 + the biased exponent, less
     * 2^52 + 1023 (x ≥ +0: no sign bit). */
    e = (d4)((b >> 52) | (int64_t)0x4330000000000000) - (0x1p52 + 1023.0);
    m = (d4)(fr | (int64_t)SAMPLE_LOG2_ONE);
    ci = (d4)((fr & ~(((int64_t)1 << SAMPLE_LOG2_TOP7) - 1)) | (int64_t)SAMPLE_LOG2_ONE | (int64_t)SAMPLE_LOG2_MID);
    t0 = (d4)_mm256_i64gather_pd(&ls_log2_table[0][0], (__m256i)(ix * 2), 8);
    t1 = (d4)_mm256_i64gather_pd(&ls_log2_table[0][1], (__m256i)(ix * 2), 8);
    r = (m - ci) * t1;
    r2 = r * r;
    y = e + (t0 + r * SAMPLE_LOG2_POLY(r, r2));
    /* A power of two: its exponent; zero: −inf. */
    y = (d4)(((l4)e & (fr == 0)) | ((l4)y & (fr != 0)));
    y = (d4)(((l4)(d4){-INFINITY, -INFINITY, -INFINITY, -INFINITY} & (x == 0.0)) | ((l4)y & (x != 0.0)));
    _mm_storeu_ps(out, _mm256_cvtpd_ps((__m256d)(0.5 * y)));
    ok = ((x >= 0x1p-1022) & (x < INFINITY)) | (x == 0.0);
    for (k = 0; k < 4; ++k)
        if (!ok[k]) out[k] = lod_lambda_base(c, &q[k]);
}
#endif

#endif /* SAMPLE_LOD_LANES_H */
