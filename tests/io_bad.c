/* Bad input to every libsample_io entry point: a clear error, nothing
 * returned, no file (or temporary) left behind. Run under ASan/LSan in CI.
 * Usage: io_bad TESTIMAGES_DIR SCRATCH_DIR */
#include "io_util.h"

#include <stdint.h>

static size_t slurp(const char *name, unsigned char *buf, size_t cap)
{
    char p[1024];
    FILE *f = fopen(io_path(p, sizeof p, io_images, name), "rb");
    size_t n = f ? fread(buf, 1, cap, f) : 0;
    if (f) fclose(f);
    CHECK(n > 0, "cannot read %s", p);
    return n;
}

static void spit(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    CHECK(f && fwrite(data, 1, n, f) == n, "cannot write %s", path);
    if (f) fclose(f);
}

/* Reading `path` (or the bytes, when data is non-NULL) must fail with `want`
 * (or any error when want is SAMPLE_OK), with a message and no texture. */
static void expect_read_error(const char *path, const void *data, size_t n, const char *hint, sample_status want,
                              const char *what)
{
    sample_texture *t = (sample_texture *)&t; /* must be reset to NULL */
    sample_error e;
    sample_status st;
    e.message[0] = '\0';
    st = data ? sample_io_read_memory(data, n, hint, NULL, NULL, &t, &e) : sample_io_read_texture(path, NULL, NULL, &t, &e);
    CHECK(st != SAMPLE_OK && (want == SAMPLE_OK || st == want), "%s: status %s (%s)", what, sample_strerror(st),
          e.message);
    CHECK(t == NULL, "%s: a texture was returned with an error", what);
    CHECK(st == SAMPLE_OK || e.message[0] != '\0', "%s: no message", what);
    if (st == SAMPLE_OK) sample_texture_destroy(t);
}

static void test_missing_and_empty(void)
{
    char p[1024];
    expect_read_error(io_path(p, sizeof p, io_scratch, "does-not-exist.png"), NULL, 0, NULL, SAMPLE_E_IO, "missing");
    spit(io_path(p, sizeof p, io_scratch, "empty.png"), "", 0);
    expect_read_error(p, NULL, 0, NULL, SAMPLE_OK, "zero-size file");
    expect_read_error(NULL, "", 0, "png", SAMPLE_E_CORRUPT, "zero-size memory");
    expect_read_error(NULL, NULL, 0, NULL, SAMPLE_E_INVALID_ARGUMENT, "NULL path");
}

static void test_truncated_and_corrupt(void)
{
    static const char *const names[] = {"rgb8.png", "rgba16.tif", "rgba_half.exr", "rgb8.jpg", "rgb.hdr"};
    /* Where the header is damaged: the magic number, except for Radiance
     * HDR, whose reader does not insist on "#?", so its resolution line. */
    static const size_t at[] = {0, 0, 0, 0, 35};
    unsigned char buf[65536];
    char p[1024], what[128];
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; ++k) {
        size_t n = slurp(names[k], buf, sizeof buf);
        snprintf(what, sizeof what, "%s truncated to half", names[k]);
        snprintf(p, sizeof p, "%s/trunc_%s", io_scratch, names[k]);
        spit(p, buf, n / 2);
        expect_read_error(p, NULL, 0, NULL, SAMPLE_OK, what);
        /* Corrupt header: three bytes inverted. */
        buf[at[k]] ^= 0xff, buf[at[k] + 1] ^= 0xff, buf[at[k] + 2] ^= 0xff;
        snprintf(what, sizeof what, "%s with a corrupt header", names[k]);
        snprintf(p, sizeof p, "%s/corrupt_%s", io_scratch, names[k]);
        spit(p, buf, n);
        expect_read_error(p, NULL, 0, NULL, SAMPLE_OK, what);
        expect_read_error(NULL, buf, n, names[k], SAMPLE_OK, what);
    }
}

/* Every prefix length of every test image (in steps) from memory: an error
 * or a texture, never a crash, hang or leak. */
static void test_prefixes(void)
{
    static const char *const names[] = {"rgb8.png", "rgba16.tif", "rgba_half.exr", "rgb_float.exr", "rgb.hdr",
                                        "rgb8.tga", "rgb8.jpg"};
    unsigned char buf[65536];
    size_t k, len;
    for (k = 0; k < sizeof names / sizeof names[0]; ++k) {
        size_t n = slurp(names[k], buf, sizeof buf), step = n / 23 + 1;
        for (len = 1; len < n; len += step) {
            sample_texture *t = NULL;
            sample_error e;
            sample_status st = sample_io_read_memory(buf, len, names[k], NULL, NULL, &t, &e);
            CHECK((st == SAMPLE_OK) == (t != NULL), "%s[%zu]: status and texture disagree", names[k], len);
            sample_texture_destroy(t);
        }
    }
}

