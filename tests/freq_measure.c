/*
 * The frequency harness reproduces responses known in closed form
 * (doc/frequency-tests.md §4).
 */
#include "check.h"
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The libsample backend of registry entry `name` (tools/filters.h). */
static const fq_backend *backend(const char *name)
{
    static fq_backend b;
    static fq_tool_cfg cfg;
    const tool_filter *f = tool_filter_by_name(name);
    tool_backend_close(&cfg.own);
    if (!f || fq_libsample_backend(f, &cfg, &b) != 0) return NULL;
    return &b;
}

/* Measure wave (p, q) on an n-texel texture with backend `name`. */
static fq_result measure(const char *name, int n, int p, int q, const fq_layout *l)
{
    const fq_backend *b = backend(name);
    fq_wave w;
    sample_texture *tex = NULL;
    fq_result r = {0};
    char err[256] = "";
    void *ctx;
    w.n = n;
    w.p = p;
    w.q = q;
    w.f = sqrt((double)p * p + (double)q * q) / n;
    w.theta = atan2((double)q, (double)p);
    CHECK(b != NULL, "backend %s", name);
    if (!b) return r;
    CHECK(fq_grating_texture(&w, &tex, NULL) == SAMPLE_OK, "texture");
    ctx = b->prepare(b, tex, NULL, n, 2, err, sizeof err);
    CHECK(ctx != NULL, "%s", err);
    if (ctx) {
        CHECK(fq_measure(b, ctx, &w, l, &r, err, sizeof err) == 0, "%s", err);
        b->release(ctx);
    }
    sample_texture_destroy(tex);
    return r;
}

/* Bilinear at magnification, every sample at sub-texel phase δ from a texel
 * centre: y = (1 − δ)·T_i + δ·T_{i+1}, so against the grating at the sample
 * H = ((1 − δ) + δ·e^{2πif})·e^{−2πifδ} (doc §4.1). */
static void test_bilinear_fixed_phase(void)
{
    static const double deltas[] = {0.0, 0.25, 0.5, 0.8};
    static const int ps[] = {5, 16, 40, 77, 100};
    size_t a, b;
    for (a = 0; a < sizeof deltas / sizeof deltas[0]; ++a)
        for (b = 0; b < sizeof ps / sizeof ps[0]; ++b) {
            double d = deltas[a], f = ps[b] / 256.0;
            double hr = (1 - d) + d * cos(2 * FQ_PI * f), hi = d * sin(2 * FQ_PI * f);
            double er = hr * cos(2 * FQ_PI * f * d) + hi * sin(2 * FQ_PI * f * d);
            double ei = hi * cos(2 * FQ_PI * f * d) - hr * sin(2 * FQ_PI * f * d);
            fq_layout l;
            fq_result r;
            /* m = 1, θ = 0: λ = 0 is magnification, so bilinear on level 0;
             * integer steps keep every sample at phase δ. */
            fq_layout_init(&l, 1.0, 1.0);
            l.subtexel = 0.5 + d;
            r = measure("bilinear", 256, ps[b], 0, &l);
            CHECK_NEAR(r.re, er, 1e-3);
            CHECK_NEAR(r.im, ei, 1e-3);
            CHECK_NEAR(r.amp, hypot(er, ei), 1e-3);
            CHECK_NEAR(r.F, f, 1e-12);
        }
}

/* Trilinear at m = 2 (λ = 1 exactly), samples at level-1 texel centres:
 * the output is level 1's texel, the 2 × 2 box of the base, which is
 * cos(π k_u)·cos(π k_v) times the grating at the texel centre; at screen
 * frequency F = 2f along u that is cos(πF/2) (doc §4.2). */
static void test_box_level_m2(void)
{
    static const int ps[] = {3, 10, 32, 51, 64, 90, 120};
    size_t b;
    for (b = 0; b < sizeof ps / sizeof ps[0]; ++b) {
        double f = ps[b] / 256.0;
        fq_layout l;
        fq_result r;
        fq_layout_init(&l, 2.0, 1.0);
        l.subtexel = 1.0; /* base u = 2i + 1: the centre of level-1 texel i */
        l.lattice = 2;
        r = measure("trilinear", 256, ps[b], 0, &l);
        CHECK_NEAR(r.re, cos(FQ_PI * f), 1e-3);
        CHECK_NEAR(r.im, 0.0, 1e-3);
        CHECK_NEAR(r.F, 2 * f, 1e-12);
    }
    {
        /* A diagonal wave: both box factors. */
        fq_layout l;
        fq_result r;
        fq_layout_init(&l, 2.0, 1.0);
        l.subtexel = 1.0;
        l.lattice = 2;
        /* θ = 45°: the screen steps are m·(1, 1)/√2, not on the level-1
         * lattice; use a single pixel per row to stay on texel centres. */
        l.width = 1;
        l.rows = 1;
        l.phases = 256;
        r = measure("trilinear", 256, 20, 20, &l);
        CHECK_NEAR(r.re, cos(FQ_PI * 20 / 256.0) * cos(FQ_PI * 20 / 256.0), 1e-3);
        CHECK_NEAR(r.im, 0.0, 1e-3);
    }
}

