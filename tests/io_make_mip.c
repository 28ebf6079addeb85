#define _GNU_SOURCE /* memmem */
/* sample_io_make_mip, what `texsample mip` runs, loses nothing
 * (doc/io-and-colour.md, "texsample mip"): levels built in float from the
 * file's linear values, not from an 8-bit level above; straight alpha
 * multiplied in so that transparent colour does not bleed; channel names
 * and counts kept or refused; the output format the extension names; 8-bit
 * sRGB output in TIFF; half overflow counted or clamped. Files are read
 * back through libsample_io (and compared with maketx's where installed).
 * Usage: io_make_mip TESTIMAGES SCRATCH [MAKETX] */
#include "io_util.h"
#include "io_internal.h"

#include <stdint.h>

static const char *maketx;
static sample_error make_err;

/* sample_io_make_mip(in, SCRATCH/out) with write options `wo` (NULL:
 * defaults); the message stays in make_err. */
static sample_status make(const char *in, const char *out, const sample_io_exr_options *wo)
{
    char p[1024];
    make_err.message[0] = '\0';
    return sample_io_make_mip(in, io_path(p, sizeof p, io_scratch, out), NULL, NULL, wo, &make_err);
}

/* Write an 8-bit picture with named channels, as the file's own writer
 * would (no colour conversion: the codes are given). */
static void write_u8(const char *name, const unsigned char *px, int w, int h, int nchan,
                     const char *const *names, char *path, size_t size)
{
    io_colour_label srgb = {"sRGB", 0, {0}};
    sample_error e;
    io_path(path, size, io_scratch, name);
    CHECK(io_oiio_write(path, path, px, IO_U8, w, h, nchan, names, &srgb, &e) == SAMPLE_OK, "%s: %s", name,
          e.message);
}

static double srgb_decode(unsigned char code)
{
    double c = code / 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* Level 1 of a random 96 × 64 sRGB PNG is the 2 × 2 box of the decoded
 * base, and level 2 the 4 × 4 box, to half's rounding (2^−12 relative, at
 * most 2.5e-4 below 1): the levels are built in float, never re-quantised
 * to 8 bits on the way (that costs up to 3.7e-3). */
static void test_float_levels(void)
{
    enum { W = 96, H = 64 };
    static unsigned char px[W * H * 3];
    char in[1024];
    sample_texture *t;
    unsigned x = 2024u;
    double worst = 0.0;
    int i, j, c, k;
    for (i = 0; i < W * H * 3; ++i) {
        x = x * 1664525u + 1013904223u;
        px[i] = (unsigned char)(x >> 24);
    }
    write_u8("random.png", px, W, H, 3, NULL, in, sizeof in);
    CHECK(make(in, "random.exr", NULL) == SAMPLE_OK, "random.png: %s", make_err.message);
    if (!(t = io_read(io_path(in, sizeof in, io_scratch, "random.exr"), NULL, 1))) return;
    for (k = 1; k <= 2; ++k)
        for (j = 0; j < H >> k; ++j)
            for (i = 0; i < W >> k; ++i) {
                float v[4];
                sample_texture_texel(t, k, i, j, v);
                for (c = 0; c < 3; ++c) {
                    double sum = 0.0, want;
                    int a, b, n = 1 << k;
                    for (b = 0; b < n; ++b)
                        for (a = 0; a < n; ++a) sum += srgb_decode(px[((j * n + b) * W + i * n + a) * 3 + c]);
                    want = sum / (n * n);
                    if (fabs(v[c] - want) > worst) worst = fabs(v[c] - want);
                }
            }
    CHECK(worst <= 2.5e-4, "levels 1-2 are %.3g from the linear-light box (half allows 2.5e-4)", worst);
    sample_texture_destroy(t);
}

/* An 8 × 8 PNG, opaque red on the left half, transparent green on the
 * right: premultiplied, green weighs nothing, so level 3 (1 × 1) is
 * (0.5, 0, 0, 0.5), as maketx makes it; straight filtering gave
 * (0.5, 0.5, 0, 0.5). The file says its colour is premultiplied. */
