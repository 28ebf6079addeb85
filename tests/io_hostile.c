/* Hostile files (doc/guarantees.md, "Files and tools"): what is not a
 * regular file is refused before any library sees it, within a second
 * (a FIFO would block open(2), /dev/zero would feed OpenImageIO's format
 * probe for ever); files whose data cannot hold what their header claims
 * are refused before the pixels are allocated; data a reader would make
 * up is an error. Crafted files are written here, byte by byte.
 * Usage: io_hostile TESTIMAGES SCRATCH */
#define _GNU_SOURCE
#include "io_util.h"

#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Reading `path` fails with `want` and a message containing `words`, in
 * under a second (the alarm set in main ends a hang). */
static void expect_refused(const char *path, const sample_io_options *o, sample_status want, const char *words,
                           const char *what)
{
    sample_texture *t = NULL;
    sample_error e;
    double t0 = now();
    sample_status st;
    e.message[0] = '\0';
    st = sample_io_read_texture(path, o, NULL, &t, &e);
    CHECK(st == want, "%s: status %s, expected %s (%s)", what, sample_strerror(st), sample_strerror(want), e.message);
    CHECK(!t, "%s: a texture was returned", what);
    CHECK(strstr(e.message, words) != NULL, "%s: message '%s' lacks '%s'", what, e.message, words);
    CHECK(now() - t0 < 1.0, "%s: took %.2f s", what, now() - t0);
    sample_texture_destroy(t);
}

