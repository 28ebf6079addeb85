/*
 * Stochastic filtering (sample_batch_args.u, libsample/src/stochastic.c;
 * doc/footprint-filters.md, "Stochastic filtering"): for every filter the
 * mean of the estimates over many uniform u (fixed seed) converges to the
 * deterministic result at the 1/√n rate, a constant texture gives the
 * constant in expectation (and in every draw where the weights are ≥ 0),
 * and u outside [0, 1) is read as its fractional part.
 */
#include "footprint_util.h"

#include <string.h>

typedef struct config {
    const char *name;
    sample_filter min;
    sample_footprint fp;
    sample_ewa_kernel kern;
    unsigned draws;
    int positive; /* every weight ≥ 0: each draw of a constant is the constant */
} config;

static const config configs[] = {
    {"trilinear", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_NONE, SAMPLE_EWA_GAUSSIAN, 0, 1},
    {"aniso16", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_ANISOTROPIC, SAMPLE_EWA_GAUSSIAN, 0, 1},
    {"feline", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_FELINE, SAMPLE_EWA_GAUSSIAN, 0, 1},
    {"ewa", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_EWA, SAMPLE_EWA_GAUSSIAN, 1, 1},
    {"ewa k=4", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_EWA, SAMPLE_EWA_GAUSSIAN, 4, 1},
    {"blinn-newell", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL, SAMPLE_EWA_GAUSSIAN, 1, 1},
    {"ewa-lanczos2", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_EWA, SAMPLE_EWA_LANCZOS2, 2, 0},
};
enum { NC = sizeof configs / sizeof configs[0], NQ = 8, NU = 512 };

static void set_sampler(sample_sampler *s, const config *cf)
{
    sample_sampler_init(s);
    s->min_filter = cf->min;
    s->footprint = cf->fp;
    s->ewa_kernel = cf->kern;
    s->max_anisotropy = 16.0f;
}

static float f_rough(int i, int j, int ch) { return (float)((i * 37 + j * 91 + ch * 13) % 101) / 128.0f; }
static float f_const(int i, int j, int ch) { (void)i; (void)j; return ch == 3 ? 1.0f : 0.3f + 0.1f * ch; }

/* The first n estimates of query q under config cf (u from the test's
 * generator) into est (n × 4 floats); the deterministic result into det. */
static void estimates(const sample_texture *t, const config *cf, const sample_query *q, int n, float *est,
                      float det[4], float *u)
{
    static sample_query qs[NU];
    sample_sampler s;
    sample_batch_args a;
    int m;
    set_sampler(&s, cf);
    for (m = 0; m < n; ++m) qs[m] = *q, u[m] = (float)urand(0, 1);
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = q;
    a.rgba = det;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "deterministic");
    a.count = (size_t)n;
    a.queries = qs;
    a.rgba = est;
    a.u = u;
    a.draws = cf->draws;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "stochastic");
}

/* Group means of g consecutive estimates against the deterministic value:
 * the sum of their squared errors (over NU/g groups). */
static double group_sq_error(const float *est, int ch, int g, double det)
{
    double e = 0.0;
    int m, j;
    for (m = 0; m < NU; m += g) {
        double s = 0.0;
        for (j = 0; j < g; ++j) s += est[4 * (m + j) + ch];
        e += (s / g - det) * (s / g - det);
    }
    return e;
}

/* The mean of NU estimates against the deterministic value: within 5
 * standard errors for every query and channel; and the RMS error of means
 * of 16 estimates is twice that of means of 64 (1/√n; over every query
 * and channel, 32 and 8 groups each: the bound allows 1.6 to 2.5). */
