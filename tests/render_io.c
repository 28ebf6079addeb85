/* Renderer I/O: image textures in scene files (paths relative to the scene
 * file), the built-in photo-plane scene, EXR/PNG pictures and the EXR
 * buffers read back through libsample_io, and the parser's limits. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "render.h"

#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"

static char dir[64];

static void path_in(char *out, size_t n, const char *name) { snprintf(out, n, "%s/%s", dir, name); }

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    int ok = f && fputs(text, f) >= 0;
    if (f) ok = fclose(f) == 0 && ok;
    return ok;
}

/* Texel (i, j) of a texture's base level, exactly (nearest at its centre). */
static void texel(const sample_texture *tex, int i, int j, float out[4])
{
    sample_texture_info info;
    sample_sampler s;
    sample_query q = {0, 0, 0, 0, 0, 0};
    sample_texture_info_get(tex, &info);
    sample_sampler_init(&s);
    q.s = (i + 0.5f) / (float)info.width;
    q.t = (j + 0.5f) / (float)info.height;
    sample_one(tex, &s, &q, out);
}

/* Read a file back: "raw" takes the values as stored (no colour change). */
static sample_texture *read_back(const char *path, const char *colorspace, int w, int h)
{
    sample_io_options o;
    sample_texture *tex = NULL;
    sample_texture_info info;
    sample_error e;
    sample_io_options_init(&o);
    o.colorspace = colorspace;
    if (sample_io_read_texture(path, &o, NULL, &tex, &e) != SAMPLE_OK) {
        CHECK(0, "reading %s: %s", path, e.message);
        return NULL;
    }
    sample_texture_info_get(tex, &info);
    CHECK(info.width == w && info.height == h, "%s is %d x %d, expected %d x %d", path, info.width,
          info.height, w, h);
    return tex;
}

/* A 4 × 4 PNG on a unit quad that fills a 4 × 4 image exactly (the
 * zoneplate camera: fov 45°, eye 0.5 / tan 22.5° above the centre), t = 0
 * at the top: pixel (i, j) sees texel (i, j) at its centre, one texel per
 * pixel, so λ = 0 and the nearest mag filter returns the texel itself. */
static const char quad_scene[] =
    "{\"width\":4,\"height\":4,\"camera\":{\"eye\":[0.5,0.5,1.2071067811865475],"
    "\"look\":[0.5,0.5,0],\"up\":[0,1,0],\"fov\":45},"
    "\"sampler\":{\"min\":\"nearest\",\"mag\":\"nearest\"},"
    "\"textures\":[{\"name\":\"p\",\"type\":\"image\",\"file\":\"tex.png\"}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"p\"}],"
    "\"objects\":[{\"type\":\"polygons\",\"material\":\"m\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],"
    "[1,1,0],[0,1,0]],\"st\":[[0,1],[1,1],[1,0],[0,0]]}]}]}";

