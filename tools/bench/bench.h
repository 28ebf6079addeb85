/*
 * bench's private header: where its pieces meet (doc/benchmarks.md).
 *
 *   queries.c    the standard query sets, from a fixed seed
 *   textures.c   synthetic textures in each format (libsample's objects)
 *   engines.c    the filters measured: registry entries (tools/filters.h),
 *                on libsample and on their OIIO twins, each row through
 *                its backend (tools/backend.h)
 *   timing.c     runs over pthreads, medians
 *   gl.c         the OpenGL twins of the filters, through tools/backend.h,
 *                with upload and read-back timed apart from the sampling
 *   report.c     the text table and the JSON
 *   save.c       --save: the queries and a manifest, for re-timing elsewhere
 *   cmd_bench.c  the subcommand
 *
 * oiio_replay.cpp, beside them, is a separate program (doc/benchmarks.md,
 * "Re-timing the same queries independently"): it reads what save.c
 * writes and shares no code with bench.
 */
#ifndef TEXSAMPLE_BENCH_H
#define TEXSAMPLE_BENCH_H

/* By its path: programs built from bench's sources (tests/probes.cmake,
 * scripts/perf_probe.sh) name only tools/bench in their include path. */
#include "../backend.h"
#include "../filters.h"
#include "oiio_ts.h"
#include "sample/sample.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* ---- Query sets (queries.c) ------------------------------------------- */

typedef enum bench_set {
    BENCH_SET_MAGNIFY = 0,  /* isotropic footprint 0.25 texel, random (s, t), angle */
    BENCH_SET_MINIFY = 1,   /* isotropic footprint 2.5 texels */
    BENCH_SET_ANISO = 2,    /* 8:1, minor axis 1.5 texels, random angle */
    BENCH_SET_PLANE = 3,    /* ground plane to the horizon, scanline order */
    BENCH_SET_SHUFFLED = 4, /* the plane's queries in a fixed random order */
    BENCH_SET_COUNT
} bench_set;

extern const char *const bench_set_names[BENCH_SET_COUNT];
/* The splitmix64 seed each set starts from (the shuffle's, for
 * plane-shuffled); 0: the set draws no random numbers (plane). */
extern const unsigned bench_set_seeds[BENCH_SET_COUNT];

/* Fill q[0 … n) with set `set` for a size × size base level. The plane set
 * is a ⌈√n⌉-wide image, so n need not be a square. Deterministic. */
void bench_queries(bench_set set, int size, sample_query *q, size_t n);

/* ---- Textures (textures.c) -------------------------------------------- */

typedef enum bench_format {
    BENCH_FMT_F32 = 0,
    BENCH_FMT_F16 = 1,
    BENCH_FMT_SRGB8 = 2,
    BENCH_FMT_COUNT
} bench_format;

extern const char *const bench_format_names[BENCH_FMT_COUNT];
/* OIIO's file for each format as --save names it ("bench_float.tx"). */
extern const char *const bench_oiio_file_names[BENCH_FMT_COUNT];

/* One format of the synthetic texture. OpenImageIO's rows read the file
 * their backend writes of `ours` in its own format (tools/backends/oiio.c,
 * tool_oiio_store_native_formats). */
typedef struct bench_texture {
    sample_texture *ours;
    /* bench --cache-mb: the same texels read from OpenImageIO's file
     * through a texture system (sample/texsys.h), which libsample's rows
     * sample through `cached_backend` (tools/backend.h); NULL otherwise. */
    const sample_texture *cached;
    void *sys;
    tool_backend *cached_backend;
    /* bench --textures: an existing OpenImageIO file of the texture, which
     * OIIO's rows read as it is (ours is then NULL); NULL otherwise. */
    const char *file;
} bench_texture;

/* The synthetic size × size RGBA content (linear, in [0, 1]); caller frees. */
float *bench_content(int size);
/* Build format `fmt` from `content`: libsample's texture with a box pyramid
 * (REPEAT). Returns 0, or reports on stderr and returns −1. */
int bench_texture_make(const float *content, int size, bench_format fmt, bench_texture *out);
/* Open `path` (OpenImageIO's file of t's texels) through a texture system
 * of cache_mb MiB for libsample's rows (t->cached). Returns 0, or reports
 * and returns −1. */
int bench_texture_cache(bench_texture *t, const char *path, double cache_mb);
/* A texture system's batch (sys: the sample_texsys), for libsample's
 * backend over it (tool_backend_libsample_ctx). */
sample_status bench_texsys_batch(void *sys, const sample_texture *tex, const sample_sampler *s,
                                 const sample_batch_args *a);
