/*
 * Reconstruction on one level (DESIGN §4) and texel formats (DESIGN §2):
 * exact averages, bit-exact texel reads for all four formats, the sRGB EOTF
 * to 1 ulp, half conversion, and what each cubic variant must and must not do.
 */
#include "check.h"
#include "internal.h"
#include "sample/testing.h"

#include <stdint.h>
#include <stdlib.h>

static sample_texture *make_tex(int w, int h, int ch, sample_format f, const void *data)
{
    sample_image im = {w, h, ch, f, data, 0};
    sample_texture *t = NULL;
    sample_error err;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_OK, "create: %s", err.message);
    return t;
}

static void sampler_for(sample_sampler *s, sample_filter f, sample_wrap w)
{
    sample_sampler_init(s);
    s->mag_filter = s->min_filter = f;
    s->wrap_s = s->wrap_t = w;
}

static float at(const sample_texture *t, const sample_sampler *s, float u, float v, int c)
{
    sample_query q = {0};
    float out[4];
    q.s = u;
    q.t = v;
    CHECK(sample_one(t, s, &q, out) == SAMPLE_OK, "sample");
    return out[c];
}

/* Halfway between texels the bilinear weights are exactly ½ (and ¼ in 2D),
 * so the result is the exact average. */
static void bilinear_exact_average(void)
{
    const float px[16] = {1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1, 5, 0, 0, 1};
    sample_texture *t = make_tex(2, 2, 4, SAMPLE_FORMAT_F32, px);
    sample_sampler s;
    sampler_for(&s, SAMPLE_LINEAR, SAMPLE_WRAP_CLAMP_TO_EDGE);
    CHECK_EQF(at(t, &s, 0.5f, 0.5f, 0), 2.75f);   /* (1+2+3+5)/4 */
    CHECK_EQF(at(t, &s, 0.5f, 0.25f, 0), 1.5f);   /* row 0: (1+2)/2 */
    CHECK_EQF(at(t, &s, 0.25f, 0.5f, 0), 2.0f);   /* column 0: (1+3)/2 */
    CHECK_EQF(at(t, &s, 0.375f, 0.25f, 0), 1.25f); /* u=0.75 → α=¼: ¾·1 + ¼·2 */
    sample_texture_destroy(t);
}

/* Random texels of every format, read back at texel centres with NEAREST:
 * the result is the decoded texel, bit for bit. Expected values are decoded
 * here independently of the library's tables. */
static double srgb_eotf(double v) { return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4); }

static float half_ref(uint16_t h)
{
    int e = (h >> 10) & 31, m = h & 1023;
    double v = e == 0 ? ldexp(m, -24) : (e == 31 ? (m ? NAN : INFINITY) : ldexp(1024 + m, e - 25));
    return (float)((h & 0x8000) ? -v : v);
}

static void nearest_bit_exact_formats(void)
{
    enum { W = 7, H = 5 };
    int f, ch, i, j, c;
    srand(7);
    for (f = 0; f < SAMPLE_FORMAT_COUNT; ++f) {
        for (ch = 1; ch <= 4; ++ch) {
            unsigned char raw[W * H * 4 * 4];
            sample_texture *t;
            sample_sampler s;
            size_t k, nbytes = (size_t)W * H * ch * sample_format_bytes((sample_format)f);
            for (k = 0; k < nbytes; ++k) raw[k] = (unsigned char)(rand() & 255);
            if (f == SAMPLE_FORMAT_F32) /* keep floats finite and not NaN */
                for (k = 0; k < nbytes; k += 4) raw[k + 3] &= 0x3f;
            if (f == SAMPLE_FORMAT_F16)
                for (k = 0; k < nbytes; k += 2) raw[k + 1] &= 0x7b;
            t = make_tex(W, H, ch, (sample_format)f, raw);
            sampler_for(&s, SAMPLE_NEAREST, SAMPLE_WRAP_REPEAT);
            for (j = 0; j < H; ++j)
                for (i = 0; i < W; ++i) {
                    sample_query q = {0};
                    float out[4], want[4] = {0, 0, 0, 1};
                    const unsigned char *p =
                        raw + ((size_t)j * W + i) * ch * sample_format_bytes((sample_format)f);
                    q.s = ((float)i + 0.5f) / W;
                    q.t = ((float)j + 0.5f) / H;
                    sample_one(t, &s, &q, out);
                    for (c = 0; c < ch; ++c) {
                        if (f == SAMPLE_FORMAT_F32) memcpy(&want[c], p + 4 * c, 4);
                        else if (f == SAMPLE_FORMAT_F16) want[c] = half_ref((uint16_t)(p[2 * c] | p[2 * c + 1] << 8));
                        else if (f == SAMPLE_FORMAT_UNORM8 || c == 3) want[c] = (float)((double)p[c] / 255.0);
                        else want[c] = (float)srgb_eotf(p[c] / 255.0);
                    }
                    for (c = 0; c < 4; ++c) {
                        if (f == SAMPLE_FORMAT_SRGB8 && c < ch && c < 3)
                            /* table entries are the EOTF rounded to float:
                             * allow the 1 ulp of the design's bound */
                            CHECK(fabsf(out[c] - want[c]) <= nextafterf(want[c], 2.0f) - want[c],
                                  "srgb texel (%d,%d) c%d: %.9g vs %.9g", i, j, c, (double)out[c], (double)want[c]);
                        else
                            CHECK(memcmp(&out[c], &want[c], 4) == 0, "%s/%dch texel (%d,%d) c%d: %.9g vs %.9g",
                                  sample_format_name((sample_format)f), ch, i, j, c, (double)out[c], (double)want[c]);
                    }
                }
            sample_texture_destroy(t);
        }
    }
}

