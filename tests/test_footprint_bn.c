/*
 * Blinn–Newell against brute force (DESIGN §7): the filter should be the
 * pyramid-weighted integral of the bilinearly reconstructed texture over the
 * 2 × 2-pixel quadrilateral. The references here integrate that densely in
 * screen space (u = P(x, y), du = |det DP| dx dy) on a one-level texture, so
 * the level choice plays no part; they share only the bilinear lookup
 * (recon_level, tested in test_reconstruct.c) with the library.
 */
#include "footprint_proj.h"

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
 * quad path (projective map, here affine) must agree with the affine path
 * to rounding (measured 6e-8, one ulp; bound 2e-5);
 * listing the corners in the mirrored order (an "inside-out" quad, the
 * columns swapped) changes nothing; a bow-tie is filtered as the
 * parallelogram of its centre Jacobian (documented fallback). */
static void corners_parallelogram(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    double worst = 0.0;
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
        worst = fmax(worst, fmax(fabs(oq[0] - o[0]), fabs(om[0] - o[0])));
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
    printf("parallelogram corners vs Jacobian mode: worst %.3g\n", worst);
    sample_texture_destroy(t);
}

/* Random perspective planes: corner mode takes the corners of a true
 * homography (footprint_proj.h; semi-axes 3 to 10 texels, w on the square
 * within 1 ± kk, kk up to 0.6, i.e. far corners up to 4 times as far as
 * near ones) and is checked against the dense texture-space integral
 * ∫ pyr(H⁻¹(u))·T_bil(u) du through that homography. Corner mode rebuilds
 * H from the corners exactly (up to their float rounding), so what remains
 * is the moment-matched reconstruction (here a texture-space stretch about
 * the centre, exact only for parallelograms) and the sampling at texel
 * centres, as for parallelograms above. Measured worst 1.5e-3 (mean
 * 2.7e-4; it grows with kk); bound 3e-3, as for parallelograms.
 * The Jacobian mode given the exact centre and centre Jacobian of the same
 * map is farther on average (measured mean 1.4e-2 against the quad's
 * 2.7e-4): the quad path does use the quad's shape. */
static void perspective_vs_brute_force(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 0);
    sample_sampler s;
    sample_ctx c;
    double worst = 0.0, err_quad = 0.0, err_affine = 0.0;
    int n;
    sample_sampler_init(&s);
    c = ctx_for(t, &s);
    for (n = 0; n < 60; ++n) {
        proj_map m = proj_random(urand(3, 10), urand(3, 10), urand(0, 0.6), urand(0.2, 0.8) * 64,
                                 urand(0.2, 0.8) * 64);
        sample_quad quad = proj_quad(&m, 64, 64);
        sample_query q;
        double ref = proj_reference(&c, &m, 1);
        float o[4], oa[4];
        memset(&q, 0, sizeof q);
        fp_blinn_newell(&c, &q, &quad, 0.0f, o, NULL, NULL, NULL);
        /* Exact centre and centre Jacobian A − c·kᵀ (w = 1 there). */
        q.s = (float)(m.c[0] / 64);
        q.t = (float)(m.c[1] / 64);
        q.dsdx = (float)((m.A[0][0] - m.c[0] * m.k[0]) / 64);
        q.dsdy = (float)((m.A[0][1] - m.c[0] * m.k[1]) / 64);
        q.dtdx = (float)((m.A[1][0] - m.c[1] * m.k[0]) / 64);
        q.dtdy = (float)((m.A[1][1] - m.c[1] * m.k[1]) / 64);
        fp_blinn_newell(&c, &q, NULL, 0.0f, oa, NULL, NULL, NULL);
        if (fabs(o[0] - ref) > worst) worst = fabs(o[0] - ref);
        err_quad += fabs(o[0] - ref);
        err_affine += fabs(oa[0] - ref);
    }
    printf("perspective: quad worst %.3g mean %.3g, Jacobian mode mean %.3g\n", worst, err_quad / 60,
           err_affine / 60);
    CHECK(worst <= 3e-3, "worst |BN quad - reference| = %.3g", worst);
    CHECK(err_quad < err_affine, "quad mean error %.3g not below affine %.3g", err_quad / 60, err_affine / 60);
    sample_texture_destroy(t);
}

/* Quads that are no projective image of the square take the documented
 * fallback, the parallelogram of the bilinear centre Jacobian about the
 * corner mean: darts (one corner pulled past the diagonal) and the corners
 * of homographies whose w changes sign inside the square (the plane
 * "through the horizon": kk from 1.05 to 3, which gives bow-ties and
 * darts). Convex quads with a corner too near the horizon (w ratio over
 * 2^(20/3) ≈ 101.6, i.e. kk over 0.9805: kk from 0.985 to 0.999) or too eccentric (16:1 and beyond) are
 * filtered as the Jacobian mode at the map's exact centre and centre
 * Jacobian, which the corners still determine. All within the texel cap.
 * Tolerance 2e-5, as corners_parallelogram (the test rounds the Jacobian
 * to float; the library keeps it in double). */
