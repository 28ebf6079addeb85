/* Renderer shading: reflection formula, environment map indexing, the
 * lat-long seam, determinism across thread counts, bad scene files. */
#include "check.h"
#include "rn_internal.h"

#include <stdlib.h>

/* Blinn–Newell's formula for the eye on +z: R = (2 Xn Zn, 2 Yn Zn, 2 Zn² − 1). */
static void test_reflection_formula(void)
{
    const double N[3] = {0.48, 0.6, 0.64}, V[3] = {0, 0, 1};
    double R[3];
    env_reflect(N, V, R);
    CHECK_NEAR(R[0], 2 * 0.48 * 0.64, 1e-15);
    CHECK_NEAR(R[1], 2 * 0.6 * 0.64, 1e-15);
    CHECK_NEAR(R[2], 2 * 0.64 * 0.64 - 1, 1e-15);
}

static void test_latlong_mapping(void)
{
    static const double dirs[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    static const double want[6][2] = {{-1, 0}, {-1, 1}, {0, 0.5}, {0.25, 0.5}, {0.5, 0.5}, {0.75, 0.5}};
    double st[2], d[2][3];
    int k;
    for (k = 0; k < 6; ++k) {
        env_latlong(dirs[k], st, NULL);
        if (want[k][0] >= 0) CHECK_NEAR(st[0], want[k][0], 1e-15);
        CHECK_NEAR(st[1], want[k][1], 1e-15);
    }
    /* Just below azimuth 2π: s → 1 from below, continuous derivative. */
    {
        const double R[3] = {1, -1e-9, 0};
        env_latlong(R, st, d);
        CHECK(st[0] > 0.999999 && st[0] < 1.0, "s = %.17g", st[0]);
        CHECK_NEAR(d[0][1], 1.0 / (2 * RN_PI), 1e-12);
        CHECK_NEAR(d[1][2], -1.0 / RN_PI, 1e-12);
    }
}

/* The seam: a lookup exactly at azimuth 0 blends the last column and the
 * first (REPEAT on s), not the first column alone. */
static void test_latlong_seam_filtered(void)
{
    float px[8 * 4 * 4];
    sample_image img = {8, 4, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mip;
    rn_env e;
    render_hit h;
    sample_sampler smp;
    const double V[3] = {1, 0, 0}, zero[3] = {0, 0, 0};
    float out[4];
    int i, j, c;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 8; ++i)
            for (c = 0; c < 4; ++c) px[4 * (j * 8 + i) + c] = c == 3 ? 1.0f : i == 0 ? 1.0f : i == 7 ? 0.0f : 0.5f;
    memset(&e, 0, sizeof e);
    memset(&h, 0, sizeof h);
    sample_mip_params_init(&mip);
    mip.wrap_s = SAMPLE_WRAP_REPEAT;
    CHECK(sample_texture_create(&img, &mip, &e.map, NULL) == SAMPLE_OK, "texture");
    e.kind = RN_ENV_LATLONG;
    e.strength = 1.0f;
    v3_set(h.N, 1, 0, 0); /* N = V = +x: R = +x, s = 0, t = ½ */
    sample_sampler_init(&smp);
    smp.wrap_s = SAMPLE_WRAP_CLAMP_TO_EDGE; /* env_lookup must override it */
    env_lookup(&e, &smp, &h, V, zero, zero, out);
    CHECK_NEAR(out[0], 0.5, 1e-6);
    env_release(&e);
}

static void test_cube_faces(void)
{
    static const double R[3][3] = {{1, 0.2, 0.1}, {0.1, -0.9, 0.3}, {-0.2, 0.1, -0.7}};
    static const int face[3] = {0, 3, 5};
    /* By table 8.19: +X sc = −rz, tc = −ry; −Y sc = rx, tc = −rz; −Z sc = −rx, tc = −ry. */
    static const double st_want[3][2] = {{0.45, 0.4}, {0.5 * (0.1 / 0.9 + 1), 0.5 * (-0.3 / 0.9 + 1)},
                                         {0.5 * (0.2 / 0.7 + 1), 0.5 * (-0.1 / 0.7 + 1)}};
    double st[2], d[2][3];
    int k;
    for (k = 0; k < 3; ++k) {
        CHECK(env_cube(R[k], st, d) == face[k], "face of case %d", k);
        CHECK_NEAR(st[0], st_want[k][0], 1e-15);
        CHECK_NEAR(st[1], st_want[k][1], 1e-15);
    }
    /* +X: ds/dry = 0, ds/drz = −½/|rx|, ds/drx = −½ sc/rx². */
    env_cube(R[0], st, d);
    CHECK_NEAR(d[0][2], -0.5, 1e-15);
    CHECK_NEAR(d[0][0], -0.5 * -0.1, 1e-15);
}

static int render_bytes(int threads, float **out, int *n)
{
    render_scene *sc;
    render_options o;
    render_image img;
    char err[256];
    if (render_scene_builtin("teapot", 48, 40, &sc, err, sizeof err) != 0) return 0;
    render_options_init(&o);
    o.threads = threads;
    o.corners = 1;
    if (render_image_run(sc, &o, &img, err, sizeof err) != 0) {
        render_scene_destroy(sc);
        return 0;
    }
    *n = img.width * img.height * 4;
    *out = img.rgba;
    img.rgba = NULL;
    render_image_free(&img);
    render_scene_destroy(sc);
    return 1;
}

static void test_deterministic(void)
{
    float *a = NULL, *b = NULL, *c = NULL;
    int na = 0, nb = 0, nc = 0;
    CHECK(render_bytes(1, &a, &na) && render_bytes(2, &b, &nb) && render_bytes(3, &c, &nc), "renders");
    CHECK(na == 48 * 40 * 4 && na == nb && na == nc, "sizes");
    CHECK(a && b && c && memcmp(a, b, sizeof *a * (size_t)na) == 0, "1 vs 2 threads differ");
    CHECK(a && c && memcmp(a, c, sizeof *a * (size_t)na) == 0, "1 vs 3 threads differ");
    free(a);
    free(b);
    free(c);
}

static void test_bad_scenes(void)
{
    static const char *const bad[] = {
        "", "{", "[1]", "{}", "{\"objects\":3}",
        "{\"objects\":[{\"type\":\"sphere\",\"radius\":-1}]}",
        "{\"objects\":[{\"type\":\"torus\"}]}",
        "{\"camera\":{\"eye\":[0,0,0],\"look\":[0,0,0]},\"objects\":[{\"type\":\"sphere\"}]}",
        "{\"objects\":[{\"type\":\"sphere\",\"material\":\"nope\"}]}",
        "{\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],[2,0,0]],"
        "\"st\":[[0,0],[1,0],[2,0]]}]}]}",
        "{\"textures\":[{\"type\":\"checker\",\"size\":0}],\"objects\":[{\"type\":\"plane\"}]}",
        "{\"sampler\":{\"mag\":\"linear_mipmap_linear\"},\"objects\":[{\"type\":\"plane\"}]}",
    };
    size_t k;
    for (k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        render_scene *sc = (render_scene *)1;
        char err[256] = "";
        int r = render_scene_parse(bad[k], strlen(bad[k]), 0, 0, &sc, err, sizeof err);
        CHECK(r != 0 && sc == NULL && err[0], "bad scene %zu accepted (%s)", k, err);
    }
}

int main(void)
{
    RUN(test_reflection_formula);
    RUN(test_latlong_mapping);
    RUN(test_latlong_seam_filtered);
    RUN(test_cube_faces);
    RUN(test_deterministic);
    RUN(test_bad_scenes);
    return check_finish();
}