/* Every 8-bit code of UNORM8 (all channels) and of SRGB8's linear alpha is
 * c / 255 correctly rounded (GL 4.6 eq. 2.1): (float)(c / 255.0) is that,
 * since rounding a double quotient to float is innocuous. Both paths, since
 * each reads the codes through the decode table. */
static void unorm8_every_code(void)
{
    unsigned char raw[256 * 4];
    int f, c, k, path;
    for (c = 0; c < 256; ++c) {
        raw[4 * c] = (unsigned char)c;
        raw[4 * c + 1] = (unsigned char)(255 - c);
        raw[4 * c + 2] = (unsigned char)(c ^ 0x55);
        raw[4 * c + 3] = (unsigned char)c;
    }
    for (f = SAMPLE_FORMAT_UNORM8; f <= SAMPLE_FORMAT_SRGB8; ++f) {
        sample_texture *t = make_tex(256, 1, 4, (sample_format)f, raw);
        for (path = 0; path < 2; ++path) {
            sample_sampler s;
            sampler_for(&s, SAMPLE_NEAREST, SAMPLE_WRAP_CLAMP_TO_EDGE);
            for (c = 0; c < 256; ++c) {
                sample_query q = {0};
                float out[4];
                q.s = ((float)c + 0.5f) / 256.0f;
                q.t = 0.5f;
                sample_batch_args a = {.count = 1, .queries = &q, .rgba = out};
                CHECK((path ? sample_batch_reference(t, &s, &a) : sample_batch(t, &s, &a)) == SAMPLE_OK, "sample");
                for (k = f == SAMPLE_FORMAT_SRGB8 ? 3 : 0; k < 4; ++k) {
                    float want = (float)((double)raw[4 * c + k] / 255.0);
                    CHECK(memcmp(&out[k], &want, 4) == 0, "%s path %d code %d channel %d: %.9g vs %.9g",
                          sample_format_name((sample_format)f), path, raw[4 * c + k], k,
                          (double)out[k], (double)want);
                }
            }
        }
        sample_texture_destroy(t);
    }
}

/* The 256-entry sRGB table against the exact EOTF in double: within 1 ulp. */
static void srgb_table_exact(void)
{
    int c;
    for (c = 0; c < 256; ++c) {
        double e = srgb_eotf(c / 255.0);
        float f = ls_srgb_table[c];
        float ulp = nextafterf((float)e, 2.0f) - (float)e;
        CHECK(fabs((double)f - e) <= ulp, "code %d: %.9g vs %.12g", c, (double)f, e);
        /* the function sees c/255 rounded to float; the EOTF amplifies that
         * input error by its log-slope (≤ 2.4), so allow 3 ulp */
        CHECK(fabsf(sample_srgb_to_linear((float)(c / 255.0)) - f) <= 3 * ulp, "function vs table at %d", c);
        /* encode inverts decode on every code */
        CHECK((int)(sample_linear_to_srgb(f) * 255.0f + 0.5f) == c, "round trip code %d", c);
    }
    CHECK_NEAR(sample_srgb_to_linear(0.5f), 0.214041140, 1e-7);
}

