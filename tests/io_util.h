/* Helpers shared by the libsample_io tests (header-only, static). */
#ifndef SAMPLE_TEST_IO_UTIL_H
#define SAMPLE_TEST_IO_UTIL_H

#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "sample/sample_io.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Set by main from argv: the testimages folder and a scratch folder. */
static const char *io_images, *io_scratch;

static inline const char *io_path(char *buf, size_t size, const char *dir, const char *name)
{
    snprintf(buf, size, "%s/%s", dir, name);
    return buf;
}

static inline int io_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Number of entries of dir whose name contains ".tmp" (left-over temporaries). */
static inline int io_count_tmp(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d) return -1;
    while ((e = readdir(d)) != NULL)
        if (strstr(e->d_name, ".tmp")) n++;
    closedir(d);
    return n;
}

/* Every texel of every level equal (decoded linear values, exactly). */
static inline int io_same_texels(const sample_texture *a, const sample_texture *b, int levels, float tol)
{
    int k, i, j, c, bad = 0;
    for (k = 0; k < levels && bad < 5; ++k) {
        int wa, ha, wb, hb;
        sample_texture_level_size(a, k, &wa, &ha);
        sample_texture_level_size(b, k, &wb, &hb);
        if (wa != wb || ha != hb || wa == 0) return 0;
        for (j = 0; j < ha; ++j)
            for (i = 0; i < wa; ++i) {
                float x[4], y[4];
                sample_texture_texel(a, k, i, j, x);
                sample_texture_texel(b, k, i, j, y);
                for (c = 0; c < 4; ++c)
                    if (!(fabsf(x[c] - y[c]) <= tol)) {
                        if (bad++ < 5)
                            fprintf(stderr, "  level %d texel (%d,%d) channel %d: %.9g vs %.9g\n", k, i, j, c,
                                    (double)x[c], (double)y[c]);
                    }
            }
    }
    return bad == 0;
}

/* Read a file or return NULL (failing the current check). */
static inline sample_texture *io_read(const char *path, const char *colorspace, int use_file_levels)
{
    sample_io_options o;
    sample_texture *t = NULL;
    sample_error e;
    sample_status st;
    sample_io_options_init(&o);
    o.colorspace = colorspace;
    o.use_file_levels = use_file_levels;
    st = sample_io_read_texture(path, &o, NULL, &t, &e);
    CHECK(st == SAMPLE_OK, "reading %s: %s", path, st == SAMPLE_OK ? "" : e.message);
    return st == SAMPLE_OK ? t : NULL;
}

/* A w × h texture of `nchan` channels (F32 or F16) holding deterministic
 * values in [−1, 3) from `seed`, with the pyramid `kernel` (max_levels 0: all). */
static inline sample_texture *io_test_texture(int w, int h, int nchan, sample_format fmt, unsigned seed,
                                              sample_mipgen kernel, int max_levels)
{
    size_t n = (size_t)w * (size_t)h * (size_t)nchan, i;
    unsigned x = seed;
    void *px = malloc(n * 4);
    sample_image img = {w, h, nchan, fmt, px, 0};
    sample_mip_params mip;
    sample_texture *t = NULL;
    sample_error e;
    for (i = 0; px && i < n; ++i) {
        float v;
        x = x * 1664525u + 1013904223u;
        v = (float)(x >> 8) / 16777216.0f * 4.0f - 1.0f;
        if (fmt == SAMPLE_FORMAT_F16) {
            uint16_t hv = sample_float_to_half(v);
            memcpy((char *)px + 2 * i, &hv, 2);
        } else {
            memcpy((char *)px + 4 * i, &v, 4);
        }
    }
    sample_mip_params_init(&mip);
    mip.filter = kernel;
    mip.max_levels = max_levels;
    CHECK(sample_texture_create(&img, &mip, &t, &e) == SAMPLE_OK, "%s", e.message);
    free(px);
    return t;
}

#endif
