/*
 * Blinn–Newell against brute force (DESIGN §7): the filter should be the
 * pyramid-weighted integral of the bilinearly reconstructed texture over the
 * 2 × 2-pixel quadrilateral. The references here integrate that densely in
 * screen space (u = P(x, y), du = |det DP| dx dy) on a one-level texture, so
 * the level choice plays no part; they share only the bilinear lookup
 * (recon_level, tested in test_reconstruct.c) with the library.
 */
#include "footprint_util.h"

static float f_mild(int i, int j, int ch)
{
    (void)ch;
    return (float)(0.5 + 0.2 * sin(0.27 * i + 0.1) * cos(0.19 * j + 0.4) + 0.1 * sin(0.05 * (i + 2 * j)));
}

static double pyr(double x, double y) { return (1.0 - fabs(x)) * (1.0 - fabs(y)); }

/* Corner k of the 2 × 2 region: (−1,−1), (+1,−1), (+1,+1), (−1,+1). */
static const double corner_xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

/* ∫ pyr · T_bil(P) |det DP| / ∫ pyr |det DP| over a G × G midpoint grid;
 * P is the bilinear map of the four corners (affine for a parallelogram). */
static double reference(const sample_ctx *c, double P[4][2])
{
    enum { G = 120 };
    double num = 0.0, den = 0.0;
    int a, b;
    for (b = 0; b < G; ++b)
        for (a = 0; a < G; ++a) {
            double x = -1.0 + (a + 0.5) * 2.0 / G, y = -1.0 + (b + 0.5) * 2.0 / G;
            double al = 0.5 * (x + 1.0), be = 0.5 * (y + 1.0), p[2], dx[2], dy[2], w;
            float T[4];
            int k;
            for (k = 0; k < 2; ++k) {
                double g = P[0][k] - P[1][k] + P[2][k] - P[3][k];
                p[k] = P[0][k] + (P[1][k] - P[0][k]) * al + (P[3][k] - P[0][k]) * be + g * al * be;
                dx[k] = 0.5 * (P[1][k] - P[0][k] + g * be);
                dy[k] = 0.5 * (P[3][k] - P[0][k] + g * al);
            }
            w = pyr(x, y) * fabs(dx[0] * dy[1] - dx[1] * dy[0]);
            recon_level(c, 0, SAMPLE_LINEAR, (float)p[0], (float)p[1], T, NULL, NULL);
            num += w * T[0];
            den += w;
        }
    return num / den;
}

static void quad_of(const sample_query *q, double P[4][2])
{
    int k;
    for (k = 0; k < 4; ++k) {
        P[k][0] = q->s + corner_xy[k][0] * q->dsdx + corner_xy[k][1] * q->dsdy;
        P[k][1] = q->t + corner_xy[k][0] * q->dtdx + corner_xy[k][1] * q->dtdy;
    }
}

/* Random parallelograms with semi-axes of 1.5 to 8 texels. The filter
 * weights texel centres by the pyramid widened to the covariance of
 * pyramid ⊛ tent; on f_mild (third derivatives ≤ 0.02 per texel³) the
 * mean and covariance fix the integral up to fourth-order terms, and what
 * remains is the sampling of a kernel a few texels wide at texel centres.
 * Measured worst case over these 200 footprints: 1.5e-3; bound 3e-3 (½ % of
 * the content's 0.6 range). */
static void affine_vs_brute_force(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 0);
    sample_sampler s;
    sample_ctx c;
    double worst = 0.0;
    int n;
    sample_sampler_init(&s);
    c = ctx_for(t, &s);
    for (n = 0; n < 200; ++n) {
        double a = urand(1.5, 8.0), b = urand(1.5, a);
        sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, b, urand(0, 6.3), urand(-1.2, 1.2), 64, 64);
        double P[4][2], ref;
        float o[4];
        quad_of(&q, P);
        ref = reference(&c, P);
        fp_blinn_newell(&c, &q, NULL, 0.0f, o, NULL, NULL, NULL);
        if (fabs(o[0] - ref) > worst) worst = fabs(o[0] - ref);
    }
    CHECK(worst <= 3e-3, "worst |BN - reference| = %.3g", worst);
    sample_texture_destroy(t);
}

/* Exact corners of a parallelogram describe the Jacobian's footprint: the
 * quad path (bilinear inverse) must agree with the affine path to rounding;
 * listing the corners in the mirrored order (an "inside-out" quad, the
 * columns swapped) changes nothing; a bow-tie is filtered as the
 * parallelogram of its centre Jacobian (documented fallback). */
