/*
 * Environment maps (doc/environment-maps.md). Cube maps (GL 4.6 §8.13):
 * face selection and (s, t) by table 8.19, λ from the face coordinates'
 * derivatives, seamless filtering across edges and corners (§8.13.1),
 * pyramids continuous across edges, every format, continuity of every
 * filter across edges and corners, and bad input (of lat-long maps too:
 * test_extreme_directions). The lat-long maps' own tests: test_latlong.c.
 */
#include "env_test.h"

#include "sample/testing.h"

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
    {
        /* (1, 0, −1): the x–z tie goes to +X, where sc = −rz = 1, s = 1:
         * u = n, which NEAREST clamps to texel n − 1 of +X (t = ½: row 2). */
        const float r[3] = {1.0f, 0.0f, -1.0f};
        sample_query3 q = q_dir(r);
        float out[4];
        s.mag_filter = SAMPLE_NEAREST;
        one(tex, &s, &q, out, NULL);
        for (c = 0; c < 4; ++c) CHECK_EQF(out[c], tval(0, n - 1, n / 2, c, n));
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

/* Every corner of the cube: LINEAR at the corner direction is the mean
 * of the three corner texels that meet there, each found from table 8.19
 * on its own face (s, t ∈ {0, 1} at the corner). */
static void test_all_corners(void)
{
    const int n = 4;
    sample_texture *tex = make_cube(n, NULL);
    sample_sampler s;
    int x, y, z, a, c;
    sample_sampler_init(&s);
    for (x = -1; x <= 1; x += 2)
        for (y = -1; y <= 1; y += 2)
            for (z = -1; z <= 1; z += 2) {
                float r[3] = {(float)x, (float)y, (float)z}, out[4], expect[4] = {0, 0, 0, 0};
                double d[3] = {x, y, z};
                sample_query3 q = q_dir(r);
                for (a = 0; a < 3; ++a) {
                    int f = 2 * a + (d[a] < 0.0);
                    double fs, ft;
                    cube_face_st(f, d, &fs, &ft);
                    for (c = 0; c < 4; ++c) expect[c] += tval(f, fs > 0.5 ? n - 1 : 0, ft > 0.5 ? n - 1 : 0, c, n);
                }
                one(tex, &s, &q, out, NULL);
                for (c = 0; c < 4; ++c) CHECK_NEAR(out[c], expect[c] / 3.0f, 2e-7);
            }
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

/* A constant cube under the footprint filters where their footprints
 * reach past a corner (read there by direction, blended with the unfolded
 * texels past an edge: env_addr.c, footprint_texel; anisotropic probes by
 * direction) gives the constant exactly: directions on the diagonal near
 * each of the 8 corners, footprints of 2 × ½, 3 × 3 and 6 × 1 texels. */
static void test_corner_constant(void)
{
    const int n = 8;
    static float d[6 * 8 * 8 * 4];
    const float v[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    static const double size[3][2] = {{2.0, 0.5}, {3.0, 3.0}, {6.0, 1.0}};
    sample_image faces[6];
    sample_mip_params mp;
    sample_texture *tex = NULL;
    int f, i, k, fi;
    for (i = 0; i < 6 * n * n; ++i) memcpy(d + 4 * i, v, sizeof v);
    for (f = 0; f < 6; ++f) faces[f] = (sample_image){n, n, 4, SAMPLE_FORMAT_F32, d + (size_t)f * n * n * 4, 0};
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create_cube(faces, &mp, &tex, NULL) == SAMPLE_OK, "create");
    for (fi = 0; fi < CONT_FILTERS; ++fi) {
        sample_sampler s;
        sample_query3 q[8 * 3 * 3];
        float out[8 * 3 * 3][4];
        sample_batch3_args a;
        int m = 0, e, z, w;
        if (cont_filters[fi].fp == SAMPLE_FOOTPRINT_NONE) continue;
        cont_sampler(fi, &s);
        for (e = 0; e < 8; ++e)
            for (z = 0; z < 3; ++z)
                for (w = 0; w < 3; ++w, ++m) {
                    /* Near corner e: (1, 1 − ε, 1 − ε)·signs, ε = 0, ¼, ½ texel. */
                    double c[3] = {(e & 1) ? -1 : 1, (e & 2) ? -1 : 1, (e & 4) ? -1 : 1}, eps = z * 0.25 * 2.0 / n;
                    for (k = 0; k < 3; ++k) {
                        q[m].p[k] = (float)(c[k] * (k == 0 ? 1.0 : 1.0 - eps));
                        /* dR/dx along (−2, 1, 1)·signs (across the corner), dR/dy along (0, 1, −1)·signs. */
                        q[m].dpdx[k] = (float)(c[k] * (k == 0 ? -2.0 : 1.0) / 2.449 * 2.0 * size[w][0] / n);
                        q[m].dpdy[k] = (float)(c[k] * (k == 0 ? 0.0 : (k == 1 ? 1.0 : -1.0)) / 1.414 * 2.0 * size[w][1] / n);
                    }
                }
        memset(&a, 0, sizeof a);
        a.count = (size_t)m;
        a.queries = q;
        a.rgba = &out[0][0];
        CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK, "batch");
        for (i = 0; i < m; ++i)
            for (k = 0; k < 4; ++k)
                CHECK(out[i][k] == v[k], "%s: query %d channel %d gives %.9g, not %g", cont_filters[fi].name, i, k,
                      out[i][k], v[k]);
    }
    sample_texture_destroy(tex);
}

/* λ for axis-aligned derivatives at a face centre (|ma| = 1): dR/dx =
 * (d, 0, 0) on +Z is ∂s/∂x = d/2, ρ = N·d/2; the switch from
 * magnification to level 1 at ρ = 1 and 2, and the ma term: along the
 * major axis at sc = ½, ∂s = −½·sc·∂ma, which an implementation that
 * drops the term sees as no footprint at all. */
static void test_lod(void)
{
    const int n = 16;
    sample_mip_params mp;
    sample_texture *tex;
    sample_sampler s;
    sample_stats st;
    float out[4];
    int k;
    sample_mip_params_init(&mp);
    tex = make_cube(n, &mp);
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    for (k = -2; k <= 4; ++k) {
        sample_query3 q;
        memset(&q, 0, sizeof q);
        q.p[2] = 1.0f;
        q.dpdx[0] = ldexpf(2.0f / n, k); /* ρ = 2^k */
        q.dpdy[1] = ldexpf(1.0f / n, k); /* half as long: ρ is the longer */
        one(tex, &s, &q, out, &st);
        CHECK(st.lod == (float)k, "λ %g, expected %d", st.lod, k);
        CHECK(st.level0 == (k <= 0 ? 0 : (k < 4 ? k : 4)) && (k <= 0 || k >= 4 ? st.level1 == -1 : 1), "k %d: levels %d %d", k,
              st.level0, st.level1);
        /* The same footprint with a bias of −k is magnification again. */
    }
    {
        /* ma term: R = (0.5, 0, 1) on +Z (sc = ½), dR/dx = (0, 0, δ):
         * ∂s/∂x = ½(0·1 − ½·δ)/1 = −δ/4, ∂t = 0; ρ = N·δ/4: δ = 8/N → λ = 1. */
        sample_query3 q;
        memset(&q, 0, sizeof q);
        q.p[0] = 0.5f;
        q.p[2] = 1.0f;
        q.dpdx[2] = 8.0f / n;
        one(tex, &s, &q, out, &st);
        CHECK(st.lod == 1.0f, "ma term: λ %g, expected 1", st.lod);
        /* R and its derivative scaled together: the same λ (s depends on
         * R/|ma| only). */
        q.p[0] = 2.0f;
        q.p[2] = 4.0f;
        q.dpdx[2] = 32.0f / n;
        one(tex, &s, &q, out, &st);
        CHECK(st.lod == 1.0f, "scaled: λ %g, expected 1", st.lod);
    }
    {
        /* Bias, clamps and base level as for 2D. */
        sample_query3 q;
        float bias = -1.0f;
        sample_batch3_args a;
        memset(&q, 0, sizeof q);
        q.p[2] = 1.0f;
        q.dpdx[0] = 8.0f / n; /* λ = 2 */
        memset(&a, 0, sizeof a);
        a.count = 1;
        a.queries = &q;
        a.lod_bias = &bias;
        a.rgba = out;
        a.stats = &st;
        CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK && st.lod == 1.0f, "bias: λ %g", st.lod);
        s.max_lod = 0.5f;
        CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK && st.lod == 0.5f, "max_lod: λ %g", st.lod);
        /* λ is in texels of the base level (4 × 4 at base 2): ρ = 4. */
        s.max_lod = 1000.0f;
        s.base_level = 2;
        s.min_filter = SAMPLE_LINEAR_MIPMAP_NEAREST;
        q.dpdx[0] = 32.0f / n;
        bias = 0.0f;
        CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK && st.level0 == 4, "base level 2, λ 2: level %d",
              st.level0);
    }
    sample_texture_destroy(tex);
}

