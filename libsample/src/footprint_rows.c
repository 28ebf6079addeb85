/*
 * The inner loops of Blinn–Newell and EWA without derivatives: one row of
 * the footprint, its weights and their weighted sums (fp_sums). Built once
 * per instruction set next to fast_gl.c (libsample/CMakeLists.txt, isa.c)
 * and reached through isa_kernels (bn_row, ewa_row).
 *
 * Footprint rows are short — about four texels on a 2.5-texel minification,
 * a handful more on 8:1 footprints — so a loop of scalar weights plus a
 * call per texel spends most of its time on overhead. Here the weights of
 * four texels come from one pass of 4-lane double vectors (GCC/Clang vector
 * extensions: AVX in the AVX2 and AVX-512 builds, SSE2 pairs in the SSE2
 * one), and each texel's four channels are added as one vector. The
 * portable build (SAMPLE_NO_SIMD, or a compiler without the extensions)
 * runs the same formulas one lane at a time.
 *
 * Every operation is lane-wise IEEE (no FMA: -ffp-contract=off, and none
 * is written), weights are formed by the same expressions in the same
 * order as the scalar form, and the sums are added texel by texel in row
 * order, so every build returns the same bits (tests/test_fastpath.c).
 */
#include "internal.h"

#ifndef SAMPLE_ISA
#error "footprint_rows.c is built once per instruction set with SAMPLE_ISA set (libsample/CMakeLists.txt)"
#endif

#if defined(__GNUC__) && !defined(SAMPLE_NO_SIMD)
#define FP_ROWS_VECTOR 1
/* 32-byte vectors in the SSE2 build: GCC warns that passing them by value
 * would differ from an AVX caller's ABI; every function here that does is
 * static and inlined, so no such call exists. */
#pragma GCC diagnostic ignored "-Wpsabi"
#if defined(__AVX__)
#include <immintrin.h>
#endif
typedef double d4 __attribute__((vector_size(32)));
typedef float f4 __attribute__((vector_size(16)));
typedef int64_t l4 __attribute__((vector_size(32)));
typedef int32_t i4 __attribute__((vector_size(16)));

static inline d4 d4_set1(double x) { return (d4){x, x, x, x}; }
/* |x|: the sign bit cleared, as fabs. */
static inline l4 l4_set1(int64_t x) { return (l4){x, x, x, x}; }
static inline d4 d4_abs(d4 x) { return (d4)((l4)x & INT64_MAX); }
/* x > 0 ? x : +0 on each lane (NaN gives +0). */
static inline d4 d4_pos(d4 x) { return (d4)((l4)x & (x > 0.0)); }
#endif

/* Texel p's weighted channels added to the sums when w > 0 (fp_sums_add);
 * w ≤ 0 (outside the footprint) adds nothing: a texel there may be ±inf or
 * NaN. */
#if FP_ROWS_VECTOR
typedef struct sums_reg {
    d4 t;
    double w;
    uint32_t n;
} sums_reg;

static inline void sums_load(sums_reg *r, const fp_sums *s)
{
    memcpy(&r->t, s->sT, sizeof r->t);
    r->w = s->sw;
    r->n = s->n;
}

static inline void sums_store(fp_sums *s, const sums_reg *r)
{
    memcpy(s->sT, &r->t, sizeof r->t);
    s->sw = r->w;
    s->n = r->n;
}

/* Texels k < e of a chunk whose weights (lanes of w) are ≥ +0 and never
 * NaN. A texel of weight 0 must add nothing (it may be ±inf or NaN), so its
 * product is masked to +0 rather than skipped: +0 added to a sum that
 * started at +0 leaves it unchanged (round-to-nearest never makes −0 from a
 * +0 start), and so does adding its weight to Σw. The result is
 * fp_sums_add's on the texels with w > 0, in order, without a branch. */
static inline void sums_chunk(sums_reg *r, d4 w, const unsigned char *p, int e)
{
    l4 in = w > 0.0;
    int j;
    for (j = 0; j < e; ++j) {
        d4 wv = d4_set1(w[j]), t;
#if defined(__AVX__)
        t = _mm256_cvtps_pd(_mm_loadu_ps((const float *)(const void *)(p + 16 * (size_t)j)));
#else
        f4 f;
        memcpy(&f, p + 16 * (size_t)j, sizeof f);
        t = __builtin_convertvector(f, d4);
#endif
        r->t += (d4)((l4)(wv * t) & l4_set1(in[j]));
        r->w += w[j];
        r->n -= (uint32_t)in[j];
    }
}
#endif

/* ---- Blinn–Newell (footprint_blinn_newell.c, the parallelogram) --------- */