static void degenerate_fallback(void)
{
    sample_texture *t = tex_from(64, 64, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    uint32_t saved = test_rng;
    double worst = 0.0;
    int n, k, kind;
    sample_sampler_init(&s);
    /* Its own draws: the later tests see the same footprints as before. */
    test_rng = 777u;
    for (kind = 0; kind < 4; ++kind)
        for (n = 0; n < 50; ++n) {
            double sc = exp2(urand(-2, 4));
            proj_map m = proj_random(sc * urand(1, 3), sc * urand(1, 3), 0.0, urand(0.2, 0.8) * 64,
                                     urand(0.2, 0.8) * 64);
            sample_quad quad;
            sample_query j, q;
            float o[4], oj[4], ds[4], dt[4];
            uint32_t texels;
            memset(&q, 0, sizeof q);
            s.options = (n & 1) ? SAMPLE_OPT_BN_AREA_WEIGHT : 0u;
            c = ctx_for(t, &s);
            if (kind == 0 || kind == 1) {
                double ms = 0, mt = 0;
                if (kind == 0) { /* dart: corner 2 pulled past the diagonal 1–3 */
                    quad = proj_quad(&m, 64, 64);
                    for (k = 0; k < 2; ++k)
                        quad.st[2][k] = (float)(quad.st[0][k] + urand(0.1, 0.9) * (quad.st[2][k] - quad.st[0][k]) * 0.5);
                } else { /* through the horizon */
                    double kk = urand(1.05, 3.0), ph = urand(0, 6.3);
                    m.k[0] = kk * cos(ph) / (fabs(cos(ph)) + fabs(sin(ph)));
                    m.k[1] = kk * sin(ph) / (fabs(cos(ph)) + fabs(sin(ph)));
                    quad = proj_quad(&m, 64, 64);
                }
                for (k = 0; k < 4; ++k) { ms += 0.25 * quad.st[k][0]; mt += 0.25 * quad.st[k][1]; }
                j.s = (float)ms;
                j.t = (float)mt;
                j.dsdx = (float)(0.25 * ((quad.st[1][0] + quad.st[2][0]) - (quad.st[0][0] + quad.st[3][0])));
                j.dtdx = (float)(0.25 * ((quad.st[1][1] + quad.st[2][1]) - (quad.st[0][1] + quad.st[3][1])));
                j.dsdy = (float)(0.25 * ((quad.st[2][0] + quad.st[3][0]) - (quad.st[0][0] + quad.st[1][0])));
                j.dtdy = (float)(0.25 * ((quad.st[2][1] + quad.st[3][1]) - (quad.st[0][1] + quad.st[1][1])));
            } else {
                if (kind == 2) { /* near the horizon, still convex */
                    double kk = urand(0.985, 0.999), ph = urand(0, 6.3);
                    m.k[0] = kk * cos(ph) / (fabs(cos(ph)) + fabs(sin(ph)));
                    m.k[1] = kk * sin(ph) / (fabs(cos(ph)) + fabs(sin(ph)));
                } else { /* eccentric: 17:1 to 40:1, mild perspective */
                    double a = sc * urand(17, 40);
                    m = proj_random(a, sc, urand(0, 0.3), urand(0.2, 0.8) * 64, urand(0.2, 0.8) * 64);
                }
                quad = proj_quad(&m, 64, 64);
                /* The map's exact centre and centre Jacobian A − c·kᵀ
                 * (proj_random's A already holds c·kᵀ for kind 3; for kind
                 * 2 k changed after, so compute it here in general). */
                j.s = (float)(m.c[0] / 64);
                j.t = (float)(m.c[1] / 64);
                j.dsdx = (float)((m.A[0][0] - m.c[0] * m.k[0]) / 64);
                j.dsdy = (float)((m.A[0][1] - m.c[0] * m.k[1]) / 64);
                j.dtdx = (float)((m.A[1][0] - m.c[1] * m.k[0]) / 64);
                j.dtdy = (float)((m.A[1][1] - m.c[1] * m.k[1]) / 64);
            }
            texels = fp_blinn_newell(&c, &q, &quad, 0.0f, o, ds, dt, NULL);
            fp_blinn_newell(&c, &j, NULL, 0.0f, oj, NULL, NULL, NULL);
            CHECK(texels <= SAMPLE_MAX_FOOTPRINT_TEXELS, "texels %u", (unsigned)texels);
            CHECK(isfinite(ds[0]) && isfinite(dt[0]), "derivatives finite");
            CHECK(fabs(o[0] - oj[0]) <= 2e-5, "kind %d quad %d: %.9g vs fallback %.9g", kind, n, o[0], oj[0]);
            worst = fmax(worst, fabs(o[0] - oj[0]));
        }
    printf("degenerate quads vs their fallback: worst %.3g\n", worst);
    test_rng = saved;
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
    RUN(degenerate_fallback);
    RUN(derivatives);
    return check_finish();
}
