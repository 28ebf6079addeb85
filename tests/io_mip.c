/* Tiled mip-mapped OpenEXR: our writer against the in-memory pyramid, and
 * files made by maketx. Usage: io_mip TESTIMAGES SCRATCH [MAKETX [OIIOTOOL]] */
#include "io_util.h"

static const char *maketx, *oiiotool;

/* A w × h RGBA texture of deterministic values, pyramid `kernel`. */
static sample_texture *make_tex(int w, int h, sample_format fmt, sample_mipgen kernel, int max_levels)
{
    return io_test_texture(w, h, 4, fmt, 12345u, kernel, max_levels);
}

/* Write, read back, compare every level exactly. */
static void check_file_equals(const sample_texture *t, const char *name, int use_float)
{
    char out[1024];
    sample_io_exr_options o;
    sample_error e;
    sample_texture *b;
    sample_texture_info a, bi;
    sample_io_exr_options_init(&o);
    o.use_float = use_float;
    o.tile_w = 16, o.tile_h = 8; /* several tiles per level, partial edge tiles */
    CHECK(sample_io_write_mip_exr(io_path(out, sizeof out, io_scratch, name), t, &o, &e) == SAMPLE_OK, "%s",
          e.message);
    if (!(b = io_read(out, NULL, 1))) return;
    sample_texture_info_get(t, &a);
    sample_texture_info_get(b, &bi);
    CHECK(bi.levels == a.levels, "%s: %d levels read, %d written", name, bi.levels, a.levels);
    CHECK(io_same_texels(t, b, a.levels, 0.0f), "%s: levels differ", name);
    sample_texture_destroy(b);
}

static void test_float_pyramid(void)
{
    sample_texture *t = make_tex(37, 20, SAMPLE_FORMAT_F32, SAMPLE_MIPGEN_BOX, 0);
    if (t) check_file_equals(t, "f32_37x20.exr", 1);
    sample_texture_destroy(t);
}

static void test_half_pyramid(void)
{
    /* Half storage round-trips exactly through a half file. */
    sample_texture *t = make_tex(64, 5, SAMPLE_FORMAT_F16, SAMPLE_MIPGEN_LANCZOS3, 0);
    if (t) check_file_equals(t, "f16_64x5.exr", 0);
    sample_texture_destroy(t);
}

static void test_srgb_pyramid(void)
{
    /* An SRGB8 pyramid is written as its decoded linear values. */
    char in[1024];
    sample_mip_params mip;
    sample_texture *t = NULL;
    sample_error e;
    sample_mip_params_init(&mip);
    CHECK(sample_io_read_texture(io_path(in, sizeof in, io_images, "rgba8.png"), NULL, &mip, &t, &e) == SAMPLE_OK,
          "%s", e.message);
    if (t) check_file_equals(t, "srgb8.exr", 1);
    sample_texture_destroy(t);
}

static void test_one_level_and_partial(void)
{
    char out[1024];
    sample_texture *one = make_tex(9, 9, SAMPLE_FORMAT_F32, SAMPLE_MIPGEN_NONE, 0);
    sample_texture *part = make_tex(16, 16, SAMPLE_FORMAT_F32, SAMPLE_MIPGEN_BOX, 2);
    sample_error e;
    if (one) check_file_equals(one, "one_level.exr", 1);
    if (part) {
        CHECK(sample_io_write_mip_exr(io_path(out, sizeof out, io_scratch, "partial.exr"), part, NULL, &e) ==
                  SAMPLE_E_UNSUPPORTED,
              "a partial chain must be refused");
        CHECK(!io_exists(out) && io_count_tmp(io_scratch) == 0, "refused write left a file");
    }
    sample_texture_destroy(one);
    sample_texture_destroy(part);
}

static int run(const char *cmd)
{
    int rc = system(cmd);
    CHECK(rc == 0, "'%s' failed (%d)", cmd, rc);
    return rc;
}

/* maketx's levels are taken from the file as stored: each level equals the
 * one oiiotool extracts with --selectmip. Lanczos-3 (not our default box)
 * so that a rebuilt pyramid could not pass by accident. */
static void test_maketx(void)
{
    static const char *const outs[] = {"maketx.exr", "maketx.tx"};
    char in[1024], cmd[4096];
    size_t f;
    int k;
    if (!maketx || !*maketx || !oiiotool || !*oiiotool) {
        check_skip("maketx or oiiotool not found: maketx's pyramids not compared");
        return;
    }
    io_path(in, sizeof in, io_images, "rgba_half.exr");
    for (f = 0; f < 2; ++f) {
        char out[1024];
        sample_texture *t;
        sample_texture_info inf;
        io_path(out, sizeof out, io_scratch, outs[f]);
        snprintf(cmd, sizeof cmd, "'%s' --filter lanczos3 -d float '%s' -o '%s'", maketx, in, out);
        if (run(cmd) != 0 || !(t = io_read(out, NULL, 1))) continue;
        sample_texture_info_get(t, &inf);
        CHECK(inf.levels == 4, "%s: 13 x 9 has 4 levels, read %d", outs[f], inf.levels);
        for (k = 0; k < inf.levels; ++k) {
            char lv[1024], name[64];
            sample_texture *l;
            snprintf(name, sizeof name, "%s.level%d.exr", outs[f], k);
            io_path(lv, sizeof lv, io_scratch, name);
            snprintf(cmd, sizeof cmd, "'%s' '%s' --selectmip %d -d float -o '%s'", oiiotool, out, k, lv);
            if (run(cmd) != 0 || !(l = io_read(lv, NULL, 0))) continue;
            {
                /* Compare level k of t with level 0 of l. */
                int w, h, lw, lh, i, j, c, bad = 0;
                sample_texture_level_size(t, k, &w, &h);
                sample_texture_level_size(l, 0, &lw, &lh);
                CHECK(w == lw && h == lh, "%s level %d: %d x %d vs %d x %d", outs[f], k, w, h, lw, lh);
                for (j = 0; j < h && w == lw && h == lh; ++j)
                    for (i = 0; i < w; ++i) {
                        float a[4], b[4];
                        sample_texture_texel(t, k, i, j, a);
                        sample_texture_texel(l, 0, i, j, b);
                        for (c = 0; c < 4; ++c) bad += a[c] != b[c];
                    }
                CHECK(bad == 0, "%s level %d: %d values differ from the file's level", outs[f], k, bad);
            }
            sample_texture_destroy(l);
        }
        sample_texture_destroy(t);
    }
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_mip TESTIMAGES SCRATCH [MAKETX [OIIOTOOL]]\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    maketx = argc > 3 ? argv[3] : NULL;
    oiiotool = argc > 4 ? argv[4] : NULL;
    RUN(test_float_pyramid);
    RUN(test_half_pyramid);
    RUN(test_srgb_pyramid);
    RUN(test_one_level_and_partial);
    RUN(test_maketx);
    return check_finish();
}
