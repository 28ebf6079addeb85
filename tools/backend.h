/*
 * Backends (doc/backends.md): the samplers that compare, freq and bench
 * measure, behind one interface, so that every row is asked the same
 * queries on the same texels and scored against the same ground truth.
 *
 *   backends/libsample.c  libsample itself (sample_batch), any registry entry
 *   backends/oiio.c       OpenImageIO's TextureSystem (tools/oiio/oiio_ts.h)
 *                         at a registry entry's twin settings
 *   backends/gl.c         an OpenGL driver through EGL: textureGrad in a
 *                         fragment shader (Mesa llvmpipe by default, any
 *                         EGL device by name)
 *   backends/program.c    an outside program that speaks the `lookup` file
 *                         protocol (texture and query files in, RGBA float32
 *                         out)
 *
 * A backend is opened once (a GL context, a command line) and then serves
 * any number of (texture, sampler) pairs: prepare moves the texture's levels
 * to it and fixes the sampler state, sample answers a batch of 2D queries,
 * release forgets the texture. A backend that cannot do a configuration
 * (a wrap mode OpenGL lacks, a cube map, a footprint filter) says why from
 * prepare with TOOL_BACKEND_NA, so the tools print the row as "n/a: reason"
 * instead of leaving it out.
 */
#ifndef TEXSAMPLE_BACKEND_H
#define TEXSAMPLE_BACKEND_H

#include "oiio/oiio_ts.h"
#include "sample/sample.h"

#include <stddef.h>
#include <stdio.h>

/* prepare's and sample's results besides 0 (success). */
enum {
    TOOL_BACKEND_ERROR = -1, /* something failed: err says what */
    TOOL_BACKEND_NA = -2,    /* the backend cannot do this configuration: err says why */
};

/* Where a batch's time went (seconds, added to): moving texels and queries
 * in, sampling, moving results out. A backend that cannot tell the parts
 * apart puts everything in `sample`. */
typedef struct tool_backend_times {
    double upload, sample, readback;
} tool_backend_times;

typedef struct tool_backend tool_backend;
typedef struct tool_backend_tex tool_backend_tex;

/* A batch with everything a row may ask: 2D queries or, on the texture
 * prepare saw, direction queries (an environment map: sample_batch_env) or
 * volume queries (a 3D texture: sample_batch_3d); the exact footprint
 * corners and the stochastic draws of sample_batch_args (DESIGN §7,
 * doc/footprint-filters.md "Stochastic"). */
typedef struct tool_backend_batch {
    size_t count;
    const sample_query *q;       /* 2D queries, or NULL with q3 */
    const sample_query3 *q3;     /* direction or volume queries, or NULL */
    const sample_quad *corners;  /* exact corners (2D only), or NULL */
    const float *u;              /* per query a uniform in [0, 1): stochastic, or NULL */
    unsigned draws;              /* texels per EWA / Blinn–Newell estimate with u */
    float *rgba;                 /* count × 4 out */
    sample_stats *stats;         /* per query, by backends that count texels; or NULL */
} tool_backend_batch;

typedef struct tool_backend_ops {
    /* tex: a 2D or other texture of libsample (its levels are what the
     * backend receives); smp: the full sampler state. Returns 0 with *out
     * set, TOOL_BACKEND_NA or TOOL_BACKEND_ERROR with a message. */
    int (*prepare)(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                   tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen);
    /* n queries → n × 4 floats; texels (may be NULL) gets the texels read
     * added, by backends that count them (libsample). Returns 0, or
     * TOOL_BACKEND_NA (an outside program may find out only here) or
     * TOOL_BACKEND_ERROR with a message. */
    int (*sample)(tool_backend *b, tool_backend_tex *tx, const sample_query *q, size_t n,
                  float *rgba, double *texels, tool_backend_times *t, char *err, size_t errlen);
    /* Optional: prepare an environment map (a lat-long 2D texture or a cube
     * map) for direction queries; NULL: the backend has none (n/a). */
    int (*prepare_env)(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                       tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen);
    /* Optional: the whole batch (direction and volume queries, corners,
     * stochastic draws). A backend without it answers 2D batches through
     * `sample`, and anything more is n/a (tool_backend_run). */
    int (*run)(tool_backend *b, tool_backend_tex *tx, const tool_backend_batch *a,
               tool_backend_times *t, char *err, size_t errlen);
    void (*release)(tool_backend *b, tool_backend_tex *tx);
    void (*close)(tool_backend *b);
} tool_backend_ops;