static void corners_parallelogram(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    int n, k;
    sample_sampler_init(&s);
    c = ctx_for(t, &s);
    for (n = 0; n < 60; ++n) {
        double a = exp2(urand(0, 5)), b = a * exp2(urand(-3, 0)), P[4][2];
        sample_query q = footprint((float)urand(0, 1), (float)urand(0, 1), a, b, urand(0, 6.3), urand(-1.2, 1.2), 64, 64);
        sample_quad quad, mirrored, bowtie;
        float o[4], oq[4], om[4], ob[4], oj[4];
        /* A centre the corners' float average reproduces exactly. */
        q.s = (float)(floor(q.s * 256.0) / 256.0);
        q.t = (float)(floor(q.t * 256.0) / 256.0);
        quad_of(&q, P);
        for (k = 0; k < 4; ++k) {
            quad.st[k][0] = (float)P[k][0];
            quad.st[k][1] = (float)P[k][1];
            mirrored.st[k][0] = (float)P[(4 - k) & 3][0];
            mirrored.st[k][1] = (float)P[(4 - k) & 3][1];
        }
        /* Bow-tie: swap corners 2 and 3. Its centre Jacobian has columns
         * ((P1 + P3) − (P0 + P2))/4 and ((P3 + P2) − (P0 + P1))/4. */
        bowtie = quad;
        memcpy(bowtie.st[2], quad.st[3], sizeof bowtie.st[2]);
        memcpy(bowtie.st[3], quad.st[2], sizeof bowtie.st[3]);
        fp_blinn_newell(&c, &q, NULL, 0.0f, o, NULL, NULL, NULL);
        fp_blinn_newell(&c, &q, &quad, 0.0f, oq, NULL, NULL, NULL);
        fp_blinn_newell(&c, &q, &mirrored, 0.0f, om, NULL, NULL, NULL);
        CHECK_NEAR(oq[0], o[0], 2e-5);
        CHECK_NEAR(om[0], o[0], 2e-5);
        {
            sample_query j = q;
            double ms = 0, mt = 0;
            for (k = 0; k < 4; ++k) { ms += 0.25 * bowtie.st[k][0]; mt += 0.25 * bowtie.st[k][1]; }
            j.s = (float)ms;
            j.t = (float)mt;
            j.dsdx = (float)(0.25 * ((bowtie.st[1][0] + bowtie.st[2][0]) - (bowtie.st[0][0] + bowtie.st[3][0])));
            j.dtdx = (float)(0.25 * ((bowtie.st[1][1] + bowtie.st[2][1]) - (bowtie.st[0][1] + bowtie.st[3][1])));
            j.dsdy = (float)(0.25 * ((bowtie.st[2][0] + bowtie.st[3][0]) - (bowtie.st[0][0] + bowtie.st[1][0])));
            j.dtdy = (float)(0.25 * ((bowtie.st[2][1] + bowtie.st[3][1]) - (bowtie.st[0][1] + bowtie.st[1][1])));
            fp_blinn_newell(&c, &q, &bowtie, 0.0f, ob, NULL, NULL, NULL);
            fp_blinn_newell(&c, &j, NULL, 0.0f, oj, NULL, NULL, NULL);
            CHECK_NEAR(ob[0], oj[0], 2e-5);
        }
    }
    sample_texture_destroy(t);
}

/* A genuinely non-affine quad (a perspective trapezoid: the far edge half
 * as long as the near one, plus shear) against the dense integral through
 * the bilinear inverse. The filter's widening is computed from the centre
 * Jacobian only: measured worst 5.7e-4 over these footprints of 3 to 10
 * texels; bound 1.5e-3. The parallelogram of the same centre Jacobian is
 * checked to be farther from the reference on average (measured mean 4.4e-3
 * against the quad's 1.5e-4): the quad path does use the quad's shape. */