static void test_not_regular(void)
{
    char fifo[1024], cfg[1024], img[1024];
    sample_io_options o;
    sample_error e;
    expect_refused("/dev/zero", NULL, SAMPLE_E_IO, "is a character device", "/dev/zero");
    expect_refused(io_scratch, NULL, SAMPLE_E_IO, "is a directory", "a directory");
    io_path(fifo, sizeof fifo, io_scratch, "fifo.png");
    CHECK(mkfifo(fifo, 0600) == 0, "mkfifo %s failed", fifo);
    expect_refused(fifo, NULL, SAMPLE_E_IO, "is a FIFO", "a FIFO");
    /* The OCIO config too (it is read whatever the image). */
    sample_io_options_init(&o);
    o.ocio_config = io_path(cfg, sizeof cfg, io_scratch, "fifo.png");
    expect_refused(io_path(img, sizeof img, io_images, "rgb8.png"), &o, SAMPLE_E_COLOR, "OCIO config", "config FIFO");
    o.ocio_config = "/dev/zero";
    expect_refused(img, &o, SAMPLE_E_COLOR, "is a character device", "config /dev/zero");
    /* The public check itself, as programs call it for their own files. */
    CHECK(sample_io_check_regular_file(img, "image", &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_io_check_regular_file(fifo, "scene", &e) == SAMPLE_E_IO && strstr(e.message, "scene '") &&
              strstr(e.message, "FIFO"),
          "FIFO as a scene: %s", e.message);
    CHECK(sample_io_check_regular_file("/nonexistent/x", NULL, &e) == SAMPLE_E_IO &&
              strstr(e.message, "No such file"),
          "missing: %s", e.message);
    CHECK(sample_io_check_regular_file(NULL, "image", &e) == SAMPLE_E_INVALID_ARGUMENT, "NULL path");
    remove(fifo);
}

/* ---- Crafted files ------------------------------------------------------- */

typedef struct bytes {
    unsigned char b[1024];
    size_t n;
} bytes;

static void put(bytes *o, uint32_t v, int n)
{
    int k;
    for (k = 0; k < n; ++k) o->b[o->n++] = (unsigned char)(v >> (8 * k));
}

static const char *save(const bytes *o, const char *name, char *path, size_t size)
{
    FILE *f = fopen(io_path(path, size, io_scratch, name), "wb");
    CHECK(f && fwrite(o->b, 1, o->n, f) == o->n, "cannot write %s", path);
    if (f) fclose(f);
    return path;
}

/* A little-endian 8-bit grey TIFF: w × h, `rows` per strip, nstrips table
 * entries, strip k at offsets[k] with counts[k] bytes; 8 bytes of data 0x80
 * at offset 8. Tables of more than one entry follow the directory. */
static void tiff(bytes *o, uint32_t w, uint32_t h, uint32_t rows, int nstrips, const uint32_t *offsets,
                 const uint32_t *counts)
{
    const uint32_t nent = 9, ifd = 16, tables = ifd + 2 + nent * 12 + 4;
    int k;
    o->n = 0;
    put(o, 0x002A4949u, 4); /* "II", 42 */
    put(o, ifd, 4);
    for (k = 0; k < 8; ++k) put(o, 0x80, 1);
    put(o, nent, 2);
#define ENTRY(tag, type, count, value) (put(o, tag, 2), put(o, type, 2), put(o, count, 4), put(o, value, 4))
    ENTRY(256, 4, 1, w);
    ENTRY(257, 4, 1, h);
    ENTRY(258, 3, 1, 8);
    ENTRY(259, 3, 1, 1); /* no compression */
    ENTRY(262, 3, 1, 1); /* black is zero */
    ENTRY(273, 4, (uint32_t)nstrips, nstrips == 1 ? offsets[0] : tables);
    ENTRY(277, 3, 1, 1);
    ENTRY(278, 4, 1, rows);
    ENTRY(279, 4, (uint32_t)nstrips, nstrips == 1 ? counts[0] : tables + 4 * (uint32_t)nstrips);
#undef ENTRY
    put(o, 0, 4);
    if (nstrips > 1) {
        for (k = 0; k < nstrips; ++k) put(o, offsets[k], 4);
        for (k = 0; k < nstrips; ++k) put(o, counts[k], 4);
    }
}

/* A Targa file: colour-mapped (type 1 / RLE 9) with a 2-entry 24-bit map,
 * or true colour (2 / RLE 10) 24-bit; then the pixel bytes given. */
static void tga(bytes *o, int type, int w, int h, const unsigned char *px, size_t n)
{
    int mapped = type == 1 || type == 9;
    o->n = 0;
    put(o, 0, 1);
    put(o, (uint32_t)mapped, 1);
    put(o, (uint32_t)type, 1);
    put(o, 0, 2);
    put(o, mapped ? 2 : 0, 2);
    put(o, mapped ? 24 : 0, 1);
    put(o, 0, 4);
    put(o, (uint32_t)w, 2);
    put(o, (uint32_t)h, 2);
    put(o, mapped ? 8 : 24, 1);
    put(o, 0x20, 1); /* top-left origin */
    if (mapped) put(o, 0xff0000, 3), put(o, 0x00ff00, 3); /* B, G, R bytes: red, green */
    memcpy(o->b + o->n, px, n);
    o->n += n;
}

/* Refused from the file and from memory with `words` in the message. */
static void expect_corrupt(const bytes *o, const char *name, const char *hint, const char *words)
{
    char p[1024];
    sample_texture *t = NULL;
    sample_error e;
    expect_refused(save(o, name, p, sizeof p), NULL, SAMPLE_E_CORRUPT, words, name);
    e.message[0] = '\0';
    CHECK(sample_io_read_memory(o->b, o->n, hint, NULL, NULL, &t, &e) == SAMPLE_E_CORRUPT && !t &&
              strstr(e.message, words),
          "%s from memory: %s", name, e.message);
    sample_texture_destroy(t);
}

/* Read, from the file and from memory; texel (x, 0) channel 0 is returned. */
static float read_ok(const bytes *o, const char *name, const char *hint, int x)
{
    char p[1024];
    sample_texture *t = NULL, *m = NULL;
    sample_error e;
    float v[4] = {-1, -1, -1, -1};
    CHECK(sample_io_read_texture(save(o, name, p, sizeof p), NULL, NULL, &t, &e) == SAMPLE_OK, "%s: %s", name,
          e.message);
    CHECK(sample_io_read_memory(o->b, o->n, hint, NULL, NULL, &m, &e) == SAMPLE_OK, "%s from memory: %s", name,
          e.message);
    if (t) sample_texture_texel(t, 0, x, 0, v);
    sample_texture_destroy(t);
    sample_texture_destroy(m);
    return v[0];
}

/* A 1 KB TIFF claiming 32768 × 32768 with one strip: refused before the
 * 1 GiB image is allocated (OpenImageIO would allocate it and fill 32767
 * strips with zeros); a strip past the end of the file; an uncompressed
 * strip shorter than its rows. The same file with a consistent table
 * reads. */
static void test_tiff_claims(void)
{
    bytes o;
    const uint32_t one_off[] = {8}, one_cnt[] = {8};
    const uint32_t offs[] = {8, 12}, cnts[] = {4, 4}, past[] = {8, 100000}, shortc[] = {4, 3};
    tiff(&o, 32768, 32768, 1, 1, one_off, one_cnt);
    expect_corrupt(&o, "huge.tif", "tif", "strip table has 1 entries of the 32768 it needs");
    tiff(&o, 4, 2, 1, 2, past, cnts);
    expect_corrupt(&o, "past.tif", "tif", "strip 1 (4 bytes at offset 100000) is not inside");
    tiff(&o, 4, 2, 1, 2, offs, shortc);
    expect_corrupt(&o, "short.tif", "tif", "strip 1 holds 3 bytes; its rows need 4");
    tiff(&o, 4, 2, 1, 2, offs, cnts);
    CHECK_NEAR(read_ok(&o, "ok.tif", "tif", 3), 0.21586050, 1e-6); /* sRGB code 128 */
}

/* Targa: an RLE packet of 128 pixels in a 16-pixel image (colour-mapped and
 * true colour), an RLE stream that stops at pixel 4, a colour-map index
 * past the 2-entry map. The consistent files read. */
static void test_tga_made_up(void)
{
    static const unsigned char run128[] = {0xff, 1}, run128rgb[] = {0xff, 1, 2, 3}, run4[] = {0x83, 1};
    static const unsigned char bad_index[16] = {0, 1, 5, 1}, good_index[16] = {0, 1, 0, 1},
                               rle_ok[] = {0x8f, 1};
    bytes o;
    tga(&o, 9, 4, 4, run128, sizeof run128);
    expect_corrupt(&o, "overrun.tga", "tga", "RLE packet at pixel 0 holds 128 pixels; the image has 16 left");
    tga(&o, 10, 4, 4, run128rgb, sizeof run128rgb);
    expect_corrupt(&o, "overrun_rgb.tga", "tga", "holds 128 pixels");
    tga(&o, 9, 4, 4, run4, sizeof run4);
    expect_corrupt(&o, "short.tga", "tga", "RLE data ends at pixel 4 of 16");
    tga(&o, 1, 4, 4, bad_index, sizeof bad_index);
    expect_corrupt(&o, "index.tga", "tga", "pixel 2 has colour-map index 5, outside the map (entries 0 to 1)");
    tga(&o, 1, 4, 4, good_index, sizeof good_index);
    CHECK_NEAR(read_ok(&o, "ok.tga", "tga", 0), 1.0, 1e-6); /* entry 0: red */
    tga(&o, 9, 4, 4, rle_ok, sizeof rle_ok);
    CHECK_NEAR(read_ok(&o, "ok_rle.tga", "tga", 0), 0.0, 1e-6); /* entry 1 is green */
}

/* The byte budget counts the levels the reader will build, not only the
 * base: rgb8.png (19 × 13 × 3) is 2964 bytes as float, 3792 with its
 * pyramid of 5 levels. */
static void test_budget_counts_pyramid(void)
{
    char p[1024];
    sample_io_options o;
    sample_mip_params mip;
    sample_texture *t = NULL;
    sample_error e;
    sample_io_options_init(&o);
    sample_mip_params_init(&mip);
    o.max_bytes = 3000;
    io_path(p, sizeof p, io_images, "rgb8.png");
    CHECK(sample_io_read_texture(p, &o, NULL, &t, &e) == SAMPLE_OK, "base alone within 3000 bytes: %s", e.message);
    sample_texture_destroy(t);
    t = NULL;
    CHECK(sample_io_read_texture(p, &o, &mip, &t, &e) == SAMPLE_E_TOO_LARGE && !t && strstr(e.message, "levels need"),
          "base + pyramid over 3000 bytes: %s", e.message);
    sample_texture_destroy(t);
    o.max_bytes = 3792;
    t = NULL;
    CHECK(sample_io_read_texture(p, &o, &mip, &t, &e) == SAMPLE_OK, "exactly 3792 bytes: %s", e.message);
    sample_texture_destroy(t);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_hostile TESTIMAGES SCRATCH\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    /* A hang is a failure, not a stuck test run. */
    alarm(20);
    RUN(test_not_regular);
    RUN(test_tiff_claims);
    RUN(test_tga_made_up);
    RUN(test_budget_counts_pyramid);
    return check_finish();
}
