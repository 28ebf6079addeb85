/*
 * Feline (SAMPLE_FOOTPRINT_FELINE, libsample/src/footprint_feline.c;
 * doc/footprint-filters.md, "Feline"): constants, invariance under
 * Jacobian column swaps and sign flips, a round footprint is one trilinear
 * probe, the probe count and cap, non-finite input.
 */
#include "footprint_feline.h"
#include "quality_util.h"

static float f_const(int i, int j, int ch) { (void)i; (void)j; return ch == 3 ? 1.0f : 0.3f + 0.1f * ch; }
static float f_rough(int i, int j, int ch) { return (float)((i * 37 + j * 91 + ch * 13) % 101) / 128.0f; }

static sample_ctx feline_ctx(const sample_texture *t, sample_sampler *s)
{
    sample_sampler_init(s);
    s->footprint = SAMPLE_FOOTPRINT_FELINE;
    return ctx_for(t, s);
}

/* Constants within 2 ulps (the probes are float bilinear reads, as the
 * anisotropic filter's), four wraps. */
static void constant(void)
{
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT,
                                        SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    sample_texture *t = tex_from(37, 20, f_const, 1);
    int w, n, k;
    for (w = 0; w < 4; ++w) {
        sample_sampler s;
        sample_ctx c = feline_ctx(t, &s);
        s.wrap_s = wraps[w];
        s.wrap_t = wraps[(w + 1) & 3];
        c = ctx_for(t, &s);
        for (n = 0; n < 60; ++n) {
            double a = exp2(urand(-3, 9)), b = a * exp2(urand(-8, 0));
            sample_query q = footprint((float)urand(-2, 3), (float)urand(-2, 3), a, b, urand(0, 6.3), urand(0, 6.3),
                                       37, 20);
            float out[4];
            ls_fp_feline(&c, &q, 0.0f, NULL, out, NULL, NULL, NULL);
            for (k = 0; k < 4; ++k) {
                float want = k == 3 ? 1.0f : 0.3f + 0.1f * k;
                CHECK_NEAR(out[k], want, 2.0 * 6e-8 * want);
            }
        }
    }
    sample_texture_destroy(t);
}

/* Swapping or negating the Jacobian's columns spans the same ellipse: the
 * same probes (the ±k pairs exchanged), the same result to rounding. */
static void column_symmetry(void)
{
    sample_texture *t = tex_from(64, 64, f_rough, 1);
    sample_sampler s;
    sample_ctx c = feline_ctx(t, &s);
    double worst = 0.0;
    int n, k;
    for (n = 0; n < 200; ++n) {
        double a = exp2(urand(0, 6)), b = a * exp2(urand(-5, 0));
        sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, b, urand(0, 6.3), urand(0, 6.3), 64, 64),
                     qs = q, qn = q;
        float o[4], os[4], on[4];
        qs.dsdx = q.dsdy, qs.dtdx = q.dtdy, qs.dsdy = q.dsdx, qs.dtdy = q.dtdx;
        qn.dsdy = -q.dsdy, qn.dtdy = -q.dtdy;
        ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, NULL);
        ls_fp_feline(&c, &qs, 0.0f, NULL, os, NULL, NULL, NULL);
        ls_fp_feline(&c, &qn, 0.0f, NULL, on, NULL, NULL, NULL);
        for (k = 0; k < 4; ++k) worst = fmax(worst, fmax(fabs(o[k] - os[k]), fabs(o[k] - on[k])));
    }
    CHECK(worst <= 1e-5, "column swap / sign flip changed a result by %.3g", worst);
    sample_texture_destroy(t);
}

/* A round footprint (J a rotation times σ) is one trilinear probe at
 * λ = log2 σ: GL's LINEAR_MIPMAP_LINEAR of the same query, whose λ is the
 * same to float rounding. */
static void round_is_trilinear(void)
{
    sample_texture *t = tex_from(64, 64, f_rough, 1);
    sample_sampler s, tri;
    sample_ctx c = feline_ctx(t, &s);
    double worst = 0.0;
    int n, k;
    sample_sampler_init(&tri);
    tri.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    for (n = 0; n < 100; ++n) {
        double a = exp2(urand(0.1, 5.5));
        sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, a, urand(0, 6.3), 0.0, 64, 64);
        float o[4], g[4];
        sample_stats st;
        uint32_t texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, &st);
        CHECK(sample_one(t, &tri, &q, g) == SAMPLE_OK, "trilinear");
        for (k = 0; k < 4; ++k) worst = fmax(worst, fabs(o[k] - g[k]));
        CHECK(texels <= 8, "round footprint read %u texels", texels);
    }
    CHECK(worst <= 1e-5, "round footprint vs trilinear: %.3g", worst);
    sample_texture_destroy(t);
}

/* N = 2h + 1 probes, h = ⌈√(σ0² − σ1²)/σ1⌉ − 1: 8:1 gives h = 7 (15 probes,
 * 120 texels on two levels); the eccentricity clamp holds 1000:1 to 31
 * probes. Extreme queries through sample_batch stay finite and within the
 * cap; non-finite ones give the border colour. */
static void probes_and_cap(void)
{
    static sample_query qs[EXTREME_NQ];
    sample_texture *t = tex_from(256, 128, f_rough, 1);
    sample_sampler s;
    sample_ctx c = feline_ctx(t, &s);
    sample_query q = footprint(0.5f, 0.5f, 24.0, 3.0, 0.3, 0.0, 256, 128);
    float o[4];
    uint32_t texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, NULL);
    CHECK(texels == 15 * 8, "8:1 read %u texels, want 120", texels);
    q = footprint(0.5f, 0.5f, 3000.0, 3.0, 0.3, 0.0, 256, 128);
    texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, NULL);
    CHECK(texels == FP_PROBES_MAX * 8, "1000:1 read %u texels", texels);
    extreme_queries(qs, 256, 128);
    extreme_batch(t, &s, qs, FP_PROBES_MAX * 8, "feline");
    CHECK(sample_footprint_parse("feline") == SAMPLE_FOOTPRINT_FELINE, "name");
    sample_texture_destroy(t);
}

int main(void)
{
    (void)run_filter; /* footprint_util.h's, for the other footprint tests */
    RUN(constant);
    RUN(column_symmetry);
    RUN(round_is_trilinear);
    RUN(probes_and_cap);
    return check_finish();
}
