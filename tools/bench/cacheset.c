/*
 * bench --textures N: a working set larger than the cache, the case a
 * texture system exists for (doc/texture-system.md, "Benchmark"). N tiled,
 * mip-mapped half-float OpenEXR files are sampled by frames of the plane
 * set (queries.c) cut into screen tiles of CS_TILE² pixels, as a
 * renderer's buckets; in frame f, screen tile j samples texture
 * (j + f) mod N, so every texture switches per screen tile and, over the N
 * frames of one timed run, every texture is seen across the whole plane.
 * libsample samples through one texture system of --cache-mb MiB,
 * OpenImageIO through its TextureSystem with the same max_memory_MB; both
 * get the same queries in the same order, each side through its backend
 * (tools/backend.h: libsample's over the texture system, OpenImageIO's on
 * the files as they are), one row per texture prepared before the clock
 * and one run per screen tile. Threads take screen tiles first
 * come first served. A timed run lasts seconds, so threads are created per
 * run (their start-up is microseconds) instead of timing.c's pool.
 */
#define _DEFAULT_SOURCE
#include "bench.h"
#include "sample/texsys.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

/* Screen tiles: 16 × 16 pixels, 256 queries, one batch each. */
#define CS_TILE 16

typedef struct cs_job {
    int tex;        /* which texture */
    size_t q0, n;   /* queries [q0, q0 + n) of the tile-ordered frame */
} cs_job;

typedef struct cs_run {
    const bench_engine *e;
    const bench_row *rows; /* the engine's row on each of the N textures */
    const sample_query *q;
    const cs_job *jobs;
    size_t njobs;
    atomic_size_t next;
    atomic_int failed;
} cs_run;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *worker(void *arg)
{
    cs_run *r = arg;
    float rgba[CS_TILE * CS_TILE * 4];
    size_t k;
    while ((k = atomic_fetch_add(&r->next, 1)) < r->njobs && !atomic_load(&r->failed)) {
        const cs_job *j = &r->jobs[k];
        if (bench_row_run(r->e, &r->rows[j->tex], r->q + j->q0, j->n, rgba, NULL) != 0)
            atomic_store(&r->failed, 1);
    }
    return NULL;
}

/* One run of every job on `threads` threads: its seconds, or −1. */
static double timed_run(cs_run *r, int threads)
{
    pthread_t th[64];
    int k, started = 0;
    double t0 = now();
    atomic_store(&r->next, 0);
    atomic_store(&r->failed, 0);
    for (k = 1; k < threads && k < 64; ++k)
        if (pthread_create(&th[k], NULL, worker, r) == 0) ++started;
    worker(r);
    for (k = 1; k <= started; ++k) pthread_join(th[k], NULL);
    return atomic_load(&r->failed) ? -1.0 : now() - t0;
}

/* The plane frame of n queries reordered screen tile by screen tile, and
 * the jobs of N frames over it. Returns 0, or −1 (out of memory). */
static int make_frames(size_t n, int ntex, sample_query **qout, cs_job **jout, size_t *njobs)
{
    sample_query *plane = malloc(n * sizeof *plane), *q = malloc(n * sizeof *q);
    size_t W = (size_t)ceil(sqrt((double)n)), rows = (n + W - 1) / W, at = 0, nt = 0, i;
    size_t tw = (W + CS_TILE - 1) / CS_TILE, th = (rows + CS_TILE - 1) / CS_TILE, tx, ty, x, y;
    cs_job *tiles = malloc(tw * th * sizeof *tiles), *jobs = malloc(tw * th * (size_t)ntex * sizeof *jobs);
    int f;
    if (!plane || !q || !tiles || !jobs) {
        free(plane), free(q), free(tiles), free(jobs);
        return -1;
    }
    bench_queries(BENCH_SET_PLANE, 1, plane, n);
    for (ty = 0; ty < th; ++ty)
        for (tx = 0; tx < tw; ++tx) {
            tiles[nt].q0 = at;
            for (y = ty * CS_TILE; y < (ty + 1) * CS_TILE && y < rows; ++y)
                for (x = tx * CS_TILE; x < (tx + 1) * CS_TILE && x < W; ++x)
                    if ((i = y * W + x) < n) q[at++] = plane[i];
            tiles[nt].n = at - tiles[nt].q0;
            if (tiles[nt].n) ++nt;
        }
    *njobs = 0;
    for (f = 0; f < ntex; ++f)
        for (i = 0; i < nt; ++i) {
            jobs[*njobs] = tiles[i];
            jobs[(*njobs)++].tex = (int)((i + (size_t)f) % (size_t)ntex);
        }
    free(plane);
    free(tiles);
    *qout = q;
    *jout = jobs;
    return 0;
}

