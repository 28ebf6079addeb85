/*
 * The elliptical filter's radial kernels (sample_sampler.ewa_kernel,
 * libsample/src/footprint_kernels.c; doc/footprint-filters.md, "Radial
 * kernels"): constants exact for every kernel with and without the clamp,
 * invariance under Jacobian column swaps and sign flips, convergence to
 * dense numerical integration of the same kernel over the same ellipse,
 * ringing at a step edge and its clamp, derivatives against central
 * differences, texel cap and non-finite input.
 */
#include "footprint_kernels.h"
#include "quality_util.h"

static const sample_ewa_kernel kernels[] = {SAMPLE_EWA_LANCZOS2, SAMPLE_EWA_LANCZOS3, SAMPLE_EWA_MITCHELL};
enum { NK = 3 };

static sample_ctx kernel_ctx(const sample_texture *t, sample_sampler *s, sample_ewa_kernel k, unsigned opt)
{
    sample_sampler_init(s);
    s->footprint = SAMPLE_FOOTPRINT_EWA;
    s->max_anisotropy = 16.0f;
    s->ewa_kernel = k;
    s->options = opt;
    return ctx_for(t, s);
}

static float f_const(int i, int j, int ch) { (void)i; (void)j; return ch == 3 ? 1.0f : 0.3f + 0.1f * ch; }

static void names_and_validation(void)
{
    sample_sampler s;
    int k;
    for (k = 0; k < SAMPLE_EWA_KERNEL_COUNT; ++k)
        CHECK(sample_ewa_kernel_parse(sample_ewa_kernel_name((sample_ewa_kernel)k)) == k, "name %d", k);
    CHECK(strcmp(sample_ewa_kernel_name(SAMPLE_EWA_LANCZOS3), "lanczos3") == 0, "lanczos3");
    CHECK(sample_ewa_kernel_parse("sinc") == -1, "unknown name");
    sample_sampler_init(&s);
    CHECK(s.ewa_kernel == SAMPLE_EWA_GAUSSIAN, "default Gaussian");
    s.ewa_kernel = SAMPLE_EWA_KERNEL_COUNT;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "out of range rejected");
}

/* A constant texture comes back exactly (double sums; negative lobes
 * included), for every kernel, with and without the clamp, four wraps,
 * 30 footprints each. */
static void constant_exact(void)
{
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT,
                                        SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    sample_texture *t = tex_from(37, 20, f_const, 1);
    int kk, w, n, k, cl;
    for (kk = 0; kk < NK; ++kk)
        for (cl = 0; cl < 2; ++cl)
            for (w = 0; w < 4; ++w) {
                sample_sampler s;
                sample_ctx c = kernel_ctx(t, &s, kernels[kk], cl ? SAMPLE_OPT_EWA_CLAMP : 0);
                s.wrap_s = wraps[w];
                s.wrap_t = wraps[(w + 1) & 3];
                c = ctx_for(t, &s);
                for (n = 0; n < 30; ++n) {
                    /* Up to 2^7 texels: the support still fits the cap on
                     * the 1 × 1 level (beyond, the float bilinear fallback). */
                    double a = exp2(urand(-3, 7)), b = a * exp2(urand(-6, 0));
                    sample_query q = footprint((float)urand(-2, 3), (float)urand(-2, 3), a, b, urand(0, 6.3),
                                               urand(0, 6.3), 37, 20);
                    float out[4];
                    ls_fp_ewa(&c, &q, 0.0f, out, NULL, NULL, NULL);
                    for (k = 0; k < 4; ++k) {
                        float want = k == 3 ? 1.0f : 0.3f + 0.1f * k;
                        CHECK(out[k] == want, "%s clamp %d wrap %d: %.9g != %.9g",
                              sample_ewa_kernel_name(kernels[kk]), cl, w, out[k], want);
                    }
                }
            }
    sample_texture_destroy(t);
}

static float f_rough(int i, int j, int ch) { return (float)((i * 37 + j * 91 + ch * 13) % 101) / 128.0f; }

/* Swapping the Jacobian's columns or negating one spans the same ellipse:
 * the same result to double rounding of the ellipse's coefficients. */
static void column_symmetry(void)
{
    sample_texture *t = tex_from(64, 64, f_rough, 1);
    double worst = 0.0;
    int kk, n, k;
    for (kk = 0; kk < NK; ++kk) {
        sample_sampler s;
        sample_ctx c = kernel_ctx(t, &s, kernels[kk], 0);
        for (n = 0; n < 40; ++n) {
            double a = exp2(urand(0, 5)), b = a * exp2(urand(-4, 0));
            sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, b, urand(0, 6.3), urand(0, 6.3),
                                       64, 64),
                         qs = q, qn = q;
            float o[4], os[4], on[4];
            qs.dsdx = q.dsdy, qs.dtdx = q.dtdy, qs.dsdy = q.dsdx, qs.dtdy = q.dtdx;
            qn.dsdx = -q.dsdx, qn.dtdx = -q.dtdx;
            ls_fp_ewa(&c, &q, 0.0f, o, NULL, NULL, NULL);
            ls_fp_ewa(&c, &qs, 0.0f, os, NULL, NULL, NULL);
            ls_fp_ewa(&c, &qn, 0.0f, on, NULL, NULL, NULL);
            for (k = 0; k < 4; ++k) {
                double d = fmax(fabs(o[k] - os[k]), fabs(o[k] - on[k]));
                if (d > worst) worst = d;
            }
        }
    }
    CHECK(worst <= 1e-5, "column swap / sign flip changed a result by %.3g", worst);
    sample_texture_destroy(t);
}

