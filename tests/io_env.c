/* Environment maps in files (doc/environment-maps.md, "Files"): round
 * trips of both layouts, the attributes OpenImageIO reads, conversion
 * between layouts (exact at face centres), maketx --envlatl output read
 * back, and OpenEXR's own exrenvmap as the independent judge of the cube
 * layout's face order and orientation.
 * Usage: io_env TESTIMAGES SCRATCH [MAKETX [OIIOTOOL [EXRENVMAP]]] */
#include "io_util.h"

static const char *maketx, *oiiotool, *exrenvmap;

/* Six faces of n × n float RGBA, face f's texel (i, j) = value(f, i, j). */
static sample_texture *make_cube(int n, float (*value)(int f, int i, int j, int c), const sample_mip_params *mip)
{
    float *px = (float *)malloc((size_t)6 * (size_t)n * (size_t)n * 4 * sizeof(float));
    sample_image faces[6];
    sample_texture *t = NULL;
    sample_error e;
    int f, i, j, c;
    for (f = 0; px && f < 6; ++f) {
        float *p = px + (size_t)f * (size_t)n * (size_t)n * 4;
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i)
                for (c = 0; c < 4; ++c) p[((size_t)j * (size_t)n + (size_t)i) * 4 + (size_t)c] = value(f, i, j, c);
        faces[f].width = faces[f].height = n;
        faces[f].channels = 4;
        faces[f].format = SAMPLE_FORMAT_F32;
        faces[f].data = p;
        faces[f].row_stride = 0;
    }
    CHECK(px && sample_texture_create_cube(faces, mip, &t, &e) == SAMPLE_OK, "cube: %s", px ? e.message : "no memory");
    free(px);
    return t;
}

/* Distinct values: face, texel and channel all show. */
static float distinct(int f, int i, int j, int c) { return (float)(f * 1000 + j * 32 + i) + 0.25f * (float)c; }
/* One constant per face. */
static float per_face(int f, int i, int j, int c)
{
    (void)i, (void)j;
    return c == 3 ? 1.0f : (float)(f + 1) * (c == 0 ? 0.125f : c == 1 ? 0.25f : 0.5f);
}

static sample_texture *read_env(const char *path)
{
    sample_texture *t = NULL;
    sample_error e;
    sample_mip_params mip;
    sample_mip_params_init(&mip);
    CHECK(sample_io_read_env(path, NULL, &mip, &t, &e) == SAMPLE_OK, "reading %s: %s", path, e.message);
    return t;
}

static void write_env(const char *path, const sample_texture *t)
{
    sample_io_exr_options o;
    sample_error e;
    sample_io_exr_options_init(&o);
    o.use_float = 1;
    o.tile_w = o.tile_h = 16;
    CHECK(sample_io_write_env(path, t, &o, &e) == SAMPLE_OK, "writing %s: %s", path, e.message);
}