static render_scene *quad_setup(void)
{
    float px[4 * 4 * 4]; /* the writer takes RGBA and writes the first 3 */
    char png[128], json[128], err[256] = "";
    render_scene *sc = NULL;
    sample_error e;
    int k;
    for (k = 0; k < 64; ++k) /* 48 distinct levels in R, G, B; alpha 1 */
        px[k] = k % 4 == 3 ? 1.0f : (float)((k - k / 4) * 37 % 48) / 47.0f;
    path_in(png, sizeof png, "tex.png");
    path_in(json, sizeof json, "scene.json");
    CHECK(sample_io_write_image(png, px, 4, 4, 3, NULL, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(write_text(json, quad_scene), "writing %s", json);
    /* The working directory is not dir: tex.png is found beside scene.json. */
    CHECK(render_scene_load(json, 0, 0, &sc, err, sizeof err) == 0, "%s", err);
    return sc;
}

static int quad_render(const render_scene *sc, render_image *img)
{
    render_options o;
    char err[256] = "";
    render_options_init(&o);
    o.shade = RENDER_SHADE_TEXTURE;
    o.buffers = RENDER_BUF_ST | RENDER_BUF_JACOBIAN | RENDER_BUF_LOD | RENDER_BUF_TEXELS |
                RENDER_BUF_DEPTH | RENDER_BUF_NORMAL | RENDER_BUF_ID;
    CHECK(render_image_run(sc, &o, img, err, sizeof err) == 0, "%s", err);
    return img->rgba != NULL;
}

/* The render shows the image file's texels, and the pictures written from
 * it read back as the same values: float EXR bit for bit, the 8-bit sRGB
 * PNG as the very codes of the source PNG. */
static void test_image_texture_pictures(void)
{
    render_scene *sc = quad_setup();
    render_image img;
    sample_texture *src, *exr, *png;
    char p_src[128], p_exr[128], p_png[128], err[256] = "";
    int i, j, c;
    if (!sc || !quad_render(sc, &img)) {
        render_scene_destroy(sc);
        return;
    }
    path_in(p_src, sizeof p_src, "tex.png");
    path_in(p_exr, sizeof p_exr, "out.exr");
    path_in(p_png, sizeof p_png, "out.png");
    CHECK(render_image_write(&img, p_exr, err, sizeof err) == 0, "%s", err);
    CHECK(render_image_write(&img, p_png, err, sizeof err) == 0, "%s", err);
    src = read_back(p_src, NULL, 4, 4);
    exr = read_back(p_exr, "raw", 4, 4);
    png = read_back(p_png, NULL, 4, 4);
    for (j = 0; src && exr && png && j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            float a[4], b[4], d[4];
            const float *r = img.rgba + 4 * (j * 4 + i);
            texel(src, i, j, a);
            texel(exr, i, j, b);
            texel(png, i, j, d);
            for (c = 0; c < 3; ++c) {
                CHECK(r[c] == a[c], "pixel (%d,%d)[%d] = %.9g, texel %.9g", i, j, c, r[c], a[c]);
                CHECK(b[c] == r[c], "EXR (%d,%d)[%d] = %.9g, rendered %.9g", i, j, c, b[c], r[c]);
                CHECK(d[c] == a[c], "PNG (%d,%d)[%d] = %.9g, source %.9g", i, j, c, d[c], a[c]);
            }
            CHECK(b[3] == 1.0f, "EXR alpha %.9g", b[3]);
        }
    sample_texture_destroy(src);
    sample_texture_destroy(exr);
    sample_texture_destroy(png);
    render_image_free(&img);
    render_scene_destroy(sc);
}

/* Channel names straight from the OpenEXR header's "channels" attribute
 * (chlist: name, NUL, 16 bytes of type and sampling, ...; an empty name
 * ends it), so that the check does not depend on any reader's ordering. */
static int exr_channels(const char *path, char names[][16], int max)
{
    unsigned char buf[4096];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0, p = 8;
    int count = 0;
    if (f) fclose(f);
    while (p < n && buf[p]) {
        const char *name = (const char *)buf + p, *type;
        size_t q = p + strnlen(name, n - p) + 1, end;
        uint32_t size;
        type = (const char *)buf + q;
        q += strnlen(type, n - q) + 1;
        if (q + 4 > n) return -1;
        size = (uint32_t)buf[q] | (uint32_t)buf[q + 1] << 8 | (uint32_t)buf[q + 2] << 16 |
               (uint32_t)buf[q + 3] << 24;
        q += 4;
        if (size > n - q) return -1;
        end = q + size;
        if (strcmp(name, "channels") == 0 && strcmp(type, "chlist") == 0) {
            while (q < end && buf[q] && count < max) {
                size_t len = strnlen((const char *)buf + q, end - q);
                if (len >= 16) return -1;
                memcpy(names[count], buf + q, len + 1);
                ++count;
                q += len + 1 + 16;
            }
            return count;
        }
        p = end;
    }
    return -1;
}

/* Environment files: a cube map of one colour per face written by
 * sample_io_write_env, seen in a mirror sphere from −y. The pixel at the
 * sphere's centre reflects −y (the world is z up), the maps' +z (y up), so
 * it shows the +Z face's colour exactly (a 2° view: the footprint is
 * smaller than a texel), whether the scene keeps the cube
 * or resamples it into a lat-long map ("type", "size"). */
static void test_env_file(void)
{
    static const char *const scenes[] = {
        "{\"width\":9,\"height\":9,\"camera\":{\"eye\":[0,-5,0],\"look\":[0,0,0],\"up\":[0,0,1],\"fov\":2},"
        "\"materials\":[{\"name\":\"m\",\"ambient\":0,\"diffuse\":[0,0,0],\"gloss\":0,\"reflect\":1}],"
        "\"environment\":{\"file\":\"env.exr\"},\"objects\":[{\"type\":\"sphere\",\"material\":\"m\"}]}",
        "{\"width\":9,\"height\":9,\"camera\":{\"eye\":[0,-5,0],\"look\":[0,0,0],\"up\":[0,0,1],\"fov\":2},"
        "\"materials\":[{\"name\":\"m\",\"ambient\":0,\"diffuse\":[0,0,0],\"gloss\":0,\"reflect\":1}],"
        "\"environment\":{\"file\":\"env.exr\",\"type\":\"latlong\",\"size\":32},"
        "\"objects\":[{\"type\":\"sphere\",\"material\":\"m\"}]}"};
    float px[6 * 4 * 4 * 4];
    sample_image faces[6];
    sample_texture *cube = NULL;
    sample_io_exr_options o;
    sample_error e;
    char path[128], json[128], err[256] = "";
    size_t k;
    int f;
    for (k = 0; k < sizeof px / sizeof px[0]; ++k) px[k] = k % 4 == 3 ? 1.0f : (float)(k / 64 + 1) * 0.125f * (float)(k % 4 + 1);
    for (f = 0; f < 6; ++f) {
        faces[f].width = faces[f].height = 4;
        faces[f].channels = 4;
        faces[f].format = SAMPLE_FORMAT_F32;
        faces[f].data = px + f * 64;
        faces[f].row_stride = 0;
    }
    sample_io_exr_options_init(&o);
    o.use_float = 1;
    path_in(path, sizeof path, "env.exr");
    CHECK(sample_texture_create_cube(faces, NULL, &cube, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(cube && sample_io_write_env(path, cube, &o, &e) == SAMPLE_OK, "%s", e.message);
    sample_texture_destroy(cube);
    path_in(json, sizeof json, "env.json");
    for (k = 0; k < 2; ++k) {
        render_scene *sc = NULL;
        render_options ro;
        render_image img;
        CHECK(write_text(json, scenes[k]), "writing %s", json);
        CHECK(render_scene_load(json, 0, 0, &sc, err, sizeof err) == 0, "scene %zu: %s", k, err);
        if (!sc) continue;
        render_options_init(&ro);
        ro.threads = 1;
        CHECK(render_image_run(sc, &ro, &img, err, sizeof err) == 0, "%s", err);
        if (img.rgba) {
            const float *c = img.rgba + 4 * (4 * 9 + 4), *want = px + 4 * 64; /* face 4: +Z */
            for (f = 0; f < 3; ++f) CHECK(c[f] == want[f], "scene %zu channel %d: %.9g, +Z face %.9g", k, f, c[f], want[f]);
        }
        render_image_free(&img);
        render_scene_destroy(sc);
    }
}

static void test_buffers_exr(void)
{
    render_scene *sc = quad_setup();
    render_image img;
    char path[128], names[32][16], err[256] = "";
    sample_texture *tex;
    int n, k, m, i, j;
    if (!sc || !quad_render(sc, &img)) {
        render_scene_destroy(sc);
        return;
    }
    path_in(path, sizeof path, "buffers.exr");
    CHECK(render_image_write_buffers(&img, path, err, sizeof err) == 0, "%s", err);
    n = exr_channels(path, names, 32);
    CHECK(n == RENDER_BUFFER_CHANNELS, "%d channels in %s", n, path);
    for (k = 0; k < RENDER_BUFFER_CHANNELS; ++k) {
        int found = 0;
        for (m = 0; m < n; ++m) found |= strcmp(names[m], render_buffer_names[k]) == 0;
        CHECK(found, "channel '%s' missing", render_buffer_names[k]);
    }
    CHECK(strcmp(render_buffer_names[0], "s") == 0 && strcmp(render_buffer_names[8], "Z") == 0 &&
              strcmp(render_buffer_names[13], "prim") == 0,
          "documented names changed");
    /* Values: the reader keeps four channels, OpenImageIO's order puts the
     * layer-less ones first, sorted: Z, dsdx, dsdy, dtdx. Head-on, one
     * texel per pixel: ds/dx = 1/4, ds/dy = dt/dx = 0, depth 1.2071. */
    tex = read_back(path, "raw", 4, 4);
    for (j = 0; tex && j < 4; ++j)
        for (i = 0; i < 4; ++i) {
            size_t px = (size_t)j * 4 + i;
            float v[4];
            texel(tex, i, j, v);
            CHECK(v[0] == img.depth[px], "Z (%d,%d) = %.9g, rendered %.9g", i, j, v[0], img.depth[px]);
            CHECK(v[1] == img.jacobian[4 * px], "dsdx (%d,%d) = %.9g", i, j, v[1]);
            CHECK(v[2] == img.jacobian[4 * px + 2], "dsdy (%d,%d) = %.9g", i, j, v[2]);
            CHECK(v[3] == img.jacobian[4 * px + 1], "dtdx (%d,%d) = %.9g", i, j, v[3]);
            CHECK_NEAR(v[0], 1.2071067811865475, 1e-6);
            CHECK_NEAR(v[1], 0.25, 1e-6);
            CHECK_NEAR(v[2], 0.0, 1e-6);
            CHECK_NEAR(v[3], 0.0, 1e-6);
        }
    sample_texture_destroy(tex);
    render_image_free(&img);
    render_scene_destroy(sc);
}

/* The built-in photo-plane: testimages/photo.jpg on a receding plane. The
 * top-left pixel is sky (the background, exactly); the bottom-centre one
 * is the photograph. Both read back from EXR exactly, from PNG as their
 * sRGB 8-bit code. */
static void test_photo_plane(void)
{
    render_scene *sc = NULL;
    render_image img;
    render_options o;
    sample_texture *exr = NULL, *png = NULL;
    char p_exr[128], p_png[128], err[256] = "";
    static const int pix[2][2] = {{0, 0}, {20, 29}};
    int k, c;
    if (render_scene_builtin("photo-plane", 40, 30, &sc, err, sizeof err) != 0) {
        CHECK(0, "%s", err);
        return;
    }
    render_options_init(&o);
    CHECK(render_image_run(sc, &o, &img, err, sizeof err) == 0, "%s", err);
    path_in(p_exr, sizeof p_exr, "photo.exr");
    path_in(p_png, sizeof p_png, "photo.png");
    CHECK(render_image_write(&img, p_exr, err, sizeof err) == 0, "%s", err);
    CHECK(render_image_write(&img, p_png, err, sizeof err) == 0, "%s", err);
    CHECK(img.rgba[0] == 0.5f && img.rgba[1] == 0.6f && img.rgba[2] == 0.8f, "sky %g %g %g",
          img.rgba[0], img.rgba[1], img.rgba[2]);
    exr = read_back(p_exr, "raw", 40, 30);
    png = read_back(p_png, NULL, 40, 30);
    for (k = 0; exr && png && k < 2; ++k) {
        const float *r = img.rgba + 4 * (pix[k][1] * 40 + pix[k][0]);
        float a[4], b[4];
        texel(exr, pix[k][0], pix[k][1], a);
        texel(png, pix[k][0], pix[k][1], b);
        for (c = 0; c < 3; ++c) {
            float code = floorf(sample_linear_to_srgb(r[c]) * 255.0f + 0.5f);
            CHECK(a[c] == r[c], "EXR pixel %d [%d] = %.9g, rendered %.9g", k, c, a[c], r[c]);
            /* The code exactly; its decoding to within the float rounding
             * of the two sRGB EOTF implementations (a code step is ~4e-3). */
            CHECK(fabsf(b[c] - sample_srgb_to_linear(code / 255.0f)) <= 1e-6f,
                  "PNG pixel %d [%d] = %.9g, code %g", k, c, b[c], code);
        }
    }
    CHECK(img.rgba[4 * (29 * 40 + 20)] != 0.5f, "the bottom centre shows sky, not the photo");
    sample_texture_destroy(exr);
    sample_texture_destroy(png);
    render_image_free(&img);
    render_scene_destroy(sc);
}
#endif /* TEXSAMPLE_HAVE_IO */

static int parse_fails_with(const char *json, const char *words)
{
    render_scene *sc = NULL;
    char err[256] = "";
    int r = render_scene_parse(json, strlen(json), 0, 0, &sc, err, sizeof err);
    render_scene_destroy(sc);
    CHECK(r != 0 && strstr(err, words), "expected an error with '%s', got r = %d '%s'", words, r, err);
    return r != 0;
}

/* Every loop and allocation that scene data drives is bounded. */
static void test_limits(void)
{
    size_t cap = 1100 * 20 + 64, n = 0;
    char *big = malloc(cap);
    int k;
    parse_fails_with("{\"textures\":[{\"type\":\"fourier\",\"size\":8192,\"samples\":16}],"
                     "\"objects\":[{\"type\":\"plane\"}]}",
                     "exceed the limits");
    parse_fails_with("{\"textures\":[{\"type\":\"image\",\"file\":\"no-such-file.png\"}],"
                     "\"objects\":[{\"type\":\"plane\"}]}",
#ifdef TEXSAMPLE_HAVE_IO
                     "No such file or directory"
#else
                     "no image support"
#endif
    );
    parse_fails_with("{\"textures\":[{\"type\":\"image\"}],\"objects\":[{\"type\":\"plane\"}]}",
                     "needs a 'file'");
    if (!big) return;
    n += (size_t)snprintf(big, cap, "{\"objects\":[");
    for (k = 0; k < 1025; ++k)
        n += (size_t)snprintf(big + n, cap - n, "%s{\"type\":\"sphere\"}", k ? "," : "");
    snprintf(big + n, cap - n, "]}");
    parse_fails_with(big, "at most 1024");
    n = (size_t)snprintf(big, cap, "{\"objects\":[");
    for (k = 0; k < 65; ++k)
        n += (size_t)snprintf(big + n, cap - n, "%s{\"type\":\"teapot\"}", k ? "," : "");
    snprintf(big + n, cap - n, "]}");
    parse_fails_with(big, "at most 64 teapots");
    free(big);
    {
        render_parse_options po;
        render_scene *sc = NULL;
        char err[256] = "";
        static const char img[] = "{\"textures\":[{\"type\":\"image\",\"file\":\"x.png\"}],"
                                  "\"objects\":[{\"type\":\"plane\"}]}";
        render_parse_options_init(&po);
        po.images = 0;
        CHECK(render_scene_parse_ex(img, strlen(img), 0, 0, &po, &sc, err, sizeof err) != 0 &&
                  strstr(err, "not allowed"),
              "images refused: '%s'", err);
        render_scene_destroy(sc);
    }
}

int main(void)
{
#ifdef TEXSAMPLE_HAVE_IO
    snprintf(dir, sizeof dir, "/tmp/render_io_XXXXXX");
    if (!mkdtemp(dir)) {
        fprintf(stderr, "cannot make a temporary folder\n");
        return 1;
    }
    RUN(test_image_texture_pictures);
    RUN(test_buffers_exr);
    RUN(test_photo_plane);
    RUN(test_env_file);
    {
        static const char *const files[] = {"tex.png", "scene.json", "out.exr", "out.png",
                                            "buffers.exr", "photo.exr", "photo.png", "env.exr", "env.json"};
        char p[128];
        size_t k;
        for (k = 0; k < sizeof files / sizeof files[0]; ++k) {
            path_in(p, sizeof p, files[k]);
            remove(p);
        }
        rmdir(dir);
    }
#endif
    RUN(test_limits);
    return check_finish();
}
