/* libsample_io reading: storage formats, round trips through the writers,
 * memory reading. Usage: io_read TESTIMAGES_DIR SCRATCH_DIR */
#include "io_util.h"

/* Linear RGBA of level 0 (w × h × 4), caller frees. */
static float *texels(const sample_texture *t, int *w, int *h)
{
    int i, j;
    float *px;
    sample_texture_level_size(t, 0, w, h);
    px = malloc((size_t)*w * (size_t)*h * 4 * sizeof(float));
    if (!px) return NULL;
    for (j = 0; j < *h; ++j)
        for (i = 0; i < *w; ++i) sample_texture_texel(t, 0, i, j, px + 4 * ((size_t)j * (size_t)*w + (size_t)i));
    return px;
}

/* file → texture (expected format/channels) → write as `type` → read →
 * identical texels. */
static void round_trip(const char *name, sample_format want_format, int want_channels, const char *out_name,
                       sample_io_type type)
{
    char in[1024], out[1024];
    sample_texture *a = io_read(io_path(in, sizeof in, io_images, name), NULL, 1), *b;
    sample_texture_info inf;
    sample_io_write_options wo;
    sample_error e;
    float *px;
    int w, h;
    if (!a) return;
    sample_texture_info_get(a, &inf);
    CHECK(inf.format == want_format, "%s: format %s, expected %s", name, sample_format_name(inf.format),
          sample_format_name(want_format));
    CHECK(inf.channels == want_channels, "%s: %d channels, expected %d", name, inf.channels, want_channels);
    CHECK(inf.levels == 1, "%s: %d levels without mip params", name, inf.levels);
    if (out_name) {
        px = texels(a, &w, &h);
        sample_io_write_options_init(&wo);
        wo.type = type;
        CHECK(sample_io_write_image_ex(io_path(out, sizeof out, io_scratch, out_name), px, w, h,
                                       inf.channels == 4 ? 4 : 3, &wo, &e) == SAMPLE_OK,
              "writing %s: %s", out, e.message);
        free(px);
        if ((b = io_read(out, NULL, 1)) != NULL) {
            sample_texture_info ib;
            sample_texture_info_get(b, &ib);
            CHECK(ib.format == inf.format, "%s: re-read as %s", out_name, sample_format_name(ib.format));
            CHECK(io_same_texels(a, b, 1, 0.0f), "%s → %s changed texels", name, out_name);
            sample_texture_destroy(b);
        }
    }
    sample_texture_destroy(a);
}

static void test_png8(void) { round_trip("rgb8.png", SAMPLE_FORMAT_SRGB8, 3, "rt_rgb8.png", SAMPLE_IO_TYPE_U8); }
static void test_png8_alpha(void)
{
    /* Straight alpha is kept as stored (no premultiplication on read). */
    round_trip("rgba8.png", SAMPLE_FORMAT_SRGB8, 4, "rt_rgba8.png", SAMPLE_IO_TYPE_U8);
}
static void test_tiff16(void) { round_trip("rgba16.tif", SAMPLE_FORMAT_F32, 4, "rt_rgba16.tif", SAMPLE_IO_TYPE_U16); }
static void test_exr_half(void)
{
    round_trip("rgba_half.exr", SAMPLE_FORMAT_F16, 4, "rt_half.exr", SAMPLE_IO_TYPE_HALF);
}
static void test_exr_float(void)
{
    round_trip("rgb_float.exr", SAMPLE_FORMAT_F32, 3, "rt_float.exr", SAMPLE_IO_TYPE_FLOAT);
}
static void test_other_formats(void)
{
    round_trip("grey8.png", SAMPLE_FORMAT_SRGB8, 1, NULL, SAMPLE_IO_TYPE_AUTO);
    round_trip("rgb8.tga", SAMPLE_FORMAT_SRGB8, 3, NULL, SAMPLE_IO_TYPE_AUTO);
    round_trip("rgb8.jpg", SAMPLE_FORMAT_SRGB8, 3, NULL, SAMPLE_IO_TYPE_AUTO);
    round_trip("rgb.hdr", SAMPLE_FORMAT_F32, 3, NULL, SAMPLE_IO_TYPE_AUTO);
}

/* Linear 8-bit data stays UNORM8 (no conversion); another curve becomes
 * half through OCIO. */