static void test_alpha_premultiplied(void)
{
    static unsigned char px[8 * 8 * 4];
    char in[1024], out[1024];
    sample_texture *t;
    int i;
    for (i = 0; i < 64; ++i) {
        unsigned char *p = px + 4 * i;
        int left = i % 8 < 4;
        p[0] = left ? 255 : 0, p[1] = left ? 0 : 255, p[2] = 0, p[3] = left ? 255 : 0;
    }
    write_u8("halfalpha.png", px, 8, 8, 4, NULL, in, sizeof in);
    io_path(out, sizeof out, io_scratch, "halfalpha.exr");
    CHECK(make(in, "halfalpha.exr", NULL) == SAMPLE_OK, "halfalpha.png: %s", make_err.message);
    if ((t = io_read(out, NULL, 1)) != NULL) {
        float v[4];
        sample_texture_texel(t, 3, 0, 0, v);
        CHECK(v[0] == 0.5f && v[1] == 0.0f && v[2] == 0.0f && v[3] == 0.5f, "level 3 is %g %g %g %g, not 0.5 0 0 0.5",
              (double)v[0], (double)v[1], (double)v[2], (double)v[3]);
        sample_texture_texel(t, 0, 7, 0, v);
        CHECK(v[0] == 0.0f && v[1] == 0.0f && v[3] == 0.0f, "transparent green stored as %g %g %g %g", (double)v[0],
              (double)v[1], (double)v[2], (double)v[3]);
        sample_texture_destroy(t);
    }
    {
        char *hdr = NULL;
        size_t n = 0;
        hdr = (char *)check_slurp(out, &n);
        CHECK(hdr && memmem(hdr, n, "libsample:alpha", 16) && memmem(hdr, n, "premultiplied", 13),
              "the file does not say its colour is premultiplied");
        free(hdr);
    }
    if (maketx && *maketx) {
        char cmd[4096];
        snprintf(cmd, sizeof cmd, "'%s' '%s' -o '%s/halfalpha_maketx.exr' >/dev/null 2>&1", maketx, in, io_scratch);
        CHECK(check_shell(cmd) == 0, "maketx failed");
        if ((t = io_read(io_path(out, sizeof out, io_scratch, "halfalpha_maketx.exr"), NULL, 1)) != NULL) {
            float v[4];
            sample_texture_texel(t, 3, 0, 0, v);
            CHECK(v[0] == 0.5f && v[1] == 0.0f && v[3] == 0.5f, "maketx: level 3 is %g %g %g %g", (double)v[0],
                  (double)v[1], (double)v[2], (double)v[3]);
            sample_texture_destroy(t);
        }
    } else {
        check_skip("maketx not found: our premultiplied level not compared with maketx's");
    }
}

/* Channel names and counts: grey stays Y, grey + alpha stays Y, A (and
 * is premultiplied: a half-transparent white is 0.5 0.5); five channels
 * are refused, naming them. */
