/*
 * Image files in scenes, by use (doc/renderer.md, "Image textures"): a grey
 * or grey + alpha picture used for colour renders as (Y, Y, Y[, A]), not red
 * as libsample's R and RG formats read it; 8-bit data maps (bump, normal)
 * are raw unless "colorspace" says otherwise; a lat-long "environment"
 * file is what a mirror reflects. The pictures are 2 × 2 and 8 × 4 PNGs the
 * test writes itself (zlib), so that grey and grey + alpha files exist.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "render.h"

#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#if defined(TEXSAMPLE_HAVE_IO) && defined(RENDER_TEST_HAVE_ZLIB)
#include "sample/sample_io.h"

#include <zlib.h>

static char dir[64];

static void be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void png_chunk(FILE *f, const char *type, const unsigned char *data, uint32_t n)
{
    unsigned char b[8];
    uLong crc = crc32(crc32(0L, (const Bytef *)type, 4), data, n);
    be32(b, n);
    memcpy(b + 4, type, 4);
    fwrite(b, 1, 8, f);
    if (n) fwrite(data, 1, n, f);
    be32(b, (uint32_t)crc);
    fwrite(b, 1, 4, f);
}

/* An 8-bit PNG (PNG spec. §11) of ch = 1 (grey), 2 (grey + alpha) or 3
 * (RGB) channels, rows unfiltered, in dir. */
static int write_png(const char *name, int w, int h, int ch, const unsigned char *px)
{
    static const unsigned char colour_type[] = {0, 0, 4, 2};
    size_t row = 1 + (size_t)w * (size_t)ch, raw = row * (size_t)h;
    uLongf zn = compressBound((uLong)raw);
    unsigned char *r = malloc(raw), *z = malloc(zn), ihdr[13];
    char path[128];
    FILE *f;
    int j, ok;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (!r || !z || !(f = fopen(path, "wb"))) {
        free(r);
        free(z);
        return 0;
    }
    for (j = 0; j < h; ++j) {
        r[(size_t)j * row] = 0; /* filter type None */
        memcpy(r + (size_t)j * row + 1, px + (size_t)j * (row - 1), row - 1);
    }
    ok = compress(z, &zn, r, (uLong)raw) == Z_OK;
    fwrite("\x89PNG\r\n\x1a\n", 1, 8, f);
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;
    ihdr[9] = colour_type[ch];
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    png_chunk(f, "IHDR", ihdr, 13);
    png_chunk(f, "IDAT", z, (uint32_t)zn);
    png_chunk(f, "IEND", NULL, 0);
    ok = fclose(f) == 0 && ok;
    free(r);
    free(z);
    return ok;
}

/* The scene text (with the name of its folder's files) as a file in dir,
 * loaded from there: 2 × 2 pixels on the unit quad seen head-on (fov 45°,
 * eye 0.5 / tan 22.5° above its centre), so that pixel (i, j) sees texel
 * (i, j) of a 2 × 2 texture at its centre, with NEAREST filters. */
static int load(const char *materials, const char *textures, render_scene **sc, char *err,
                size_t errlen)
{
    char path[128];
    FILE *f;
    snprintf(path, sizeof path, "%s/scene.json", dir);
    if (!(f = fopen(path, "w"))) return -1;
    fprintf(f,
            "{\"width\":2,\"height\":2,\"camera\":{\"eye\":[0.5,0.5,1.2071067811865475],"
            "\"look\":[0.5,0.5,0],\"up\":[0,1,0],\"fov\":45},"
            "\"sampler\":{\"min\":\"nearest\",\"mag\":\"nearest\"},\"textures\":[%s],"
            "\"materials\":[%s],\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":"
            "[[0,0,0],[1,0,0],[1,1,0],[0,1,0]],\"st\":[[0,1],[1,1],[1,0],[0,0]]}]}]}",
            textures, materials);
    if (fclose(f) != 0) return -1;
    return render_scene_load(path, 0, 0, sc, err, errlen);
}

