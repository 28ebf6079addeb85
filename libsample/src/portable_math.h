/*
 * The elementary
 * functions the sampling path needs (log2 for λ, GL 4.6 §8.14.1; hypot for
 * the footprint's singular values, footprint_common.c) and the mip
 * builder's sin πx (its windowed sincs, mip.c), written with IEEE
 * 754's basic operations alone (+, −, ×, ÷, √, exact scaling by powers of
 * two), which every conforming machine rounds the same way.
 *
 * Why not libm: DESIGN asks for the same answers bit for bit on any
 * machine, and libm's log2 and hypot are not correctly rounded — their
 * last bit depends on the C library and its version (glibc 2.35 replaced
 * hypot, for one). A λ one ulp apart moves a trilinear blend weight and
 * with it the result's last bits. With these, results depend only on the
 * compiler honouring -ffp-contract=off and evaluating double as double
 * (FLT_EVAL_METHOD 0; the x87 unit does not), checked below.
 * doc/performance.md, "Run-time ISA dispatch".
 */
#ifndef SAMPLE_PORTABLE_MATH_H
#define SAMPLE_PORTABLE_MATH_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "libsample's bit-for-bit results need FLT_EVAL_METHOD 0 (SSE2 arithmetic on x86, not x87)"
#endif

/* log2 x with an absolute error below 2^−52·max(1, |log2 x|)
 * (tests/test_math.c), exact where x is a power of two (subnormals
 * included: λ = 0 at ρ = 1 decides magnification, GL 4.6 §8.14);
 * log2 ±0 = −inf, log2 +inf = +inf, NaN for x < 0 and NaN.
 * x = 2^e·m, m ∈ [1, 2); c = 1 + (i + ½)/128 is the centre of m's 1/128th
 * (i: m's top seven fraction bits), so m − c is exact and |r| < 2^−8 for
 * r = (m − c)/c, and log2 m = log2 c + log2(1 + r) with log2 c from
 * ls_log2_table (portable_math.c) and log2(1 + r) = (r − r²/2 + … +
 * r⁷/7)/ln 2 (what it leaves out is below 2^−67), evaluated in Estrin's
 * order: a short dependency chain, since λ of one query waits on it. */
extern const double ls_log2_table[128][2];

/* The pieces of sample_log2 that lod_lanes.h's four-lane version (λ of a
 * block of queries) writes with vectors: the same constants, masks and
 * polynomial, so that both round identically. SAMPLE_LOG2_POLY takes r and
 * r² of either type (GCC's vector extensions broadcast the constants). */
#define SAMPLE_LOG2_FRAC 0x000fffffffffffffull   /* the fraction bits */
#define SAMPLE_LOG2_ONE 0x3ff0000000000000ull    /* 1.0's exponent */
#define SAMPLE_LOG2_TOP7 45                       /* i = the top 7 fraction bits */
#define SAMPLE_LOG2_MID (1ull << 44)              /* c: the bit after them */
/* (−1)^(k+1)/(k·ln 2), k = 1 … 7, each the nearest double. */
#define SAMPLE_LOG2_POLY(r, r2)                                                                                     \
    ((0x1.71547652b82fep+0 + (r) * -0x1.71547652b82fep-1) + (r2) * (0x1.ec709dc3a03fdp-2 + (r) * -0x1.71547652b82fep-2) + \
     ((r2) * (r2)) * ((0x1.2776c50ef9bfep-2 + (r) * -0x1.ec709dc3a03fdp-3) + (r2) * 0x1.a61762a7aded9p-3))

static inline double sample_log2(double x)
{
    uint64_t b;
    int e, i;
    double m, c, r, r2, p;
    if (!(x > 0.0)) return x == 0.0 ? -INFINITY : NAN;
    if (!(x < INFINITY)) return x;
    memcpy(&b, &x, sizeof b);
    e = (int)(b >> 52) - 1023;
    if (e == -1023) { /* subnormal: 2^54·x is normal and exact */
        x *= 0x1p54;
        memcpy(&b, &x, sizeof b);
        e = (int)(b >> 52) - 1023 - 54;
    }
    b &= SAMPLE_LOG2_FRAC;
    if (b == 0) return (double)e;
    i = (int)(b >> SAMPLE_LOG2_TOP7);
    /* m, and c: m's top seven fraction bits, then a one (integer steps). */
    b |= SAMPLE_LOG2_ONE;
    memcpy(&m, &b, sizeof m);
    b = (b & ~((1ull << SAMPLE_LOG2_TOP7) - 1)) | SAMPLE_LOG2_MID;
    memcpy(&c, &b, sizeof c);
    r = (m - c) * ls_log2_table[i][1];
    r2 = r * r;
    p = SAMPLE_LOG2_POLY(r, r2);
    return (double)e + (ls_log2_table[i][0] + r * p);
}