/* The N files: `files` as given, else written into dir as cs_NN.exr from
 * bench_content, each texture's red channel shifted by k/256 so that no
 * two files are the same image (OpenImageIO deduplicates identical files
 * by their SHA-1). Returns 0, or −1 (reported). */
static int make_files(const bench_cacheset_opts *o, const char *dir, char (*path)[1100])
{
    float *c;
    size_t n = (size_t)o->texsize * (size_t)o->texsize, i;
    char err[512];
    int k;
    if (o->files) {
        for (k = 0; k < o->textures; ++k) snprintf(path[k], sizeof path[k], "%s", o->files[k]);
        return 0;
    }
    if (!(c = bench_content(o->texsize))) {
        fprintf(stderr, "texsample bench: out of memory\n");
        return -1;
    }
    for (k = 0; k < o->textures; ++k) {
        snprintf(path[k], sizeof path[k], "%s/cs_%02d.exr", dir, k);
        if (k > 0)
            for (i = 0; i < n; ++i) c[4 * i] += 1.0f / 256.0f;
        if (oiio_ts_make_texture(c, o->texsize, o->texsize, OIIO_TS_HALF, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT,
                                 path[k], err, sizeof err) != 0) {
            fprintf(stderr, "texsample bench: %s\n", err);
            free(c);
            return -1;
        }
    }
    free(c);
    return 0;
}

/* Open the N files in a new texture system of mb MiB, libsample's
 * backend over it in *lib (OpenImageIO's rows read the files as they are).
 * Returns the system, or NULL (reported). */
static sample_texsys *open_all(const bench_cacheset_opts *o, double mb, char (*path)[1100], tool_backend *lib,
                               bench_texture *tex)
{
    sample_texsys_options so;
    sample_texsys *sys = NULL;
    sample_error err;
    int k;
    sample_texsys_options_init(&so);
    so.max_memory_mb = mb;
    if (sample_texsys_create(&so, &sys, &err) != SAMPLE_OK) {
        fprintf(stderr, "texsample bench: %s\n", err.message);
        return NULL;
    }
    if (tool_backend_libsample_ctx(lib, bench_texsys_batch, sys, "texture system") != 0) {
        fprintf(stderr, "texsample bench: out of memory\n");
        sample_texsys_destroy(sys);
        return NULL;
    }
    for (k = 0; k < o->textures; ++k) {
        const sample_texture *t;
        if (sample_texsys_open(sys, path[k], &t, &err) != SAMPLE_OK) {
            fprintf(stderr, "texsample bench: %s\n", err.message);
            tool_backend_close(lib);
            sample_texsys_destroy(sys);
            return NULL;
        }
        tex[k].cached = t;
        tex[k].sys = sys;
        tex[k].cached_backend = lib;
        tex[k].file = path[k];
    }
    return sys;
}

/* Engine e's rows on the N textures. Returns 0, or −1 (reported; none
 * left prepared). */
static int prepare_rows(const bench_engine *e, const bench_texture *tex, int n, bench_row *rows)
{
    int k;
    for (k = 0; k < n; ++k)
        if (bench_row_prepare(e, &tex[k], &rows[k]) != 0) {
            while (k-- > 0) bench_row_release(&rows[k]);
            return -1;
        }
    return 0;
}

static void release_rows(bench_row *rows, int n)
{
    int k;
    for (k = 0; k < n; ++k) bench_row_release(&rows[k]);
}

/* The process's peak resident memory in MiB: Linux's VmHWM, which
 * rss_peak_reset sets back to the memory resident now (proc(5),
 * /proc/pid/clear_refs, value 5), so that a peak can be had per phase;
 * elsewhere getrusage's ru_maxrss, the peak of the whole run. */
static double status_mib(const char *field)
{
    char line[256];
    FILE *f = fopen("/proc/self/status", "r");
    double kib = -1.0;
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, field, strlen(field)) == 0) kib = atof(line + strlen(field));
    if (f) fclose(f);
    return kib < 0.0 ? -1.0 : kib / 1024.0;
}

static double peak_rss_mib(void)
{
    struct rusage ru;
    double mib = status_mib("VmHWM:");
    if (mib < 0.0 && getrusage(RUSAGE_SELF, &ru) == 0) mib = (double)ru.ru_maxrss / 1024.0;
    return mib;
}

/* 1 if the peak now starts again from the resident memory. */
static int rss_peak_reset(void)
{
    FILE *f = fopen("/proc/self/clear_refs", "w");
    int ok = f && fputs("5", f) >= 0;
    if (f) ok = fclose(f) == 0 && ok;
    return ok;
}

/* Tiles and bytes one side has read so far. */
static void counts(const cs_run *r, sample_texsys *sys, oiio_ts *ts, double *tiles, double *bytes)
{
    if (r->e->oiio) {
        oiio_ts_stats os;
        oiio_ts_stats_get(ts, &os);
        *tiles = (double)os.tiles_read;
        *bytes = (double)os.bytes_read;
    } else {
        sample_texsys_stats st;
        sample_texsys_stats_get(sys, &st);
        *tiles = (double)st.tiles_read;
        *bytes = (double)st.bytes_read;
    }
}