/* What the texture system of a cached texture read (nothing otherwise). */
void bench_texture_stats(const bench_texture *t, FILE *f);
void bench_texture_free(bench_texture *t);

/* ---- Engines (engines.c) ---------------------------------------------- */

/* One filter as measured: a libsample sampler state, or an OIIO mode. */
typedef struct bench_engine {
    const char *name;  /* "trilinear" */
    int oiio;          /* 0: libsample, 1: OIIO's TextureSystem */
    int match;         /* for libsample rows: index of OIIO's matching row, or −1 */
    sample_sampler smp;
    int reference;     /* libsample rows: 1 runs sample_batch_reference (--scalar) */
    oiio_ts_opts opts;
    /* 0: 2D queries (sample_query); BENCH_ENV_*: direction queries
     * (sample_query3) of an environment map (env.c) */
    int env;
    /* OIIO rows: their backend (bench_engines_open_oiio); NULL until then */
    tool_backend *backend;
} bench_engine;

enum { BENCH_ENV_LATLONG = 1, BENCH_ENV_CUBE = 2 };

/* bench's default filters, NULL-terminated registry names. */
extern const char *const bench_default_filters[];
/* Engines for registry entries filters[0 … count): libsample's in that
 * order, then the OIIO twins of those that have one. Returns how many, or
 * −1 if max is less than 2 × count. */
int bench_engines_of(const tool_filter *const *filters, int count, bench_engine *out, int max);
/* The same for bench_default_filters. */
int bench_engines(bench_engine *out, int max);

/* Open the OIIO rows' backends (tools/backends/oiio.c at each row's twin
 * settings) over `store`. Returns 0, or −1 (reported). */
int bench_engines_open_oiio(bench_engine *e, int n, tool_oiio_store *store);
/* Close what bench_engines_open_oiio opened. */
void bench_engines_close(bench_engine *e, int n);

/* An engine's row on one texture (its backend and the texture prepared
 * there): prepared once, then any number of batches from any number of
 * threads. */
typedef struct bench_row {
    tool_backend *b;
    tool_backend_tex *x;
} bench_row;
/* Returns 0, or −1 (reported). */
int bench_row_prepare(const bench_engine *e, const bench_texture *t, bench_row *out);
/* Sample queries [0, n) into rgba (n × 4), optionally with stats (libsample
 * only). q: sample_query, or sample_query3 for an environment engine
 * (e->env). Returns 0, or −1 (reported). */
int bench_row_run(const bench_engine *e, const bench_row *r, const void *q, size_t n, float *rgba,
                  sample_stats *stats);
void bench_row_release(bench_row *r);
/* Prepare, run once, release. */
int bench_engine_run(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
                     float *rgba, sample_stats *stats);

/* ---- Timing (timing.c) ------------------------------------------------ */

typedef struct bench_timing {
    double median, min, max; /* samples per second over the timed runs */
    int runs;
} bench_timing;

/* Median, min and max of v[0 … n) (n ≥ 1; sorts v). */
void bench_timing_of(double *v, int n, bench_timing *out);

/* Time `runs` passes of all n queries on `threads` threads (tiles taken
 * first come first served, in batches of `batch`), after one untimed
 * warm-up pass. Returns 0, or −1 if a pass failed. */
int bench_time(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
               int threads, int runs, size_t batch, bench_timing *out);

/* bench_time in three steps, so that several engines' passes can take
 * turns (cmd_bench.c): open makes the pool and runs the warm-up pass (NULL
 * on failure), each bench_timer_pass times one pass (−1 on failure or past
 * `runs`), close fills *out once all `runs` passes are timed (0; −1
 * otherwise) and frees the timer either way. */
typedef struct bench_timer bench_timer;
bench_timer *bench_timer_open(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
                              int threads, int runs, size_t batch);
int bench_timer_pass(bench_timer *tm);
int bench_timer_close(bench_timer *tm, bench_timing *out);

/* ---- OpenGL (gl.c) ----------------------------------------------------- */

/* One libsample filter's OpenGL twin on one set and format: the texture's
 * upload once, then per pass the queries' upload, the draw (sampling) and
 * the results' read-back, each timed to glFinish (tools/backends/gl.c). */
typedef struct bench_gl_result {
    bench_set set;
    bench_format format;
    int engine;                 /* libsample's engine whose state GL runs */
    int na;                     /* 1: the driver cannot (note says why) */
    char note[160];
    double texture_upload_s;    /* all levels, once */
    bench_timing sampling;      /* samples per second of the draw alone */
    double query_upload_s, readback_s; /* per pass, medians */
} bench_gl_result;

