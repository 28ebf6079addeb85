/*
 * The texture system's other kinds and opens (doc/texture-system.md, "Cube
 * maps and volumes", "Colour spaces"), and bench's working set larger than
 * the cache:
 *   - a cube map file (sample_io_write_env) opens as SAMPLE_TEXTURE_CUBE
 *     and a lat-long one as 2D, a multi-page TIFF volume (oiiotool) as
 *     SAMPLE_TEXTURE_3D; sample_batch_env / sample_batch_3d on random
 *     queries give the bits of the textures sample_io_read_env and
 *     sample_io_read_volume make (memcmp), for several filters;
 *   - sample_texsys_open_colorspace: one file as colour and as "data" is
 *     two textures with the texels sample_io_read_texture gives each way;
 *     an unknown colour space is refused;
 *   - `texsample bench --textures` runs (two small files, a cache smaller
 *     than their working set) and prints both sides' tiles read.
 * Arguments: testimages dir, scratch dir, texsample (may be ""), oiiotool
 * (may be "": the volume part is skipped).
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "sample/sample_io.h"
#include "sample/texsys.h"

#include <stdint.h>

static const char *images, *dir, *texsample, *oiiotool;

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static float unit(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (float)(rng >> 40) / 16777216.0f;
}

static int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

/* n random directions with footprints from a tenth of a texel to many. */
static void random_dirs(sample_query3 *q, int n)
{
    int k, c;
    for (k = 0; k < n; ++k) {
        float scale = 0.002f * (1.0f + 60.0f * unit() * unit());
        for (c = 0; c < 3; ++c) {
            q[k].p[c] = 2.0f * unit() - 1.0f;
            q[k].dpdx[c] = scale * (2.0f * unit() - 1.0f);
            q[k].dpdy[c] = scale * (2.0f * unit() - 1.0f);
        }
    }
}

/* Random points in the unit cube with small footprints. */
static void random_points(sample_query3 *q, int n)
{
    int k, c;
    for (k = 0; k < n; ++k) {
        float scale = 0.02f + 0.3f * unit() * unit();
        for (c = 0; c < 3; ++c) {
            q[k].p[c] = unit();
            q[k].dpdx[c] = scale * (2.0f * unit() - 1.0f);
            q[k].dpdy[c] = scale * (2.0f * unit() - 1.0f);
        }
    }
}

typedef sample_status (*batch3_fn)(const sample_texture *, const sample_sampler *, const sample_batch3_args *);

/* The same queries through both textures, for nearest, trilinear and
 * anisotropic filtering: the same bytes. */
static void same_bits(const char *what, batch3_fn fn, const sample_texture *a, const sample_texture *b,
                      const sample_query3 *q, int n)
{
    static const sample_filter mins[] = {SAMPLE_NEAREST, SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR_MIPMAP_LINEAR};
    float *ra = malloc(sizeof(float) * 4 * (size_t)n), *rb = malloc(sizeof(float) * 4 * (size_t)n);
    int f;
    for (f = 0; ra && rb && f < 3; ++f) {
        sample_sampler s;
        sample_batch3_args x;
        sample_status sa, sb;
        sample_sampler_init(&s);
        s.min_filter = mins[f];
        s.mag_filter = f ? SAMPLE_LINEAR : SAMPLE_NEAREST;
        if (f == 2) s.max_anisotropy = 16.0f;
        memset(&x, 0, sizeof x);
        x.count = (size_t)n;
        x.queries = q;
        x.rgba = ra;
        sa = fn(a, &s, &x);
        x.rgba = rb;
        sb = fn(b, &s, &x);
        CHECK(sa == SAMPLE_OK && sb == SAMPLE_OK, "%s: filter %d: %d, %d", what, f, (int)sa, (int)sb);
        CHECK(memcmp(ra, rb, sizeof(float) * 4 * (size_t)n) == 0, "%s: filter %d: results differ", what, f);
    }
    free(ra);
    free(rb);
}

static void check_kind(sample_texsys *sys, const sample_texture *t, sample_texture_kind kind, const char *what)
{
    sample_texsys_info info;
    sample_error e;
    CHECK(sample_texsys_texture_info(sys, t, &info, &e) == SAMPLE_OK, "%s: %s", what, e.message);
    CHECK(info.texture.kind == kind, "%s: kind %d, not %d", what, (int)info.texture.kind, (int)kind);
}

