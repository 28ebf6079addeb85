/*
 * The frequency harness reproduces responses known in closed form
 * (doc/frequency-tests.md §4).
 */
#include "check.h"
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const fq_backend *backend(const char *name)
{
    int k;
    for (k = 0; k < fq_libsample_backend_count; ++k)
        if (strcmp(fq_libsample_backends[k].name, name) == 0) return &fq_libsample_backends[k];
    return NULL;
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
    ctx = b->prepare(b, tex, NULL, n, err, sizeof err);
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
    /* Not f = ¼: at level-1 centres its phases are ±π/2 only and the fit
     * is degenerate (fq_measure says so). */
    static const int ps[] = {3, 10, 32, 51, 63, 90, 120};
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

int main(void)
{
    RUN(test_bilinear_fixed_phase);
    RUN(test_box_level_m2);
    return check_finish();
}