typedef struct cs_result {
    bench_timing timing;
    double tiles, bytes; /* per timed run */
    double working_set;  /* libsample's rows: bytes one run reads through a cache that never evicts */
} cs_result;

/* One engine on `threads` threads: a warm-up run, then o->runs timed
 * ones. Returns 0, or −1 (reported). */
static int measure(cs_run *r, sample_texsys *sys, oiio_ts *ts, int threads, int runs, size_t nq,
                   cs_result *out)
{
    double v[1000], t0, b0, t1, b1, s;
    int k;
    if (timed_run(r, threads) < 0) return -1;
    counts(r, sys, ts, &t0, &b0);
    for (k = 0; k < runs; ++k) {
        if ((s = timed_run(r, threads)) < 0) return -1;
        v[k] = (double)nq / s;
    }
    counts(r, sys, ts, &t1, &b1);
    bench_timing_of(v, runs, &out->timing);
    out->tiles = (t1 - t0) / runs;
    out->bytes = (b1 - b0) / runs;
    return 0;
}

static void print_row(const char *name, int threads, double cache_mb, const cs_result *ours, const cs_result *theirs)
{
    printf("| %s | %.1f (%.1f x) | %d | %.2f | ", name, ours->working_set / 1048576.0,
           ours->working_set / 1048576.0 / cache_mb, threads, ours->timing.median / 1e6);
    if (theirs)
        printf("%.2f | %.2f | ", theirs->timing.median / 1e6, ours->timing.median / theirs->timing.median);
    else
        printf("- | - | ");
    printf("%.0f | %.1f | ", ours->tiles, ours->bytes / 1048576.0);
    if (theirs)
        printf("%.0f | %.1f |\n", theirs->tiles, theirs->bytes / 1048576.0);
    else
        printf("- | - |\n");
}

/* Bytes one run of the first libsample engine reads through a cache that
 * never evicts: the working set the cache is measured against. */
static int working_set(const bench_cacheset_opts *o, char (*path)[1100], cs_run *r, double *bytes)
{
    bench_texture *tex = calloc((size_t)o->textures, sizeof *tex);
    bench_row *rows = calloc((size_t)o->textures, sizeof *rows);
    tool_backend lib;
    sample_texsys *sys = tex && rows ? open_all(o, 1048576.0, path, &lib, tex) : NULL;
    sample_texsys_stats st;
    cs_run w = *r;
    int rc = -1;
    if (sys) {
        w.rows = rows;
        if (prepare_rows(r->e, tex, o->textures, rows) == 0) {
            if (timed_run(&w, 1) >= 0) {
                sample_texsys_stats_get(sys, &st);
                *bytes = (double)st.bytes_read;
                rc = 0;
            }
            release_rows(rows, o->textures);
        }
        tool_backend_close(&lib);
        sample_texsys_destroy(sys);
    }
    free(rows);
    free(tex);
    return rc;
}

