/* The direct OpenEXR reader of tiled mip-mapped files (exr_read.cpp): it is
 * the path taken, and it gives exactly the levels OpenImageIO gives.
 * Usage: io_exr_direct TESTIMAGES SCRATCH [MAKETX [OIIOTOOL]] */
#include "io_util.h"
#include "io_internal.h"

#include <stdint.h>

static const char *maketx;

/* A w × h texture of `nchan` deterministic values, full box chain. */
static sample_texture *make_tex(int w, int h, int nchan, sample_format fmt)
{
    return io_test_texture(w, h, nchan, fmt, 777u, SAMPLE_MIPGEN_BOX, 0);
}

/* Every level of `path`: the direct reader's bytes equal OIIO's bytes (same
 * type, bit for bit), and the texture the public call builds through the
 * direct path holds those values. */
static void check_same_as_oiio(const char *path, int expect_float, int expect_levels)
{
    io_exr_tiled *x = NULL;
    io_reader *r = NULL;
    io_reader_info xi, ri;
    sample_texture *t = NULL;
    sample_error e;
    unsigned long before = io_exr_direct_reads();
    int k;
    CHECK(io_exr_tiled_open(path, NULL, 0, &x, &e) == SAMPLE_OK && x, "%s: not taken by the direct reader", path);
    CHECK(io_reader_open(path, NULL, 0, NULL, &r, &e) == SAMPLE_OK, "%s: %s", path, e.message);
    if (x && r) {
        io_exr_tiled_info_get(x, &xi);
        io_reader_info_get(r, &ri);
        CHECK(xi.width == ri.width && xi.height == ri.height && xi.channels == ri.channels &&
                  xi.nlevels == ri.nlevels && xi.native == ri.native,
              "%s: direct %dx%dx%d %d levels type %d, OIIO %dx%dx%d %d levels type %d", path, xi.width,
              xi.height, xi.channels, xi.nlevels, (int)xi.native, ri.width, ri.height, ri.channels, ri.nlevels,
              (int)ri.native);
        CHECK(xi.native == (expect_float ? IO_FLOAT : IO_HALF), "%s: type %d", path, (int)xi.native);
        CHECK(expect_levels == 0 || xi.nlevels == expect_levels, "%s: %d levels", path, xi.nlevels);
        /* The public read through the direct path holds the same values. */
        CHECK(sample_io_read_texture(path, NULL, NULL, &t, &e) == SAMPLE_OK, "%s: %s", path, e.message);
        CHECK(io_exr_direct_reads() == before + 1, "%s: the direct path was not taken", path);
        for (k = 0; k < xi.nlevels && k < ri.nlevels; ++k) {
            int w, h, w2, h2, i, bad = 0;
            size_t n, bytes;
            unsigned char *a, *b;
            CHECK(io_exr_tiled_level_size(x, k, &w, &h, &e) == SAMPLE_OK, "%s", e.message);
            CHECK(io_reader_level_size(r, k, &w2, &h2, &e) == SAMPLE_OK && w == w2 && h == h2,
                  "%s level %d: %dx%d vs %dx%d", path, k, w, h, w2, h2);
            n = (size_t)w * (size_t)h * (size_t)xi.channels;
            bytes = n * (expect_float ? 4 : 2);
            a = malloc(bytes);
            b = malloc(bytes);
            if (a && b && w == w2 && h == h2) {
                CHECK(io_exr_tiled_read(x, k, xi.native, xi.channels, a, &e) == SAMPLE_OK, "%s", e.message);
                CHECK(io_reader_read(r, k, ri.native, ri.channels, b, &e) == SAMPLE_OK, "%s", e.message);
                CHECK(memcmp(a, b, bytes) == 0, "%s level %d: direct bytes differ from OIIO's", path, k);
                /* The texture: texel c of (i, j) is OIIO's value, exactly. */
                for (i = 0; t && (size_t)i < n && bad < 5; ++i) {
                    int c = i % xi.channels, px = i / xi.channels;
                    float v[4], want;
                    if (expect_float) {
                        memcpy(&want, b + 4 * (size_t)i, 4);
                    } else {
                        uint16_t hv;
                        memcpy(&hv, b + 2 * (size_t)i, 2);
                        want = sample_half_to_float(hv);
                    }
                    sample_texture_texel(t, k, px % w, px / w, v);
                    if (memcmp(&v[c], &want, 4) != 0 && bad++ < 5)
                        fprintf(stderr, "  %s level %d (%d,%d) c%d: %.9g vs %.9g\n", path, k, px % w, px / w, c,
                                (double)v[c], (double)want);
                }
                CHECK(bad == 0, "%s level %d: texture differs from OIIO's values", path, k);
            }
            free(a);
            free(b);
        }
        if (t) {
            sample_texture_info ti;
            sample_texture_info_get(t, &ti);
            CHECK(ti.levels == xi.nlevels, "%s: texture has %d levels, file %d", path, ti.levels, xi.nlevels);
            CHECK(ti.format == (expect_float ? SAMPLE_FORMAT_F32 : SAMPLE_FORMAT_F16), "%s: format %d", path,
                  (int)ti.format);
        }
    }
    sample_texture_destroy(t);
    io_exr_tiled_close(x);
    io_reader_close(r);
}