static void half_conversion(void)
{
    uint32_t h;
    CHECK_EQF(sample_half_to_float(0x3c00), 1.0f);
    CHECK_EQF(sample_half_to_float(0xc000), -2.0f);
    CHECK_EQF(sample_half_to_float(0x7bff), 65504.0f);
    CHECK_EQF(sample_half_to_float(0x0001), 5.9604644775390625e-8f); /* 2^-24 */
    CHECK_EQF(sample_half_to_float(0x0400), 6.103515625e-5f);        /* 2^-14 */
    CHECK_EQF(sample_half_to_float(0x3555), 0.333251953125f);
    CHECK(isinf(sample_half_to_float(0x7c00)), "inf");
    CHECK(isnan(sample_half_to_float(0x7e00)), "nan");
    /* Every finite half survives float and back bit for bit. */
    for (h = 0; h < 0x10000u; ++h) {
        if ((h & 0x7c00u) == 0x7c00u) continue;
        CHECK(sample_float_to_half(sample_half_to_float((uint16_t)h)) == h, "half 0x%04x", (unsigned)h);
        CHECK(sample_half_to_float((uint16_t)h) == half_ref((uint16_t)h) || (h & 0x7fff) == 0, "decode 0x%04x", (unsigned)h);
    }
    /* Round to nearest even at halfway points. */
    CHECK(sample_float_to_half(1.0f + 1.0f / 2048.0f) == 0x3c00, "tie to even down");
    CHECK(sample_float_to_half(1.0f + 3.0f / 2048.0f) == 0x3c02, "tie to even up");
    CHECK(sample_float_to_half(65520.0f) == 0x7c00, "overflow to inf");
    CHECK(sample_float_to_half(1e-9f) == 0x0000, "underflow to zero");
}

/* Cubic kernels: hand values of the weights at f = 0 and f = ½. */
static void cubic_kernel_values(void)
{
    double w[4], dw[4];
    ls_cubic_weights(SAMPLE_CUBIC_CATMULL_ROM, 0.5f, w, dw);
    CHECK_NEAR(w[0], -1.0 / 16, 1e-7); CHECK_NEAR(w[1], 9.0 / 16, 1e-7);
    CHECK_NEAR(w[2], 9.0 / 16, 1e-7);  CHECK_NEAR(w[3], -1.0 / 16, 1e-7);
    ls_cubic_weights(SAMPLE_CUBIC_CATMULL_ROM, 0.0f, w, dw);
    CHECK(w[0] == 0.0 && w[1] == 1.0 && w[2] == 0.0 && w[3] == 0.0, "CR at f=0 is (0,1,0,0)");
    ls_cubic_weights(SAMPLE_CUBIC_BSPLINE, 0.5f, w, dw);
    CHECK_NEAR(w[0], 1.0 / 48, 1e-7); CHECK_NEAR(w[1], 23.0 / 48, 1e-7);
    ls_cubic_weights(SAMPLE_CUBIC_BSPLINE, 0.0f, w, dw);
    CHECK_NEAR(w[0], 1.0 / 6, 1e-7); CHECK_NEAR(w[1], 2.0 / 3, 1e-7); CHECK_NEAR(w[2], 1.0 / 6, 1e-7);
    CHECK_NEAR(w[3], 0.0, 1e-7);
    /* Mitchell (⅓, ⅓): k(0) = (6 − 2B)/6 = 8/9, k(1) = B/6 = 1/18. */
    ls_cubic_weights(SAMPLE_CUBIC_MITCHELL, 0.0f, w, dw);
    CHECK_NEAR(w[0], 1.0 / 18, 1e-7); CHECK_NEAR(w[1], 8.0 / 9, 1e-7); CHECK_NEAR(w[2], 1.0 / 18, 1e-7);
    /* Derivative: Catmull–Rom at f = 0 has slope (T1 − T−1)/2. */
    ls_cubic_weights(SAMPLE_CUBIC_CATMULL_ROM, 0.0f, w, dw);
    CHECK_NEAR(dw[0], -0.5, 1e-7); CHECK_NEAR(dw[1], 0.0, 1e-7); CHECK_NEAR(dw[2], 0.5, 1e-7);
}

/* All three variants reproduce constants and linear ramps (linear
 * precision); only Catmull–Rom interpolates; the clamp bounds overshoot. */
