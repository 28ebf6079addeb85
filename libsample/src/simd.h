/*
 * A thin 4-float vector layer (stb style): one RGBA texel or result per
 * vector. SSE2 where the compiler targets it (every x86-64), plain structs
 * otherwise or when SAMPLE_NO_SIMD is defined. The fast path (fast_gl.c) is
 * compiled once per instruction set with this header (isa.c): plain structs
 * (the portable "scalar" kernels), SSE2, and SSE2 code re-encoded with VEX
 * (-mavx2, -mavx512*) plus F16C's half conversion; the operations are the
 * same lane-wise IEEE ones in every build.
 *
 * Only IEEE-exact lane-wise operations are offered (add, sub, mul, div,
 * exact int → float): with fused multiply-add off (-ffp-contract=off, and no
 * FMA intrinsics here) each lane then rounds exactly as the scalar C
 * expression would, so the vector and scalar builds give the same bits.
 */
#ifndef SAMPLE_SIMD_H
#define SAMPLE_SIMD_H

#include "sample/sample.h"

#include <stdint.h>
#include <string.h>

/* The plain builds' vector V of four T: a struct, loads and stores by
 * memcpy, and lane-wise operations as loops (v4f and v4d below). */
#define SAMPLE_PLAIN_LANES(V, T, load, store)                                  \
    typedef struct V {                                                         \
        T v[4];                                                                \
    } V;                                                                       \
    static inline V load(const T *p)                                           \
    {                                                                          \
        V r;                                                                   \
        memcpy(r.v, p, sizeof r.v);                                            \
        return r;                                                              \
    }                                                                          \
    static inline void store(T *p, V a) { memcpy(p, a.v, sizeof a.v); }
#define SAMPLE_PLAIN_LANEWISE(V, name, op)                                     \
    static inline V name(V a, V b)                                             \
    {                                                                          \
        int k;                                                                 \
        for (k = 0; k < 4; ++k) a.v[k] = a.v[k] op b.v[k];                     \
        return a;                                                              \
    }

#if defined(__SSE2__) && !defined(SAMPLE_NO_SIMD)
#define SAMPLE_SIMD_SSE2 1
#include <emmintrin.h>
#if defined(__F16C__)
#include <immintrin.h>
#endif

typedef __m128 v4f;
static inline v4f v4_load(const float *p) { return _mm_loadu_ps(p); }
static inline void v4_store(float *p, v4f a) { _mm_storeu_ps(p, a); }
static inline v4f v4_set1(float x) { return _mm_set1_ps(x); }
static inline v4f v4_set(float x, float y, float z, float w) { return _mm_setr_ps(x, y, z, w); }
static inline v4f v4_add(v4f a, v4f b) { return _mm_add_ps(a, b); }
static inline v4f v4_sub(v4f a, v4f b) { return _mm_sub_ps(a, b); }
static inline v4f v4_mul(v4f a, v4f b) { return _mm_mul_ps(a, b); }
#if defined(__F16C__)
/* Four IEEE halves (8 bytes at p) widened exactly: the same bits as
 * sample_half_to_float on each lane. In the builds that have F16C (the
 * AVX2 and AVX-512 kernels, isa.c) VCVTPH2PS does the work: every finite
 * half, subnormals included, is exact in float, and the instruction
 * ignores MXCSR.DAZ (Intel SDM vol. 2, VCVTPH2PS: "the correct normal
 * result is returned. MXCSR.DAZ is ignored"). Only NaNs need care: it
 * returns a signalling NaN quieted (bit 22 set), while
 * sample_half_to_float moves the payload as it is. The quiet bit is
 * cleared again on the lanes whose half was a signalling NaN (exponent all
 * ones, mantissa ≠ 0, half bit 9 clear), with a few integer operations.
 * tests/test_isa.c checks all 65536 halves against sample_half_to_float
 * in every build. */