static void test_channels(void)
{
    static const char *const ya[2] = {"Y", "A"}, *const five[5] = {"R", "G", "B", "A", "Z"};
    static unsigned char grey_alpha[4 * 2 * 2];
    static float f5[2 * 2 * 5];
    sample_io_file_info fi;
    sample_error e;
    char in[1024], out[1024];
    int i;
    CHECK(make(io_path(in, sizeof in, io_images, "grey8.png"), "grey.exr", NULL) == SAMPLE_OK, "grey8.png: %s",
          make_err.message);
    CHECK(sample_io_describe(io_path(out, sizeof out, io_scratch, "grey.exr"), NULL, &fi, &e) == SAMPLE_OK, "%s",
          e.message);
    CHECK(fi.channels == 1 && strcmp(fi.channel_names[0], "Y") == 0, "grey came out as %d channels, %s",
          fi.channels, fi.channel_names[0]);
    for (i = 0; i < 8; ++i) grey_alpha[2 * i] = 255, grey_alpha[2 * i + 1] = 128;
    write_u8("ya.png", grey_alpha, 4, 2, 2, ya, in, sizeof in);
    CHECK(make(in, "ya.exr", NULL) == SAMPLE_OK, "ya.png: %s", make_err.message);
    CHECK(sample_io_describe(io_path(out, sizeof out, io_scratch, "ya.exr"), NULL, &fi, &e) == SAMPLE_OK, "%s",
          e.message);
    CHECK(fi.channels == 2 && strcmp(fi.channel_names[0], "Y") == 0 && strcmp(fi.channel_names[1], "A") == 0 &&
              fi.alpha_channel == 1,
          "grey + alpha came out as %d channels, %s %s, alpha %d", fi.channels, fi.channel_names[0],
          fi.channel_names[1], fi.alpha_channel);
    {
        sample_texture *t = io_read(out, NULL, 1);
        float v[4];
        if (t) {
            sample_texture_texel(t, 0, 0, 0, v);
            CHECK_NEAR(v[0], 128.0 / 255.0, 2.5e-4);
            CHECK_NEAR(v[1], 128.0 / 255.0, 2.5e-4);
            sample_texture_destroy(t);
        }
    }
    for (i = 0; i < 20; ++i) f5[i] = (float)i;
    CHECK(sample_io_write_channels(io_path(in, sizeof in, io_scratch, "five.exr"), f5, 2, 2, 5, five, &e) == SAMPLE_OK,
          "%s", e.message);
    CHECK(make(in, "five_out.exr", NULL) == SAMPLE_E_UNSUPPORTED &&
              strstr(make_err.message, "has 5 channels (R, G, B, A, Z); a texture holds at most 4"),
          "5 channels: %s", make_err.message);
    CHECK(!io_exists(io_path(out, sizeof out, io_scratch, "five_out.exr")), "an output was written");
}

/* The extension decides the format: .png is refused (no file); the 8-bit
 * type writes a tiled sRGB TIFF whose levels read back as SRGB8 holding
 * the encoded float levels (within one code); 8-bit OpenEXR is refused. */
static void test_formats(void)
{
    char in[1024], out[1024];
    sample_io_exr_options wo;
    sample_io_file_info fi;
    sample_error e;
    sample_texture *t, *ref;
    io_path(in, sizeof in, io_images, "rgb8.png");
    CHECK(make(in, "out.png", NULL) == SAMPLE_E_INVALID_ARGUMENT && strstr(make_err.message, ".png files hold no mip levels"),
          ".png: %s", make_err.message);
    CHECK(!io_exists(io_path(out, sizeof out, io_scratch, "out.png")), "out.png was written");
    sample_io_exr_options_init(&wo);
    wo.type = SAMPLE_IO_TYPE_U8;
    CHECK(make(in, "u8.exr", &wo) == SAMPLE_E_INVALID_ARGUMENT && strstr(make_err.message, "no 8- or 16-bit"),
          "u8 .exr: %s", make_err.message);
    wo.tile_w = wo.tile_h = 16; /* TIFF tiles are multiples of 16 (TIFF 6.0, section 15) */
    CHECK(make(in, "u8.tx", &wo) == SAMPLE_OK, "u8.tx: %s", make_err.message);
    CHECK(sample_io_describe(io_path(out, sizeof out, io_scratch, "u8.tx"), NULL, &fi, &e) == SAMPLE_OK, "%s",
          e.message);
    CHECK(strcmp(fi.format, "tiff") == 0 && strcmp(fi.pixel_type, "uint8") == 0 && fi.levels == 5 &&
              fi.tile_width == 16 && fi.texture_format == SAMPLE_FORMAT_SRGB8 && fi.texture_file_levels == 5,
          "u8.tx: %s %s, %d levels, tiles %d, format %d, %d file levels", fi.format, fi.pixel_type, fi.levels,
          fi.tile_width, (int)fi.texture_format, fi.texture_file_levels);
    wo.type = SAMPLE_IO_TYPE_FLOAT;
    CHECK(make(in, "f.exr", &wo) == SAMPLE_OK, "f.exr: %s", make_err.message);
    t = io_read(out, NULL, 1);
    ref = io_read(io_path(out, sizeof out, io_scratch, "f.exr"), NULL, 1);
    /* Half an 8-bit sRGB code is at most 0.5/255 · 2.4/1.055 < 0.0045 linear. */
    if (t && ref) CHECK(io_same_texels(t, ref, 5, 0.0045f), "u8 levels differ from the float levels by over a code");
    sample_texture_destroy(t);
    sample_texture_destroy(ref);
}

