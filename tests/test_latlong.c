/*
 * Lat-long environment maps (doc/environment-maps.md): OpenImageIO's
 * convention at texel centres, the seam and the poles, the Jacobian,
 * continuity over the seam and the poles, and bad input.
 */
#include "env_test.h"

#include "sample/testing.h"

static void ll_one(const sample_texture *tex, const sample_sampler *s, const double r[3], float out[4])
{
    sample_query3 q;
    sample_batch3_args a;
    int k;
    memset(&q, 0, sizeof q);
    for (k = 0; k < 3; ++k) q.p[k] = (float)r[k];
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = &q;
    a.rgba = out;
    CHECK(sample_batch_latlong(tex, s, &a) == SAMPLE_OK, "sample_batch_latlong");
}

/* The convention by hand (+y up at t = 0, +z at s = ½, +x at s = ¼),
 * texel centres (NEAREST exact, LINEAR within the rounding of the
 * trigonometry), the seam (LINEAR at s = 1 is the mean of the first and
 * last texels of the row) and the pole (+y: LINEAR blends the two texels
 * each side of s = ½ with the two at s + ½ over the pole). */
static void test_latlong_values(void)
{
    sample_texture *tex = make_latlong();
    sample_sampler s;
    sample_query o;
    int i, j, c;
    static const struct { float r[3], s, t; } conv[] = {
        {{0, 1, 0}, 0.5f, 0.0f}, {{0, -1, 0}, 0.5f, 1.0f}, {{0, 0, 1}, 0.5f, 0.5f},
        {{1, 0, 0}, 0.25f, 0.5f}, {{-1, 0, 0}, 0.75f, 0.5f}, {{0, 0, -1}, 1.0f, 0.5f},
    };
    for (i = 0; i < (int)(sizeof conv / sizeof conv[0]); ++i) {
        sample_query3 q = q_dir(conv[i].r);
        CHECK(ls_latlong_query(&q, &o) == 0 && o.s == conv[i].s && o.t == conv[i].t, "direction %d: (%g, %g)", i,
              o.s, o.t);
    }
    sample_sampler_init(&s);
    for (j = 0; j < LH; ++j)
        for (i = 0; i < LW; ++i) {
            double r[3];
            float a[4], b[4];
            latlong_dir((i + 0.5) / LW, (j + 0.5) / LH, r);
            s.mag_filter = SAMPLE_NEAREST;
            ll_one(tex, &s, r, a);
            s.mag_filter = SAMPLE_LINEAR;
            ll_one(tex, &s, r, b);
            for (c = 0; c < 4; ++c) {
                CHECK_EQF(a[c], ll_data[j][i][c]);
                CHECK_NEAR(b[c], ll_data[j][i][c], 1e-5);
            }
        }
    for (j = 0; j < LH; ++j) {
        double r[3];
        float a[4];
        latlong_dir(1.0, (j + 0.5) / LH, r);
        r[0] = 0.0; /* exactly on the seam */
        ll_one(tex, &s, r, a);
        for (c = 0; c < 4; ++c) CHECK_NEAR(a[c], 0.5f * (ll_data[j][0][c] + ll_data[j][LW - 1][c]), 1e-5);
    }
    {
        double r[3] = {0, 1, 0};
        float a[4];
        ll_one(tex, &s, r, a);
        for (c = 0; c < 4; ++c)
            CHECK_NEAR(a[c], 0.25f * (ll_data[0][LW / 2 - 1][c] + ll_data[0][LW / 2][c] + ll_data[0][LW - 1][c] +
                                      ll_data[0][0][c]),
                       1e-6);
    }
    sample_texture_destroy(tex);
}

/* The Jacobian of (s, t) against central differences of the mapping,
 * away from the seam and poles; and on the poles' axis ∂s = 0 (its limit
 * along the step's own meridian) with ∂t that of the latitude. */
static void test_latlong_jacobian(void)
{
    uint32_t seed = 3;
    int i, k;
    for (i = 0; i < 50; ++i) {
        sample_query3 q, qp, qm;
        sample_query o, op, om;
        const float h = 1e-3f;
        memset(&q, 0, sizeof q);
        for (k = 0; k < 3; ++k) {
            q.p[k] = 2.0f * rnd(&seed) - 1.0f;
            q.dpdx[k] = 2.0f * rnd(&seed) - 1.0f;
        }
        if (fabsf(q.p[0]) + fabsf(q.p[2]) < 0.3f || (q.p[2] < 0.0f && fabsf(q.p[0]) < 0.1f)) continue;
        qp = qm = q;
        for (k = 0; k < 3; ++k) {
            qp.p[k] += h * q.dpdx[k];
            qm.p[k] -= h * q.dpdx[k];
        }
        ls_latlong_query(&q, &o);
        ls_latlong_query(&qp, &op);
        ls_latlong_query(&qm, &om);
        CHECK_NEAR(o.dsdx, (op.s - om.s) / (2.0f * h), 2e-3);
        CHECK_NEAR(o.dtdx, (op.t - om.t) / (2.0f * h), 2e-3);
    }
    {
        sample_query3 q;
        sample_query o;
        memset(&q, 0, sizeof q);
        q.p[1] = 2.0f;
        q.dpdx[0] = 0.5f; /* off the north pole by 0.25 rad per pixel: ∂t = 0.25/π */
        ls_latlong_query(&q, &o);
        CHECK(o.dsdx == 0.0f && o.dsdy == 0.0f && o.dtdy == 0.0f, "pole: %g %g %g", o.dsdx, o.dsdy, o.dtdy);
        CHECK_NEAR(o.dtdx, 0.25 / 3.14159265358979323846, 1e-7);
    }
}