/* √(x² + y²) within about 1 ulp, without overflow or underflow in between
 * (exact power-of-two scaling where the squares would leave double's
 * range); +inf if either is ±inf (even with a NaN, as C's hypot), else NaN
 * if either is NaN. */
static inline double sample_hypot(double x, double y)
{
    double a = fabs(x), b = fabs(y), t;
    if (a == INFINITY || b == INFINITY) return INFINITY;
    if (a != a || b != b) return a + b;
    if (a < b) {
        t = a;
        a = b;
        b = t;
    }
    if (a > 0x1p500) {
        a *= 0x1p-600;
        b *= 0x1p-600;
        return sqrt(a * a + b * b) * 0x1p600;
    }
    if (a < 0x1p-500) {
        a *= 0x1p600;
        b *= 0x1p600;
        return sqrt(a * a + b * b) * 0x1p-600;
    }
    return sqrt(a * a + b * b);
}

/* ceil and floor, for the footprint filters' row and column bounds (twice
 * per row; without SSE4.1 GCC expands ceil() into some twenty
 * instructions) and sample_sinpi's argument reduction. Any |x| ≥ 2^52 is already integral, NaN and ±inf pass
 * through; the values are ceil's and floor's except that a zero result is
 * always +0 (ceil(−0.5) = −0), which the callers' arithmetic does not see. */
static inline double fp_ceil(double x)
{
    double t;
    if (!(fabs(x) < 0x1p52)) return x;
    t = (double)(int64_t)x;
    return t < x ? t + 1.0 : t;
}

static inline double fp_floor(double x)
{
    double t;
    if (!(fabs(x) < 0x1p52)) return x;
    t = (double)(int64_t)x;
    return t > x ? t - 1.0 : t;
}

/* sin(π·x) within about 2^−53 absolute for every finite x, exactly 0 at
 * the integers (libm's sin(π·n) is not); NaN for ±inf and NaN. The mip
 * builder's windowed-sinc kernels (mip.c), not the sampling path: with it
 * a pyramid built from the same image is the same on any machine too.
 * x = n + r, n the nearest integer, |r| ≤ ½ (exact: x − n needs no
 * rounding), sin(πx) = (−1)^n·sin(πr), and sin(πr) by its Taylor series to
 * (πr)^23/23! (the rest is below 2^−59 for |πr| ≤ π/2); ±1 exactly at
 * the half-integers. */
static inline double sample_sinpi(double x)
{
    /* (−1)^k·π^(2k+1)/(2k+1)!, k = 0 … 11, each the nearest double. */
    static const double c[12] = {
        0x1.921fb54442d18p+1,  -0x1.4abbce625be53p+2, 0x1.466bc6775aae2p+1,  -0x1.32d2cce62bd86p-1,
        0x1.50783487ee782p-4,  -0x1.e3074fde8871fp-8, 0x1.e8f434d018d63p-12, -0x1.6fadb9f155744p-16,
        0x1.aaec32af93359p-21, -0x1.8a404211f9547p-26, 0x1.2877020d52cf0p-31, -0x1.7215f879e1ac9p-37,
    };
    double n, r, r2, p;
    int k;
    if (!(fabs(x) < INFINITY)) return x - x; /* NaN */
    if (!(fabs(x) < 0x1p52)) return 0.0;     /* an integer (and even beyond 2^53) */
    n = fp_floor(x + 0.5);
    r = x - n;
    if (r == 0.0) return 0.0;
    if (fabs(r) == 0.5) p = 1.0; /* the series' rounding would give 1 − ulp */
    else {
        r2 = r * r;
        p = c[11];
        for (k = 10; k >= 0; --k) p = c[k] + r2 * p;
        p *= fabs(r);
    }
    if (r < 0.0) p = -p;
    return ((int64_t)n & 1) ? -p : p;
}

#endif /* SAMPLE_PORTABLE_MATH_H */