static void write_mip(const char *path, int w, int h, int nchan, int use_float)
{
    sample_io_exr_options o;
    sample_error e;
    sample_texture *t = make_tex(w, h, nchan, use_float ? SAMPLE_FORMAT_F32 : SAMPLE_FORMAT_F16);
    sample_io_exr_options_init(&o);
    o.use_float = use_float;
    o.tile_w = 16, o.tile_h = 8; /* partial edge tiles */
    if (t) CHECK(sample_io_write_mip_exr(path, t, &o, &e) == SAMPLE_OK, "%s", e.message);
    sample_texture_destroy(t);
}

static void test_our_writer(void)
{
    char p[1024];
    write_mip(io_path(p, sizeof p, io_scratch, "ours_half.exr"), 37, 20, 4, 0);
    check_same_as_oiio(p, 0, 6);
    write_mip(io_path(p, sizeof p, io_scratch, "ours_float.exr"), 20, 37, 3, 1);
    check_same_as_oiio(p, 1, 6);
    write_mip(io_path(p, sizeof p, io_scratch, "ours_one.exr"), 64, 1, 1, 1);
    check_same_as_oiio(p, 1, 7);
}

static void test_maketx(void)
{
    static const char *const types[2] = {"half", "float"};
    char in[1024], out[1024], cmd[4096];
    int f;
    if (!maketx || !*maketx) {
        check_skip("maketx not found: its files not read directly");
        return;
    }
    io_path(in, sizeof in, io_images, "rgba_half.exr");
    for (f = 0; f < 2; ++f) {
        char name[64];
        int rc;
        snprintf(name, sizeof name, "maketx_%s.exr", types[f]);
        io_path(out, sizeof out, io_scratch, name);
        snprintf(cmd, sizeof cmd, "'%s' --filter lanczos3 -d %s '%s' -o '%s'", maketx, types[f], in, out);
        rc = system(cmd);
        CHECK(rc == 0, "'%s' failed (%d)", cmd, rc);
        if (rc == 0) check_same_as_oiio(out, f, 4);
    }
}

/* Memory input goes through the memory IStream and gives the same texture. */
static void test_memory(void)
{
    char p[1024];
    size_t size;
    void *buf = check_slurp(io_path(p, sizeof p, io_scratch, "ours_half.exr"), &size);
    sample_texture *a = NULL, *b = NULL;
    sample_error e;
    unsigned long before = io_exr_direct_reads();
    CHECK(buf != NULL, "cannot read %s", p);
    if (!buf) return;
    CHECK(sample_io_read_memory(buf, size, NULL, NULL, NULL, &a, &e) == SAMPLE_OK, "%s", e.message);
    CHECK(io_exr_direct_reads() == before + 1, "memory read did not take the direct path");
    CHECK(sample_io_read_texture(p, NULL, NULL, &b, &e) == SAMPLE_OK, "%s", e.message);
    if (a && b) CHECK(io_same_texels(a, b, 6, 0.0f), "memory and file reads differ");
    sample_texture_destroy(a);
    sample_texture_destroy(b);
    free(buf);
}