static void check_textureformat(const char *path, const char *want)
{
    sample_io_file_info info;
    sample_error e;
    CHECK(sample_io_describe(path, NULL, &info, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(strcmp(info.textureformat, want) == 0, "%s: textureformat '%s', expected '%s'", path, info.textureformat,
          want);
}

/* Every face texel of every level back as written. */
static void test_cube_round_trip(void)
{
    sample_mip_params mip;
    sample_texture *t, *b;
    sample_texture_info a, bi;
    char p[1024];
    int k, f, i, j, bad = 0;
    sample_mip_params_init(&mip);
    t = make_cube(8, distinct, &mip);
    if (!t) return;
    write_env(io_path(p, sizeof p, io_scratch, "cube.exr"), t);
    check_textureformat(p, "CubeFace Environment");
    if ((b = read_env(p)) != NULL) {
        sample_texture_info_get(t, &a);
        sample_texture_info_get(b, &bi);
        CHECK(bi.kind == SAMPLE_TEXTURE_CUBE && bi.width == 8 && bi.levels == a.levels, "kind %d, %d wide, %d levels",
              (int)bi.kind, bi.width, bi.levels);
        for (k = 0; k < a.levels && k < bi.levels; ++k)
            for (f = 0; f < 6; ++f)
                for (j = 0; j < 8 >> k; ++j)
                    for (i = 0; i < 8 >> k; ++i) {
                        float x[4], y[4];
                        sample_texture_texel_layer(t, k, f, i, j, x);
                        sample_texture_texel_layer(b, k, f, i, j, y);
                        if (memcmp(x, y, sizeof x) != 0 && bad++ < 3)
                            CHECK(0, "level %d face %d texel (%d,%d): %g vs %g", k, f, i, j, (double)y[0], (double)x[0]);
                    }
        CHECK(bad == 0, "%d texels differ", bad);
    }
    /* The stacked image: 8 x 48 and its levels down to 1 x 1. */
    {
        sample_io_file_info info;
        sample_error e;
        CHECK(sample_io_describe(p, NULL, &info, &e) == SAMPLE_OK, "%s", e.message);
        CHECK(info.width == 8 && info.height == 48 && info.levels == 6, "%d x %d, %d levels", info.width, info.height,
              info.levels);
    }
    sample_texture_destroy(b);
    sample_texture_destroy(t);
}

static void test_latlong_round_trip(void)
{
    sample_texture *t = io_test_texture(32, 16, 4, SAMPLE_FORMAT_F32, 7u, SAMPLE_MIPGEN_BOX, 0), *b;
    sample_io_file_info info;
    sample_error e;
    char p[1024];
    if (!t) return;
    write_env(io_path(p, sizeof p, io_scratch, "latlong.exr"), t);
    check_textureformat(p, "LatLong Environment");
    CHECK(sample_io_describe(p, NULL, &info, &e) == SAMPLE_OK && strcmp(info.wrapmodes, "periodic,clamp") == 0,
          "wrapmodes '%s'", info.wrapmodes);
    if ((b = read_env(p)) != NULL) CHECK(io_same_texels(t, b, 6, 0.0f), "lat-long levels differ");
    sample_texture_destroy(b);
    sample_texture_destroy(t);
}

/* The lat-long texel whose centre is nearest direction (x, y, z). */
static void latlong_texel_at(const sample_texture *t, double x, double y, double z, float v[4])
{
    int w, h, i, j;
    double s = atan2(-x, z) / (2 * 3.14159265358979323846) + 0.5, tt = 0.5 - atan2(y, hypot(x, z)) / 3.14159265358979323846;
    sample_texture_level_size(t, 0, &w, &h);
    i = (int)floor(s * w), j = (int)floor(tt * h);
    i = i < 0 ? 0 : i >= w ? w - 1 : i;
    j = j < 0 ? 0 : j >= h ? h - 1 : j;
    sample_texture_texel(t, 0, i, j, v);
}

/* Cube → lat-long → cube, with one constant per face: wherever a new
 * texel's footprint lies inside one face the result is that face's value
 * exactly, at every face centre in particular, in both directions. */
static void test_convert_face_centres(void)
{
    static const double axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    sample_mip_params mip;
    sample_texture *cube, *ll = NULL, *back = NULL;
    sample_texture_info inf;
    sample_error e;
    int f, c, w, h;
    sample_mip_params_init(&mip);
    if (!(cube = make_cube(16, per_face, &mip))) return;
    CHECK(sample_io_env_convert(cube, SAMPLE_TEXTURE_2D, 0, &mip, &ll, &e) == SAMPLE_OK, "%s", e.message);
    if (ll) {
        sample_texture_level_size(ll, 0, &w, &h);
        sample_texture_info_get(ll, &inf);
        CHECK(w == 64 && h == 32 && inf.kind == SAMPLE_TEXTURE_2D, "lat-long %d x %d", w, h);
        for (f = 0; f < 6; ++f) {
            float v[4];
            latlong_texel_at(ll, axis[f][0], axis[f][1], axis[f][2], v);
            for (c = 0; c < 4; ++c) CHECK(v[c] == per_face(f, 0, 0, c), "lat-long at face %d channel %d: %.9g", f, c, (double)v[c]);
        }
        CHECK(sample_io_env_convert(ll, SAMPLE_TEXTURE_CUBE, 8, &mip, &back, &e) == SAMPLE_OK, "%s", e.message);
    }
    if (back) {
        sample_texture_info_get(back, &inf);
        CHECK(inf.kind == SAMPLE_TEXTURE_CUBE && inf.width == 8 && inf.levels == 4, "cube %d, %d levels", inf.width,
              inf.levels);
        for (f = 0; f < 6; ++f) {
            float v[4];
            int i, j;
            for (j = 3; j <= 4; ++j)
                for (i = 3; i <= 4; ++i) {
                    sample_texture_texel_layer(back, 0, f, i, j, v);
                    for (c = 0; c < 4; ++c)
                        CHECK(v[c] == per_face(f, 0, 0, c), "cube face %d (%d,%d) channel %d: %.9g", f, i, j, c, (double)v[c]);
                }
        }
    }
    sample_texture_destroy(back);
    sample_texture_destroy(ll);
    sample_texture_destroy(cube);
}

/* A smooth environment, f(R) = ½ + ½·R̂ per channel, through both
 * conversions: within a small bound of the function everywhere, and
 * a face's mirrored orientation would miss by about 1. */
static float smooth_at(const float r[3], int c)
{
    double n = sqrt((double)r[0] * r[0] + (double)r[1] * r[1] + (double)r[2] * r[2]);
    return c == 3 ? 1.0f : (float)(0.5 + 0.5 * r[c] / n);
}

/* The centre direction of texel (i, j) of face f on an n-sided cube (GL
 * 4.6 table 8.19 as axis, s and t directions). */
static void cube_dir(int f, int n, int i, int j, float r[3])
{
    static const float frame[6][3][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
        {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
    };
    float sc = 2.0f * ((float)i + 0.5f) / (float)n - 1.0f, tc = 2.0f * ((float)j + 0.5f) / (float)n - 1.0f;
    int a;
    for (a = 0; a < 3; ++a) r[a] = frame[f][0][a] + sc * frame[f][1][a] + tc * frame[f][2][a];
}

static float smooth_cube(int f, int i, int j, int c)
{
    float r[3];
    cube_dir(f, 16, i, j, r);
    return smooth_at(r, c);
}

/* Largest |texel − f(its direction)| of a cube, texels at least skip_edge
 * in from the face's edges. */
static double cube_error(const sample_texture *t, int skip_edge)
{
    sample_texture_info inf;
    double worst = 0;
    int f, i, j, c, n;
    sample_texture_info_get(t, &inf);
    n = inf.width;
    for (f = 0; f < 6; ++f)
        for (j = skip_edge; j < n - skip_edge; ++j)
            for (i = skip_edge; i < n - skip_edge; ++i) {
                float v[4], r[3];
                sample_texture_texel_layer(t, 0, f, i, j, v);
                cube_dir(f, n, i, j, r);
                for (c = 0; c < 3; ++c) {
                    double d = fabs((double)v[c] - (double)smooth_at(r, c));
                    if (d > worst) worst = d;
                }
            }
    return worst;
}

/* Largest |texel − f(its direction)| of a lat-long map, rows 1 … h − 2. */
static double latlong_error(const sample_texture *t)
{
    double worst = 0, pi = 3.14159265358979323846;
    int w, h, i, j, c;
    sample_texture_level_size(t, 0, &w, &h);
    for (j = 1; j < h - 1; ++j)
        for (i = 0; i < w; ++i) {
            double phi = 2 * pi * ((i + 0.5) / w - 0.5), th = pi * (0.5 - (j + 0.5) / h);
            float r[3] = {(float)(-sin(phi) * cos(th)), (float)sin(th), (float)(cos(phi) * cos(th))}, v[4];
            sample_texture_texel(t, 0, i, j, v);
            for (c = 0; c < 3; ++c) {
                double d = fabs((double)v[c] - (double)smooth_at(r, c));
                if (d > worst) worst = d;
            }
        }
    return worst;
}

static sample_texture *smooth_env_cube(void)
{
    sample_mip_params mip;
    sample_mip_params_init(&mip);
    return make_cube(16, smooth_cube, &mip);
}

static void test_convert_smooth(void)
{
    sample_mip_params mip;
    sample_texture *cube = smooth_env_cube(), *ll = NULL, *back = NULL;
    sample_error e;
    sample_mip_params_init(&mip);
    if (!cube) return;
    CHECK(sample_io_env_convert(cube, SAMPLE_TEXTURE_2D, 32, &mip, &ll, &e) == SAMPLE_OK, "%s", e.message);
    if (ll) {
        double d = latlong_error(ll);
        CHECK(d < 0.03, "cube -> lat-long misses f by %.4f", d);
        CHECK(sample_io_env_convert(ll, SAMPLE_TEXTURE_CUBE, 16, &mip, &back, &e) == SAMPLE_OK, "%s", e.message);
    }
    if (back) {
        double d = cube_error(back, 0);
        CHECK(d < 0.05, "lat-long -> cube misses f by %.4f", d);
    }
    sample_texture_destroy(back);
    sample_texture_destroy(ll);
    sample_texture_destroy(cube);
}

/* OpenEXR's exrenvmap makes the cube from our lat-long file and the
 * lat-long from our cube file, with its own ImfEnvmap.cpp: read back,
 * each matches the smooth function, which a wrong face order or a face not
 * mirrored would miss by up to 1. */
static void test_exrenvmap(void)
{
    sample_mip_params mip;
    sample_texture *cube = smooth_env_cube(), *ll = NULL, *t;
    sample_error e;
    char a[1024], b[1024], cmd[4096];
    if (!cube) return;
    sample_mip_params_init(&mip);
    if (!exrenvmap || !*exrenvmap) {
        check_skip("exrenvmap not found: OpenEXR's cube layout not cross-checked");
        sample_texture_destroy(cube);
        return;
    }
    CHECK(sample_io_env_convert(cube, SAMPLE_TEXTURE_2D, 64, &mip, &ll, &e) == SAMPLE_OK, "%s", e.message);
    if (ll) {
        write_env(io_path(a, sizeof a, io_scratch, "smooth_ll.exr"), ll);
        snprintf(cmd, sizeof cmd, "'%s' -c -w 16 '%s' '%s' >/dev/null 2>&1", exrenvmap, a,
                 io_path(b, sizeof b, io_scratch, "exrenvmap_cube.exr"));
        CHECK(check_shell(cmd) == 0, "%s failed", cmd);
        if ((t = read_env(b)) != NULL) {
            double d = cube_error(t, 1);
            CHECK(d < 0.08, "exrenvmap's cube of our lat-long misses f by %.4f", d);
            sample_texture_destroy(t);
        }
    }
    write_env(io_path(a, sizeof a, io_scratch, "smooth_cube.exr"), cube);
    snprintf(cmd, sizeof cmd, "'%s' -l -w 64 '%s' '%s' >/dev/null 2>&1", exrenvmap, a,
             io_path(b, sizeof b, io_scratch, "exrenvmap_ll.exr"));
    CHECK(check_shell(cmd) == 0, "%s failed", cmd);
    if ((t = read_env(b)) != NULL) {
        double d = latlong_error(t);
        CHECK(d < 0.08, "exrenvmap's lat-long of our cube misses f by %.4f", d);
        sample_texture_destroy(t);
    }
    sample_texture_destroy(ll);
    sample_texture_destroy(cube);
}

/* maketx --envlatl output: a lat-long texture whose levels are maketx's,
 * its base the input's texels exactly. */
static void test_maketx_latlong(void)
{
    sample_texture *src = io_test_texture(32, 16, 3, SAMPLE_FORMAT_F32, 99u, SAMPLE_MIPGEN_NONE, 0), *t;
    float *px = NULL;
    sample_error e;
    char in[1024], out[1024], cmd[4096];
    int i, j;
    if (!src) return;
    if (!maketx || !*maketx) {
        check_skip("maketx not found: maketx --envlatl output not read");
        sample_texture_destroy(src);
        return;
    }
    if ((px = (float *)malloc(32 * 16 * 4 * sizeof(float))) != NULL) {
        for (j = 0; j < 16; ++j)
            for (i = 0; i < 32; ++i) sample_texture_texel(src, 0, i, j, px + (j * 32 + i) * 4);
        CHECK(sample_io_write_channels(io_path(in, sizeof in, io_scratch, "ll_src.exr"), px, 32, 16, 4,
                                       (const char *const[]){"R", "G", "B", "A"}, &e) == SAMPLE_OK,
              "%s", e.message);
    }
    snprintf(cmd, sizeof cmd, "'%s' --envlatl -d float '%s' -o '%s' >/dev/null 2>&1", maketx, in,
             io_path(out, sizeof out, io_scratch, "maketx_ll.exr"));
    CHECK(check_shell(cmd) == 0, "%s failed", cmd);
    if ((t = read_env(out)) != NULL) {
        sample_texture_info inf;
        sample_texture_info_get(t, &inf);
        CHECK(inf.kind == SAMPLE_TEXTURE_2D && inf.levels == 6, "kind %d, %d levels", (int)inf.kind, inf.levels);
        /* maketx makes each pole's row its mean and the seam's two
         * columns equal (OpenImageIO's maketexture.cpp, fix_latl_edges);
         * every other texel is the input's. */
        for (j = 1; j < 15; ++j)
            for (i = 1; i < 31; ++i) {
                float a[4], b[4];
                sample_texture_texel(src, 0, i, j, a);
                sample_texture_texel(t, 0, i, j, b);
                if (memcmp(a, b, 3 * sizeof(float)) != 0) {
                    CHECK(0, "maketx texel (%d,%d): %.9g, input %.9g", i, j, (double)b[0], (double)a[0]);
                    j = 15;
                    break;
                }
            }
        sample_texture_destroy(t);
    }
    free(px);
    sample_texture_destroy(src);
}

/* What OpenImageIO itself makes of the files the round trips wrote: one
 * oiiotool run (its start-up is most of its time). Both are environments,
 * and both keep texel centres at (i + ½)/w (oiio:sampleborder 0, which the
 * files store because OpenImageIO's OpenEXR reader assumes 1, OpenEXR's
 * convention, for any file with an envmap attribute). */
static void test_oiio_reads_env(void)
{
    char a[1024], b[1024], cmd[4096];
    if (!oiiotool || !*oiiotool) {
        check_skip("oiiotool not found: OpenImageIO's reading of the attributes not checked");
        return;
    }
    io_path(a, sizeof a, io_scratch, "cube.exr");
    io_path(b, sizeof b, io_scratch, "latlong.exr");
    snprintf(cmd, sizeof cmd,
             "'%s' --info -v '%s' '%s' > '%s/oiio_info.txt' 2>&1 && grep -q 'textureformat: \"CubeFace Environment\"' "
             "'%s/oiio_info.txt' && grep -q 'textureformat: \"LatLong Environment\"' '%s/oiio_info.txt' && "
             "test \"$(grep -c 'oiio:sampleborder: 0' '%s/oiio_info.txt')\" = 2",
             oiiotool, a, b, io_scratch, io_scratch, io_scratch, io_scratch);
    CHECK(check_shell(cmd) == 0, "oiiotool does not read %s and %s as environment maps (%s/oiio_info.txt)", a, b,
          io_scratch);
}

static void test_bad_input(void)
{
    sample_texture *t = io_test_texture(24, 8, 4, SAMPLE_FORMAT_F32, 3u, SAMPLE_MIPGEN_NONE, 0), *o = NULL;
    sample_error e;
    char p[1024];
    if (!t) return;
    /* 3:1 with no envmap attribute: neither layout. */
    CHECK(sample_io_write_mip_exr(io_path(p, sizeof p, io_scratch, "plain.exr"), t, NULL, &e) == SAMPLE_OK, "%s",
          e.message);
    CHECK(sample_io_read_env(p, NULL, NULL, &o, &e) == SAMPLE_E_UNSUPPORTED && !o, "a 3:1 image read as a map");
    CHECK(strstr(e.message, "2:1") != NULL, "message: %s", e.message);
    CHECK(sample_io_write_env(io_path(p, sizeof p, io_scratch, "env.png"), t, NULL, &e) == SAMPLE_E_INVALID_ARGUMENT,
          "an environment map written as PNG");
    CHECK(!io_exists(p), "a refused write left %s", p);
    CHECK(sample_io_env_convert(t, SAMPLE_TEXTURE_CUBE, -1, NULL, &o, &e) == SAMPLE_E_INVALID_ARGUMENT && !o,
          "size -1 accepted");
    CHECK(sample_io_env_convert(t, SAMPLE_TEXTURE_3D, 0, NULL, &o, &e) == SAMPLE_E_INVALID_ARGUMENT && !o,
          "a 3D target accepted");
    sample_texture_destroy(t);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: io_env TESTIMAGES SCRATCH [MAKETX [OIIOTOOL [EXRENVMAP]]]\n");
        return 2;
    }
    io_images = argv[1];
    io_scratch = argv[2];
    maketx = argc > 3 ? argv[3] : NULL;
    oiiotool = argc > 4 ? argv[4] : NULL;
    exrenvmap = argc > 5 ? argv[5] : NULL;
    RUN(test_cube_round_trip);
    RUN(test_latlong_round_trip);
    RUN(test_convert_face_centres);
    RUN(test_convert_smooth);
    RUN(test_exrenvmap);
    RUN(test_maketx_latlong);
    RUN(test_oiio_reads_env);
    RUN(test_bad_input);
    return check_finish();
}
