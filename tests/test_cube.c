/*
 * Cube maps (doc/environment-maps.md, GL 4.6 §8.13): face selection and
 * (s, t) by table 8.19, λ from the face coordinates' derivatives, seamless
 * filtering across edges and corners (§8.13.1), pyramids continuous
 * across edges, every format, and bad input.
 */
#include "check.h"
#include "internal.h"

#include <stdint.h>
#include <stdlib.h>

static float rnd(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return (float)(*s >> 8) * (1.0f / 16777216.0f);
}

/* Texel value of face f, texel (i, j), channel c of an n-sized test cube:
 * distinct exact floats. */
static float tval(int f, int i, int j, int c, int n) { return (float)(((f * n + j) * n + i) * 4 + c) / 4096.0f; }

/* A float RGBA cube of n × n faces holding tval, levels by mip (NULL: base only). */
static sample_texture *make_cube(int n, const sample_mip_params *mip)
{
    sample_image faces[6];
    float *d = (float *)malloc((size_t)6 * n * n * 4 * sizeof(float));
    sample_texture *tex = NULL;
    sample_error err;
    int f, i, j, c;
    for (f = 0; f < 6; ++f) {
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i)
                for (c = 0; c < 4; ++c) d[(((size_t)f * n + j) * n + i) * 4 + c] = tval(f, i, j, c, n);
        faces[f] = (sample_image){n, n, 4, SAMPLE_FORMAT_F32, d + (size_t)f * n * n * 4, 0};
    }
    if (sample_texture_create_cube(faces, mip, &tex, &err) != SAMPLE_OK) fprintf(stderr, "%s\n", err.message);
    free(d);
    return tex;
}

/* Direction of face f's point (s, t). */
static void face_dir(int f, double s, double t, float r[3])
{
    double d[3];
    int k;
    cube_direction(f, 2.0 * s - 1.0, 2.0 * t - 1.0, d);
    for (k = 0; k < 3; ++k) r[k] = (float)d[k];
}

static void one(const sample_texture *tex, const sample_sampler *s, const sample_query3 *q, float out[4],
                sample_stats *st)
{
    sample_batch3_args a;
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = q;
    a.rgba = out;
    a.stats = st;
    CHECK(sample_batch_cube(tex, s, &a) == SAMPLE_OK, "sample_batch_cube failed");
}

static sample_query3 q_dir(const float r[3])
{
    sample_query3 q;
    memset(&q, 0, sizeof q);
    memcpy(q.p, r, sizeof q.p);
    return q;
}

/* Table 8.19: each axis direction selects its face and lands at (½, ½);
 * the face frames' corners by hand. */
static void test_face_selection(void)
{
    static const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    /* (s, t) of a direction with a small offset, from table 8.19 by hand:
     * +X at (1, 0.5, 0.25): sc = −rz = −0.25, tc = −ry = −0.5 → (0.375, 0.25). */
    static const struct { float r[3]; int face; float s, t; } cases[] = {
        {{1, 0.5f, 0.25f}, 0, 0.375f, 0.25f},
        {{-1, 0.5f, 0.25f}, 1, 0.625f, 0.25f},
        {{0.5f, 1, 0.25f}, 2, 0.75f, 0.625f},
        {{0.5f, -1, 0.25f}, 3, 0.75f, 0.375f},
        {{0.5f, 0.25f, 1}, 4, 0.75f, 0.375f},
        {{0.5f, 0.25f, -1}, 5, 0.25f, 0.375f},
        {{2, 2, 2}, 0, 0.0f, 0.0f}, /* ties: x over y over z */
        {{0, -3, 3}, 3, 0.5f, 0.0f},
    };
    int f, k;
    for (f = 0; f < 6; ++f) {
        sample_query3 q = q_dir(axes[f]);
        sample_query o;
        CHECK(ls_cube_query(&q, &o) == f && o.s == 0.5f && o.t == 0.5f, "axis %d", f);
    }
    for (k = 0; k < (int)(sizeof cases / sizeof cases[0]); ++k) {
        sample_query3 q = q_dir(cases[k].r);
        sample_query o;
        int got = ls_cube_query(&q, &o);
        CHECK(got == cases[k].face && o.s == cases[k].s && o.t == cases[k].t, "case %d: face %d (%g, %g)", k, got,
              o.s, o.t);
    }
}

