/*
 * SAMPLE_OPT_BN_AREA_WEIGHT (doc/footprint-filters.md): Blinn–Newell's
 * corner mode with each texel's pyramid weight divided by |det DP| of the
 * projective quad map at its preimage, so that the filter is the SCREEN-space
 * integral ∫ pyr(x, y)·T(P(x, y)) dx dy / ∫ pyr — the DESIGN §8 ground
 * truth — instead of the paper's texture-space pyramid ∫ pyr(P⁻¹(u))·T(u) du
 * (the default). The references integrate densely in screen space on a
 * one-level texture (no level choice involved) and share only the bilinear
 * lookup (ls_recon_level, tested in test_reconstruct.c) with the library.
 */
#include "footprint_proj.h"

/* Random values are drawn into named variables, one initializer or
 * statement each, before the call that uses them: the order in which a
 * call's arguments are evaluated is unspecified in C (GCC goes right to
 * left, Clang left to right), so several urand() calls in one argument
 * list gave the two compilers different queries. The variables are drawn
 * last argument first, the order GCC used, so the queries are the ones the
 * suite has always tested. */

static float f_mild(int i, int j, int ch)
{
    (void)ch;
    return (float)(0.5 + 0.2 * sin(0.27 * i + 0.1) * cos(0.19 * j + 0.4) + 0.1 * sin(0.05 * (i + 2 * j)));
}

/* Corner k of the 2 × 2 region: (−1,−1), (+1,−1), (+1,+1), (−1,+1). */
static const double corner_xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

/* A perspective trapezoid on a w × h texture: semi-axes a, b texels, the
 * far edge (y = +1) `taper` times the near one, shear sh, rotation th,
 * centre (s0, t0) texels. Corners rounded to multiples of 2⁻¹⁶ (exact in
 * float, and shifted exactly by the derivative test's step). */
static void trapezoid(double a, double b, double th, double taper, double sh, double s0, double t0, int w,
                      int h, sample_quad *quad, double P[4][2])
{
    double cs = cos(th), sn = sin(th);
    int k;
    for (k = 0; k < 4; ++k) {
        double x = corner_xy[k][0] * (corner_xy[k][1] > 0 ? taper : 1.0) + sh * corner_xy[k][1];
        double y = corner_xy[k][1];
        double u = s0 + cs * a * x - sn * b * y, v = t0 + sn * a * x + cs * b * y;
        quad->st[k][0] = (float)(floor(u / w * 65536.0) / 65536.0);
        quad->st[k][1] = (float)(floor(v / h * 65536.0) / 65536.0);
        P[k][0] = quad->st[k][0];
        P[k][1] = quad->st[k][1];
    }
}

/* Random perspective planes (footprint_proj.h: true homographies, semi-
 * axes 3 to 10 texels, w on the square within 1 ± kk, kk up to 0.6). With
 * the option on, corner mode approximates the screen-space integral
 * ∫ pyr(x, y)·T(H(x, y)) dx dy through the same homography; off, the
 * texture-space one (the far side, with more texels per screen area,
 * weighs more). Measured over 60 maps: RMS against the screen-space
 * integral 1.2e-4 (worst 3.1e-4) with the option, 1.7e-2 (worst 4.5e-2)
 * without, the gap the area factor closes; what remains is what remains in
 * Jacobian mode against its own reference (moment-matched reconstruction,
 * sampling at texel centres). Bounds: worst 1e-3 with the option, and an
 * RMS at least 10 times smaller than without (measured 145 times). The
 * default is also checked against its own (texture-space) reference
 * (measured worst 1.0e-3; bound 3e-3 as test_footprint_bn.c), so each mode
 * is what it says. */
static void perspective_vs_screen_space(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 0);
    sample_sampler s0, s1;
    sample_ctx c0, c1;
    double worst_on = 0.0, worst_off = 0.0, ss_on = 0.0, ss_off = 0.0, worst_def = 0.0;
    int n;
    sample_sampler_init(&s0);
    s1 = s0;
    s1.options |= SAMPLE_OPT_BN_AREA_WEIGHT;
    c0 = ctx_for(t, &s0);
    c1 = ctx_for(t, &s1);
    for (n = 0; n < 60; ++n) {
        double ct = urand(0.2, 0.8) * 64, cs = urand(0.2, 0.8) * 64, kk = urand(0, 0.6), axis_b = urand(3, 10),
               axis_a = urand(3, 10);
        proj_map m = proj_random(axis_a, axis_b, kk, cs, ct);
        sample_quad quad = proj_quad(&m, 64, 64);
        double ref_screen = proj_reference(&c0, &m, 0), ref_tex = proj_reference(&c0, &m, 1), e_on, e_off;
        sample_query q;
        float on[4], off[4];
        memset(&q, 0, sizeof q);
        ls_fp_blinn_newell(&c1, &q, &quad, 0.0f, on, NULL, NULL, NULL);
        ls_fp_blinn_newell(&c0, &q, &quad, 0.0f, off, NULL, NULL, NULL);
        e_on = fabs(on[0] - ref_screen);
        e_off = fabs(off[0] - ref_screen);
        worst_on = fmax(worst_on, e_on);
        worst_off = fmax(worst_off, e_off);
        worst_def = fmax(worst_def, fabs(off[0] - ref_tex));
        ss_on += e_on * e_on;
        ss_off += e_off * e_off;
    }
    printf("screen-space reference: option on RMS %.3g worst %.3g, off RMS %.3g worst %.3g (ratio %.3g); "
           "default vs texture-space reference worst %.3g\n",
           sqrt(ss_on / 60), worst_on, sqrt(ss_off / 60), worst_off, sqrt(ss_off / ss_on), worst_def);
    CHECK(worst_on <= 1e-3, "worst |BN area - screen-space reference| = %.3g", worst_on);
    CHECK(ss_on * 100.0 <= ss_off, "RMS with the option %.3g not 10x below without %.3g", sqrt(ss_on / 60),
          sqrt(ss_off / 60));
    CHECK(worst_def <= 3e-3, "worst |BN default - texture-space reference| = %.3g", worst_def);
    sample_texture_destroy(t);
}