static void perspective_vs_brute_force(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 0);
    sample_sampler s;
    sample_ctx c;
    double worst = 0.0, err_quad = 0.0, err_affine = 0.0;
    int n, k;
    sample_sampler_init(&s);
    c = ctx_for(t, &s);
    for (n = 0; n < 60; ++n) {
        double a = urand(3, 10), b = urand(3, 10), th = urand(0, 6.3), taper = urand(0.4, 0.7), sh = urand(-0.3, 0.3);
        double cs = cos(th), sn = sin(th), P[4][2], ref;
        double s0 = urand(0.2, 0.8) * 64, t0 = urand(0.2, 0.8) * 64;
        sample_quad quad;
        sample_query q;
        float o[4], oa[4];
        for (k = 0; k < 4; ++k) {
            /* near edge (y = −1) full width, far edge (y = +1) tapered */
            double x = corner_xy[k][0] * (corner_xy[k][1] > 0 ? taper : 1.0) + sh * corner_xy[k][1];
            double y = corner_xy[k][1];
            double u = s0 + cs * a * x - sn * b * y, v = t0 + sn * a * x + cs * b * y;
            quad.st[k][0] = (float)(u / 64.0);
            quad.st[k][1] = (float)(v / 64.0);
            P[k][0] = quad.st[k][0];
            P[k][1] = quad.st[k][1];
        }
        memset(&q, 0, sizeof q);
        ref = reference(&c, P);
        fp_blinn_newell(&c, &q, &quad, 0.0f, o, NULL, NULL, NULL);
        q.s = (float)(0.25 * (P[0][0] + P[1][0] + P[2][0] + P[3][0]));
        q.t = (float)(0.25 * (P[0][1] + P[1][1] + P[2][1] + P[3][1]));
        q.dsdx = (float)(0.25 * (P[1][0] + P[2][0] - P[0][0] - P[3][0]));
        q.dtdx = (float)(0.25 * (P[1][1] + P[2][1] - P[0][1] - P[3][1]));
        q.dsdy = (float)(0.25 * (P[2][0] + P[3][0] - P[0][0] - P[1][0]));
        q.dtdy = (float)(0.25 * (P[2][1] + P[3][1] - P[0][1] - P[1][1]));
        fp_blinn_newell(&c, &q, NULL, 0.0f, oa, NULL, NULL, NULL);
        if (fabs(o[0] - ref) > worst) worst = fabs(o[0] - ref);
        err_quad += fabs(o[0] - ref);
        err_affine += fabs(oa[0] - ref);
    }
    CHECK(worst <= 1.5e-3, "worst |BN quad - reference| = %.3g", worst);
    CHECK(err_quad < err_affine, "quad mean error %.3g not below affine %.3g", err_quad / 60, err_affine / 60);
    sample_texture_destroy(t);
}

/* ∂result/∂s and ∂/∂t at fixed footprint are analytic (weight gradients,
 * quotient rule). Against central differences with h = 4e-6 (0.00026
 * texels, so a difference rarely straddles one of the pyramid's creases):
 * 2 % or 0.02, the float resolution of s near 0.5 being 6e-8. */
static void derivatives(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    int n, f;
    sample_sampler_init(&s);
    s.max_anisotropy = 16.0f;
    c = ctx_for(t, &s);
    for (n = 0; n < 30; ++n) {
        sample_query q = footprint((float)urand(0.3, 0.7), (float)urand(0.3, 0.7), urand(1.5, 12), urand(0.5, 1.5),
                                   urand(0, 6.3), urand(-1, 1), 64, 64);
        for (f = 0; f < FILTER_N; ++f) {
            float o[4], ds[4], dt[4], a[4], b[4];
            const float h = 4e-6f;
            sample_query qa = q, qb = q;
            run_filter(f, &c, &q, NULL, o, ds, dt, NULL);
            qa.s += h; qb.s -= h;
            run_filter(f, &c, &qa, NULL, a, NULL, NULL, NULL);
            run_filter(f, &c, &qb, NULL, b, NULL, NULL, NULL);
            CHECK_NEAR(ds[0], (a[0] - b[0]) / (qa.s - qb.s), 0.02 + 0.02 * fabs(ds[0]));
            qa = q; qb = q;
            qa.t += h; qb.t -= h;
            run_filter(f, &c, &qa, NULL, a, NULL, NULL, NULL);
            run_filter(f, &c, &qb, NULL, b, NULL, NULL, NULL);
            CHECK_NEAR(dt[0], (a[0] - b[0]) / (qa.t - qb.t), 0.02 + 0.02 * fabs(dt[0]));
        }
    }
    sample_texture_destroy(t);
}

int main(void)
{
    RUN(affine_vs_brute_force);
    RUN(corners_parallelogram);
    RUN(perspective_vs_brute_force);
    RUN(derivatives);
    return check_finish();
}