/* Texel (i, j) of level 0 of a file read on its own through libsample_io. */
static void file_texel(const char *name, const char *colorspace, int i, int j, float out[4])
{
    char path[128];
    sample_io_options o;
    sample_texture *tex = NULL;
    sample_error e;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    sample_io_options_init(&o);
    o.colorspace = colorspace;
    memset(out, 0, 4 * sizeof *out);
    CHECK(sample_io_read_texture(path, &o, NULL, &tex, &e) == SAMPLE_OK, "%s", e.message);
    if (tex) sample_texture_texel(tex, 0, i, j, out);
    sample_texture_destroy(tex);
}

static const unsigned char grey[4] = {0, 64, 128, 255};
static const unsigned char grey_alpha[8] = {0, 255, 64, 128, 128, 0, 255, 64};
static const unsigned char rgb[12] = {255, 128, 0, 10, 20, 30, 200, 100, 50, 128, 128, 255};

/* A grey picture renders grey, a grey + alpha one (Y, Y, Y, A): the shaded
 * texture at each pixel, and the ground truth's value. */
static void test_grey_is_grey(void)
{
    static const char *const files[] = {"g.png", "ga.png"};
    int f;
    CHECK(write_png("g.png", 2, 2, 1, grey) && write_png("ga.png", 2, 2, 2, grey_alpha), "PNGs");
    for (f = 0; f < 2; ++f) {
        char tex[128], err[512] = "";
        render_scene *sc = NULL;
        render_image img;
        render_options o;
        int i, j, c;
        snprintf(tex, sizeof tex, "{\"name\":\"p\",\"type\":\"image\",\"file\":\"%s\"}", files[f]);
        CHECK(load("{\"texture\":\"p\"}", tex, &sc, err, sizeof err) == 0, "%s", err);
        if (!sc) continue;
        render_options_init(&o);
        o.shade = RENDER_SHADE_TEXTURE;
        CHECK(render_image_run(sc, &o, &img, err, sizeof err) == 0, "%s", err);
        for (j = 0; j < 2 && img.rgba; ++j)
            for (i = 0; i < 2; ++i) {
                float y[4], want[4], truth[4];
                const float *px = img.rgba + 4 * (j * 2 + i);
                file_texel(files[f], NULL, i, j, y);
                want[0] = want[1] = want[2] = y[0];
                want[3] = f ? y[1] : 1.0f; /* RG: alpha is the second channel */
                render_scene_texture_truth(sc, 0, (i + 0.5) / 2, (j + 0.5) / 2, NULL, truth);
                for (c = 0; c < 4; ++c) {
                    CHECK(px[c] == want[c], "%s pixel (%d, %d)[%d] = %.9g, expected %.9g",
                          files[f], i, j, c, px[c], want[c]);
                    CHECK(truth[c] == want[c], "%s truth (%d, %d)[%d] = %.9g, expected %.9g",
                          files[f], i, j, c, truth[c], want[c]);
                }
            }
        render_image_free(&img);
        render_scene_destroy(sc);
    }
}

/* 8-bit data maps are raw (code / 255) by default, decoded when their
 * "colorspace" says so; one picture cannot be colour and data by default. */
static void test_data_maps_are_raw(void)
{
    render_scene *sc = NULL;
    char err[512] = "";
    float t[4], s[4];
    CHECK(write_png("n.png", 2, 2, 3, rgb) && write_png("g.png", 2, 2, 1, grey), "PNGs");
    CHECK(load("{\"normal_map\":\"n\"},{\"bump\":\"h\"}",
               "{\"name\":\"n\",\"type\":\"image\",\"file\":\"n.png\"},"
               "{\"name\":\"h\",\"type\":\"image\",\"file\":\"g.png\"}",
               &sc, err, sizeof err) == 0,
          "%s", err);
    if (sc) {
        int k, c;
        for (k = 0; k < 4; ++k) {
            sample_texture_texel(render_scene_texture(sc, 0), 0, k % 2, k / 2, t);
            for (c = 0; c < 3; ++c)
                CHECK(t[c] == rgb[3 * k + c] / 255.0f, "normal map texel %d[%d] = %.9g, code %d",
                      k, c, t[c], rgb[3 * k + c]);
            sample_texture_texel(render_scene_texture(sc, 1), 0, k % 2, k / 2, t);
            CHECK(t[0] == grey[k] / 255.0f, "bump texel %d = %.9g, code %d", k, t[0], grey[k]);
        }
    }
    render_scene_destroy(sc);
    sc = NULL;
    CHECK(load("{\"normal_map\":\"n\"}",
               "{\"name\":\"n\",\"type\":\"image\",\"file\":\"n.png\",\"colorspace\":\"srgb\"}", &sc,
               err, sizeof err) == 0,
          "%s", err);
    if (sc) {
        sample_texture_texel(render_scene_texture(sc, 0), 0, 1, 0, t);
        file_texel("n.png", "srgb", 1, 0, s);
        CHECK(t[0] == s[0] && t[0] < 0.01f, "'colorspace' decodes: %.9g vs %.9g", t[0], s[0]);
    }
    render_scene_destroy(sc);
    sc = NULL;
    CHECK(load("{\"texture\":\"n\",\"bump\":\"n\"}",
               "{\"name\":\"n\",\"type\":\"image\",\"file\":\"n.png\"}", &sc, err, sizeof err) != 0 &&
              strstr(err, "used as colour and as data"),
          "'%s'", err);
    render_scene_destroy(sc);
}

