/* Helpers of the texture system's tests (texsys_cache.c, texsys_threads.c):
 * files to open, and the resident texture the same file reads as. */
#ifndef TESTS_TEXSYS_UTIL_H
#define TESTS_TEXSYS_UTIL_H

#include "io_util.h" /* first: it sets _POSIX_C_SOURCE */
#include "io_internal.h"
#include "query_gen.h"
#include "sample/sample_io.h"
#include "sample/texsys.h"

/* A tiled mip-mapped file of `tex` (tiles of `tile` texels, wraps as given). */
static inline void ts_write(const char *path, const sample_texture *tex, int tile, sample_wrap ws, sample_wrap wt,
                            int use_float)
{
    sample_io_exr_options o;
    sample_error e;
    sample_io_exr_options_init(&o);
    o.tile_w = o.tile_h = tile;
    o.wrap_s = ws;
    o.wrap_t = wt;
    o.use_float = use_float;
    CHECK(sample_io_write_mip(path, tex, &o, &e) == SAMPLE_OK, "writing %s: %s", path, e.message);
}

/* The shipped OCIO config, loaded once for every ts_resident (parsing it
 * is most of a small file's read). */
static io_colour *ts_col;

/* The file read whole, as the texture system reads untiled files: the box
 * pyramid with the file's wrap modes where it has no levels
 * (sample_io_read_texture with a config already loaded). */
static inline sample_texture *ts_resident(const char *path)
{
    sample_io_options o;
    sample_mip_params mip;
    sample_texture *t = NULL;
    sample_error e;
    sample_io_options_init(&o);
    o.mip_wrap_from_file = 1;
    sample_mip_params_init(&mip);
    if (!ts_col) CHECK(io_colour_open(NULL, &ts_col, &e) == SAMPLE_OK, "OCIO config: %s", e.message);
    CHECK(io_read_texture_col(path, ts_col, &o, &mip, &t, &e) == SAMPLE_OK, "reading %s: %s", path, e.message);
    return t;
}

/* Random queries: inside, near the edges, far out; footprints of every size. */
static inline void ts_queries(sample_query *q, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        q[i].s = rnd() % 4 ? frand(-0.1f, 1.1f) : coord();
        q[i].t = rnd() % 4 ? frand(-0.1f, 1.1f) : coord();
        q[i].dsdx = deriv();
        q[i].dtdx = deriv();
        q[i].dsdy = deriv();
        q[i].dtdy = deriv();
    }
}

/* Sampler number k of the 12 kinds of filtering (query_gen.h). */
#define ts_sampler kind_sampler
#define TS_KINDS KIND_SAMPLERS

#endif