struct tool_backend {
    const tool_backend_ops *ops;
    /* What produced the rows, for tables and pages: "libsample 1.2",
     * "llvmpipe (LLVM 15.0.6, 256 bits); 4.5 (Core Profile) Mesa 22.3.6",
     * "program: python3 tools/examples/bilinear.py". */
    char driver[384];
    int counts_texels; /* 1: sample adds the texels read */
    /* 1: sample and run may be called from many threads at once on one
     * prepared texture (libsample, OpenImageIO); 0: one caller at a time
     * (a GL context, a program's files). */
    int thread_safe;
    void *impl;
};

/* ---- Opening ------------------------------------------------------------- */

/* libsample: 2D batches through `batch` (NULL: sample_batch; the tools
 * give sample_batch_reference for the reference path, sample/testing.h),
 * direction queries through sample_batch_env, volume queries through
 * sample_batch_3d. Returns 0, or TOOL_BACKEND_ERROR (out of memory). */
typedef sample_status (*tool_batch_fn)(const sample_texture *tex, const sample_sampler *smp,
                                       const sample_batch_args *args);
int tool_backend_libsample(tool_backend *b, tool_batch_fn batch);
/* libsample with a context: 2D batches through batch(ctx, …), e.g. a
 * texture system's sample_texsys_batch on a texture it opened (bench
 * --cache-mb, sample/texsys.h); `driver` names it. Direction and volume
 * queries are n/a. Returns 0, or TOOL_BACKEND_ERROR (out of memory). */
typedef sample_status (*tool_batch_ctx_fn)(void *ctx, const sample_texture *tex,
                                           const sample_sampler *smp,
                                           const sample_batch_args *args);
int tool_backend_libsample_ctx(tool_backend *b, tool_batch_ctx_fn batch, void *ctx,
                               const char *driver);

/* OpenImageIO's TextureSystem (backends/oiio.c) at the settings `opts`
 * (a registry entry's twin: tool_filter_oiio_opts; the wrap modes come
 * from the sampler prepare gets). prepare writes the texture's base level
 * as OpenImageIO's own mip-mapped file (oiio_ts_make_texture, as maketx
 * would) and opens it; prepare_env writes an environment map's as
 * OpenImageIO's lat-long map (sample_io_write_env).
 * Backends opened on one store share its TextureSystem (cache_mb MiB;
 * 0: OpenImageIO's default) and its last file, so that rows asked the same
 * texels read the same file. Returns 0, or TOOL_BACKEND_ERROR (no
 * OpenImageIO in this build, no temporary folder). */
typedef struct tool_oiio_store tool_oiio_store;
int tool_oiio_available(void);
tool_oiio_store *tool_oiio_store_open(double cache_mb, char *err, size_t errlen);
/* The same with its folder under `base` (NULL or "": $TMPDIR, else /tmp). */
tool_oiio_store *tool_oiio_store_open_in(double cache_mb, const char *base, char *err,
                                         size_t errlen);
void tool_oiio_store_close(tool_oiio_store *s);
/* From now on the store writes a 2D texture's file in the texture's own
 * texel format — half for SAMPLE_FORMAT_F16, 8-bit codes for UNORM8 and
 * SRGB8 (OpenImageIO reads them as code/255: the same memory traffic and
 * work as libsample's, not the same values), float otherwise — so that a
 * timing compares the same texel format on both sides (bench). Without
 * it every file is float: the values libsample decodes, which is what
 * compare and freq score. */
void tool_oiio_store_native_formats(tool_oiio_store *s);
int tool_backend_oiio_open(tool_backend *b, tool_oiio_store *store, const oiio_ts_opts *opts,
                           char *err, size_t errlen);