/* Texel centres give the texel under NEAREST and LINEAR, on every face;
 * NEAREST at s = 1 clamps to the face's own edge texel. */
static void test_texel_centres(void)
{
    const int n = 4;
    sample_texture *tex = make_cube(n, NULL);
    sample_sampler s;
    int f, i, j, lin, c;
    sample_sampler_init(&s);
    for (lin = 0; lin < 2; ++lin) {
        s.mag_filter = s.min_filter = lin ? SAMPLE_LINEAR : SAMPLE_NEAREST;
        for (f = 0; f < 6; ++f)
            for (j = 0; j < n; ++j)
                for (i = 0; i < n; ++i) {
                    float r[3], out[4];
                    sample_query3 q;
                    face_dir(f, (i + 0.5) / n, (j + 0.5) / n, r);
                    q = q_dir(r);
                    one(tex, &s, &q, out, NULL);
                    for (c = 0; c < 4; ++c) CHECK_EQF(out[c], tval(f, i, j, c, n));
                }
    }
    sample_texture_destroy(tex);
}

/* The neighbour over each edge, by hand from table 8.19: LINEAR exactly
 * on an edge is the mean of the two texels across it; at a corner (the
 * direction (1, 1, 1)-like) the mean of the three texels that meet. */
static void test_edges_and_corners(void)
{
    const int n = 4;
    sample_texture *tex = make_cube(n, NULL);
    sample_sampler s;
    float out[4], r[3];
    sample_query3 q;
    int c;
    sample_sampler_init(&s);
    s.mag_filter = SAMPLE_LINEAR;
    /* +X face, s = 0 edge (sc = −1: rz = +1), at t of row 1's centre:
     * direction (1, −tc, 1) with tc = −0.25·… Its neighbour is +Z at its
     * s = 1 edge (rx = 1), same row (tc = −ry on both). */
    face_dir(0, 0.0, 1.5 / n, r);
    q = q_dir(r);
    one(tex, &s, &q, out, NULL);
    for (c = 0; c < 4; ++c) CHECK_EQF(out[c], 0.5f * (tval(0, 0, 1, c, n) + tval(4, n - 1, 1, c, n)));
    /* +Y face, t = 1 edge (tc = +1: rz = +1) at column 2's centre: its
     * neighbour is +Z at t = 0 (tc = −ry = −1), same column (sc = rx). */
    face_dir(2, 2.5 / n, 1.0, r);
    r[1] = 1.0f; /* ties go to y over z: on +Y */
    q = q_dir(r);
    one(tex, &s, &q, out, NULL);
    for (c = 0; c < 4; ++c) CHECK_EQF(out[c], 0.5f * (tval(2, 2, n - 1, c, n) + tval(4, 2, 0, c, n)));
    /* The corner (1, 1, 1): +X (tie winner) texel (0, 0) (sc = −rz, tc =
     * −ry), +Y texel (n−1, n−1) (sc = rx, tc = rz), +Z texel (n−1, 0).
     * The 2 × 2 block has its corner texel replaced by their mean, so the
     * result is that mean too. */
    r[0] = r[1] = r[2] = 1.0f;
    q = q_dir(r);
    one(tex, &s, &q, out, NULL);
    for (c = 0; c < 4; ++c)
        CHECK_NEAR(out[c], (tval(0, 0, 0, c, n) + tval(2, n - 1, n - 1, c, n) + tval(4, n - 1, 0, c, n)) / 3.0f,
                   1e-7);
    sample_texture_destroy(tex);
}

