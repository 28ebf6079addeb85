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

/* The world (z up) in the maps' frame (y up): a rotation, +z → +y. */
static void test_map_frame(void)
{
    static const double w[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    static const double m[3][3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    double r[3];
    int k, i;
    for (k = 0; k < 3; ++k) {
        env_to_map(w[k], r);
        for (i = 0; i < 3; ++i) CHECK(r[i] == m[k][i], "axis %d component %d: %g", k, i, r[i]);
    }
}

/* The seam: a lookup exactly on it (the map frame's −z, the world's +y)
 * blends the last column and the first, not the first column alone. */
static void test_latlong_seam_filtered(void)
{
    float px[8 * 4 * 4];
    sample_image img = {8, 4, 4, SAMPLE_FORMAT_F32, px, 0};
    rn_env e;
    render_hit h;
    sample_sampler smp;
    const double V[3] = {0, 1, 0}, zero[3] = {0, 0, 0};
    float out[4];
    int i, j, c;
    for (j = 0; j < 4; ++j)
        for (i = 0; i < 8; ++i)
            for (c = 0; c < 4; ++c) px[4 * (j * 8 + i) + c] = c == 3 ? 1.0f : i == 0 ? 1.0f : i == 7 ? 0.0f : 0.5f;
    memset(&e, 0, sizeof e);
    memset(&h, 0, sizeof h);
    CHECK(sample_texture_create(&img, NULL, &e.tex, NULL) == SAMPLE_OK, "texture");
    e.kind = RN_ENV_LATLONG;
    e.strength = 1.0f;
    v3_set(h.N, 0, 1, 0); /* N = V = +y: R = +y, the seam, t = ½ */
    sample_sampler_init(&smp);
    smp.wrap_s = SAMPLE_WRAP_CLAMP_TO_EDGE; /* not used by lat-long lookups */
    env_lookup(&e, &smp, &h, V, zero, zero, out);
    CHECK_NEAR(out[0], 0.5, 1e-6);
    env_release(&e);
}

/* A mirror's reflection across a cube map's face edge: an 8² cube of
 * random texels, the reflected direction swept across the edge between
 * +X and +Z (of the map's frame) in 200 steps of 0.015 texel, each lookup
 * filtered by a footprint about a quarter texel wide. Seamless, the result
 * moves by at most 0.05 a step; six separate clamped faces would jump by
 * the difference of two unrelated texels at the edge (about ⅓ on
 * average). */
static void test_cube_no_seam(void)
{
    float px[6 * 8 * 8 * 4];
    sample_image faces[6];
    rn_env e;
    render_hit h;
    sample_sampler smp;
    const double zero[3] = {0, 0, 0};
    float prev[4] = {0, 0, 0, 0}, out[4];
    double worst = 0;
    unsigned x = 12345u;
    int f, k, c;
    for (k = 0; k < 6 * 8 * 8 * 4; ++k) {
        x = x * 1664525u + 1013904223u;
        px[k] = (k & 3) == 3 ? 1.0f : (float)(x >> 8) / 16777216.0f;
    }
    for (f = 0; f < 6; ++f) {
        faces[f].width = faces[f].height = 8;
        faces[f].channels = 4;
        faces[f].format = SAMPLE_FORMAT_F32;
        faces[f].data = px + f * 8 * 8 * 4;
        faces[f].row_stride = 0;
    }
    memset(&e, 0, sizeof e);
    memset(&h, 0, sizeof h);
    CHECK(sample_texture_create_cube(faces, NULL, &e.tex, NULL) == SAMPLE_OK, "cube");
    e.kind = RN_ENV_CUBE;
    e.strength = 1.0f;
    sample_sampler_init(&smp);
    smp.min_filter = smp.mag_filter = SAMPLE_LINEAR;
    for (k = 0; k <= 200 && e.tex; ++k) {
        /* Map direction (1, 0.1, a) is world (1, −a, 0.1); with N = V the
         * reflection is V itself. The edge is at a = 1; a texel is ¼. */
        double a = 1.0 + (k - 100) * 0.015 / 4.0, V[3] = {1, -a, 0.1};
        v3_normalize(V);
        v3_copy(h.N, V);
        v3_set(h.dNdx, 0, -0.25 / 16.0, 0);
        v3_set(h.dNdy, 0, 0, 0.25 / 16.0);
        env_lookup(&e, &smp, &h, V, zero, zero, out);
        for (c = 0; k > 0 && c < 3; ++c)
            if (fabs((double)out[c] - prev[c]) > worst) worst = fabs((double)out[c] - prev[c]);
        memcpy(prev, out, sizeof prev);
    }
    printf("cube edge: the reflection moves at most %.4f a step\n", worst);
    CHECK(worst <= 0.05, "the reflection jumps by %.3f across the face edge", worst);
    env_release(&e);
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
    RUN(test_map_frame);
    RUN(test_latlong_seam_filtered);
    RUN(test_cube_no_seam);
    RUN(test_deterministic);
    RUN(test_bad_scenes);
    return check_finish();
}