/* Finite floats beyond half's 65504 are counted (and ±inf in the file), or
 * clamped to ±65504. Level 0 has two; level 1's averages do not. */
static void test_half_overflow(void)
{
    static const char *const rgb[3] = {"R", "G", "B"};
    float px[2 * 2 * 3];
    char in[1024], out[1024];
    sample_io_exr_options wo;
    sample_error e;
    sample_texture *t;
    size_t overflows = 99;
    int i;
    for (i = 0; i < 12; ++i) px[i] = 1.0f;
    px[0] = 1e5f, px[4] = -7e4f;
    CHECK(sample_io_write_channels(io_path(in, sizeof in, io_scratch, "big.exr"), px, 2, 2, 3, rgb, &e) == SAMPLE_OK,
          "%s", e.message);
    sample_io_exr_options_init(&wo);
    wo.half_overflows = &overflows;
    CHECK(make(in, "big_half.exr", &wo) == SAMPLE_OK && overflows == 2, "%zu overflows: %s", overflows,
          make_err.message);
    if ((t = io_read(io_path(out, sizeof out, io_scratch, "big_half.exr"), NULL, 1)) != NULL) {
        float v[4];
        sample_texture_texel(t, 0, 0, 0, v);
        CHECK(isinf(v[0]) && v[0] > 0, "1e5 stored as %g", (double)v[0]);
        sample_texture_destroy(t);
    }
    wo.half_clamp = 1;
    overflows = 99;
    CHECK(make(in, "big_clamp.exr", &wo) == SAMPLE_OK && overflows == 2, "%zu overflows: %s", overflows,
          make_err.message);
    if ((t = io_read(io_path(out, sizeof out, io_scratch, "big_clamp.exr"), NULL, 1)) != NULL) {
        float v[4];
        sample_texture_texel(t, 0, 0, 0, v);
        CHECK(v[0] == 65504.0f, "1e5 clamped to %g", (double)v[0]);
        sample_texture_texel(t, 0, 1, 0, v);
        CHECK(v[1] == -65504.0f, "-7e4 clamped to %g", (double)v[1]);
        sample_texture_texel(t, 0, 1, 1, v);
        CHECK(v[1] == 1.0f, "1.0 became %g", (double)v[1]);
        sample_texture_destroy(t);
    }
}

/* What a read reports through options.file_info is what sample_io_describe
 * says, on the direct OpenEXR path and on OpenImageIO's alike; the written
 * OpenEXR file names the colour space it holds, and both formats store the
 * wrap modes, which both parse. want_colorspace "": the rule decides. */