int bench_cacheset(const bench_cacheset_opts *o)
{
    char (*path)[1100] = calloc((size_t)o->textures, sizeof *path);
    bench_texture *tex = calloc((size_t)o->textures, sizeof *tex);
    bench_row *rows = calloc((size_t)o->textures, sizeof *rows);
    bench_engine *eng = calloc((size_t)o->neng, sizeof *eng);
    tool_backend lib = {0};
    tool_oiio_store *store = NULL;
    char dir[1024], err[512];
    sample_query *q = NULL;
    cs_job *jobs = NULL;
    size_t njobs = 0, nq;
    sample_texsys *sys = NULL;
    sample_texsys_stats st;
    oiio_ts *ts = NULL;
    cs_result *res = NULL;
    double rss_setup, rss_phase[2] = {-1.0, -1.0}, rss_start[2] = {-1.0, -1.0};
    int e, k, reset = 0, nthr = o->threads > 1 ? 2 : 1, rc = 1, made_dir = 0;

    if (!path || !tex || !rows || !eng || make_frames(o->queries, o->textures, &q, &jobs, &njobs) != 0) {
        fprintf(stderr, "texsample bench: out of memory\n");
        goto done;
    }
    if (!o->files) {
        snprintf(dir, sizeof dir, "%s/texsample-cacheset-XXXXXX", o->tmpdir);
        if (!mkdtemp(dir)) {
            fprintf(stderr, "texsample bench: cannot create a directory in %s\n", o->tmpdir);
            goto done;
        }
        made_dir = 1;
    }
    if (make_files(o, dir, path) != 0) goto done;
    /* OpenImageIO's rows: its TextureSystem with the same cache. */
    memcpy(eng, o->eng, (size_t)o->neng * sizeof *eng);
    if (o->oiio) {
        if (!(store = tool_oiio_store_open_in(o->cache_mb, o->tmpdir, err, sizeof err))) {
            fprintf(stderr, "texsample bench: %s\n", err);
            goto done;
        }
        if (bench_engines_open_oiio(eng, o->neng, store) != 0) goto done;
        ts = tool_oiio_store_ts(store);
    }
    if (!(sys = open_all(o, o->cache_mb, path, &lib, tex))) goto done;
    if (!(res = calloc((size_t)o->neng * 2, sizeof *res))) goto done;
    nq = o->queries * (size_t)o->textures;
    rss_setup = peak_rss_mib();
    /* libsample's engines first, then OIIO's, the peak RSS of each group
     * apart where it can be reset. */
    for (k = 0; k < 2; ++k) {
        reset = rss_peak_reset();
        rss_start[k] = status_mib("VmRSS:");
        for (e = 0; e < o->neng; ++e) {
            cs_run r = {&eng[e], rows, q, jobs, njobs, 0, 0};
            int t, failed = 0;
            if (eng[e].oiio != k || (eng[e].oiio && !ts)) continue;
            if (prepare_rows(&eng[e], tex, o->textures, rows) != 0) goto done;
            for (t = 0; t < nthr && !failed; ++t)
                failed = measure(&r, sys, ts, t ? o->threads : 1, o->runs, nq, &res[2 * e + t]) != 0;
            release_rows(rows, o->textures);
            if (failed) {
                fprintf(stderr, "texsample bench: %s failed\n", eng[e].name);
                goto done;
            }
        }
        rss_phase[k] = peak_rss_mib();
    }
    /* Last: the freed tiles of a cache that never evicts would stay in
     * the heap, resident, under the RSS of the timed runs. */
    for (e = 0; e < o->neng; ++e) {
        cs_run r = {&eng[e], rows, q, jobs, njobs, 0, 0};
        if (!eng[e].oiio && working_set(o, path, &r, &res[2 * e].working_set) != 0) goto done;
        res[2 * e + 1].working_set = res[2 * e].working_set;
    }
    sample_texsys_stats_get(sys, &st);
    printf("%d textures of %d^2 half (tiled 64^2, mip-mapped), cache %g MiB on both sides\n", o->textures,
           o->texsize, o->cache_mb);
    printf("one timed run: %d plane frames of %zu queries, screen tiles of %d^2 cycling textures (%zu queries)\n",
           o->textures, o->queries, CS_TILE, nq);
    printf("working set: the MiB one run reads through a cache that never evicts (libsample), and that "
           "over the cache\n\n");
    printf("| filter | working set MiB | threads | ours Msamples/s | OIIO Msamples/s | ratio | ours tiles/run | ours MiB/run "
           "| OIIO tiles/run | OIIO MiB/run |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (e = 0; e < o->neng; ++e) {
        int t, m;
        if (o->eng[e].oiio) continue;
        m = o->eng[e].match >= 0 && ts ? o->eng[e].match : -1;
        for (t = 0; t < nthr; ++t)
            print_row(o->eng[e].name, t ? o->threads : 1, o->cache_mb, &res[2 * e + t],
                      m >= 0 ? &res[2 * m + t] : NULL);
    }
    printf("\nlibsample: peak cache memory %.1f MiB (limit %g MiB)\n", (double)st.peak_memory / 1048576.0,
           o->cache_mb);
    if (ts) {
        oiio_ts_stats os;
        oiio_ts_stats_get(ts, &os);
        printf("OIIO: cache memory at the end %.1f MiB, peak %lld tiles\n", (double)os.memory / 1048576.0,
               os.peak_tiles);
    }
    if (reset)
        printf("process RSS: peak %.0f MiB writing and opening the files; libsample's runs from %.0f MiB to a peak "
               "of %.0f MiB (+%.1f), OIIO's from %.0f to %.0f MiB (+%.1f)\n",
               rss_setup, rss_start[0], rss_phase[0], rss_phase[0] - rss_start[0], rss_start[1], rss_phase[1],
               rss_phase[1] - rss_start[1]);
    else
        printf("process peak RSS: %.0f MiB (the whole run's)\n", peak_rss_mib());
    rc = 0;
done:
    if (sys) tool_backend_close(&lib);
    sample_texsys_destroy(sys);
    if (eng) bench_engines_close(eng, o->neng);
    tool_oiio_store_close(store);
    if (made_dir) {
        for (k = 0; k < o->textures; ++k)
            if (path[k][0]) remove(path[k]);
        rmdir(dir);
    }
    free(res);
    free(path);
    free(rows);
    free(eng);
    free(tex);
    free(q);
    free(jobs);
    return rc;
}
