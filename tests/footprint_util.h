/*
 * Shared helpers of the footprint-filter tests: textures from functions, a
 * per-batch context built as sample_batch() builds it, and one call per
 * filter so that a test can loop over all three.
 */
#ifndef SAMPLE_TEST_FOOTPRINT_UTIL_H
#define SAMPLE_TEST_FOOTPRINT_UTIL_H

#include "check.h"
#include "internal.h"

#include <stdint.h>
#include <stdlib.h>

enum { FILTER_ANISO, FILTER_BN, FILTER_EWA, FILTER_N };
static const char *const filter_names[FILTER_N] = {"aniso", "blinn-newell", "ewa"};

typedef float (*texfn)(int i, int j, int ch);

/* RGBA float texture from f(i, j, channel); mip = box pyramid or none. */
static sample_texture *tex_from(int w, int h, texfn f, int mip)
{
    float *px = (float *)malloc((size_t)w * h * 4 * sizeof(float));
    sample_image im = {w, h, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mp;
    sample_texture *t = NULL;
    sample_error err;
    int i, j, c;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i)
            for (c = 0; c < 4; ++c) px[((size_t)j * w + i) * 4 + c] = f(i, j, c);
    sample_mip_params_init(&mp);
    mp.wrap_s = mp.wrap_t = SAMPLE_WRAP_REPEAT;
    if (!mip) mp.filter = SAMPLE_MIPGEN_NONE;
    CHECK(sample_texture_create(&im, &mp, &t, &err) == SAMPLE_OK, "create: %s", err.message);
    free(px);
    return t;
}

/* The context sample_batch() builds for a sampler. */
static sample_ctx ctx_for(const sample_texture *t, const sample_sampler *s)
{
    sample_ctx c;
    ls_ctx_init(&c, t, s, ls_isa_kernels_active());
    return c;
}

/* The default sampler with max_anisotropy 16 (the footprint tests'
 * common setting) in *s, and its context; *s must outlive the context. */
static inline sample_ctx footprint_ctx(const sample_texture *t, sample_sampler *s)
{
    sample_sampler_init(s);
    s->max_anisotropy = 16.0f;
    return ctx_for(t, s);
}

static uint32_t run_filter(int which, const sample_ctx *c, const sample_query *q, const sample_quad *quad,
                           float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    switch (which) {
    case FILTER_ANISO: return ls_fp_anisotropic(c, q, 0.0f, out, dds, ddt, st);
    case FILTER_BN: return ls_fp_blinn_newell(c, q, quad, 0.0f, out, dds, ddt, st);
    default: return ls_fp_ewa(c, q, 0.0f, out, dds, ddt, st);
    }
}

/* Deterministic uniform in [lo, hi) (xorshift; the tests never depend on
 * the C library's rand()). */
static uint32_t test_rng = 12345u;
static double urand(double lo, double hi)
{
    test_rng ^= test_rng << 13;
    test_rng ^= test_rng >> 17;
    test_rng ^= test_rng << 5;
    return lo + (hi - lo) * (test_rng / 4294967296.0);
}

/* A Jacobian with singular values a ≥ b (texels of a w × h base) rotated by
 * θ, with a random skew between its columns, in normalized units. */
static sample_query footprint(float s, float t, double a, double b, double th, double skew, int w, int h)
{
    sample_query q;
    double c = cos(th), sn = sin(th), cs = cos(skew), ss = sin(skew);
    /* J = R(θ)·diag(a, b)·R(skew) */
    double j00 = c * a * cs - sn * b * ss, j01 = -c * a * ss - sn * b * cs;
    double j10 = sn * a * cs + c * b * ss, j11 = -sn * a * ss + c * b * cs;
    q.s = s;
    q.t = t;
    q.dsdx = (float)(j00 / w);
    q.dsdy = (float)(j01 / w);
    q.dtdx = (float)(j10 / h);
    q.dtdy = (float)(j11 / h);
    return q;
}

#endif