/* The pyramid at texel ilo + k, k < n, of a row: with du = (ilo + k) − u0,
 * x = m₀·du + m₁ and y = m₂·du + m₃ (the row's offset folded into m₁, m₃),
 * w = (1 − |x|)(1 − |y|) where both are inside (−1, 1), else 0. Each
 * factor is clamped at 0 instead of testing |x| < 1: 1 − |x| ≤ 0 exactly
 * when |x| ≥ 1. ilo is integral, so ilo + k is exact. */
static void bn_row(fp_sums *s, const unsigned char *p, int n, double ilo, double u0, const double m[4])
{
    int k;
#if FP_ROWS_VECTOR
    const d4 m0 = d4_set1(m[0]), m1 = d4_set1(m[1]), m2 = d4_set1(m[2]), m3 = d4_set1(m[3]);
    d4 kk = {0.0, 1.0, 2.0, 3.0};
    sums_reg r;
    sums_load(&r, s);
    for (k = 0; k < n; k += 4, kk += 4.0) {
        d4 du = (ilo + kk) - u0, w;
        int e = n - k < 4 ? n - k : 4;
        /* Both factors in [+0, 1]: w is ≥ +0 and not NaN (sums_chunk). */
        w = d4_pos(1.0 - d4_abs(m0 * du + m1)) * d4_pos(1.0 - d4_abs(m2 * du + m3));
        sums_chunk(&r, w, p + 16 * (size_t)k, e);
    }
    sums_store(s, &r);
#else
    for (k = 0; k < n; ++k) {
        double du = (ilo + k) - u0, fx = 1.0 - fabs(m[0] * du + m[1]), fy = 1.0 - fabs(m[2] * du + m[3]);
        float t4[4];
        fx = fx > 0.0 ? fx : 0.0;
        fy = fy > 0.0 ? fy : 0.0;
        if (!(fx * fy > 0.0)) continue;
        memcpy(t4, p + 16 * (size_t)k, sizeof t4);
        fp_sums_add(s, fx * fy, t4);
    }
#endif
}

/* ---- EWA (footprint_ewa.c) ---------------------------------------------- */

/* The truncated Gaussian at texel ilo + k, k < n, of the row dv texels from
 * the centre: r² = A·du² + B·du·dv + C·dv² (abc = A, B, C), weight
 * fp_ewa_weight(r²) where r² < 1 (r² < 0, rounding, as 0), else 0. */
static void ewa_row(fp_sums *s, const unsigned char *p, int n, double ilo, double u0, double dv, const double abc[3])
{
    const double A = abc[0], B = abc[1], cvv = abc[2] * dv * dv;
    int k;
#if FP_ROWS_VECTOR
    d4 kk = {0.0, 1.0, 2.0, 3.0};
    sums_reg r;
    sums_load(&r, s);
    for (k = 0; k < n; k += 4, kk += 4.0) {
        d4 du = (ilo + kk) - u0, r2 = A * du * du + B * du * dv + cvv, w;
        l4 in = r2 < 1.0;
        int e = n - k < 4 ? n - k : 4;
        d4 x, lo, hi;
        i4 ie;
        /* fp_ewa_weight on four lanes; lanes outside read the table at 0
         * and are masked out after. r² < 1 keeps the index ≤ 127. */
        r2 = (d4)((l4)d4_pos(r2) & in);
        x = r2 * 128.0;
        ie = __builtin_convertvector(x, i4);
        lo = (d4){fp_ewa_lut[ie[0]], fp_ewa_lut[ie[1]], fp_ewa_lut[ie[2]], fp_ewa_lut[ie[3]]};
        hi = (d4){fp_ewa_lut[ie[0] + 1], fp_ewa_lut[ie[1] + 1], fp_ewa_lut[ie[2] + 1], fp_ewa_lut[ie[3] + 1]};
        w = lo + (x - __builtin_convertvector(ie, d4)) * (hi - lo);
        /* Table values are in [0, 1): w is ≥ +0 and not NaN. */
        w = (d4)((l4)w & in);
        sums_chunk(&r, w, p + 16 * (size_t)k, e);
    }
    sums_store(s, &r);
#else
    for (k = 0; k < n; ++k) {
        double du = (ilo + k) - u0, r2 = A * du * du + B * du * dv + cvv, w;
        float t4[4];
        if (!(r2 < 1.0)) continue;
        w = fp_ewa_weight(r2 > 0.0 ? r2 : 0.0, NULL);
        if (!(w > 0.0)) continue;
        memcpy(t4, p + 16 * (size_t)k, sizeof t4);
        fp_sums_add(s, w, t4);
    }
#endif
}

/* ---- This build's row kernels (isa.c) ----------------------------------- */

const fp_row_kernels SAMPLE_ISA_NAME(fp_row_kernels) = {bn_row, ewa_row};
