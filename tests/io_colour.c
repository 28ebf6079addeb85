/* Colour conversion of known values through the shipped OCIO config.
 * Usage: io_colour TESTIMAGES_DIR SCRATCH_DIR */
#include "io_util.h"
#include "io_internal.h"

static io_colour *col;

/* One RGB triple through name → scene_linear (or back). */
static void conv(const char *name, int to_linear, float r, float g, float b, float out[3])
{
    sample_error e;
    out[0] = r, out[1] = g, out[2] = b;
    CHECK(io_colour_apply(col, name, to_linear, out, 1, 3, &e) == SAMPLE_OK, "%s: %s", name, e.message);
}

static void test_srgb(void)
{
    float v[3];
    conv("srgb", 1, 0.5f, 1.0f, 0.0f, v);
    CHECK_NEAR(v[0], 0.214041, 1e-6); /* ((0.5 + 0.055) / 1.055)^2.4 */
    CHECK_NEAR(v[1], 1.0, 1e-6);
    CHECK_NEAR(v[2], 0.0, 1e-7);
    conv("srgb", 1, 0.04045f, 0.2f, 0.8f, v);
    CHECK_NEAR(v[0], 0.0031308, 2e-6); /* the break point, linear segment */
    CHECK_NEAR(v[1], 0.0331048, 1e-6);
    CHECK_NEAR(v[2], 0.6038273, 1e-6);
    conv("sRGB", 0, 0.214041f, 0.18f, 0.0f, v); /* alias, inverse direction */
    CHECK_NEAR(v[0], 0.5, 1e-6);
    CHECK_NEAR(v[1], 0.4613561, 1e-6);
    CHECK(io_colour_is_srgb(col, "srgb"), "srgb must be recognised as the exact sRGB EOTF");
    CHECK(!io_colour_is_srgb(col, "g22_rec709"), "gamma 2.2 is not sRGB");
    CHECK(!io_colour_is_srgb(col, "lin_rec709"), "linear is not sRGB");
}

static void test_others(void)
{
    float v[3];
    conv("g22_rec709", 1, 0.5f, 0.25f, 1.0f, v);
    CHECK_NEAR(v[0], 0.2176376, 1e-6); /* 0.5^2.2 */
    CHECK_NEAR(v[1], 0.0473661, 1e-6);
    CHECK_NEAR(v[2], 1.0, 1e-6);
    conv("acescg", 1, 1.0f, 0.0f, 0.0f, v); /* AP1 red in linear Rec.709 */
    CHECK_NEAR(v[0], 1.7050510, 1e-5);
    CHECK_NEAR(v[1], -0.1302564, 1e-5);
    CHECK_NEAR(v[2], -0.0240034, 1e-5);
    conv("acescg", 1, 0.18f, 0.18f, 0.18f, v); /* neutral stays neutral */
    CHECK_NEAR(v[0], 0.18, 1e-5);
    CHECK_NEAR(v[1], 0.18, 1e-5);
    conv("raw", 1, 0.5f, 7.0f, -1.0f, v);
    CHECK_EQF(v[0], 0.5f);
    CHECK_EQF(v[1], 7.0f);
    CHECK_EQF(v[2], -1.0f);
    CHECK(io_colour_is_linear(col, "raw") && io_colour_is_linear(col, "linear") &&
              io_colour_is_linear(col, "scene_linear") && !io_colour_is_linear(col, "srgb"),
          "linear/data classification");
    CHECK(!io_colour_known(col, "no such space") && io_colour_known(col, "ACEScg"), "name resolution");
}

/* Grey (1 channel) converts as grey; alpha (4th) is never converted. */
static void test_channels(void)
{
    float g[2] = {0.5f, 0.5f}, rgba[4] = {0.5f, 0.5f, 0.5f, 0.5f};
    sample_error e;
    CHECK(io_colour_apply(col, "srgb", 1, g, 1, 2, &e) == SAMPLE_OK, "%s", e.message);
    CHECK_NEAR(g[0], 0.214041, 1e-6);
    CHECK_EQF(g[1], 0.5f);
    CHECK(io_colour_apply(col, "srgb", 1, rgba, 1, 4, &e) == SAMPLE_OK, "%s", e.message);
    CHECK_NEAR(rgba[2], 0.214041, 1e-6);
    CHECK_EQF(rgba[3], 0.5f);
}

/* End to end through the public API: linear 0.214041 written "in sRGB" to
 * a float file holds 0.5; read back as raw it is 0.5, as sRGB 0.214041,
 * and by metadata ("Linear") it is 0.5 again. */
static void test_public(void)
{
    float px[4] = {0.214041f, 1.0f, 0.0f, 1.0f};
    char out[1024];
    sample_io_write_options wo;
    sample_texture *t;
    sample_error e;
    float v[4];
    sample_io_write_options_init(&wo);
    wo.colorspace = "srgb";
    wo.type = SAMPLE_IO_TYPE_FLOAT;
    CHECK(sample_io_write_image_ex(io_path(out, sizeof out, io_scratch, "srgb_float.exr"), px, 1, 1, 4, &wo, &e) ==
              SAMPLE_OK,
          "%s", e.message);
    if ((t = io_read(out, "raw", 1)) != NULL) {
        sample_texture_texel(t, 0, 0, 0, v);
        CHECK_NEAR(v[0], 0.5, 1e-6);
        sample_texture_destroy(t);
    }
    /* OpenEXR files always read as "Linear" (OIIO does not store the name
     * there), so the source space is given explicitly. */
    if ((t = io_read(out, "srgb", 1)) != NULL) {
        sample_texture_texel(t, 0, 0, 0, v);
        CHECK_NEAR(v[0], 0.214041, 1e-6);
        sample_texture_destroy(t);
    }
    if ((t = io_read(out, NULL, 1)) != NULL) {
        sample_texture_texel(t, 0, 0, 0, v);
        CHECK_NEAR(v[0], 0.5, 1e-6);
        sample_texture_destroy(t);
    }
}

int main(int argc, char **argv)
{
    sample_error e;
    if (argc < 3) return fprintf(stderr, "usage: io_colour TESTIMAGES_DIR SCRATCH_DIR\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    if (io_colour_open(NULL, &col, &e) != SAMPLE_OK) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    RUN(test_srgb);
    RUN(test_others);
    RUN(test_channels);
    RUN(test_public);
    io_colour_close(col);
    return check_finish();
}