/* DESIGN §10: NaN, infinite or zero directions, non-finite derivatives or
 * bias give the border colour; no level is read. */
static void test_bad_input(void)
{
    sample_texture *tex = make_cube(4, NULL), *flat;
    sample_sampler s;
    const float nan = NAN, inf = INFINITY;
    sample_query3 q[6];
    float out[6][4], bias[6] = {0, 0, 0, 0, 0, nan}, img[4] = {1, 1, 1, 1};
    sample_stats st[6];
    sample_batch3_args a;
    sample_image im = {1, 1, 4, SAMPLE_FORMAT_F32, img, 0};
    int i, c;
    sample_sampler_init(&s);
    s.border_color[0] = 0.25f;
    s.border_color[3] = 0.5f;
    memset(q, 0, sizeof q);
    for (i = 0; i < 6; ++i) q[i].p[2] = 1.0f;
    q[0].p[0] = nan;
    q[1].p[2] = 0.0f; /* zero direction */
    q[2].p[1] = inf;
    q[3].dpdx[0] = inf;
    q[4].dpdy[2] = nan;
    memset(&a, 0, sizeof a);
    a.count = 6;
    a.queries = q;
    a.lod_bias = bias;
    a.rgba = &out[0][0];
    a.stats = st;
    CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_OK, "batch");
    for (i = 0; i < 6; ++i) {
        for (c = 0; c < 4; ++c) CHECK_EQF(out[i][c], s.border_color[c]);
        CHECK(st[i].level0 == -1 && st[i].texels == 0, "query %d read level %d", i, st[i].level0);
    }
    /* Kinds: a 2D texture is refused by sample_batch_cube, a cube by
     * sample_batch; NULLs too. */
    CHECK(sample_texture_create(&im, NULL, &flat, NULL) == SAMPLE_OK, "2D texture");
    CHECK(sample_batch_cube(flat, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "2D texture accepted by sample_batch_cube");
    {
        sample_query q2 = {0.5f, 0.5f, 0, 0, 0, 0};
        CHECK(sample_one(tex, &s, &q2, out[0]) == SAMPLE_E_INVALID_ARGUMENT, "cube accepted by sample_batch");
    }
    CHECK(sample_batch_cube(NULL, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "NULL texture");
    a.queries = NULL;
    CHECK(sample_batch_cube(tex, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "NULL queries");
    sample_texture_destroy(flat);
    sample_texture_destroy(tex);
}

/* Finite directions and derivatives of any magnitude (FLT_MAX, 1e-45,
 * denormals, −0) give finite results within the texel cap, on cube and
 * lat-long maps, under every footprint filter. */
static void test_extreme_directions(void)
{
    static const float mags[] = {FLT_MAX, 1e30f, 1.0f, 1e-30f, 1e-45f, 0.0f, -0.0f};
    const int nm = (int)(sizeof mags / sizeof mags[0]);
    sample_mip_params mp;
    sample_texture *cube, *ll;
    uint32_t seed = 1;
    int fp, i, k, c, kind;
    sample_mip_params_init(&mp);
    cube = make_cube(8, &mp);
    ll = make_latlong();
    for (kind = 0; kind < 2; ++kind)
        for (fp = 0; fp < SAMPLE_FOOTPRINT_COUNT; ++fp) {
            sample_sampler s;
            sample_query3 q[64];
            float out[64][4];
            sample_stats st[64];
            sample_batch3_args a;
            sample_sampler_init(&s);
            s.min_filter = SAMPLE_CUBIC_MIPMAP_LINEAR;
            s.mag_filter = SAMPLE_CUBIC;
            s.footprint = (sample_footprint)fp;
            s.max_anisotropy = 16.0f;
            for (i = 0; i < 64; ++i)
                for (k = 0; k < 3; ++k) {
                    float sg = (rnd_u32_of(&seed) & 1) ? -1.0f : 1.0f;
                    q[i].p[k] = sg * mags[rnd_u32_of(&seed) % nm] * rnd(&seed);
                    q[i].dpdx[k] = mags[rnd_u32_of(&seed) % nm] * (rnd(&seed) - 0.5f);
                    q[i].dpdy[k] = mags[rnd_u32_of(&seed) % nm] * (rnd(&seed) - 0.5f);
                }
            memset(&a, 0, sizeof a);
            a.count = 64;
            a.queries = q;
            a.rgba = &out[0][0];
            a.stats = st;
            CHECK((kind ? sample_batch_latlong(ll, &s, &a) : sample_batch_cube(cube, &s, &a)) == SAMPLE_OK, "batch");
            for (i = 0; i < 64; ++i) {
                for (c = 0; c < 4; ++c) CHECK(isfinite(out[i][c]), "kind %d fp %d query %d: %g", kind, fp, i, out[i][c]);
                CHECK(st[i].texels <= SAMPLE_MAX_FOOTPRINT_TEXELS + 64, "kind %d fp %d: %u texels", kind, fp,
                      st[i].texels);
            }
        }
    sample_texture_destroy(cube);
    sample_texture_destroy(ll);
}

/* Creation: faces must be square, equal, of one format; levels checked;
 * nothing is returned on error, with a message naming the face. */
static void test_create_errors(void)
{
    float d[4 * 4 * 4] = {0};
    sample_image faces[12];
    sample_texture *tex = (sample_texture *)&tex;
    sample_error err;
    int f;
    for (f = 0; f < 12; ++f) faces[f] = (sample_image){4, 4, 4, SAMPLE_FORMAT_F32, d, 0};
    faces[3].width = 2;
    CHECK(sample_texture_create_cube(faces, NULL, &tex, &err) == SAMPLE_E_BAD_SIZE && !tex &&
              strstr(err.message, "-Y"),
          "unequal face: %s", err.message);
    faces[3].width = 4;
    faces[0].height = 2;
    faces[0].width = 2;
    CHECK(sample_texture_create_cube(faces, NULL, &tex, &err) == SAMPLE_E_BAD_SIZE, "face 0 smaller: accepted");
    faces[0].width = 4;
    faces[0].height = 4;
    faces[5].channels = 3;
    CHECK(sample_texture_create_cube(faces, NULL, &tex, &err) == SAMPLE_E_INVALID_ARGUMENT, "channels: %s",
          err.message);
    faces[5].channels = 4;
    CHECK(sample_texture_create_cube(NULL, NULL, &tex, &err) == SAMPLE_E_INVALID_ARGUMENT, "NULL faces");
    /* Levels: level 1 must be 2 × 2. */
    for (f = 6; f < 12; ++f) faces[f].width = faces[f].height = 2;
    faces[8].width = 3;
    CHECK(sample_texture_create_cube_levels(faces, 2, &tex, &err) == SAMPLE_E_BAD_SIZE, "level 1 face 2: %s",
          err.message);
    faces[8].width = 2;
    CHECK(sample_texture_create_cube_levels(faces, 2, &tex, &err) == SAMPLE_OK && tex, "two levels: %s",
          err.message);
    sample_texture_destroy(tex);
    CHECK(sample_texture_create_cube_levels(faces, 4, &tex, &err) == SAMPLE_E_BAD_SIZE, "4 levels of a 4-cube");
}

/* Pyramids. The box on even faces stays inside each face: every face of
 * every level is that face's 2D box pyramid, bit for bit. A kernel that
 * reaches over edges (Lanczos-3, odd size) reads the neighbours: a cube
 * lit on +X only puts energy into level 1 of the four faces around it,
 * and a constant cube stays constant on every level. */
static void test_pyramids(void)
{
    const int n = 8;
    sample_mip_params mp;
    sample_texture *cube;
    int f, k, i, j, c;
    sample_mip_params_init(&mp);
    cube = make_cube(n, &mp);
    for (f = 0; f < 6; ++f) {
        float *d = (float *)malloc((size_t)n * n * 4 * sizeof(float));
        sample_image im = {n, n, 4, SAMPLE_FORMAT_F32, d, 0};
        sample_texture *flat;
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i)
                for (c = 0; c < 4; ++c) d[(j * n + i) * 4 + c] = tval(f, i, j, c, n);
        CHECK(sample_texture_create(&im, &mp, &flat, NULL) == SAMPLE_OK, "2D");
        for (k = 1; k < 4; ++k)
            for (j = 0; j < n >> k; ++j)
                for (i = 0; i < n >> k; ++i) {
                    float a[4], b[4];
                    sample_texture_texel_layer(cube, k, f, i, j, a);
                    sample_texture_texel(flat, k, i, j, b);
                    CHECK(!memcmp(a, b, sizeof a), "face %d level %d texel %d %d", f, k, i, j);
                }
        sample_texture_destroy(flat);
        free(d);
    }
    sample_texture_destroy(cube);
    {
        const int m = 9;
        float d[6][9 * 9];
        sample_image faces[6];
        sample_texture *t;
        float v[4];
        for (f = 0; f < 6; ++f) {
            for (i = 0; i < m * m; ++i) d[f][i] = f == 0 ? 1.0f : 0.0f;
            faces[f] = (sample_image){m, m, 1, SAMPLE_FORMAT_F32, d[f], 0};
        }
        mp.filter = SAMPLE_MIPGEN_LANCZOS3;
        CHECK(sample_texture_create_cube(faces, &mp, &t, NULL) == SAMPLE_OK, "lanczos cube");
        /* +X's neighbours: +Y, −Y, +Z, −Z; −X is opposite and stays dark
         * at level 1 (the kernel reaches 3 · 9/4 texels, less than a face). */
        for (f = 2; f < 6; ++f) {
            float sum = 0.0f;
            for (j = 0; j < 4; ++j)
                for (i = 0; i < 4; ++i) {
                    sample_texture_texel_layer(t, 1, f, i, j, v);
                    sum += fabsf(v[0]);
                }
            CHECK(sum > 0.01f, "face %d got %g from +X", f, sum);
        }
        sample_texture_texel_layer(t, 1, 1, 0, 0, v);
        CHECK(v[0] == 0.0f, "-X got %g", v[0]);
        sample_texture_destroy(t);
        for (f = 0; f < 6; ++f)
            for (i = 0; i < m * m; ++i) d[f][i] = 0.625f;
        CHECK(sample_texture_create_cube(faces, &mp, &t, NULL) == SAMPLE_OK, "constant lanczos cube");
        for (k = 0; k < 3; ++k)
            for (f = 0; f < 6; ++f)
                for (j = 0; j < (m >> k ? m >> k : 1); ++j)
                    for (i = 0; i < (m >> k ? m >> k : 1); ++i) {
                        sample_texture_texel_layer(t, k, f, i, j, v);
                        CHECK_NEAR(v[0], 0.625f, 1e-6);
                    }
        sample_texture_destroy(t);
    }
}

/* Inside a face every filter is the 2D filter of that face: a query whose
 * footprint stays inside face f gives, bit for bit, what the reference
 * path gives for a 2D texture holding face f (same pyramid, same (s, t)
 * and Jacobian), so the footprint filters' in-face spans read face f. */
static void test_face_interior(void)
{
    const int n = 32;
    sample_mip_params mp;
    sample_texture *cube, *flat;
    float *d = (float *)malloc((size_t)n * n * 4 * sizeof(float));
    sample_image im = {n, n, 4, SAMPLE_FORMAT_F32, d, 0};
    uint32_t seed = 5;
    int f, fp, i, j, c;
    sample_mip_params_init(&mp);
    cube = make_cube(n, &mp);
    for (f = 0; f < 6; f += 5) {
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i)
                for (c = 0; c < 4; ++c) d[(j * n + i) * 4 + c] = tval(f, i, j, c, n);
        CHECK(sample_texture_create(&im, &mp, &flat, NULL) == SAMPLE_OK, "2D");
        for (fp = 0; fp < SAMPLE_FOOTPRINT_COUNT; ++fp) {
            sample_sampler s;
            sample_query3 q3[32];
            sample_query q2[32];
            float a[32][4], b[32][4];
            sample_batch3_args a3;
            sample_batch_args a2;
            sample_sampler_init(&s);
            s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
            s.footprint = (sample_footprint)fp;
            s.max_anisotropy = 8.0f;
            for (i = 0; i < 32; ++i) {
                double r[3], dx[3], dy[3];
                int k;
                cube_direction(f, 0.5 * (rnd(&seed) - 0.5), 0.5 * (rnd(&seed) - 0.5), r);
                for (k = 0; k < 3; ++k) {
                    dx[k] = (rnd(&seed) - 0.5) * 0.2;
                    dy[k] = (rnd(&seed) - 0.5) * 0.05;
                    q3[i].p[k] = (float)r[k];
                    q3[i].dpdx[k] = (float)dx[k];
                    q3[i].dpdy[k] = (float)dy[k];
                }
                CHECK(ls_cube_query(&q3[i], &q2[i]) == f, "face");
            }
            memset(&a3, 0, sizeof a3);
            a3.count = 32;
            a3.queries = q3;
            a3.rgba = &a[0][0];
            memset(&a2, 0, sizeof a2);
            a2.count = 32;
            a2.queries = q2;
            a2.rgba = &b[0][0];
            CHECK(sample_batch_cube(cube, &s, &a3) == SAMPLE_OK && sample_batch_reference(flat, &s, &a2) == SAMPLE_OK,
                  "batches");
            CHECK(!memcmp(a, b, sizeof a), "face %d footprint %d: cube and 2D differ", f, fp);
        }
        sample_texture_destroy(flat);
    }
    free(d);
    sample_texture_destroy(cube);
}

