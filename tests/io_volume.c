/*
 * Volume images (doc/volumes.md, "Files"): oiiotool writes three 4 × 2
 * slices of constant colours as a multi-page TIFF (float and 8-bit) and a
 * multi-part OpenEXR, and a TIFF whose pages differ in size;
 * sample_io_read_volume reads the pages or parts as slices, in order, the
 * values as stored; the mismatched file, a directory and a missing file are
 * refused with a message; `texsample info --volume` reads the TIFF too
 * (lookup --volume loads a volume through the same function, volload.c;
 * one start of the image program is enough). Skipped (77) without
 * oiiotool.
 *
 *   io_volume SCRATCH OIIOTOOL TEXSAMPLE
 */
#include "check.h"
#include "sample/sample_io.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *dir, *oiiotool, *texsample;

static const float colour[3][3] = {{0.25f, 0.5f, 0.75f}, {1.0f, 0.0f, 0.5f}, {0.0f, 0.125f, 1.0f}};

static void read_slices(const char *name, float tol)
{
    char path[1024];
    sample_texture *tex = NULL;
    sample_texture_info info;
    sample_error err;
    float t[4];
    int k, c;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    CHECK(sample_io_read_volume(path, NULL, &tex, &err) == SAMPLE_OK, "%s: %s", name, err.message);
    if (!tex) return;
    sample_texture_info_get(tex, &info);
    CHECK(info.kind == SAMPLE_TEXTURE_3D && info.width == 4 && info.height == 2 && info.depth == 3 &&
              info.channels == 3 && info.levels == 1,
          "%s: kind %d, %d x %d x %d, %d channels, %d levels", name, (int)info.kind, info.width, info.height,
          info.depth, info.channels, info.levels);
    for (k = 0; k < 3; ++k) {
        sample_texture_texel_layer(tex, 0, k, 3, 1, t);
        for (c = 0; c < 3; ++c) CHECK_NEAR(t[c], colour[k][c], tol);
        CHECK_EQF(t[3], 1.0f);
    }
    sample_texture_destroy(tex);
}

static void refusals(void)
{
    char path[1024];
    sample_texture *tex = (sample_texture *)1;
    sample_error err;
    snprintf(path, sizeof path, "%s/bad.tif", dir);
    CHECK(sample_io_read_volume(path, NULL, &tex, &err) == SAMPLE_E_CORRUPT && !tex, "pages of two sizes");
    CHECK(strstr(err.message, "slice 1 is 2 x 2") != NULL, "says which slice: %s", err.message);
    CHECK(sample_io_read_volume(dir, NULL, &tex, &err) == SAMPLE_E_IO, "a directory: %s", err.message);
    snprintf(path, sizeof path, "%s/none.tif", dir);
    CHECK(sample_io_read_volume(path, NULL, &tex, &err) == SAMPLE_E_IO, "missing: %s", err.message);
}

static void pyramid_of_image(void)
{
    char path[1024];
    sample_texture *tex = NULL;
    sample_mip_params mp;
    sample_texture_info info;
    float t[4];
    sample_mip_params_init(&mp);
    snprintf(path, sizeof path, "%s/vol.exr", dir);
    CHECK(sample_io_read_volume(path, &mp, &tex, NULL) == SAMPLE_OK, "exr with pyramid");
    if (!tex) return;
    sample_texture_info_get(tex, &info);
    CHECK(info.levels == 3, "levels %d", info.levels); /* 4x2x3, 2x1x1, 1x1x1 */
    /* Level 1: odd depth 3 → 1, the polyphase box's thirds. */
    sample_texture_texel_layer(tex, 1, 0, 0, 0, t);
    CHECK_NEAR(t[1], (0.5 + 0.0 + 0.125) / 3.0, 1e-6);
    sample_texture_destroy(tex);
}

static void texsample_reads_it(void)
{
    char cmd[4096], *out;
    if (!texsample || !*texsample) {
        check_skip("texsample was not built");
        return;
    }
    snprintf(cmd, sizeof cmd, "cd '%s' && '%s' info --volume vol.tif >info.txt 2>&1", dir, texsample);
    CHECK(check_shell(cmd) == 0, "%s", cmd);
    out = check_slurp_in(dir, "info.txt");
    CHECK(out && strstr(out, "file      vol.tif\ntexture\nkind      3d\nsize      4 x 2 x 3\n"),
          "info shows the depth: %s", out ? out : "");
    free(out);
}

int main(int argc, char **argv)
{
    char cmd[4096];
    if (argc < 4) return 2;
    dir = argv[1];
    oiiotool = argv[2];
    texsample = argv[3];
    if (!*oiiotool) {
        check_skip("oiiotool was not found (OpenImageIO's tools)");
        return check_finish();
    }
    /* One oiiotool run (it loads OpenImageIO once): three constant 4 × 2
     * slices as pages and parts, and two pages of different sizes. */
    snprintf(cmd, sizeof cmd,
             "cd '%s' && '%s' --pattern constant:color=0.25,0.5,0.75 4x2 3 --pattern constant:color=1,0,0.5 4x2 3 "
             "--pattern constant:color=0,0.125,1 4x2 3 --siappendall -d float -o vol.tif -o vol.exr -d uint8 "
             "-o vol8.tif --pattern constant:color=0.5 4x2 1 --pattern constant:color=0.5 2x2 1 --siappend "
             "-o bad.tif",
             dir, oiiotool);
    if (check_shell(cmd) != 0) {
        fprintf(stderr, "io_volume: %s failed\n", cmd);
        return 1;
    }
    read_slices("vol.tif", 0.0f);
    read_slices("vol.exr", 0.0f);
    /* 8-bit: c / 255 (0.125 is stored as 32 or 31, 0.5 as 128). */
    read_slices("vol8.tif", 0.5f / 255.0f + 1e-6f);
    RUN(refusals);
    RUN(pyramid_of_image);
    RUN(texsample_reads_it);
    return check_finish();
}