static void same_file_info(const char *path, int direct, const char *want_format, const char *want_colorspace)
{
    sample_io_options o;
    sample_io_file_info described, read;
    sample_texture *t = NULL;
    sample_error e;
    unsigned long before = io_exr_direct_reads();
    CHECK(sample_io_describe(path, NULL, &described, &e) == SAMPLE_OK, "describe %s: %s", path, e.message);
    sample_io_options_init(&o);
    o.file_info = &read;
    memset(&read, 0xff, sizeof read);
    CHECK(sample_io_read_texture(path, &o, NULL, &t, &e) == SAMPLE_OK, "read %s: %s", path, e.message);
    sample_texture_destroy(t);
    CHECK(io_exr_direct_reads() - before == (unsigned long)direct, "%s: direct reader used %lu times", path,
          io_exr_direct_reads() - before);
    CHECK(memcmp(&described, &read, sizeof read) == 0,
          "%s: read says %s %s %s tiles %d, levels %d/%d, '%s'; describe %s %s %s tiles %d, levels %d/%d, '%s'", path,
          read.format, read.pixel_type, read.compression, read.tile_width, read.levels, read.texture_file_levels,
          read.colorspace, described.format, described.pixel_type, described.compression, described.tile_width,
          described.levels, described.texture_file_levels, described.colorspace);
    CHECK(strcmp(read.format, want_format) == 0 && read.levels == 5 && read.texture_file_levels == 5,
          "%s: %s, %d levels, %d kept", path, read.format, read.levels, read.texture_file_levels);
    CHECK(strcmp(read.wrapmodes, "periodic,mirror") == 0 && read.has_wrap && read.wrap_s == SAMPLE_WRAP_REPEAT &&
              read.wrap_t == SAMPLE_WRAP_MIRRORED_REPEAT,
          "%s: wrapmodes '%s' (%d: %d, %d)", path, read.wrapmodes, read.has_wrap, (int)read.wrap_s,
          (int)read.wrap_t);
    CHECK(strcmp(read.colorspace, want_colorspace) == 0 && !read.colorspace_unknown &&
              read.colorspace_from_rule == !want_colorspace[0],
          "%s: colour space '%s' (unknown %d, rule %d)", path, read.colorspace, read.colorspace_unknown,
          read.colorspace_from_rule);
}

static void test_file_info(void)
{
    char in[1024], out[1024];
    sample_io_exr_options wo;
    sample_mip_params mip;
    sample_error e;
    sample_io_exr_options_init(&wo);
    sample_mip_params_init(&mip);
    mip.wrap_s = SAMPLE_WRAP_REPEAT;
    mip.wrap_t = SAMPLE_WRAP_MIRRORED_REPEAT;
    io_path(in, sizeof in, io_images, "rgb8.png");
    make_err.message[0] = '\0';
    CHECK(sample_io_make_mip(in, io_path(out, sizeof out, io_scratch, "info.exr"), NULL, &mip, NULL, &e) == SAMPLE_OK,
          "info.exr: %s", e.message);
    /* The shipped config's scene_linear space by its own name. */
    same_file_info(out, 1, "openexr", "lin_rec709");
    wo.type = SAMPLE_IO_TYPE_U8;
    wo.tile_w = wo.tile_h = 16;
    CHECK(sample_io_make_mip(in, io_path(out, sizeof out, io_scratch, "info.tx"), NULL, &mip, &wo, &e) == SAMPLE_OK,
          "info.tx: %s", e.message);
    same_file_info(out, 0, "tiff", "sRGB");
    wo.type = SAMPLE_IO_TYPE_HALF;
    CHECK(sample_io_make_mip(in, io_path(out, sizeof out, io_scratch, "info_half.tx"), NULL, &mip, &wo, &e) ==
              SAMPLE_OK,
          "info_half.tx: %s", e.message);
    /* OpenImageIO 2.4's TIFF writer does not store oiio:ColorSpace: its
     * reader says sRGB for 8-bit TIFF and nothing for half, and the rule
     * reads both as they were written. */
    same_file_info(out, 0, "tiff", "");
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_make_mip TESTIMAGES SCRATCH [MAKETX]\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    maketx = argc > 3 ? argv[3] : "";
    RUN(test_float_levels);
    RUN(test_alpha_premultiplied);
    RUN(test_channels);
    RUN(test_formats);
    RUN(test_half_overflow);
    RUN(test_file_info);
    return check_finish();
}