/* ---- Continuity across edges and corners ---------------------------------- */


/* Largest change of any channel between consecutive queries along the
 * path R(τ) = a + τ·(b − a), τ ∈ [0, 1] in `steps` steps, with a
 * footprint of `fx` × `fy` texels (dR/dx, dR/dy across the path, scaled
 * by |R|, on a face of n texels: ∂s ≈ ½·|dR|/|R|). */
static double path_jump(const sample_texture *tex, const sample_sampler *smp, const double a[3], const double b[3],
                        int steps, int n, double fx, double fy)
{
    static sample_query3 q[1024];
    static float out[1024][4];
    sample_batch3_args args;
    double jump = 0.0;
    int i, k;
    for (i = 0; i <= steps; ++i) {
        double tau = (double)i / steps, r[3], len = 0.0, u[3], v[3], ul = 0.0, vl = 0.0;
        for (k = 0; k < 3; ++k) {
            r[k] = a[k] + tau * (b[k] - a[k]);
            len += r[k] * r[k];
        }
        len = sqrt(len);
        /* u: the path's direction made orthogonal to R; v = R × u. */
        for (k = 0; k < 3; ++k) u[k] = b[k] - a[k];
        {
            double d = (u[0] * r[0] + u[1] * r[1] + u[2] * r[2]) / (len * len);
            for (k = 0; k < 3; ++k) u[k] -= d * r[k];
        }
        v[0] = r[1] * u[2] - r[2] * u[1];
        v[1] = r[2] * u[0] - r[0] * u[2];
        v[2] = r[0] * u[1] - r[1] * u[0];
        for (k = 0; k < 3; ++k) {
            ul += u[k] * u[k];
            vl += v[k] * v[k];
        }
        ul = sqrt(ul);
        vl = sqrt(vl);
        for (k = 0; k < 3; ++k) {
            q[i].p[k] = (float)r[k];
            q[i].dpdx[k] = (float)(u[k] / ul * len * 2.0 * fx / n);
            q[i].dpdy[k] = (float)(v[k] / vl * len * 2.0 * fy / n);
        }
    }
    memset(&args, 0, sizeof args);
    args.count = (size_t)steps + 1;
    args.queries = q;
    args.rgba = &out[0][0];
    CHECK(sample_batch_cube(tex, smp, &args) == SAMPLE_OK, "batch");
    {
        int wi = 0;
        for (i = 1; i <= steps; ++i)
            for (k = 0; k < 4; ++k) {
                double d = fabs((double)out[i][k] - (double)out[i - 1][k]);
                if (d > jump) jump = d, wi = i;
            }
        if (getenv("TEST_CUBE_VERBOSE") && jump > 0.05) {
            sample_query o0, o1;
            int f0 = ls_cube_query(&q[wi - 1], &o0), f1 = ls_cube_query(&q[wi], &o1);
            printf("  step %.4f at %d: face %d (%.4f %.4f) -> %d (%.4f %.4f), footprint %g x %g\n", jump, wi, f0,
                   o0.s, o0.t, f1, o1.s, o1.t, fx, fy);
        }
    }
    return jump;
}