static void test_colorspace_storage(void)
{
    char in[1024];
    sample_texture *lin = io_read(io_path(in, sizeof in, io_images, "rgb8.png"), "raw", 1);
    sample_texture *g22 = io_read(in, "g22_rec709", 1), *srgb = io_read(in, "srgb", 1);
    sample_texture_info a, b;
    float x[4], y[4], z[4];
    if (!lin || !g22 || !srgb) goto done;
    sample_texture_info_get(lin, &a);
    sample_texture_info_get(g22, &b);
    CHECK(a.format == SAMPLE_FORMAT_UNORM8, "raw 8-bit stored as %s", sample_format_name(a.format));
    CHECK(b.format == SAMPLE_FORMAT_F16, "gamma 2.2 8-bit stored as %s", sample_format_name(b.format));
    sample_texture_texel(lin, 0, 3, 2, x);
    sample_texture_texel(g22, 0, 3, 2, y);
    sample_texture_texel(srgb, 0, 3, 2, z);
    CHECK_NEAR(y[0], sample_half_to_float(sample_float_to_half(powf(x[0], 2.2f))), 1e-3 * y[0] + 1e-6);
    CHECK_NEAR(z[1], sample_srgb_to_linear(x[1]), 1e-7);
done:
    sample_texture_destroy(lin);
    sample_texture_destroy(g22);
    sample_texture_destroy(srgb);
}

/* From memory: the same texture as from the file, or a clear
 * "unsupported" for readers that cannot read memory. */
static void test_memory(void)
{
    static const char *const names[] = {"rgb8.png", "rgba16.tif", "rgba_half.exr", "rgb_float.exr",
                                        "rgb8.tga", "rgb8.jpg", "rgb.hdr"};
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; ++k) {
        char in[1024];
        FILE *f = fopen(io_path(in, sizeof in, io_images, names[k]), "rb");
        unsigned char buf[65536];
        size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
        sample_texture *a, *b = NULL;
        sample_error e;
        sample_status st;
        if (f) fclose(f);
        CHECK(n > 0, "cannot read %s", in);
        st = sample_io_read_memory(buf, n, names[k], NULL, NULL, &b, &e);
        CHECK(st == SAMPLE_OK || st == SAMPLE_E_UNSUPPORTED, "%s from memory: %s", names[k], e.message);
        if (st != SAMPLE_OK) {
            printf("note: %s: %s\n", names[k], e.message);
            continue;
        }
        if ((a = io_read(in, NULL, 1)) != NULL) CHECK(io_same_texels(a, b, 1, 0.0f), "%s: memory != file", names[k]);
        sample_texture_destroy(a);
        sample_texture_destroy(b);
    }
}

/* Row 0 is the file's first stored row: a picture written with a bright
 * row 0 reads back bright at t = 0, and a sampler sees it at small t. */
static void test_row_order(void)
{
    static const float px[2 * 2 * 4] = {1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    char out[1024];
    sample_error e;
    sample_texture *t;
    sample_sampler s;
    float v[4];
    CHECK(sample_io_write_image(io_path(out, sizeof out, io_scratch, "rows.exr"), px, 2, 2, 4, NULL, &e) == SAMPLE_OK,
          "%s", e.message);
    if (!(t = io_read(out, NULL, 1))) return;
    sample_sampler_init(&s);
    s.mag_filter = SAMPLE_NEAREST;
    sample_one(t, &s, &(sample_query){0.5f, 0.25f, 0, 0, 0, 0}, v);
    CHECK_EQF(v[0], 1.0f);
    sample_one(t, &s, &(sample_query){0.5f, 0.75f, 0, 0, 0, 0}, v);
    CHECK_EQF(v[0], 0.0f);
    sample_texture_destroy(t);
}

/* Mip params are used when the file has no levels. */
static void test_mip_params(void)
{
    char in[1024];
    sample_mip_params mip;
    sample_texture *t = NULL;
    sample_texture_info inf;
    sample_error e;
    sample_mip_params_init(&mip);
    CHECK(sample_io_read_texture(io_path(in, sizeof in, io_images, "rgb8.png"), NULL, &mip, &t, &e) == SAMPLE_OK,
          "%s", e.message);
    if (!t) return;
    sample_texture_info_get(t, &inf);
    CHECK(inf.levels == 5, "19 x 13 has 5 levels, got %d", inf.levels); /* 19,9,4,2,1 */
    sample_texture_destroy(t);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: io_read TESTIMAGES_DIR SCRATCH_DIR\n");
        return 2;
    }
    io_images = argv[1];
    io_scratch = argv[2];
    RUN(test_png8);
    RUN(test_png8_alpha);
    RUN(test_tiff16);
    RUN(test_exr_half);
    RUN(test_exr_float);
    RUN(test_other_formats);
    RUN(test_colorspace_storage);
    RUN(test_memory);
    RUN(test_row_order);
    RUN(test_mip_params);
    return check_finish();
}