/* A mirror plane (reflect 1, nothing else) under an 8 × 4 lat-long file
 * whose upper half (rows 0–1: polar angle < 90°) is one colour: looking
 * down at 45° the reflected ray points up at 45°, t = 1/4, between rows 0
 * and 1, so the pixel is that colour. */
static void test_environment_file(void)
{
    unsigned char env[8 * 4 * 3];
    float want[4];
    render_scene *sc = NULL;
    render_image img;
    render_options o;
    char path[128], err[512] = "";
    FILE *f;
    int k, c;
    for (k = 0; k < 32; ++k) {
        env[3 * k] = k < 16 ? 200 : 10;
        env[3 * k + 1] = k < 16 ? 150 : 20;
        env[3 * k + 2] = k < 16 ? 100 : 30;
    }
    CHECK(write_png("env.png", 8, 4, 3, env), "env.png");
    file_texel("env.png", NULL, 0, 0, want);
    snprintf(path, sizeof path, "%s/mirror.json", dir);
    if ((f = fopen(path, "w"))) {
        fputs("{\"width\":3,\"height\":3,\"camera\":{\"eye\":[0,-1,1],\"look\":[0,0,0],"
              "\"fov\":10},\"environment\":{\"file\":\"env.png\"},"
              "\"materials\":[{\"diffuse\":[0,0,0],\"ambient\":0,\"reflect\":1}],"
              "\"objects\":[{\"type\":\"plane\"}]}",
              f);
        fclose(f);
    }
    CHECK(render_scene_load(path, 0, 0, &sc, err, sizeof err) == 0, "%s", err);
    if (sc) {
        render_options_init(&o);
        CHECK(render_image_run(sc, &o, &img, err, sizeof err) == 0, "%s", err);
        for (c = 0; c < 3 && img.rgba; ++c)
            CHECK_NEAR(img.rgba[4 * 4 + c], want[c], 1e-6);
        render_image_free(&img);
    }
    render_scene_destroy(sc);
    sc = NULL;
    if ((f = fopen(path, "w"))) {
        fputs("{\"environment\":{\"file\":\"no-sky.png\"},\"objects\":[{\"type\":\"plane\"}]}", f);
        fclose(f);
    }
    CHECK(render_scene_load(path, 0, 0, &sc, err, sizeof err) != 0 && strstr(err, "environment") &&
              strstr(err, "no-sky.png") && strstr(err, "No such file or directory"),
          "'%s'", err);
    render_scene_destroy(sc);
}

int main(void)
{
    char cmd[128];
    snprintf(dir, sizeof dir, "/tmp/render_image_XXXXXX");
    if (!mkdtemp(dir)) {
        fprintf(stderr, "cannot make a temporary folder\n");
        return 1;
    }
    RUN(test_grey_is_grey);
    RUN(test_data_maps_are_raw);
    RUN(test_environment_file);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    check_shell(cmd);
    return check_finish();
}

#else

int main(void)
{
    check_skip("needs libsample_io and zlib");
    return check_finish();
}

#endif