static void cubic_precision_and_interpolation(void)
{
    enum { N = 16 };
    float ramp[N * N * 4], spike[N * N * 4], step[N * N * 4];
    int i, j, v;
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            float *r = &ramp[4 * (j * N + i)], *p = &spike[4 * (j * N + i)], *st = &step[4 * (j * N + i)];
            r[0] = 0.25f * (float)i + 0.5f * (float)j; /* linear in u and v */
            r[1] = 3.0f; r[2] = 0.0f; r[3] = 1.0f;     /* constant */
            p[0] = (i == 8 && j == 8) ? 1.0f : 0.0f; p[1] = p[2] = 0.0f; p[3] = 1.0f;
            st[0] = i < 8 ? 0.0f : 1.0f; st[1] = st[2] = 0.0f; st[3] = 1.0f;
        }
    for (v = 0; v < SAMPLE_CUBIC_COUNT; ++v) {
        sample_texture *tr = make_tex(N, N, 4, SAMPLE_FORMAT_F32, ramp);
        sample_texture *ts = make_tex(N, N, 4, SAMPLE_FORMAT_F32, spike);
        sample_texture *tst = make_tex(N, N, 4, SAMPLE_FORMAT_F32, step);
        sample_sampler s;
        float u, got, center;
        sampler_for(&s, SAMPLE_CUBIC, SAMPLE_WRAP_CLAMP_TO_EDGE);
        s.cubic = (sample_cubic)v;
        for (u = 3.0f; u < 11.0f; u += 0.37f) {
            float t = 14.0f - u; /* 4×4 taps stay inside the texture */
            /* value at texel coords (u, t) is 0.25(u−½) + 0.5(t−½) */
            CHECK_NEAR(at(tr, &s, u / N, t / N, 0), 0.25 * (u - 0.5) + 0.5 * (t - 0.5), 2e-6);
            CHECK_EQF(at(tr, &s, u / N, t / N, 1), 3.0f);
        }
        center = at(ts, &s, 8.5f / N, 8.5f / N, 0);
        if (v == SAMPLE_CUBIC_CATMULL_ROM) {
            CHECK_EQF(center, 1.0f); /* interpolates */
            CHECK_EQF(at(ts, &s, 9.5f / N, 8.5f / N, 0), 0.0f);
        } else if (v == SAMPLE_CUBIC_BSPLINE) {
            CHECK_NEAR(center, 4.0 / 9.0, 1e-6); /* (2/3)² */
        } else {
            CHECK_NEAR(center, 64.0 / 81.0, 1e-6); /* (8/9)² */
        }
        /* Overshoot: Catmull–Rom and Mitchell ring next to a step; the
         * clamp keeps them within the 2×2 neighbourhood's range. */
        got = at(tst, &s, 7.0f / N, 8.0f / N, 0); /* taps 0,0,0,1 at f = ½ */
        if (v != SAMPLE_CUBIC_BSPLINE) CHECK(got < 0.0f, "%s should undershoot: %g", sample_cubic_name((sample_cubic)v), (double)got);
        else CHECK(got >= 0.0f, "B-spline is non-negative: %g", (double)got);
        s.options |= SAMPLE_OPT_CUBIC_CLAMP;
        for (u = 5.0f; u < 11.0f; u += 0.1f) {
            got = at(tst, &s, u / N, 8.0f / N, 0);
            CHECK(got >= 0.0f && got <= 1.0f, "clamped %s at u=%g: %g", sample_cubic_name((sample_cubic)v),
                  (double)u, (double)got);
        }
        sample_texture_destroy(tr);
        sample_texture_destroy(ts);
        sample_texture_destroy(tst);
    }
}

/* Derivatives of the bilinear result with respect to s and t are the
 * analytic slopes: on the ramp R = 0.25 i + 0.5 j they are 0.25·w and 0.5·h. */
static void bilinear_derivatives(void)
{
    enum { N = 8 };
    float px[N * N * 4];
    int i, j;
    sample_texture *t;
    sample_sampler s;
    sample_query q = {0};
    float out[4], ds[4], dt[4];
    sample_batch_args a;
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            float *p = &px[4 * (j * N + i)];
            p[0] = 0.25f * (float)i + 0.5f * (float)j; p[1] = p[2] = 0.0f; p[3] = 1.0f;
        }
    t = make_tex(N, N, 4, SAMPLE_FORMAT_F32, px);
    sampler_for(&s, SAMPLE_LINEAR, SAMPLE_WRAP_CLAMP_TO_EDGE);
    memset(&a, 0, sizeof a);
    q.s = 0.41f;
    q.t = 0.57f;
    a.count = 1; a.queries = &q; a.rgba = out; a.drgba_ds = ds; a.drgba_dt = dt;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
    CHECK_NEAR(ds[0], 0.25 * N, 1e-5);
    CHECK_NEAR(dt[0], 0.5 * N, 1e-5);
    CHECK_EQF(ds[3], 0.0f);
    sample_texture_destroy(t);
}