static uint32_t crc32(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    size_t i;
    int k;
    for (i = 0; i < n; ++i) {
        c ^= p[i];
        for (k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

static void be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16), p[2] = (unsigned char)(v >> 8),
    p[3] = (unsigned char)v;
}

/* 100000 × 100000 claimed: refused before any pixel is allocated. */
static void test_huge(void)
{
    static const char hdr[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n\x02\x02\x80\x00";
    unsigned char png[65536];
    size_t n;
    char p[1024];
    sample_io_options o;
    sample_texture *t = NULL;
    sample_error e;
    n = slurp("rgb8.png", png, sizeof png);
    /* IHDR data at bytes 16..28, its CRC (over type + data) at 29..32. */
    be32(png + 16, 100000);
    be32(png + 20, 100000);
    be32(png + 29, crc32(png + 12, 17));
    spit(io_path(p, sizeof p, io_scratch, "huge.png"), png, n);
    expect_read_error(p, NULL, 0, NULL, SAMPLE_E_TOO_LARGE, "100000 x 100000 PNG");
    spit(io_path(p, sizeof p, io_scratch, "huge.hdr"), hdr, sizeof hdr - 1);
    expect_read_error(p, NULL, 0, NULL, SAMPLE_E_TOO_LARGE, "100000 x 100000 HDR");
    /* The byte budget. */
    sample_io_options_init(&o);
    o.max_bytes = 100;
    CHECK(sample_io_read_texture(io_path(p, sizeof p, io_images, "rgb8.png"), &o, NULL, &t, &e) ==
              SAMPLE_E_TOO_LARGE && !t,
          "max_bytes not enforced");
}

static void test_bad_colour(void)
{
    char p[1024], out[1024];
    sample_io_options o;
    sample_texture *t = NULL;
    sample_error e;
    float px[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    sample_io_options_init(&o);
    o.colorspace = "Not A Space";
    CHECK(sample_io_read_texture(io_path(p, sizeof p, io_images, "rgb8.png"), &o, NULL, &t, &e) == SAMPLE_E_COLOR && !t,
          "unknown colour space on read");
    CHECK(strstr(e.message, "Not A Space") != NULL, "message names the space: %s", e.message);
    o.colorspace = NULL;
    o.ocio_config = "/nonexistent/config.ocio";
    CHECK(sample_io_read_texture(p, &o, NULL, &t, &e) == SAMPLE_E_COLOR && !t, "missing OCIO config");
    CHECK(sample_io_write_image(io_path(out, sizeof out, io_scratch, "badcs.png"), px, 1, 1, 4, "Not A Space", &e) ==
              SAMPLE_E_COLOR,
          "unknown colour space on write");
    CHECK(!io_exists(out), "a failed write left %s", out);
}

static void test_bad_writes(void)
{
    static const char *const names[] = {"a", "b", "a"};
    float px[4 * 4] = {0};
    char out[1024], dir[1024];
    sample_error e;
    io_path(out, sizeof out, io_scratch, "w.png");
    CHECK(sample_io_write_image(out, px, 2, 2, 2, NULL, &e) == SAMPLE_E_INVALID_ARGUMENT, "2 channels accepted");
    CHECK(sample_io_write_image(out, px, 2, 2, 5, NULL, &e) == SAMPLE_E_INVALID_ARGUMENT, "5 channels accepted");
    CHECK(sample_io_write_image(out, px, 0, 2, 4, NULL, &e) == SAMPLE_E_BAD_SIZE, "zero width accepted");
    CHECK(sample_io_write_image(out, px, 100000, 2, 4, NULL, &e) == SAMPLE_E_TOO_LARGE, "huge width accepted");
    CHECK(sample_io_write_image(out, NULL, 2, 2, 4, NULL, &e) == SAMPLE_E_INVALID_ARGUMENT, "NULL pixels accepted");
    CHECK(sample_io_write_channels(out, px, 2, 2, 0, names, &e) == SAMPLE_E_INVALID_ARGUMENT, "0 channels");
    CHECK(sample_io_write_channels(io_path(out, sizeof out, io_scratch, "dup.exr"), px, 2, 2, 3, names, &e) ==
              SAMPLE_E_INVALID_ARGUMENT,
          "duplicate channel names");
    CHECK(!io_exists(out), "refused write left a file");
    /* Failures after the temporary file exists: nothing may remain. */
    CHECK(sample_io_write_image(io_path(out, sizeof out, io_scratch, "alpha.jpg"), px, 2, 2, 4, NULL, &e) ==
              SAMPLE_E_UNSUPPORTED,
          "JPEG with alpha: %s", e.message);
    CHECK(!io_exists(out), "left %s", out);
    CHECK(sample_io_write_image(io_path(out, sizeof out, io_scratch, "x.unknownext"), px, 2, 2, 4, NULL, &e) ==
              SAMPLE_E_UNSUPPORTED,
          "unknown extension: %s", e.message);
    CHECK(!io_exists(out), "left %s", out);
    CHECK(sample_io_write_image(io_path(out, sizeof out, io_scratch, "no/such/dir/x.png"), px, 2, 2, 4, NULL, &e) ==
              SAMPLE_E_IO,
          "missing directory: %s", e.message);
    /* The target is a directory: the rename fails, the temporary goes. */
    io_path(dir, sizeof dir, io_scratch, "isdir.png");
    mkdir(dir, 0777);
    CHECK(sample_io_write_image(dir, px, 2, 2, 4, NULL, &e) == SAMPLE_E_IO, "directory target: %s", e.message);
    CHECK(sample_io_write_channels(dir, px, 2, 2, 2, names, &e) == SAMPLE_E_IO, "directory target (channels)");
    CHECK(io_count_tmp(io_scratch) == 0, "temporary files left in %s", io_scratch);
    /* A good write of channels for contrast. */
    CHECK(sample_io_write_channels(io_path(out, sizeof out, io_scratch, "ok.exr"), px, 2, 2, 2, names, &e) ==
              SAMPLE_OK && io_exists(out),
          "%s", e.message);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_bad TESTIMAGES_DIR SCRATCH_DIR\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    RUN(test_missing_and_empty);
    RUN(test_truncated_and_corrupt);
    RUN(test_prefixes);
    RUN(test_huge);
    RUN(test_bad_colour);
    RUN(test_bad_writes);
    return check_finish();
}