/* A constant cube gives the constant under every filter and footprint,
 * for every format and channel count, at random directions and
 * derivatives. */
static void test_constant(void)
{
    static const sample_format fmts[4] = {SAMPLE_FORMAT_F32, SAMPLE_FORMAT_F16, SAMPLE_FORMAT_UNORM8,
                                          SAMPLE_FORMAT_SRGB8};
    uint32_t seed = 7;
    int fi, nc, filt, fp, k;
    for (fi = 0; fi < 4; ++fi)
        for (nc = 1; nc <= 4; ++nc) {
            const int n = 5;
            unsigned char buf[5 * 5 * 4 * 4];
            sample_image faces[6];
            sample_mip_params mp;
            sample_texture *tex = NULL;
            float expect[4];
            size_t tb = (size_t)nc * sample_format_bytes(fmts[fi]);
            int f, i;
            for (i = 0; i < n * n; ++i) {
                float v[4] = {0.25f, 0.5f, 0.75f, 1.0f};
                if (fmts[fi] == SAMPLE_FORMAT_F32) memcpy(buf + i * tb, v, tb);
                else if (fmts[fi] == SAMPLE_FORMAT_F16) {
                    uint16_t h[4];
                    for (k = 0; k < 4; ++k) h[k] = sample_float_to_half(v[k]);
                    memcpy(buf + i * tb, h, tb);
                } else {
                    unsigned char b[4] = {64, 128, 191, 255};
                    memcpy(buf + i * tb, b, tb);
                }
            }
            for (f = 0; f < 6; ++f) faces[f] = (sample_image){n, n, nc, fmts[fi], buf, 0};
            sample_mip_params_init(&mp);
            mp.filter = (fi & 1) ? SAMPLE_MIPGEN_LANCZOS3 : SAMPLE_MIPGEN_BOX;
            CHECK(sample_texture_create_cube(faces, &mp, &tex, NULL) == SAMPLE_OK, "create %d %d", fi, nc);
            if (!tex) continue;
            sample_texture_texel_layer(tex, 0, 3, 1, 1, expect);
            for (filt = 0; filt < SAMPLE_FILTER_COUNT; ++filt)
                for (fp = 0; fp < SAMPLE_FOOTPRINT_COUNT; ++fp) {
                    sample_sampler s;
                    sample_query3 q[16];
                    float out[16][4];
                    sample_batch3_args a;
                    sample_sampler_init(&s);
                    s.min_filter = (sample_filter)filt;
                    s.mag_filter = filt == SAMPLE_NEAREST ? SAMPLE_NEAREST : (filt >= SAMPLE_CUBIC ? SAMPLE_CUBIC : SAMPLE_LINEAR);
                    s.footprint = (sample_footprint)fp;
                    s.max_anisotropy = 8.0f;
                    for (i = 0; i < 16; ++i) {
                        for (k = 0; k < 3; ++k) {
                            q[i].p[k] = 2.0f * rnd(&seed) - 1.0f;
                            q[i].dpdx[k] = (rnd(&seed) - 0.5f) * (float)(1 << (i % 5)) * 0.2f;
                            q[i].dpdy[k] = (rnd(&seed) - 0.5f) * 0.05f;
                        }
                    }
                    memset(&a, 0, sizeof a);
                    a.count = 16;
                    a.queries = q;
                    a.rgba = &out[0][0];
                    CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK, "batch");
                    for (i = 0; i < 16; ++i)
                        for (k = 0; k < 4; ++k)
                            CHECK_NEAR(out[i][k], expect[k], 2e-6 * (filt >= SAMPLE_CUBIC ? 2 : 1));
                }
            sample_texture_destroy(tex);
        }
}

int main(void)
{
    RUN(test_face_selection);
    RUN(test_texel_centres);
    RUN(test_edges_and_corners);
    RUN(test_constant);
    return check_finish();
}