static void mean_converges(void)
{
    static float est[NU * 4], u[NU];
    sample_texture *t = tex_from(64, 64, f_rough, 1);
    int cf, n, m, k;
    for (cf = 0; cf < NC; ++cf) {
        double e16 = 0.0, e64 = 0.0, worst = 0.0, ratio;
        for (n = 0; n < NQ; ++n) {
            double a = exp2(urand(0.5, 5)), b = a * exp2(urand(-4, 0));
            sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, b, urand(0, 6.3), urand(0, 6.3), 64, 64);
            float det[4];
            estimates(t, &configs[cf], &q, NU, est, det, u);
            for (k = 0; k < 3; ++k) {
                double s1 = 0.0, s2 = 0.0, mean, sd, se;
                for (m = 0; m < NU; ++m) {
                    s1 += est[4 * m + k];
                    s2 += (double)est[4 * m + k] * est[4 * m + k];
                }
                mean = s1 / NU;
                sd = sqrt(fmax(0.0, s2 / NU - mean * mean));
                se = sd / sqrt((double)NU);
                worst = fmax(worst, fabs(mean - det[k]) / (se + 1e-7));
                CHECK(fabs(mean - det[k]) <= 5.0 * se + 1e-6, "%s: mean %.6f, deterministic %.6f, standard error %.2g",
                      configs[cf].name, mean, det[k], se);
                e16 += group_sq_error(est, k, 16, det[k]) / (NU / 16);
                e64 += group_sq_error(est, k, 64, det[k]) / (NU / 64);
            }
        }
        ratio = sqrt(e16 / e64);
        printf("%-14s worst |mean - det| %.2f standard errors; RMS error of 16-means / 64-means: %.2f (1/sqrt(n): 2)\n",
               configs[cf].name, worst, ratio);
        CHECK(ratio > 1.6 && ratio < 2.5, "%s: error ratio %.2f, want about 2", configs[cf].name, ratio);
    }
    sample_texture_destroy(t);
}

/* A constant texture: every draw is the constant where the weights are
 * ≥ 0 (2 ulps: float bilinear), the mean within 5 standard errors where
 * they are signed (each draw ±c·Σ|w|/Σw). */
static void constant(void)
{
    static float est[256 * 4], u[256];
    sample_texture *t = tex_from(37, 20, f_const, 1);
    int cf, n, m, k;
    for (cf = 0; cf < NC; ++cf)
        for (n = 0; n < 6; ++n) {
            double a = exp2(urand(0.5, 6)), b = a * exp2(urand(-5, 0));
            sample_query q = footprint((float)urand(-2, 3), (float)urand(-2, 3), a, b, urand(0, 6.3), urand(0, 6.3), 37, 20);
            float det[4];
            estimates(t, &configs[cf], &q, 256, est, det, u);
            for (k = 0; k < 4; ++k) {
                const float want = k == 3 ? 1.0f : 0.3f + 0.1f * k;
                double mean = 0.0, s2 = 0.0, se;
                for (m = 0; m < 256; ++m) {
                    if (configs[cf].positive) CHECK_NEAR(est[4 * m + k], want, 2.0 * 6e-8 * want);
                    mean += est[4 * m + k] / 256.0;
                    s2 += (double)est[4 * m + k] * est[4 * m + k] / 256.0;
                }
                se = sqrt(fmax(0.0, s2 - mean * mean) / 256.0);
                CHECK(fabs(mean - want) <= 5.0 * se + 2.0 * 6e-8 * want, "%s: mean %.6f of a constant %.6f (se %.2g)",
                      configs[cf].name, mean, want, se);
            }
        }
    sample_texture_destroy(t);
}

/* u = 1.25, −0.75 and 0.25 give the same estimate; NaN and inf read as 0. */
static void u_reduced(void)
{
    sample_texture *t = tex_from(64, 64, f_rough, 1);
    sample_query q[5];
    float u[5] = {0.25f, 1.25f, -0.75f, NAN, 0.0f}, out[20];
    sample_sampler s;
    sample_batch_args a;
    int n, k;
    for (n = 0; n < 5; ++n) q[n] = footprint(0.3f, 0.6f, 9.0, 2.0, 0.4, 0.0, 64, 64);
    set_sampler(&s, &configs[3]);
    memset(&a, 0, sizeof a);
    a.count = 5;
    a.queries = q;
    a.rgba = out;
    a.u = u;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
    for (k = 0; k < 4; ++k) {
        CHECK(out[4 + k] == out[k] && out[8 + k] == out[k], "fractional part");
        CHECK(out[12 + k] == out[16 + k], "NaN reads as 0");
    }
    sample_texture_destroy(t);
}

int main(void)
{
    (void)run_filter; /* footprint_util.h's, for the other footprint tests */
    RUN(mean_converges);
    RUN(constant);
    RUN(u_reduced);
    return check_finish();
}