/* Random texels in [0, 1] (so that a seam, which would pair unrelated
 * texels, jumps by about ⅓ on average): along paths across each of the 12
 * edges, at its middle and 0.6 of the way to a corner, 3 texels of path
 * in 200 steps (0.015 texel a step), every filter changes by at most
 * CONT_BOUND (env_test.h) a step.
 * Through each of the 8 corners (along the diagonal,
 * the worst way through) each filter stays within its corner_bound. Both
 * with a 2 × ½-texel and a 0.3-texel footprint. */
static void test_continuity(void)
{
    const int n = 16;
    uint32_t seed = 99;
    float *d = (float *)malloc((size_t)6 * n * n * 4 * sizeof(float));
    sample_image faces[6];
    sample_mip_params mp;
    sample_texture *tex = NULL;
    int f, i, e, fi;
    double worst[CONT_FILTERS] = {0}, corner[CONT_FILTERS] = {0};
    for (i = 0; i < 6 * n * n * 4; ++i) d[i] = rnd(&seed);
    for (f = 0; f < 6; ++f) faces[f] = (sample_image){n, n, 4, SAMPLE_FORMAT_F32, d + (size_t)f * n * n * 4, 0};
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create_cube(faces, &mp, &tex, NULL) == SAMPLE_OK, "create");
    free(d);
    for (fi = 0; fi < CONT_FILTERS; ++fi) {
        sample_sampler s;
        cont_sampler(fi, &s);
        /* The 12 edges: between axes x, y, z with signs; the path crosses
         * the edge at its midpoint and at 0.6 of the way to a corner,
         * where the unfolded neighbour is sheared against its own
         * coordinates (1.5 texels of the face each side). */
        for (e = 0; e < 24; ++e) {
            int ax = (e % 12) / 4, sg1 = (e & 1) ? -1 : 1, sg2 = (e & 2) ? -1 : 1, ay = (ax + 1) % 3;
            double a[3] = {0, 0, 0}, b[3] = {0, 0, 0}, off = 1.5 * 2.0 / n;
            a[ax] = sg1;
            a[ay] = sg2 * (1.0 - off);
            b[ax] = sg1 * (1.0 - off);
            b[ay] = sg2;
            a[(ax + 2) % 3] = b[(ax + 2) % 3] = e < 12 ? 0.0 : 0.6 * sg1;
            /* 1.5 texels either side: from (1, 1 − off) to (1 − off, 1). */
            worst[fi] = fmax(worst[fi], path_jump(tex, &s, a, b, 200, n, 2.0, 0.5));
            /* The 0.3-texel footprint magnifies (every filter reads
             * LINEAR's 2 × 2 block): crossed at the middle only. */
            if (e < 12) worst[fi] = fmax(worst[fi], path_jump(tex, &s, a, b, 200, n, 0.3, 0.3));
        }
        /* The 8 corners: from inside face x across the corner into the
         * region between the other two faces. */
        for (e = 0; e < 8; ++e) {
            double c[3] = {(e & 1) ? -1 : 1, (e & 2) ? -1 : 1, (e & 4) ? -1 : 1}, a[3], b[3], off = 1.5 * 2.0 / n;
            int k;
            for (k = 0; k < 3; ++k) {
                a[k] = c[k] * (k == 0 ? 1.0 : 1.0 - off);
                b[k] = c[k] * (k == 0 ? 1.0 - off : 1.0);
            }
            corner[fi] = fmax(corner[fi], path_jump(tex, &s, a, b, 200, n, 2.0, 0.5));
            corner[fi] = fmax(corner[fi], path_jump(tex, &s, a, b, 200, n, 0.3, 0.3));
        }
        CHECK(worst[fi] <= CONT_BOUND, "%s: a step of %g across an edge", cont_filters[fi].name, worst[fi]);
        CHECK(corner[fi] <= cont_filters[fi].corner_bound, "%s: a step of %g through a corner",
              cont_filters[fi].name, corner[fi]);
        if (getenv("TEST_CUBE_VERBOSE"))
            printf("continuity %s: max step %.4f across edges, %.4f through corners\n", cont_filters[fi].name,
                   worst[fi], corner[fi]);
    }
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(test_face_selection);
    RUN(test_texel_centres);
    RUN(test_edges_and_corners);
    RUN(test_all_corners);
    RUN(test_constant);
    RUN(test_corner_constant);
    RUN(test_lod);
    RUN(test_bad_input);
    RUN(test_extreme_directions);
    RUN(test_create_errors);
    RUN(test_pyramids);
    RUN(test_face_interior);
    RUN(test_continuity);
    return check_finish();
}