static inline v4f v4_from_f16x4(const unsigned char *p)
{
    __m128i h = _mm_loadl_epi64((const __m128i *)(const void *)p);
    __m128i h32 = _mm_unpacklo_epi16(h, _mm_setzero_si128());
    __m128i nan = _mm_cmpgt_epi32(_mm_and_si128(h32, _mm_set1_epi32(0x7fff)), _mm_set1_epi32(0x7c00));
    /* Bit 22 on the NaN lanes whose half bit 9 (moved by 13, as the
     * payload is) is 0. */
    __m128i clear = _mm_andnot_si128(_mm_slli_epi32(h32, 13), _mm_and_si128(nan, _mm_set1_epi32(0x400000)));
    return _mm_castsi128_ps(_mm_andnot_si128(clear, _mm_castps_si128(_mm_cvtph_ps(h))));
}
#if defined(__AVX2__)
/* Two texels' halves (16 bytes at p) as v4_from_f16x4 widens each, in one
 * 256-bit pass: the same operations on eight lanes. */
static inline void v4_pair_from_f16x8(const unsigned char *p, v4f *a, v4f *b)
{
    __m128i h = _mm_loadu_si128((const __m128i *)(const void *)p);
    __m256i h32 = _mm256_cvtepu16_epi32(h);
    __m256i nan = _mm256_cmpgt_epi32(_mm256_and_si256(h32, _mm256_set1_epi32(0x7fff)), _mm256_set1_epi32(0x7c00));
    __m256i clear = _mm256_andnot_si256(_mm256_slli_epi32(h32, 13), _mm256_and_si256(nan, _mm256_set1_epi32(0x400000)));
    __m256 v = _mm256_castsi256_ps(_mm256_andnot_si256(clear, _mm256_castps_si256(_mm256_cvtph_ps(h))));
    *a = _mm256_castps256_ps128(v);
    *b = _mm256_extractf128_ps(v, 1);
}
#endif
#else
/* Four IEEE halves (8 bytes at p) widened exactly: the same bits as
 * sample_half_to_float on each lane. Normal, inf and NaN halves move their
 * exponent and mantissa into place and rebias the exponent (+112, or +224
 * for the all-ones exponent); zero and subnormal halves are man × 2^−24,
 * exact in float. */
static inline v4f v4_from_f16x4(const unsigned char *p)
{
    __m128i z = _mm_setzero_si128(), h, em, sign, bits, isinf, issub;
    __m128 sub;
    h = _mm_unpacklo_epi16(_mm_loadl_epi64((const __m128i *)(const void *)p), z);
    sign = _mm_slli_epi32(_mm_and_si128(h, _mm_set1_epi32(0x8000)), 16);
    em = _mm_and_si128(h, _mm_set1_epi32(0x7fff));
    isinf = _mm_cmpgt_epi32(em, _mm_set1_epi32(0x7bff));
    issub = _mm_cmplt_epi32(em, _mm_set1_epi32(0x0400));
    bits = _mm_add_epi32(_mm_slli_epi32(em, 13),
                         _mm_add_epi32(_mm_set1_epi32(112 << 23),
                                       _mm_and_si128(isinf, _mm_set1_epi32(112 << 23))));
    sub = _mm_mul_ps(_mm_cvtepi32_ps(em), _mm_set1_ps(5.9604644775390625e-8f));
    bits = _mm_or_si128(_mm_andnot_si128(issub, bits), _mm_and_si128(issub, _mm_castps_si128(sub)));
    return _mm_castsi128_ps(_mm_or_si128(bits, sign));
}
#endif /* __F16C__ */
#else
SAMPLE_PLAIN_LANES(v4f, float, v4_load, v4_store)
static inline v4f v4_set(float x, float y, float z, float w)
{
    v4f r;
    r.v[0] = x; r.v[1] = y; r.v[2] = z; r.v[3] = w;
    return r;
}
static inline v4f v4_set1(float x) { return v4_set(x, x, x, x); }
SAMPLE_PLAIN_LANEWISE(v4f, v4_add, +)
SAMPLE_PLAIN_LANEWISE(v4f, v4_sub, -)
SAMPLE_PLAIN_LANEWISE(v4f, v4_mul, *)
static inline v4f v4_from_f16x4(const unsigned char *p)
{
    uint16_t h[4];
    memcpy(h, p, sizeof h);
    return v4_set(sample_half_to_float(h[0]), sample_half_to_float(h[1]),
                  sample_half_to_float(h[2]), sample_half_to_float(h[3]));
}
#endif