/* For a parallelogram det DH is constant: the factor w³ is 1 up to the
 * rounding of the λ_k (w at the corners), which are not exactly 1 for
 * corners rounded to float. Measured largest difference 1.2e-7 (two ulps
 * of values in [0.5, 1)) over 100 footprints; bound 2.4e-7 (2 ulps at 1). */
static void parallelogram_unchanged(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    sample_sampler s0, s1;
    sample_ctx c0, c1;
    double worst = 0.0;
    int n, k;
    sample_sampler_init(&s0);
    s1 = s0;
    s1.options |= SAMPLE_OPT_BN_AREA_WEIGHT;
    c0 = ctx_for(t, &s0);
    c1 = ctx_for(t, &s1);
    for (n = 0; n < 100; ++n) {
        double a = exp2(urand(0, 5)), b = a * exp2(urand(-3, 0));
        double skew = urand(-1.2, 1.2), th = urand(0, 6.3), ct = urand(0, 1), cs = urand(0, 1);
        sample_query q = footprint((float)cs, (float)ct, a, b, th, skew, 64, 64);
        sample_quad quad;
        float on[4], off[4], ds0[4], ds1[4], dt0[4], dt1[4];
        for (k = 0; k < 4; ++k) {
            quad.st[k][0] = (float)(q.s + corner_xy[k][0] * q.dsdx + corner_xy[k][1] * q.dsdy);
            quad.st[k][1] = (float)(q.t + corner_xy[k][0] * q.dtdx + corner_xy[k][1] * q.dtdy);
        }
        ls_fp_blinn_newell(&c1, &q, &quad, 0.0f, on, ds1, dt1, NULL);
        ls_fp_blinn_newell(&c0, &q, &quad, 0.0f, off, ds0, dt0, NULL);
        for (k = 0; k < 4; ++k) worst = fmax(worst, fabs(on[k] - off[k]));
        /* Derivatives: the det term's gradient is ∝ g, i.e. ~0 here. */
        CHECK_NEAR(ds1[0], ds0[0], 1e-4 * (1.0 + fabs(ds0[0])));
        CHECK_NEAR(dt1[0], dt0[0], 1e-4 * (1.0 + fabs(dt0[0])));
    }
    printf("parallelogram: largest |on - off| %.3g\n", worst);
    CHECK(worst <= 2.4e-7, "parallelogram: option changed the result by %.3g", worst);
    sample_texture_destroy(t);
}

static float f_const(int i, int j, int ch)
{
    static const float v[4] = {0.3f, 0.7071f, 1.0f / 3.0f, 1.0f};
    (void)i;
    (void)j;
    return v[ch];
}

/* A constant comes back exactly (Σw·T/Σw in double, then rounded to
 * float), with the option on and off: trapezoids and homography corners
 * from 0.05 to 40 texels on a mipmapped texture (level blends, and for
 * small quads a widened support far beyond the quad, where the |det| clamp
 * holds and the support is cut short of the horizon), strong tapers down
 * to 0.1 and w down to 0.005 at a corner (the ratio of |det| on the quad
 * up to 400³: beyond 2²⁰ the parallelogram fallback), and all four wrap modes that read no border. */
