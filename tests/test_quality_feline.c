/*
 * Feline (SAMPLE_FOOTPRINT_FELINE, libsample/src/footprint_feline.c;
 * doc/footprint-filters.md, "Feline"): constants, invariance under
 * Jacobian column swaps and sign flips, a round footprint's probe lattice
 * and value, the probe count and cap, non-finite input.
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
 * anisotropic filter's, their weighted mean in double), four wraps. */
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
 * same probes (the ±i, ±j pairs exchanged), the same result to rounding. */
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

/* An affine ramp: its mip levels (2 × 2 box averages) and bilinear reads
 * reproduce it, so a symmetric probe set returns its value at the centre. */
static float f_ramp(int i, int j, int ch)
{
    return (float)((i + 0.5) / 64.0 * (0.25 + 0.125 * ch) + (j + 0.5) / 64.0 * (0.5 - 0.0625 * ch));
}

/* A round footprint of σ = 8 texels on a 64 × 64 texture, by hand:
 * λ' = 3 − ½, level 2 (z = 4 texels, probe variance z²/4 = 4); the
 * pyramid's variance 64/6; R = √((64/6 − 4)/0.13608) = 7.0; m = ⌈R/z⌉ − 1
 * = 1 on each axis, spacing h = R/1.5: the 3 × 3 lattice (corners at
 * r² = 8/9 < 1), 9 bilinear probes on level 2 alone (36 texels), weights
 * fp_ewa_weight at r² = 0, 4/9, 8/9. On the ramp the result is the
 * centre's value. */
static void round_footprint(void)
{
    sample_texture *t = tex_from(64, 64, f_ramp, 1);
    sample_sampler s;
    sample_ctx c = feline_ctx(t, &s);
    const double R = sqrt((64.0 / 6.0 - 4.0) / 0.13608), h = R / 1.5;
    double worst = 0.0, worst_pos = 0.0, worst_w = 0.0;
    int n, k;
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    c = ctx_for(t, &s);
    for (n = 0; n < 50; ++n) {
        sample_query q = footprint((float)urand(0.3, 0.7), (float)urand(0.3, 0.7), 8.0, 8.0, urand(0, 6.3), 0.0, 64, 64);
        fp_aniso_setup a;
        fp_probe_set set;
        float o[4];
        sample_stats st;
        uint32_t texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, &st);
        CHECK(texels == 36, "round footprint read %u texels, want 36", texels);
        CHECK(st.level0 == 2 && st.level1 == -1, "levels %d %d, want 2 alone", st.level0, st.level1);
        for (k = 0; k < 4; ++k) worst = fmax(worst, fabs(o[k] - f_ramp(0, 0, k) - (q.s - 0.5 / 64) * (0.25 + 0.125 * k) -
                                                        (q.t - 0.5 / 64) * (0.5 - 0.0625 * k)));
        ls_fp_feline_setup(&c, &q, 0.0f, &a, &set);
        CHECK(a.n == 9, "%d probes, want 9", a.n);
        for (k = 0; k < a.n && k < 9; ++k) {
            const double d = hypot((set.s[k] - q.s) * 64.0, (set.t[k] - q.t) * 64.0);
            const int ring = (fabs(d - h) < 1e-3) + 2 * (fabs(d - h * sqrt(2.0)) < 1e-3);
            const double want = fp_ewa_weight(d < 1e-3 ? 0.0 : (ring == 1 ? 4.0 / 9.0 : 8.0 / 9.0), NULL);
            CHECK(d < 1e-3 || ring, "probe %d at %.6g texels from the centre", k, d);
            worst_pos = fmax(worst_pos, fmin(d, fmin(fabs(d - h), fabs(d - h * sqrt(2.0)))));
            worst_w = fmax(worst_w, fabs(set.w[k] - want));
        }
    }
    CHECK(worst <= 2e-7, "round footprint on a ramp vs its centre value: %.3g", worst);
    CHECK(worst_pos <= 1e-5, "probe positions off the lattice by %.3g texels", worst_pos);
    CHECK(worst_w <= 1e-6, "probe weights off by %.3g", worst_w);
    sample_texture_destroy(t);
}

/* 8:1 (σ = 24 × 3 texels): λ' = log2 3 − ½, level 1 (z = 2);
 * R0 = √((96 − 1)/0.13608) = 26.4, m0 = ⌈R0/z⌉ − 1 = 13; R1 = 1.92,
 * m1 = 1: 27 probes along the major axis, 21 on each side row (r² < 1
 * there for |i| ≤ 10): 69 probes, 276 texels. 1000:1 (the eccentricity
 * clamp: σ1 = σ0/16) reaches FELINE_M0 = 15: 31 + 2 · 23 = 77 probes,
 * 308 texels. Extreme queries through sample_batch stay finite and read at
 * most FP_PROBES_MAX probes of one level; non-finite ones give the border
 * colour. */
static void probes_and_cap(void)
{
    static sample_query qs[EXTREME_NQ];
    sample_texture *t = tex_from(256, 128, f_rough, 1);
    sample_sampler s;
    sample_ctx c = feline_ctx(t, &s);
    sample_query q = footprint(0.5f, 0.5f, 24.0, 3.0, 0.3, 0.0, 256, 128);
    float o[4];
    uint32_t texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, NULL);
    CHECK(texels == 69 * 4, "8:1 read %u texels, want 276", texels);
    q = footprint(0.5f, 0.5f, 3000.0, 3.0, 0.3, 0.0, 256, 128);
    texels = ls_fp_feline(&c, &q, 0.0f, NULL, o, NULL, NULL, NULL);
    CHECK(texels == 77 * 4, "1000:1 read %u texels, want 308", texels);
    extreme_queries(qs, 256, 128);
    extreme_batch(t, &s, qs, FP_PROBES_MAX * 4, "feline");
    CHECK(sample_footprint_parse("feline") == SAMPLE_FOOTPRINT_FELINE, "name");
    sample_texture_destroy(t);
}

int main(void)
{
    (void)run_filter; /* footprint_util.h's, for the other footprint tests */
    RUN(constant);
    RUN(column_symmetry);
    RUN(round_footprint);
    RUN(probes_and_cap);
    return check_finish();
}