/* A smooth texture (no pyramid: the level is the base) and a footprint of
 * several texels: the filter's sum over texel centres against dense
 * integration (1/8 texel) of the same kernel over the same ellipse
 * (JJᵀ + rc·I, the kernel's reconstruction term included) times the
 * same function. */
static double smooth(double u, double v, int ch) { return 0.5 + 0.3 * sin(6.283185307179586 * (3.0 * u + 2.0 * v) / 128.0 + ch); }
static float f_smooth(int i, int j, int ch) { return (float)smooth(i, j, ch); }

static double kernel_profile(sample_ewa_kernel k, double x)
{
    const double pi = 3.14159265358979323846;
    double a = k == SAMPLE_EWA_LANCZOS3 ? 3.0 : 2.0;
    if (x >= a) return 0.0;
    if (k == SAMPLE_EWA_MITCHELL)
        return (x < 1.0 ? 7 * x * x * x - 12 * x * x + 16.0 / 3 : -7.0 / 3 * x * x * x + 12 * x * x - 20 * x + 32.0 / 3) / 6;
    if (x < 1e-9) return 1.0;
    return sin(pi * x) / (pi * x) * sin(pi * x / a) / (pi * x / a);
}

static void dense_integration(void)
{
    sample_texture *t = tex_from(128, 128, f_smooth, 0);
    double worst[NK] = {0};
    int kk, n, ch;
    for (kk = 0; kk < NK; ++kk) {
        sample_sampler s;
        sample_ctx c = kernel_ctx(t, &s, kernels[kk], 0);
        for (n = 0; n < 4; ++n) {
            double a = urand(4.0, 6.0), b = a * urand(0.6, 1.0), r, u, v;
            sample_query q = footprint((float)urand(0.3, 0.7), (float)urand(0.3, 0.7), a, b, urand(0, 6.3),
                                       urand(0, 6.3), 128, 128);
            /* The kernel's reconstruction term at this eccentricity. */
            const fp_radial *kr = ls_fp_radial(kernels[kk]);
            double rc = ls_fp_radial_recon(kr, ls_fp_radial_minor(kr, a / b));
            double J00 = q.dsdx * 128.0, J01 = q.dsdy * 128.0, J10 = q.dtdx * 128.0, J11 = q.dtdy * 128.0;
            double M00 = J00 * J00 + J01 * J01 + rc, M01 = J00 * J10 + J01 * J11, M11 = J10 * J10 + J11 * J11 + rc;
            double det = M00 * M11 - M01 * M01, u0 = q.s * 128.0 - 0.5, v0 = q.t * 128.0 - 0.5;
            double sw = 0.0, sT[4] = {0}, h = 0.125;
            float out[4];
            ls_fp_ewa(&c, &q, 0.0f, out, NULL, NULL, NULL);
            r = 3.0 * sqrt(fmax(M00, M11)) + 1.0;
            for (v = v0 - r; v <= v0 + r; v += h)
                for (u = u0 - r; u <= u0 + r; u += h) {
                    double du = u - u0, dv = v - v0;
                    double x = sqrt((M11 * du * du - 2.0 * M01 * du * dv + M00 * dv * dv) / det);
                    double w = kernel_profile(kernels[kk], x);
                    if (w == 0.0) continue;
                    sw += w;
                    for (ch = 0; ch < 4; ++ch) sT[ch] += w * smooth(u, v, ch);
                }
            for (ch = 0; ch < 4; ++ch) {
                double d = fabs(out[ch] - sT[ch] / sw);
                if (d > worst[kk]) worst[kk] = d;
            }
        }
        CHECK(worst[kk] <= 2e-3, "%s vs dense integration: %.3g", sample_ewa_kernel_name(kernels[kk]), worst[kk]);
    }
    printf("dense integration, worst: lanczos2 %.2g lanczos3 %.2g mitchell %.2g\n", worst[0], worst[1], worst[2]);
    sample_texture_destroy(t);
}

/* A step edge (1 left of column 64, 0 right), no pyramid, an isotropic
 * footprint of 3 texels moved across it: the sharp kernels ring (results
 * outside [0, 1] beside the edge); with SAMPLE_OPT_EWA_CLAMP they stay in
 * the range of their texels. The Gaussian and the clamp never leave it. */