/* SAMPLE_OPT_CUBIC_CLAMP is continuous (reconstruct.c, cubic_clamp): on a
 * step (0 | 1 between texels 7 and 8) and on a diagonal step, swept in
 * steps of 1/512 texel across texel centres, no clamped value jumps by more
 * than the filter's own slope allows (a clamp to the central 2 × 2 alone
 * jumps by 1/6 for the B-spline and 1/18 for Mitchell at the centres of
 * texels 7 and 8). By hand: at the centre of texel 7 the B-spline gives
 * (0 + 4·0 + 1)/6 = 1/6, inside the clamp's range [0, ½] there (the
 * interpolant at x + 1 is halfway up the step), so it is kept; Catmull–Rom
 * still never leaves [0, 1]. Where the result is clamped its derivative is
 * the bound's: a finite difference agrees with it. */
static void cubic_clamp_continuous(void)
{
    enum { N = 16 };
    float step[N * N * 4], diag[N * N * 4];
    int i, j, v, which;
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            float *st = &step[4 * (j * N + i)], *d = &diag[4 * (j * N + i)];
            st[0] = i < 8 ? 0.0f : 1.0f; st[1] = st[2] = 0.0f; st[3] = 1.0f;
            d[0] = i + j < 16 ? 0.0f : 1.0f; d[1] = d[2] = 0.0f; d[3] = 1.0f;
        }
    for (which = 0; which < 2; ++which)
        for (v = 0; v < SAMPLE_CUBIC_COUNT; ++v) {
            sample_texture *t = make_tex(N, N, 4, SAMPLE_FORMAT_F32, which ? diag : step);
            sample_sampler s;
            double jump = 0.0, prev = 0.0, worst_deriv = 0.0;
            int k;
            sampler_for(&s, SAMPLE_CUBIC, SAMPLE_WRAP_CLAMP_TO_EDGE);
            s.cubic = (sample_cubic)v;
            s.options |= SAMPLE_OPT_CUBIC_CLAMP;
            for (k = 0; k <= 6 * 512; ++k) {
                const float u = 5.0f + (float)k / 512.0f, tv = which ? 16.0f - u + 0.25f : 8.5f;
                sample_query q = {0};
                sample_batch_args a;
                float out[4], ds[4], out2[4];
                q.s = u / N;
                q.t = tv / N;
                memset(&a, 0, sizeof a);
                a.count = 1; a.queries = &q; a.rgba = out; a.drgba_ds = ds;
                CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
                CHECK(out[0] >= 0.0f && out[0] <= 1.0f, "%s clamped at u = %g: %g", sample_cubic_name(s.cubic),
                      (double)u, (double)out[0]);
                if (k > 0 && fabs(out[0] - prev) > jump) jump = fabs(out[0] - prev);
                prev = out[0];
                /* Central difference of ±1/4096 texel in s against ds
                 * (per unit s: N per texel), away from texel centres
                 * and the step's edges where the slope has a kink. */
                if (!which && k % 64 == 17) {
                    const float h = 1.0f / 4096.0f;
                    float lo[4];
                    q.s = (u + h) / N;
                    a.rgba = out2; a.drgba_ds = NULL;
                    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
                    q.s = (u - h) / N;
                    a.rgba = lo;
                    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
                    {
                        double fd = (out2[0] - lo[0]) / (2.0 * h) * N, e = fabs(fd - ds[0]);
                        if (e > worst_deriv) worst_deriv = e;
                    }
                }
            }
            /* The steepest slope is below 2 per texel (Catmull–Rom's 1.25
             * on a unit step), so a step of 1/512 texel moves < 0.005. */
            CHECK(jump < 0.005, "%s%s: clamped result jumps by %g", sample_cubic_name(s.cubic),
                  which ? " (diagonal)" : "", jump);
            CHECK(worst_deriv < 0.05, "%s: derivative off a finite difference by %g", sample_cubic_name(s.cubic),
                  worst_deriv);
            if (!which && v == SAMPLE_CUBIC_BSPLINE) CHECK_NEAR(at(t, &s, 7.5f / N, 8.5f / N, 0), 1.0 / 6.0, 1e-6);
            sample_texture_destroy(t);
        }
}

int main(void)
{
    RUN(bilinear_exact_average);
    RUN(nearest_bit_exact_formats);
    RUN(srgb_table_exact);
    RUN(unorm8_every_code);
    RUN(half_conversion);
    RUN(cubic_kernel_values);
    RUN(cubic_precision_and_interpolation);
    RUN(bilinear_derivatives);
    RUN(cubic_clamp_continuous);
    return check_finish();
}