static void test_env(void)
{
    enum { N = 16, Q = 512 };
    sample_image faces[6];
    float *px = malloc(sizeof(float) * 4 * N * N * 6), *ll = malloc(sizeof(float) * 4 * 64 * 32);
    sample_texture *cube = NULL, *latlong = NULL, *rc = NULL, *rl = NULL;
    const sample_texture *tc = NULL, *tl = NULL, *again = NULL;
    sample_texsys_options o;
    sample_texsys *sys = NULL;
    sample_mip_params mip;
    sample_query3 q[Q];
    sample_image img;
    sample_error e;
    char pc[512], pl[512];
    int k;
    if (!px || !ll) {
        CHECK(0, "out of memory");
        free(px), free(ll);
        return;
    }
    for (k = 0; k < 4 * N * N * 6; ++k) px[k] = unit();
    for (k = 0; k < 4 * 64 * 32; ++k) ll[k] = 2.0f * unit();
    for (k = 0; k < 6; ++k) {
        faces[k].width = faces[k].height = N;
        faces[k].channels = 4;
        faces[k].format = SAMPLE_FORMAT_F32;
        faces[k].data = px + (size_t)k * 4 * N * N;
        faces[k].row_stride = 0;
    }
    img.width = 64;
    img.height = 32;
    img.channels = 4;
    img.format = SAMPLE_FORMAT_F32;
    img.data = ll;
    img.row_stride = 0;
    sample_mip_params_init(&mip);
    snprintf(pc, sizeof pc, "%s/cube.exr", dir);
    snprintf(pl, sizeof pl, "%s/latlong.exr", dir);
    CHECK(sample_texture_create_cube(faces, &mip, &cube, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texture_create(&img, &mip, &latlong, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(cube && sample_io_write_env(pc, cube, NULL, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(latlong && sample_io_write_env(pl, latlong, NULL, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_io_read_env(pc, NULL, &mip, &rc, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_io_read_env(pl, NULL, &mip, &rl, &e) == SAMPLE_OK, "%s", e.message);
    sample_texsys_options_init(&o);
    o.max_memory_mb = 0.01; /* the lat-long map's tiles are evicted as it is read */
    CHECK(sample_texsys_create(&o, &sys, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texsys_open(sys, pc, &tc, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texsys_open(sys, pl, &tl, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texsys_open(sys, pc, &again, &e) == SAMPLE_OK && again == tc, "the cube opens once");
    if (rc) {
        sample_texsys_stats st;
        sample_texture_info ri;
        sample_texsys_stats_get(sys, &st);
        sample_texture_info_get(rc, &ri);
        CHECK(st.held_memory == ri.bytes, "held %zu bytes, the cube has %zu", st.held_memory, ri.bytes);
    }
    {
        /* An N x 6N picture that does not say it is a cube map stays 2D. */
        const sample_texture *strip = NULL;
        char ps[512];
        snprintf(ps, sizeof ps, "%s/strip.exr", dir);
        CHECK(sample_io_write_image(ps, px, N, 6 * N, 4, NULL, &e) == SAMPLE_OK, "%s", e.message);
        CHECK(sample_texsys_open(sys, ps, &strip, &e) == SAMPLE_OK, "%s", e.message);
        if (strip) check_kind(sys, strip, SAMPLE_TEXTURE_2D, "unnamed strip");
    }
    random_dirs(q, Q);
    if (tc && rc) {
        check_kind(sys, tc, SAMPLE_TEXTURE_CUBE, "cube");
        same_bits("cube", sample_batch_env, rc, tc, q, Q);
    }
    if (tl && rl) {
        check_kind(sys, tl, SAMPLE_TEXTURE_2D, "lat-long");
        same_bits("lat-long", sample_batch_env, rl, tl, q, Q);
    }
    sample_texsys_destroy(sys);
    sample_texture_destroy(cube);
    sample_texture_destroy(latlong);
    sample_texture_destroy(rc);
    sample_texture_destroy(rl);
    free(px);
    free(ll);
}

static void test_volume(void)
{
    enum { Q = 512 };
    char cmd[2048], path[512];
    sample_texture *rv = NULL;
    const sample_texture *tv = NULL;
    sample_texsys *sys = NULL;
    sample_mip_params mip;
    sample_query3 q[Q];
    sample_error e;
    if (!*oiiotool) {
        check_skip("oiiotool was not found (OpenImageIO's tools)");
        return;
    }
    snprintf(path, sizeof path, "%s/vol.tif", dir);
    snprintf(cmd, sizeof cmd,
             "'%s' --pattern noise:type=uniform:seed=1 8x4 3 --pattern noise:type=uniform:seed=2 8x4 3 "
             "--pattern noise:type=uniform:seed=3 8x4 3 --siappendall -d float -o '%s'",
             oiiotool, path);
    CHECK(exit_code(system(cmd)) == 0, "%s failed", cmd);
    sample_mip_params_init(&mip);
    CHECK(sample_io_read_volume(path, &mip, &rv, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texsys_create(NULL, &sys, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texsys_open(sys, path, &tv, &e) == SAMPLE_OK, "%s", e.message);
    random_points(q, Q);
    if (rv && tv) {
        check_kind(sys, tv, SAMPLE_TEXTURE_3D, "volume");
        same_bits("volume", sample_batch_3d, rv, tv, q, Q);
    }
    sample_texsys_destroy(sys);
    sample_texture_destroy(rv);
}

/* rgb8.png decoded by rule (sRGB) and as data: two textures, each with the
 * texels of sample_io_read_texture told the same. */
static void test_colorspace(void)
{
    static const char *const spaces[2] = {NULL, "data"};
    const sample_texture *t[2] = {NULL, NULL};
    sample_texsys *sys = NULL;
    sample_error e;
    char path[512];
    int k;
    snprintf(path, sizeof path, "%s/rgb8.png", images);
    CHECK(sample_texsys_create(NULL, &sys, &e) == SAMPLE_OK, "%s", e.message);
    for (k = 0; k < 2; ++k) {
        sample_io_options o;
        sample_texture *whole = NULL;
        float a[4], b[4];
        CHECK(sample_texsys_open_colorspace(sys, path, spaces[k], &t[k], &e) == SAMPLE_OK, "%s", e.message);
        sample_io_options_init(&o);
        o.colorspace = spaces[k];
        CHECK(sample_io_read_texture(path, &o, NULL, &whole, &e) == SAMPLE_OK, "%s", e.message);
        if (!t[k] || !whole) continue;
        sample_texture_texel(t[k], 0, 5, 7, a);
        sample_texture_texel(whole, 0, 5, 7, b);
        CHECK(memcmp(a, b, sizeof a) == 0, "%s: texel %g, whole %g", spaces[k] ? spaces[k] : "rule", a[0], b[0]);
        sample_texture_destroy(whole);
    }
    CHECK(t[0] && t[1] && t[0] != t[1], "colour and data are two textures");
    CHECK(sample_texsys_open_colorspace(sys, path, "no such space", &t[0], &e) == SAMPLE_E_COLOR,
          "an unknown colour space is refused");
    sample_texsys_destroy(sys);
}

static void test_bench(void)
{
    char cmd[2048], out[512], line[512];
    int rows = 0, tiles = 0;
    FILE *f;
    if (!*texsample) {
        check_skip("texsample is not built");
        return;
    }
    snprintf(out, sizeof out, "%s/bench.txt", dir);
    snprintf(cmd, sizeof cmd,
             "'%s' bench --textures 2 --texsize 128 --cache-mb 0.1 --queries 1024 --runs 1 --threads 2 "
             "--tmpdir '%s' > '%s'",
             texsample, dir, out);
    CHECK(exit_code(system(cmd)) == 0, "%s failed", cmd);
    if ((f = fopen(out, "r")) != NULL) {
        while (fgets(line, sizeof line, f)) {
            rows += strncmp(line, "| trilinear | ", 14) == 0 && strstr(line, " x) | ") != NULL;
            tiles += strstr(line, "ours tiles/run") && strstr(line, "OIIO tiles/run");
        }
        fclose(f);
    }
    CHECK(rows == 2 && tiles == 1, "bench --textures printed %d rows, %d headers", rows, tiles);
}

int main(int argc, char **argv)
{
    if (argc < 5) return 2;
    images = argv[1];
    dir = argv[2];
    texsample = argv[3];
    oiiotool = argv[4];
    RUN(test_env);
    RUN(test_volume);
    RUN(test_colorspace);
    RUN(test_bench);
    return check_finish();
}