/* Four doubles: sums of four-channel float values kept in double (the
 * anisotropic filter's probes, fp_aniso_add). The same three builds: one
 * AVX register, two SSE2 ones, or a plain array; lane-wise IEEE add and
 * mul, and the exact float → double widening. */
#if defined(SAMPLE_SIMD_SSE2) && defined(__AVX__)
typedef __m256d v4d;
static inline v4d v4d_load(const double *p) { return _mm256_loadu_pd(p); }
static inline void v4d_store(double *p, v4d a) { _mm256_storeu_pd(p, a); }
static inline v4d v4d_set1(double x) { return _mm256_set1_pd(x); }
static inline v4d v4d_of(v4f a) { return _mm256_cvtps_pd(a); }
static inline v4d v4d_add(v4d a, v4d b) { return _mm256_add_pd(a, b); }
static inline v4d v4d_mul(v4d a, v4d b) { return _mm256_mul_pd(a, b); }
#elif defined(SAMPLE_SIMD_SSE2)
typedef struct v4d {
    __m128d lo, hi;
} v4d;
static inline v4d v4d_load(const double *p)
{
    v4d r;
    r.lo = _mm_loadu_pd(p);
    r.hi = _mm_loadu_pd(p + 2);
    return r;
}
static inline void v4d_store(double *p, v4d a)
{
    _mm_storeu_pd(p, a.lo);
    _mm_storeu_pd(p + 2, a.hi);
}
static inline v4d v4d_set1(double x)
{
    v4d r;
    r.lo = r.hi = _mm_set1_pd(x);
    return r;
}
static inline v4d v4d_of(v4f a)
{
    v4d r;
    r.lo = _mm_cvtps_pd(a);
    r.hi = _mm_cvtps_pd(_mm_movehl_ps(a, a));
    return r;
}
static inline v4d v4d_add(v4d a, v4d b)
{
    a.lo = _mm_add_pd(a.lo, b.lo);
    a.hi = _mm_add_pd(a.hi, b.hi);
    return a;
}
static inline v4d v4d_mul(v4d a, v4d b)
{
    a.lo = _mm_mul_pd(a.lo, b.lo);
    a.hi = _mm_mul_pd(a.hi, b.hi);
    return a;
}
#else
SAMPLE_PLAIN_LANES(v4d, double, v4d_load, v4d_store)
static inline v4d v4d_set1(double x)
{
    v4d r;
    r.v[0] = r.v[1] = r.v[2] = r.v[3] = x;
    return r;
}
static inline v4d v4d_of(v4f a)
{
    v4d r;
    int k;
    for (k = 0; k < 4; ++k) r.v[k] = a.v[k];
    return r;
}
SAMPLE_PLAIN_LANEWISE(v4d, v4d_add, +)
SAMPLE_PLAIN_LANEWISE(v4d, v4d_mul, *)
#endif

/* GCC's vector extensions on AVX registers, for kernels whose lanes are
 * rows, texels or queries rather than a texel's channels
 * (footprint_rows.c, lod_lanes.h): four doubles, four 64-bit integers
 * (comparison masks, bit patterns) and four 32-bit integers. */
#if defined(__GNUC__) && defined(SAMPLE_SIMD_SSE2) && defined(__AVX__)
#define SAMPLE_VEC_AVX 1
#include <immintrin.h>
typedef double d4 __attribute__((vector_size(32)));
typedef int64_t l4 __attribute__((vector_size(32)));
typedef int32_t i4 __attribute__((vector_size(16)));
#if defined(__AVX2__)
/* And AVX2's integer lanes and gathers (the fast path's block passes,
 * fast_gl.c and lod_lanes.h). */
#define SAMPLE_VEC_AVX2 1
#endif
#endif

#endif /* SAMPLE_SIMD_H */