static void constants_exact(void)
{
    static const sample_wrap wraps[4] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT,
                                         SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    sample_texture *t = tex_from(64, 64, f_const, 1);
    int n, k, m;
    for (m = 0; m < 4; ++m) {
        sample_sampler s;
        sample_ctx c;
        sample_sampler_init(&s);
        s.wrap_s = s.wrap_t = wraps[m];
        for (n = 0; n < 400; ++n) {
            double P[4][2], sc = exp2(urand(-4.3, 5.3));
            sample_quad quad;
            sample_query q;
            float o[4], ds[4], dt[4];
            uint32_t texels;
            /* Both settings; every other quad a homography's, w down to
             * 0.05 at a corner (cut support, near-horizon fallback). */
            s.options = (n & 2) ? SAMPLE_OPT_BN_AREA_WEIGHT : 0u;
            c = ctx_for(t, &s);
            if (n & 1) {
                double ct = urand(-0.5, 1.5) * 64, cs = urand(-0.5, 1.5) * 64, kk = urand(0, 0.995),
                       axis_b = sc * urand(1, 3), axis_a = sc * urand(1, 3);
                proj_map pm = proj_random(axis_a, axis_b, kk, cs, ct);
                quad = proj_quad(&pm, 64, 64);
            } else {
                double ct = urand(-0.5, 1.5) * 64, cs = urand(-0.5, 1.5) * 64, sh = urand(-0.5, 0.5),
                       taper = urand(0.1, 1.0), th = urand(0, 6.3), axis_b = sc * urand(1, 3),
                       axis_a = sc * urand(1, 3);
                trapezoid(axis_a, axis_b, th, taper, sh, cs, ct, 64, 64, &quad, P);
            }
            memset(&q, 0, sizeof q);
            texels = run_filter(FILTER_BN, &c, &q, &quad, o, ds, dt, NULL);
            CHECK(texels <= SAMPLE_MAX_FOOTPRINT_TEXELS, "texels %u", (unsigned)texels);
            for (k = 0; k < 4; ++k) {
                CHECK(o[k] == f_const(0, 0, k), "wrap %d quad %d ch %d: %.9g != %.9g", m, n, k, o[k],
                      f_const(0, 0, k));
                CHECK(isfinite(ds[k]) && isfinite(dt[k]), "derivatives finite");
            }
        }
    }
    sample_texture_destroy(t);
}

/* ∂result/∂s, ∂/∂t at fixed footprint in corner mode, with the option on
 * (the weight gradient then includes −w·∇|det|/|det|) and off. Against
 * central differences, moving all four corners by h = 2⁻¹⁸ (exact: corners
 * are multiples of 2⁻¹⁶ within [0, 1), so the shape does not change): 2 %
 * + 0.02, as test_footprint_bn.c's derivative test (h = 0.00024 texels
 * here). Trapezoids and corners of random homographies (kk up to 0.6). */
static void derivatives(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    const float h = 0x1p-18f;
    int n, k, axis, opt;
    for (opt = 0; opt < 2; ++opt) {
        sample_sampler s;
        sample_ctx c;
        sample_sampler_init(&s);
        if (opt) s.options |= SAMPLE_OPT_BN_AREA_WEIGHT;
        c = ctx_for(t, &s);
        for (n = 0; n < 60; ++n) {
            double P[4][2];
            sample_quad quad;
            sample_query q;
            float o[4], ds[4], dt[4], a[4], b[4];
            if (n & 1) {
                double ct = urand(0.3, 0.7) * 64, cs = urand(0.3, 0.7) * 64, kk = urand(0, 0.6),
                       axis_b = urand(1.5, 12), axis_a = urand(1.5, 12);
                proj_map m = proj_random(axis_a, axis_b, kk, cs, ct);
                quad = proj_quad(&m, 64, 64);
                for (k = 0; k < 4; ++k) {
                    quad.st[k][0] = (float)(floor(quad.st[k][0] * 65536.0) / 65536.0);
                    quad.st[k][1] = (float)(floor(quad.st[k][1] * 65536.0) / 65536.0);
                }
            } else {
                double ct = urand(0.3, 0.7) * 64, cs = urand(0.3, 0.7) * 64, sh = urand(-0.3, 0.3),
                       taper = urand(0.3, 0.9), th = urand(0, 6.3), axis_b = urand(1.5, 12), axis_a = urand(1.5, 12);
                trapezoid(axis_a, axis_b, th, taper, sh, cs, ct, 64, 64, &quad, P);
            }
            memset(&q, 0, sizeof q);
            ls_fp_blinn_newell(&c, &q, &quad, 0.0f, o, ds, dt, NULL);
            for (axis = 0; axis < 2; ++axis) {
                sample_quad qa = quad, qb = quad;
                for (k = 0; k < 4; ++k) {
                    qa.st[k][axis] += h;
                    qb.st[k][axis] -= h;
                }
                ls_fp_blinn_newell(&c, &q, &qa, 0.0f, a, NULL, NULL, NULL);
                ls_fp_blinn_newell(&c, &q, &qb, 0.0f, b, NULL, NULL, NULL);
                {
                    double fd = (a[0] - b[0]) / (2.0 * h), an = axis ? dt[0] : ds[0];
                    CHECK_NEAR(an, fd, 0.02 + 0.02 * fabs(fd));
                }
            }
        }
    }
    sample_texture_destroy(t);
}

int main(void)
{
    RUN(perspective_vs_screen_space);
    RUN(parallelogram_unchanged);
    RUN(constants_exact);
    RUN(derivatives);
    return check_finish();
}