static double sinc(double x) { return x == 0.0 ? 1.0 : sin(FQ_PI * x) / (FQ_PI * x); }

/* A one-curve sweep (θ = 0, r = 1, N = 256, F step 1/16) of one filter. */
static void sweep_one(const char *name, double m, fq_sweep *s)
{
    static const double th = 0.0, r = 1.0;
    const fq_backend *b = backend(name);
    fq_plan plan = {0};
    char err[256] = "";
    plan.m = &m;
    plan.nm = 1;
    plan.theta_deg = &th;
    plan.ntheta = 1;
    plan.r = &r;
    plan.nr = 1;
    plan.n = 256;
    plan.f_step = 1.0 / 16;
    plan.f_max = 2.0;
    plan.width = 16;
    plan.rows = 1;
    plan.phases = 64;
    plan.backends = &b;
    plan.nbackends = 1;
    CHECK(fq_sweep_run(&plan, s, err, sizeof err) == 0, "%s", err);
}

/* In the normal (random-offset) mode the coherent response of a filter that
 * is one fixed kernel on one level is that kernel's Fourier transform at the
 * grating frequency (doc §4.3): nearest is the 1-texel box, sinc(f);
 * bilinear the tent, sinc²(f); trilinear at m = 16 is level 4 (λ = 4
 * exactly), i.e. the four 2-tap boxes, Π cos(π f 2^l) =
 * sin(πF)/(16 sin(πF/16)), then the 16-texel tent, sinc²(F). Each point is
 * checked to 4 standard errors (plus 1e-3 for float). */
static double h_nearest(double f, double F) { (void)F; return sinc(f); }
static double h_bilinear(double f, double F) { (void)F; return sinc(f) * sinc(f); }
static double h_trilinear16(double f, double F)
{
    double box = f == 0.0 ? 1.0 : sin(FQ_PI * F) / (16.0 * sin(FQ_PI * f));
    return box * sinc(F) * sinc(F);
}

static double check_curve(const char *name, double (*h)(double, double), double *leak_mean)
{
    fq_sweep s = {0};
    size_t k;
    double sum = 0.0, worst = 0.0;
    int n = 0;
    sweep_one(name, 16.0, &s);
    CHECK(s.count >= 30, "%s: %zu points", name, s.count);
    for (k = 0; k < s.count; ++k) {
        const fq_result *r = &s.pts[k].res;
        double want = fabs(h(s.pts[k].wave.f, r->F)), d = fabs(r->amp - want);
        CHECK(d <= 4.0 * r->stderr_ + 1e-3, "%s F = %.4f: |H| = %.5f, closed form %.5f, stderr %.5f",
              name, r->F, r->amp, want, r->stderr_);
        if (d > worst) worst = d;
        if (r->F > FQ_STOP_ABOVE) {
            sum += r->amp;
            n++;
        }
    }
    *leak_mean = n ? sum / n : NAN;
    fq_sweep_free(&s);
    return worst;
}

static void test_leakage_m16(void)
{
    double nearest, bilinear, trilinear;
    check_curve("nearest", h_nearest, &nearest);
    check_curve("bilinear", h_bilinear, &bilinear);
    check_curve("trilinear", h_trilinear16, &trilinear);
    /* Without mips the 16:1 minified grating comes through almost whole
     * above Nyquist (sinc(f) ≥ sinc(1/8) = 0.974 there); trilinear keeps a
     * small fraction of it. */
    CHECK(nearest > 0.97, "nearest leakage %.4f", nearest);
    CHECK(bilinear > 0.94, "bilinear leakage %.4f", bilinear);
    CHECK(trilinear < 0.1, "trilinear leakage %.4f", trilinear);
}

/* An offset-free check of the estimator itself: a constant texture gives
 * the F = 0 point exactly 1 with every normalized filter. */
static void test_dc(void)
{
    fq_layout l;
    fq_result r;
    int k;
    fq_layout_init(&l, 3.0, 4.0);
    for (k = 0; k < tool_filter_count; ++k) {
        r = measure(tool_filter_name(&tool_filters[k]), 64, 0, 0, &l);
        CHECK_NEAR(r.amp, 1.0, 1e-6);
    }
}

int main(void)
{
    RUN(test_bilinear_fixed_phase);
    RUN(test_box_level_m2);
    RUN(test_leakage_m16);
    RUN(test_dc);
    return check_finish();
}