struct tool_backend;
/* Time engine e's sampler state on `gl` (a backend of tools/backend.h):
 * one warm-up pass, then `runs` timed ones. Returns 0 (out->na set where
 * the driver cannot do it), or −1 with the message in out->note. */
int bench_gl_measure(struct tool_backend *gl, const bench_engine *e, int engine,
                     const bench_texture *t, bench_set set, bench_format fmt,
                     const sample_query *q, size_t n, int runs, bench_gl_result *out);
/* ---- Environment maps (env.c) ------------------------------------------ */

/* bench --env: environment lookups of libsample (lat-long and cube maps)
 * beside OpenImageIO's environment() (lat-long), on random directions and
 * on a mirror sphere's reflection frame; prints its table. `filters`: a
 * registry list or NULL (bench's defaults). Returns an exit code. */
typedef struct bench_env_opts {
    int size, runs, threads, oiio;
    size_t queries, batch;
    const char *filters, *tmpdir;
} bench_env_opts;
int bench_env(const bench_env_opts *o);
/* ---- Volumes (volume.c) ---------------------------------------------- */

/* bench --volume: 3D texture lookups of a size³ volume on one thread,
 * random queries and the carved teapot's frame² picture, beside
 * OpenImageIO's texture3d() (its file in tmpdir) unless oiio is 0;
 * prints the table. Returns an exit code. */
int bench_volume(int size, size_t queries, int runs, int frame, int oiio, const char *tmpdir);

/* ---- A working set larger than the cache (cacheset.c) ------------------ */

/* bench --textures N: N tiled, mip-mapped half-float OpenEXR files of
 * texsize² (written to tmpdir and removed after, or the named `files`),
 * sampled by plane frames whose screen tiles cycle through the textures,
 * through one texture system of cache_mb MiB and OIIO's TextureSystem of
 * the same max_memory_MB, on 1 and `threads` threads; prints samples/s,
 * the tiles and bytes each side read, and peak memory. Returns an exit
 * code. */
typedef struct bench_cacheset_opts {
    int textures, texsize, runs, threads, oiio;
    size_t queries; /* per frame */
    double cache_mb;
    const char *tmpdir;
    char **files; /* NULL, or `textures` names of existing files */
    const bench_engine *eng; /* the filters, as bench_engines_of makes them */
    int neng;
} bench_cacheset_opts;
int bench_cacheset(const bench_cacheset_opts *o);

/* ---- Report (report.c) ------------------------------------------------ */

typedef struct bench_result {
    bench_set set;
    bench_format format;
    int engine;              /* index into the engine table */
    int threads;
    bench_timing timing;
    double texels_per_sample; /* < 0: not known (OIIO) */
} bench_result;

typedef struct bench_report {
    const bench_engine *engines;
    int engine_count;
    const bench_result *results;
    size_t count;
    int size, threads_max, runs;
    size_t queries, batch;
    const char *command; /* the command line, for the record */
    int scalar;          /* 1: libsample ran through its reference path */
    const char *isa;     /* sample_isa_name(): the instruction set it ran on */
    double load[2];      /* 1-minute load average before and after (< 0: unknown) */
    const bench_gl_result *gl; /* --gl: the OpenGL twins (ngl of them) */
    size_t ngl;
    const char *gl_driver;     /* GL_RENDERER; GL_VERSION */
} bench_report;

void bench_print_table(const bench_report *r);
/* Returns 0, or −1 if the file could not be written (reported). */
int bench_write_json(const bench_report *r, const char *path);
/* s as a JSON string literal, quotes included. */
void bench_json_string(FILE *f, const char *s);

/* ---- Saving a run (save.c) -------------------------------------------- */

/* What `--save DIR` records beyond the report: the selection, as the bit
 * masks of cmd_bench (filters: bits over libsample's engines). */
typedef struct bench_save {
    const char *dir;
    unsigned sets, formats, filters;
} bench_save;

/* One set's queries as DIR/queries_<set>.bin: n records of 6 little-endian
 * float32 in sample_query's field order. Returns 0, or nonzero (reported). */
int bench_save_queries(const char *dir, bench_set set, const sample_query *q, size_t n);
/* OpenImageIO's file of one format (`path`, as its backend wrote it) as
 * DIR/bench_oiio_file_names[fmt]. Returns 0, or nonzero (reported). */
int bench_save_texture(const char *dir, bench_format fmt, const char *path);
/* DIR/manifest.json: the query files, OIIO's texture files, every selected
 * filter's settings on both sides, and the 1-thread timings of the report.
 * Returns 0, or nonzero (reported). */
int bench_save_manifest(const bench_save *s, const bench_report *r);

#endif
