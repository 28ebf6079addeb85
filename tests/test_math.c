/*
 * portable_math.h: sample_log2 and sample_hypot, the sampling path's only
 * elementary functions, and sample_sinpi and the sRGB encoder, the mip
 * builder's, against the C library's (which are good to about half an
 * ulp, but whose last bit is theirs: the reason ours exist), and their
 * exact and special values.
 */
#include "check.h"
#include "internal.h"

#include <float.h>
#include <stdint.h>

static uint64_t rng = 0x9E3779B97F4A7C15ull;

static uint64_t rnd64(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717ull;
}

static double from_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* The promised bound: |error| < 2^−52·max(1, |log2 x|), here against libm's
 * log2 (itself within an ulp), so checked at twice that. */
static void check_log2_at(double x)
{
    double ours = sample_log2(x), ref = log2(x), mag = fabs(ref) > 1.0 ? fabs(ref) : 1.0;
    CHECK(fabs(ours - ref) <= 0x1p-51 * mag, "log2(%a) = %a, libm %a", x, ours, ref);
}

static void test_log2_powers_of_two_exact(void)
{
    int e;
    /* Every power of two, subnormals included: λ = 0 at ρ = 1 is the
     * magnification test (GL 4.6 §8.14), λ = k at ρ = 2^k the level. */
    for (e = -1074; e <= 1023; ++e) {
        double x = ldexp(1.0, e);
        CHECK(sample_log2(x) == (double)e, "log2(2^%d) = %a", e, sample_log2(x));
    }
}

static void test_log2_special(void)
{
    CHECK(sample_log2(0.0) == -INFINITY, "log2(+0) = %a", sample_log2(0.0));
    CHECK(sample_log2(-0.0) == -INFINITY, "log2(-0) = %a", sample_log2(-0.0));
    CHECK(sample_log2(INFINITY) == INFINITY, "log2(inf) = %a", sample_log2(INFINITY));
    CHECK(isnan(sample_log2(-INFINITY)), "log2(-inf) = %a", sample_log2(-INFINITY));
    CHECK(isnan(sample_log2(-1.0)), "log2(-1) = %a", sample_log2(-1.0));
    CHECK(isnan(sample_log2(-DBL_MIN)), "log2(-DBL_MIN) = %a", sample_log2(-DBL_MIN));
    CHECK(isnan(sample_log2(NAN)), "log2(NaN) = %a", sample_log2(NAN));
    check_log2_at(DBL_MAX);
    check_log2_at(DBL_TRUE_MIN * 3.0);
    check_log2_at(DBL_MIN * 1.5);
    check_log2_at(3.0);
    check_log2_at(10.0);
}

static void test_log2_near_one(void)
{
    int k;
    /* The ulps on either side of 1 (where log2 is smallest: absolute
     * accuracy is what λ needs) and either side of every table interval's
     * edge and centre. */
    for (k = 1; k <= 1000; ++k) {
        check_log2_at(1.0 + k * DBL_EPSILON);
        check_log2_at(1.0 - k * DBL_EPSILON / 2);
    }
    for (k = 0; k <= 256; ++k) {
        double x = 1.0 + k / 256.0;
        check_log2_at(x);
        check_log2_at(nextafter(x, 0.0));
        check_log2_at(nextafter(x, 4.0));
    }
}

static void test_log2_random(void)
{
    int k;
    /* Random bit patterns of positive finite doubles (every exponent), and
     * random values of the magnitudes λ sees: ρ² of 1e−12 … 1e12. */
    for (k = 0; k < 200000; ++k) {
        double x = from_bits(rnd64() >> 1);
        if (x < INFINITY) check_log2_at(x);
        check_log2_at(ldexp(1.0 + (double)(rnd64() >> 11) * 0x1p-53, (int)(rnd64() % 81) - 40));
    }
}

static void test_log2_monotone(void)
{
    int k;
    /* λ picks levels by comparisons; across each table seam and in a
     * random sweep, a larger x never gives a smaller log2. */
    for (k = 1; k < 128; ++k) {
        double seam = 1.0 + k / 128.0, lo = nextafter(seam, 0.0), hi = nextafter(seam, 4.0);
        CHECK(sample_log2(lo) <= sample_log2(seam) && sample_log2(seam) <= sample_log2(hi), "seam %d", k);
    }
    for (k = 0; k < 100000; ++k) {
        double x = 1.0 + (double)(rnd64() >> 11) * 0x1p-53, y = nextafter(x, 4.0);
        CHECK(sample_log2(x) <= sample_log2(y), "log2(%a) = %a > log2(%a) = %a", x, sample_log2(x), y, sample_log2(y));
    }
}

/* Relative error within 2 ulp of libm's hypot (within 1 of the exact). */
static void check_hypot_at(double x, double y)
{
    double ours = sample_hypot(x, y), ref = hypot(x, y);
    CHECK(fabs(ours - ref) <= 2.0 * DBL_EPSILON * ref, "hypot(%a, %a) = %a, libm %a", x, y, ours, ref);
}