/* The file a texture prepared by an OpenImageIO backend reads (valid until
 * its release): bench --save copies it, bench --cache-mb opens it in
 * libsample's texture system. */
const char *tool_oiio_file(const tool_backend_tex *x);
/* prepare for an existing OpenImageIO texture file (path) instead of a
 * texture of libsample: the file is opened as it is, not read through
 * (bench --textures: a working set larger than the cache), and stays. */
int tool_backend_oiio_prepare_file(tool_backend *b, const char *path, const sample_sampler *smp,
                                   tool_backend_tex **out, char *err, size_t errlen);
/* The store's TextureSystem, for its statistics (oiio_ts_stats_get). */
oiio_ts *tool_oiio_store_ts(tool_oiio_store *s);

/* 1 when this build has the OpenGL backend (EGL found at configure time). */
int tool_backend_gl_available(void);
/* An OpenGL 3.3 core context through EGL without a window: device NULL or
 * "" is Mesa's surfaceless platform (llvmpipe unless the environment picks
 * another Mesa driver); otherwise an EGL device (EGL_EXT_device_enumeration)
 * whose index, DRM node path or GL_RENDERER (a case-insensitive part of it)
 * matches `device`. Returns 0, or TOOL_BACKEND_ERROR with a message (no
 * EGL, no such device, no context). */
int tool_backend_gl_open(tool_backend *b, const char *device, char *err, size_t errlen);
/* The EGL devices and what each renders with, one a line, on out. Returns
 * how many, or −1 with a message in err when EGL has none to list. */
int tool_backend_gl_list(FILE *out, char *err, size_t errlen);

/* An outside program (doc/backends.md, "The lookup protocol"): `command`
 * runs through /bin/sh with the protocol's arguments appended; its files go
 * in a private folder under $TMPDIR. Returns 0, or TOOL_BACKEND_ERROR. */
int tool_backend_program_open(tool_backend *b, const char *command, char *err, size_t errlen);

/* ---- Using ---------------------------------------------------------------- */

int tool_backend_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                         tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen);
int tool_backend_sample(tool_backend *b, tool_backend_tex *tx, const sample_query *q, size_t n,
                        float *rgba, double *texels, tool_backend_times *t, char *err,
                        size_t errlen);
/* A batch of count queries (q or q3) into rgba, stats (may be NULL); no
 * corners, deterministic. */
void tool_backend_batch_init(tool_backend_batch *a, size_t count, const sample_query *q,
                             const sample_query3 *q3, float *rgba, sample_stats *stats);
/* prepare for an environment map's direction queries (prepare_env). */
int tool_backend_prepare_env(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                             tool_backend_tex **out, tool_backend_times *t, char *err,
                             size_t errlen);
/* The whole batch: through the backend's run, or, for a plain 2D batch,
 * its sample (stats then left alone). A batch the backend cannot answer
 * (direction queries on OpenGL, stochastic draws in a program) is
 * TOOL_BACKEND_NA with the reason. */
int tool_backend_run(tool_backend *b, tool_backend_tex *tx, const tool_backend_batch *a,
                     tool_backend_times *t, char *err, size_t errlen);
void tool_backend_release(tool_backend *b, tool_backend_tex *tx);
/* Accepts a backend that was never opened (zeroed). */
void tool_backend_close(tool_backend *b);

/* ---- Named rows: "NAME=COMMAND" ------------------------------------------ */

/* An outside program named on a command line. */
typedef struct tool_program_row {
    char name[48];  /* the row's name: letters, digits, '-', '_', '.' */
    const char *command;
} tool_program_row;

/* Split "NAME=COMMAND" (the --backend-program value) into rows[n]: NAME
 * must be new among rows[0 … n) and no registry name (tools/filters.h), as
 * it names the row's files and table lines. Returns 0, or −1 with what is
 * wrong in err. */
int tool_program_row_parse(const char *spec, tool_program_row *rows, int n, char *err,
                           size_t errlen);

/* The usage text of the backend options the tools share (--gl-device,
 * --backend-program): options from column 2, descriptions from column
 * `col`. */
void tool_backend_help(FILE *out, int col);

#endif