/* Files and options the direct reader leaves to OIIO. */
static void test_not_direct(void)
{
    char p[1024];
    sample_io_options o;
    sample_texture *t = NULL;
    sample_error e;
    unsigned long before = io_exr_direct_reads();
    /* A scanline EXR. */
    t = io_read(io_path(p, sizeof p, io_images, "rgba_half.exr"), NULL, 1);
    sample_texture_destroy(t);
    CHECK(io_exr_direct_reads() == before, "a scanline file took the direct path");
    /* A forced non-linear colour space: OIIO's path converts it. */
    io_path(p, sizeof p, io_scratch, "ours_half.exr");
    sample_io_options_init(&o);
    o.colorspace = "srgb";
    t = NULL;
    CHECK(sample_io_read_texture(p, &o, NULL, &t, &e) == SAMPLE_OK, "%s", e.message);
    sample_texture_destroy(t);
    CHECK(io_exr_direct_reads() == before, "a forced sRGB read took the direct path");
}

/* Options hold on the direct path: the byte budget and use_file_levels. */
static void test_options(void)
{
    char p[1024];
    sample_io_options o;
    sample_texture *t = NULL;
    sample_texture_info ti;
    sample_error e;
    io_path(p, sizeof p, io_scratch, "ours_half.exr");
    sample_io_options_init(&o);
    o.max_bytes = 1000; /* 37 × 20 × 4 floats alone are 11840 */
    CHECK(sample_io_read_texture(p, &o, NULL, &t, &e) == SAMPLE_E_TOO_LARGE && !t, "budget not enforced");
    sample_io_options_init(&o);
    o.use_file_levels = 0;
    CHECK(sample_io_read_texture(p, &o, NULL, &t, &e) == SAMPLE_OK, "%s", e.message);
    if (t) {
        sample_texture_info_get(t, &ti);
        CHECK(ti.levels == 1, "use_file_levels 0 gave %d levels", ti.levels);
    }
    sample_texture_destroy(t);
}

/* A tiled file cut short: a clear error, from a file and from memory. */
static void test_truncated(void)
{
    char p[1024], q[1024];
    size_t size, cut;
    void *buf;
    FILE *f;
    sample_texture *t = NULL;
    sample_error e;
    write_mip(io_path(p, sizeof p, io_scratch, "cut_src.exr"), 128, 96, 4, 1);
    buf = check_slurp(p, &size);
    CHECK(buf != NULL && size > 4096, "cannot read %s", p);
    if (!buf || size <= 4096) {
        free(buf);
        return;
    }
    cut = size * 2 / 3;
    io_path(q, sizeof q, io_scratch, "cut.exr");
    f = fopen(q, "wb");
    CHECK(f && fwrite(buf, 1, cut, f) == cut, "cannot write %s", q);
    if (f) fclose(f);
    CHECK(sample_io_read_texture(q, NULL, NULL, &t, &e) == SAMPLE_E_CORRUPT && !t, "truncated file accepted");
    CHECK(strstr(e.message, "level") != NULL, "unclear message: %s", e.message);
    printf("truncated file: %s\n", e.message);
    CHECK(sample_io_read_memory(buf, cut, "exr", NULL, NULL, &t, &e) == SAMPLE_E_CORRUPT && !t,
          "truncated memory accepted");
    printf("truncated memory: %s\n", e.message);
    /* Every cut (header, offset tables, any level): refused, nothing leaks. */
    {
        int k;
        for (k = 0; k < 23; ++k) {
            size_t n = size * (size_t)k / 23;
            sample_status st = sample_io_read_memory(buf, n, "exr", NULL, NULL, &t, &e);
            CHECK(st != SAMPLE_OK && !t && e.message[0], "prefix of %zu bytes: status %d", n, (int)st);
            sample_texture_destroy(t);
            t = NULL;
        }
    }
    free(buf);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_exr_direct TESTIMAGES SCRATCH [MAKETX [OIIOTOOL]]\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    maketx = argc > 3 ? argv[3] : NULL;
    RUN(test_our_writer);
    RUN(test_maketx);
    RUN(test_memory);
    RUN(test_not_direct);
    RUN(test_options);
    RUN(test_truncated);
    return check_finish();
}