static void test_hypot(void)
{
    int k;
    CHECK(sample_hypot(3.0, 4.0) == 5.0, "hypot(3, 4) = %a", sample_hypot(3.0, 4.0));
    CHECK(sample_hypot(-3.0, 4.0) == 5.0, "hypot(-3, 4) = %a", sample_hypot(-3.0, 4.0));
    CHECK(sample_hypot(0.0, 0.0) == 0.0, "hypot(0, 0) = %a", sample_hypot(0.0, 0.0));
    CHECK(sample_hypot(0.0, -2.5) == 2.5, "hypot(0, -2.5) = %a", sample_hypot(0.0, -2.5));
    CHECK(sample_hypot(INFINITY, NAN) == INFINITY, "hypot(inf, NaN) = %a", sample_hypot(INFINITY, NAN));
    CHECK(sample_hypot(NAN, -INFINITY) == INFINITY, "hypot(NaN, -inf) = %a", sample_hypot(NAN, -INFINITY));
    CHECK(isnan(sample_hypot(NAN, 1.0)), "hypot(NaN, 1) = %a", sample_hypot(NAN, 1.0));
    CHECK(isnan(sample_hypot(1.0, NAN)), "hypot(1, NaN) = %a", sample_hypot(1.0, NAN));
    /* No overflow or underflow in between. */
    check_hypot_at(1e300, 1e300);
    check_hypot_at(DBL_MAX / 2, DBL_MAX / 4);
    check_hypot_at(1e-310, 3e-310);
    check_hypot_at(DBL_TRUE_MIN, DBL_TRUE_MIN);
    check_hypot_at(1e200, 1e-200);
    CHECK(sample_hypot(DBL_MAX, DBL_MAX) == INFINITY, "hypot(DBL_MAX, DBL_MAX) = %a", sample_hypot(DBL_MAX, DBL_MAX));
    for (k = 0; k < 200000; ++k) {
        double x = from_bits(rnd64()), y = from_bits(rnd64());
        if (isfinite(x) && isfinite(y) && isfinite(hypot(x, y))) check_hypot_at(x, y);
        x = ldexp((double)(rnd64() >> 11) * 0x1p-53 - 0.5, (int)(rnd64() % 61) - 30);
        y = ldexp((double)(rnd64() >> 11) * 0x1p-53 - 0.5, (int)(rnd64() % 61) - 30);
        check_hypot_at(x, y);
    }
}

static void test_sinpi(void)
{
    const double pi = 3.14159265358979323846;
    int k;
    /* Exact zeros at the integers, ±1 at the half-integers. */
    for (k = -1000; k <= 1000; ++k) {
        CHECK(sample_sinpi((double)k) == 0.0, "sinpi(%d) = %a", k, sample_sinpi((double)k));
        CHECK(sample_sinpi(k + 0.5) == ((k & 1) ? -1.0 : 1.0), "sinpi(%d.5) = %a", k, sample_sinpi(k + 0.5));
    }
    CHECK(sample_sinpi(0x1p60) == 0.0, "sinpi(2^60) = %a", sample_sinpi(0x1p60));
    CHECK(isnan(sample_sinpi(INFINITY)) && isnan(sample_sinpi(-INFINITY)) && isnan(sample_sinpi(NAN)), "sinpi(inf)");
    CHECK(sample_sinpi(-0.25) == -sample_sinpi(0.25), "odd");
    /* Against libm's sin on the reduced argument (π·x itself would carry
     * a rounding error of |x| ulps): x = n + r exactly, sin(πx) =
     * (−1)^n·sin(πr); the mip kernels' range (|x| ≤ 3) and beyond. */
    for (k = 0; k < 200000; ++k) {
        double x = ((double)(rnd64() >> 11) * 0x1p-53 - 0.5) * 8.0, n = nearbyint(x),
               ref = (fmod(n, 2.0) != 0.0 ? -1.0 : 1.0) * sin(pi * (x - n));
        CHECK(fabs(sample_sinpi(x) - ref) <= 4.0 * DBL_EPSILON, "sinpi(%a) = %a, libm %a", x, sample_sinpi(x), ref);
    }
}

static void test_srgb_encode8(void)
{
    int k;
    float v;
    /* Every code's decoded value encodes back to the code. */
    for (k = 0; k < 256; ++k)
        CHECK(ls_srgb_encode8(ls_srgb_table[k]) == k, "code %d -> %d", k, ls_srgb_encode8(ls_srgb_table[k]));
    CHECK(ls_srgb_encode8(NAN) == 0 && ls_srgb_encode8(-1.0f) == 0 && ls_srgb_encode8(-0.0f) == 0,
          "NaN and negatives");
    CHECK(ls_srgb_encode8(1.0f) == 255 && ls_srgb_encode8(7.5f) == 255 && ls_srgb_encode8(INFINITY) == 255,
          "1 and above");
    /* Monotone, and round(255·OETF(v)) as pow computes it except within
     * 1e−6 of a tie (where pow's last bit may decide either way). */
    for (v = 0.0f; v <= 1.0f; v += 1.0f / 65536.0f) {
        double e = v <= 0.0031308f ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055, x = 255.0 * e;
        int want = (int)floor(x + 0.5), got = ls_srgb_encode8(v);
        CHECK(got == want || fabs(x - floor(x) - 0.5) < 1e-6, "encode(%a) = %d, pow says %d", v, got, want);
        CHECK(ls_srgb_encode8(nextafterf(v, 2.0f)) >= got, "monotone at %a", v);
    }
}

int main(void)
{
    RUN(test_log2_powers_of_two_exact);
    RUN(test_log2_special);
    RUN(test_log2_near_one);
    RUN(test_log2_random);
    RUN(test_log2_monotone);
    RUN(test_hypot);
    RUN(test_sinpi);
    RUN(test_srgb_encode8);
    return check_finish();
}