static float f_step(int i, int j, int ch) { (void)j; (void)ch; return i < 64 ? 1.0f : 0.0f; }

static void ringing_and_clamp(void)
{
    sample_texture *t = tex_from(128, 16, f_step, 0);
    int kk, cl, n;
    for (kk = 0; kk < NK; ++kk)
        for (cl = 0; cl < 2; ++cl) {
            sample_sampler s;
            sample_ctx c = kernel_ctx(t, &s, kernels[kk], cl ? SAMPLE_OPT_EWA_CLAMP : 0);
            double lo = 1.0, hi = 0.0, at_hi = 0.0;
            for (n = 0; n <= 160; ++n) {
                double u = 44.0 + n * 0.25; /* texel units */
                sample_query q = footprint((float)((u + 0.5) / 128.0), 0.5f, 3.0, 3.0, 0.0, 0.0, 128, 16);
                float out[4];
                ls_fp_ewa(&c, &q, 0.0f, out, NULL, NULL, NULL);
                if (out[0] < lo) lo = out[0];
                if (out[0] > hi) hi = out[0], at_hi = u - 63.5;
            }
            if (cl) CHECK(lo >= 0.0 && hi <= 1.0, "%s clamped: [%.9g, %.9g]", sample_ewa_kernel_name(kernels[kk]), lo, hi);
            else {
                CHECK(lo < -0.01 && hi > 1.01, "%s rings: [%.4g, %.4g]", sample_ewa_kernel_name(kernels[kk]), lo, hi);
                printf("%s step edge: range [%.4f, %.4f], overshoot peak %.2f texels (%.2f pixels) from the edge\n",
                       sample_ewa_kernel_name(kernels[kk]), lo, hi, at_hi, at_hi / 3.0);
            }
        }
    sample_texture_destroy(t);
}

/* ∂result/∂(s, t) at fixed footprint against central differences. */
static float f_mild(int i, int j, int ch) { return (float)(0.5 + 0.4 * sin(0.3 * i + 0.2 * j + ch)); }

static void derivatives(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    int kk, n, k;
    for (kk = 0; kk < NK; ++kk) {
        sample_sampler s;
        sample_ctx c = kernel_ctx(t, &s, kernels[kk], 0);
        for (n = 0; n < 6; ++n) {
            double a = exp2(urand(0.5, 3)), b = a * urand(0.3, 1.0);
            sample_query q = footprint((float)urand(0.2, 0.8), (float)urand(0.2, 0.8), a, b, urand(0, 6.3),
                                       urand(0, 6.3), 64, 64), qp = q, qm = q;
            float o[4], d[2][4], p[4], m[4];
            const float e = 1e-3f / 64.0f;
            int ax;
            ls_fp_ewa(&c, &q, 0.0f, o, d[0], d[1], NULL);
            for (ax = 0; ax < 2; ++ax) {
                float *cp = ax ? &qp.t : &qp.s, *cm = ax ? &qm.t : &qm.s;
                qp = q, qm = q;
                *cp += e, *cm -= e;
                ls_fp_ewa(&c, &qp, 0.0f, p, NULL, NULL, NULL);
                ls_fp_ewa(&c, &qm, 0.0f, m, NULL, NULL, NULL);
                for (k = 0; k < 3; ++k) {
                    double fd = (p[k] - m[k]) / ((double)*cp - *cm);
                    CHECK(fabs(d[ax][k] - fd) <= 0.02 * fabs(fd) + 0.02 * 64, "%s d/d%c %.6g vs %.6g",
                          sample_ewa_kernel_name(kernels[kk]), ax ? 't' : 's', d[ax][k], fd);
                }
            }
        }
    }
    sample_texture_destroy(t);
}

/* Extreme queries through sample_batch: finite results, the cap held,
 * non-finite input the border colour; every kernel, clamped or not. */
static void degenerate_and_cap(void)
{
    static sample_query qs[EXTREME_NQ];
    sample_texture *t = tex_from(256, 128, f_mild, 1);
    int kk;
    extreme_queries(qs, 256, 128);
    for (kk = 0; kk < 2 * NK; ++kk) {
        sample_sampler s;
        kernel_ctx(t, &s, kernels[kk % NK], kk >= NK ? SAMPLE_OPT_EWA_CLAMP : 0);
        s.wrap_s = (sample_wrap)(kk % SAMPLE_WRAP_COUNT);
        extreme_batch(t, &s, qs, SAMPLE_MAX_FOOTPRINT_TEXELS, sample_ewa_kernel_name(kernels[kk % NK]));
    }
    sample_texture_destroy(t);
}

int main(void)
{
    (void)run_filter; /* footprint_util.h's, for the other footprint tests */
    RUN(names_and_validation);
    RUN(constant_exact);
    RUN(column_symmetry);
    RUN(dense_integration);
    RUN(ringing_and_clamp);
    RUN(derivatives);
    RUN(degenerate_and_cap);
    return check_finish();
}