/* Continuity across the seam (paths through s = 0 = 1 at several
 * latitudes, a footprint of about 2 texels along them) and over both
 * poles (a meridian through the pole, the footprint along it), every
 * filter; the same bound as the cube maps' edges. */
static void test_latlong_continuity(void)
{
    sample_texture *tex = make_latlong();
    static sample_query3 q[401];
    static float out[401][4];
    int fi, path, i, k;
    for (fi = 0; fi < CONT_FILTERS; ++fi) {
        sample_sampler s;
        double worst = 0.0;
        cont_sampler(fi, &s);
        for (path = 0; path < 6; ++path) {
            sample_batch3_args a;
            for (i = 0; i <= 400; ++i) {
                double tau = (double)i / 400, r[3], r2[3], st, tt, h = 1e-4;
                if (path < 4) {
                    /* Across the seam at latitude t = 0.2 … 0.8. */
                    st = 1.0 - 0.2 / LW * 3 + tau * 0.4 / LW * 3;
                    tt = 0.2 + 0.2 * path;
                    latlong_dir(st, tt, r);
                    latlong_dir(st + h, tt, r2);
                } else {
                    /* Over a pole along the meridian s = 0.3 (and 0.8),
                     * stepping over the pole point itself, where s is
                     * undefined and a map whose first row is not constant
                     * has no single value. */
                    double lat = ((i + 0.5) / 400.0 - 0.5) * 3.0 / LH; /* past the pole: < 0 */
                    st = lat < 0.0 ? 0.3 : 0.8;
                    tt = fabs(lat);
                    if (path == 5) tt = 1.0 - tt;
                    latlong_dir(st, tt, r);
                    latlong_dir(st, tt + h, r2);

                }
                for (k = 0; k < 3; ++k) {
                    q[i].p[k] = (float)r[k];
                    /* A footprint of about 2 texels along the path. */
                    q[i].dpdx[k] = (float)((r2[k] - r[k]) / h * (path < 4 ? 2.0 / LW : 2.0 / LH));
                    q[i].dpdy[k] = 0.0f;
                }
            }
            memset(&a, 0, sizeof a);
            a.count = 401;
            a.queries = q;
            a.rgba = &out[0][0];
            CHECK(sample_batch_latlong(tex, &s, &a) == SAMPLE_OK, "batch");
            for (i = 1; i <= 400; ++i)
                for (k = 0; k < 4; ++k) {
                    double d = fabs((double)out[i][k] - (double)out[i - 1][k]);
                    if (d > CONT_BOUND && getenv("TEST_CUBE_VERBOSE"))
                        printf("  %s path %d step %d: %.4f\n", cont_filters[fi].name, path, i, d);
                    worst = fmax(worst, d);
                }
        }
        CHECK(worst <= CONT_BOUND, "%s: a step of %g across the seam or a pole", cont_filters[fi].name, worst);
        if (getenv("TEST_CUBE_VERBOSE"))
            printf("lat-long continuity %s: max step %.4f\n", cont_filters[fi].name, worst);
    }
    sample_texture_destroy(tex);
}

/* Bad input and kinds, as for cube maps. */
static void test_latlong_bad(void)
{
    sample_texture *tex = make_latlong(), *cube = make_cube(2, NULL);
    sample_sampler s;
    sample_query3 q[3];
    float out[3][4];
    sample_batch3_args a;
    int i, c;
    sample_sampler_init(&s);
    s.border_color[1] = 0.75f;
    memset(q, 0, sizeof q);
    q[0].p[0] = NAN;
    q[2].p[0] = 1.0f;
    q[2].dpdy[1] = INFINITY;
    memset(&a, 0, sizeof a);
    a.count = 3;
    a.queries = q;
    a.rgba = &out[0][0];
    CHECK(sample_batch_latlong(tex, &s, &a) == SAMPLE_OK, "batch");
    for (i = 0; i < 3; ++i)
        for (c = 0; c < 4; ++c) CHECK_EQF(out[i][c], s.border_color[c]);
    CHECK(sample_batch_latlong(cube, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "cube accepted as lat-long");
    sample_texture_destroy(cube);
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(test_latlong_values);
    RUN(test_latlong_jacobian);
    RUN(test_latlong_continuity);
    RUN(test_latlong_bad);
    return check_finish();
}
