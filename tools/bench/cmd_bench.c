/*
 * texsample bench: samples per second of every filter of libsample, and of
 * OpenImageIO's TextureSystem at the matching settings, on standard query
 * sets, on one thread and on all of them (doc/benchmarks.md).
 */
/* getloadavg (glibc, the BSDs, macOS). */
#define _DEFAULT_SOURCE
#include "bench.h"
#include "../backend.h"
#include "cli.h"
#include "commands.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char help[] =
    "usage: texsample bench [--quick] [--json FILE] [--save DIR] [options]\n\n"
    "Measures samples per second of each libsample filter and of OpenImageIO's\n"
    "TextureSystem at matching settings, on 1 thread and on all cores, and the\n"
    "texels each filter reads per sample. Prints a table; --json writes the same\n"
    "numbers for scripts. Timings are the median of --runs passes after one\n"
    "untimed warm-up pass, with the fastest and slowest shown.\n\n"
    "Query sets (fixed seeds): magnify (footprint 0.25 texel), minify (2.5 texels),\n"
    "aniso8 (8:1, random angles), plane (a ground plane to the horizon in scanline\n"
    "order, exact Jacobians), plane-shuffled (the same queries in random order).\n"
    "Formats: float, half, srgb8 (OIIO gets the same 8-bit codes; it does not\n"
    "decode sRGB). Filters: the tools' filter registry (doc/comparison.md); each\n"
    "runs on libsample and, where it has one, on its OIIO twin.\n\n"
    "Options:\n"
    "  --quick            a short run: --size 512 --queries 16384 --runs 3\n"
    "  --size N           texture side in texels (default 2048)\n"
    "  --queries N        queries per set (default 262144)\n"
    "  --runs N           timed passes per measurement (default 5)\n"
    "  --threads N        the 'all threads' count (default: online CPUs)\n"
    "  --batch N          queries per sample_batch call (default 256)\n"
    "  --sets LIST        comma-separated set names (default all)\n"
    "  --formats LIST     comma-separated formats (default all)\n"
    "  --filters LIST     comma-separated filters, from the list below (default, or\n"
    "                     'all': those marked *)\n"
    "  --no-oiio          measure libsample only\n"
    "  --cache-mb N       libsample reads OIIO's texture file through a texture\n"
    "                     system (sample/texsys.h) whose tile cache holds N MiB,\n"
    "                     and OIIO's TextureSystem gets the same max_memory_MB;\n"
    "                     the tiles and bytes libsample read are printed per format\n"
    "                     (doc/texture-system.md)\n"
    "  --gl               also time each filter's OpenGL twin (where it has one;\n"
    "                     n/a otherwise) through EGL: texture upload, query\n"
    "                     upload, sampling and read-back apart (doc/backends.md)\n"
    "  --gl-device NAME   the OpenGL driver: an EGL device by index, DRM node or\n"
    "                     part of its GL_RENDERER (default: Mesa's surfaceless\n"
    "                     platform, llvmpipe); implies --gl\n"
    "  --scalar           libsample through its general per-query path\n"
    "                     (sample_batch_reference), to measure the fast path\n"
    "  --tmpdir DIR       where OIIO's texture files are written (default $TMPDIR\n"
    "                     or /tmp); they are removed at the end (--save keeps\n"
    "                     copies in its directory)\n"
    "  --json FILE        also write the results as JSON ('-': stdout, no table)\n"
    "  --save DIR         keep what was timed in DIR (created if missing): each\n"
    "                     set's queries (queries_SET.bin, little-endian float32\n"
    "                     s, t, dsdx, dtdx, dsdy, dtdy per query), OIIO's texture\n"
    "                     files (written even with --no-oiio) and manifest.json\n"
    "                     (layout, settings of both sides, 1-thread samples/s),\n"
    "                     for re-timing by tools/bench/oiio_replay\n"
    ;
/* The other kinds' runs (a second string: ISO C's limit on one literal). */
static const char help_kinds[] =
    "  --env              environment lookups instead: libsample's lat-long map\n"
    "                     (--size x --size/2) and cube map (--size/4 faces) beside\n"
    "                     OpenImageIO's environment() on the lat-long map, on\n"
    "                     random directions (env-random: 2.5-texel footprints) and\n"
    "                     a mirror sphere's reflection frame (env-reflection);\n"
    "                     takes --size, --queries, --runs, --threads, --batch,\n"
    "                     --filters, --no-oiio, --tmpdir, --quick\n\n"
    "  --volume           3D texture lookups instead (doc/volumes.md): a --size^3\n"
    "                     volume (default 128) of baked wood, random queries\n"
    "                     (--queries, default 65536) and the carved teapot's\n"
    "                     frame; nearest, bilinear, trilinear, aniso16,\n"
    "                     blinn-newell and ewa on 1 thread (--runs), beside\n"
    "                     OpenImageIO's texture3d (closest, linear; not with\n"
    "                     --no-oiio; its file in --tmpdir); --threads, --batch,\n"
    "                     --sets, --formats, --filters, --cache-mb, --scalar,\n"
    "                     --json and --save do not apply\n"
    "  --frame N          the teapot frame's side with --volume (default 256)\n\n"
    "  --textures N       a working set larger than the cache instead (needs\n"
    "                     --cache-mb): N tiled mip-mapped half OpenEXR files of\n"
    "                     --texsize^2 in --tmpdir (removed after), plane frames of\n"
    "                     --queries (default 65536) whose 16^2-pixel screen tiles\n"
    "                     cycle the textures, N frames a timed run; libsample\n"
    "                     through one texture system and OIIO's TextureSystem with\n"
    "                     the same cache; prints samples/s, tiles and bytes read\n"
    "                     by each, peak memory; takes --runs, --threads (at most\n"
    "                     64), --filters (default trilinear), --no-oiio\n"
    "  --texsize N        those textures' side (default 4096)\n"
    "  --texture-file F   sample file F instead of writing one (repeat the option,\n"
    "                     once per texture; N is their count)\n\n"
    "Filters:\n";
static const char help_tail[] = "\nExit codes: 0 success, 1 runtime error, 2 usage error.\n";

enum { MAX_ENGINES = 32 };

typedef struct bench_opts {
    int size, runs, threads, oiio, scalar, gl, env;
    int volume, frame, size_given, queries_given; /* --volume and its options */
    int textures, texsize, nfiles, filters_given;  /* --textures and its options */
    char *files[256];
    float cache_mb; /* 0: resident textures, OIIO's default cache */
    const char *gl_device;
    size_t queries, batch;
    unsigned sets, formats; /* bit masks */
    const char *json, *tmpdir, *save, *filters;
} bench_opts;

/* "a,b,c" over `names` into a bit mask; returns 0, or EXIT_USAGE after
 * reporting. */
static int parse_list(const char *opt, const char *list, const char *const *names, int count,
                      unsigned *mask)
{
    const char *p = list;
    *mask = 0;
    if (!list || !*list) return cli_usage_error("bench", "%s needs a list", opt);
    while (*p) {
        size_t len = strcspn(p, ",");
        int k;
        for (k = 0; k < count; ++k)
            if (strlen(names[k]) == len && strncmp(p, names[k], len) == 0) break;
        if (k == count) return cli_usage_error("bench", "%s: unknown name '%.*s'", opt, (int)len, p);
        *mask |= 1u << k;
        p += len;
        if (*p == ',') ++p;
    }
    return 0;
}

/* An integer option in [lo, hi]; returns 0, or EXIT_USAGE after reporting. */
static int parse_size(const char *opt, const char *v, long lo, long hi, long *out)
{
    int x;
    if (!cli_parse_int(v, &x) || x < lo || x > hi)
        return cli_usage_error("bench", "%s must be an integer in [%ld, %ld], not '%s'", opt, lo,
                               hi, v ? v : "");
    *out = x;
    return 0;
}

/* Returns 0, or nonzero after reporting a usage error. */
static int parse_args(int argc, char **argv, bench_opts *o)
{
    const char *v;
    int i;
    long x = 0; /* set by parse_size before every use; GCC cannot see it */
    for (i = 1; i < argc; ++i) {
        if (cli_opt(argc, argv, &i, "--quick", NULL)) {
            o->size = 512;
            o->queries = 16384;
            o->runs = 3;
        } else if (cli_opt(argc, argv, &i, "--no-oiio", NULL)) {
            o->oiio = 0;
        } else if (cli_opt(argc, argv, &i, "--gl", NULL)) {
            o->gl = 1;
        } else if (cli_opt(argc, argv, &i, "--gl-device", &v)) {
            if (!v || !*v) return cli_usage_error("bench", "--gl-device needs a name");
            o->gl = 1;
            o->gl_device = v;
        } else if (cli_opt(argc, argv, &i, "--scalar", NULL)) {
            o->scalar = 1;
        } else if (cli_opt(argc, argv, &i, "--env", NULL)) {
            o->env = 1;
        } else if (cli_opt(argc, argv, &i, "--volume", NULL)) {
            o->volume = 1;
        } else if (cli_opt(argc, argv, &i, "--frame", &v)) {
            if (parse_size("--frame", v, 1, 4096, &x)) return -1;
            o->frame = (int)x;
        } else if (cli_opt(argc, argv, &i, "--textures", &v)) {
            if (parse_size("--textures", v, 1, 256, &x)) return -1;
            o->textures = (int)x;
        } else if (cli_opt(argc, argv, &i, "--texsize", &v)) {
            if (parse_size("--texsize", v, 16, SAMPLE_MAX_SIZE, &x)) return -1;
            o->texsize = (int)x;
        } else if (cli_opt(argc, argv, &i, "--texture-file", &v)) {
            if (!v || !*v) return cli_usage_error("bench", "--texture-file needs a file name");
            if (o->nfiles == 256) return cli_usage_error("bench", "--texture-file: at most 256 files");
            o->files[o->nfiles++] = (char *)(uintptr_t)v;
        } else if (cli_opt(argc, argv, &i, "--size", &v)) {
            if (parse_size("--size", v, 16, SAMPLE_MAX_SIZE / 4, &x)) return -1;
            o->size = (int)x;
            o->size_given = 1;
        } else if (cli_opt(argc, argv, &i, "--queries", &v)) {
            if (parse_size("--queries", v, 1, 1L << 26, &x)) return -1;
            o->queries = (size_t)x;
            o->queries_given = 1;
        } else if (cli_opt(argc, argv, &i, "--runs", &v)) {
            if (parse_size("--runs", v, 1, 1000, &x)) return -1;
            o->runs = (int)x;
        } else if (cli_opt(argc, argv, &i, "--threads", &v)) {
            if (parse_size("--threads", v, 1, 1024, &x)) return -1;
            o->threads = (int)x;
        } else if (cli_opt(argc, argv, &i, "--batch", &v)) {
            if (parse_size("--batch", v, 1, 1L << 20, &x)) return -1;
            o->batch = (size_t)x;
        } else if (cli_opt(argc, argv, &i, "--sets", &v)) {
            if (parse_list("--sets", v, bench_set_names, BENCH_SET_COUNT, &o->sets)) return -1;
        } else if (cli_opt(argc, argv, &i, "--formats", &v)) {
            if (parse_list("--formats", v, bench_format_names, BENCH_FMT_COUNT, &o->formats))
                return -1;
        } else if (cli_opt(argc, argv, &i, "--filters", &v)) {
            if (!v || !*v) return cli_usage_error("bench", "--filters needs a list");
            o->filters = v;
            o->filters_given = 1;
        } else if (cli_opt(argc, argv, &i, "--json", &v)) {
            if (!v) return cli_usage_error("bench", "--json needs a file name");
            o->json = v;
        } else if (cli_opt(argc, argv, &i, "--save", &v)) {
            if (!v || !*v) return cli_usage_error("bench", "--save needs a directory");
            /* Paths inside it are built in fixed buffers. */
            if (strlen(v) > 900) return cli_usage_error("bench", "--save: directory name too long");
            o->save = v;
        } else if (cli_opt(argc, argv, &i, "--cache-mb", &v)) {
            if (!cli_parse_float(v, &o->cache_mb) || !(o->cache_mb > 0.0f) || o->cache_mb > 1048576.0f)
                return cli_usage_error("bench", "--cache-mb must be a size in MiB above 0, not '%s'", v ? v : "");
        } else if (cli_opt(argc, argv, &i, "--tmpdir", &v)) {
            if (!v) return cli_usage_error("bench", "--tmpdir needs a directory");
            o->tmpdir = v;
        } else {
            return cli_usage_error("bench", "unknown option '%s'", argv[i]);
        }
    }
    return 0;
}

/* The command line as one string, for the record in the JSON. */
static char *join_args(int argc, char **argv)
{
    size_t len = strlen("texsample") + 1;
    char *s;
    int i;
    for (i = 0; i < argc; ++i) len += strlen(argv[i]) + 1;
    if (!(s = malloc(len))) return NULL;
    strcpy(s, "texsample");
    for (i = 0; i < argc; ++i) {
        strcat(s, " ");
        strcat(s, argv[i]);
    }
    return s;
}

/* Mean texels read per sample over the whole set (an untimed pass).
 * Returns 0, or −1 after reporting. */
static int texels_per_sample(const bench_engine *e, const bench_texture *t,
                             const sample_query *q, size_t n, double *out)
{
    sample_stats *st = malloc(n * sizeof *st);
    float *rgba = malloc(n * 4 * sizeof *rgba);
    double sum = 0.0;
    size_t i;
    int rc = -1;
    if (!st || !rgba) {
        cli_runtime_error("bench", "out of memory");
    } else if (bench_engine_run(e, t, q, n, rgba, st) == 0) {
        for (i = 0; i < n; ++i) sum += st[i].texels;
        *out = sum / (double)n;
        rc = 0;
    }
    free(st);
    free(rgba);
    return rc;
}

typedef struct bench_run {
    bench_opts o;
    bench_engine eng[MAX_ENGINES];
    int neng, nours; /* engines, of which libsample's (the first nours) */
    /* OpenImageIO's files and TextureSystem (tools/backends/oiio.c), in
     * each format's own texels; `files` writes a format's file for --save
     * and --cache-mb. NULL / unopened when neither they nor OIIO run. */
    tool_oiio_store *store;
    tool_backend files;
    bench_result *res;
    size_t nres;
    tool_backend gl; /* --gl: opened once */
    bench_gl_result *glres;
    size_t ngl;
} bench_run;

/* Is engine e measured? Every engine is one the filters named (the table
 * is built from them); OIIO's only when OIIO runs. */
static int engine_selected(const bench_run *b, int e) { return !b->eng[e].oiio || b->eng[e].backend; }

/* Every selected engine on one texture and query set, at 1 and at all
 * threads. The 1-thread passes take turns: pass r of every engine runs
 * after pass r − 1 of all of them, so that a spell in which the machine
 * runs slower (another process, a neighbour on the host, a clock change)
 * falls on libsample and on OIIO alike instead of on one engine's whole
 * measurement — the usual defence of an A/B timing (doc/benchmarks.md).
 * The all-thread passes stay engine after engine: a pool's workers poll
 * for a while after each pass (timing.c), which would take the next
 * engine's cores. Results keep the order engine, then threads. Returns 0,
 * or nonzero after reporting. */
static int measure(bench_run *b, const bench_texture *tex, bench_format fmt, bench_set set,
                   const sample_query *q, size_t *done, size_t total)
{
    int e, k, r, nthr = b->o.threads > 1 ? 2 : 1, rc = 0;
    const int thr[2] = {1, b->o.threads};
    bench_timer *tm[MAX_ENGINES] = {NULL};
    size_t slot[MAX_ENGINES] = {0}, first = b->nres;
    int sel[MAX_ENGINES] = {0};
    const char *failed = NULL;

    for (e = 0; e < b->neng; ++e) {
        const bench_engine *en = &b->eng[e];
        double tps = -1.0;
        if (!engine_selected(b, e)) continue;
        if (!en->oiio && texels_per_sample(en, tex, q, b->o.queries, &tps) != 0) return -1;
        slot[e] = b->nres;
        sel[e] = 1;
        for (k = 0; k < nthr; ++k) {
            bench_result *res = &b->res[b->nres++];
            res->set = set;
            res->format = fmt;
            res->engine = e;
            res->threads = thr[k];
            res->texels_per_sample = tps;
        }
    }
    for (e = 0; e < b->neng && !failed; ++e)
        if (sel[e] && !(tm[e] = bench_timer_open(&b->eng[e], tex, q, b->o.queries, 1, b->o.runs, b->o.batch)))
            failed = b->eng[e].name;
    for (r = 0; r < b->o.runs && !failed; ++r)
        for (e = 0; e < b->neng && !failed; ++e)
            if (tm[e] && bench_timer_pass(tm[e]) != 0) failed = b->eng[e].name;
    for (e = 0; e < b->neng; ++e) {
        if (!tm[e]) continue;
        if (bench_timer_close(tm[e], &b->res[slot[e]].timing) != 0 && !failed) failed = b->eng[e].name;
        tm[e] = NULL;
        if (!failed) cli_progress("bench", ++*done, total);
    }
    for (k = 1; k < nthr && !failed; ++k)
        for (e = 0; e < b->neng && !failed; ++e) {
            if (!sel[e]) continue;
            if (bench_time(&b->eng[e], tex, q, b->o.queries, thr[k], b->o.runs, b->o.batch,
                           &b->res[slot[e] + (size_t)k].timing) != 0)
                failed = b->eng[e].name;
            else
                cli_progress("bench", ++*done, total);
        }
    if (failed) {
        b->nres = first;
        rc = cli_runtime_error("bench", "%s on %s/%s failed", failed, bench_set_names[set],
                               bench_format_names[fmt]);
    }
    return rc;
}

static int count_bits(unsigned m)
{
    int n = 0;
    for (; m; m &= m - 1) ++n;
    return n;
}

/* OpenImageIO's file of tex, for --save and --cache-mb: written by its
 * backend in the format's own texels (*file holds it until released).
 * Returns 0, or nonzero after reporting. */
static int format_file(bench_run *b, bench_texture *tex, bench_format fmt, tool_backend_tex **file)
{
    sample_sampler smp;
    char err[512];
    const char *path;
    *file = NULL;
    if (!b->files.ops) return 0;
    sample_sampler_init(&smp); /* REPEAT, as the texture's pyramid */
    if (tool_backend_prepare(&b->files, tex->ours, &smp, file, NULL, err, sizeof err) != 0) {
        *file = NULL;
        return cli_runtime_error("bench", "OpenImageIO's %s file: %s", bench_format_names[fmt], err);
    }
    path = tool_oiio_file(*file);
    if (b->o.save && bench_save_texture(b->o.save, fmt, path) != 0) return EXIT_RUNTIME;
    if (b->o.cache_mb > 0.0f && bench_texture_cache(tex, path, b->o.cache_mb) != 0) return EXIT_RUNTIME;
    return 0;
}

static int run_all(bench_run *b)
{
    float *content = bench_content(b->o.size);
    sample_query *q = malloc(b->o.queries * sizeof *q);
    size_t done = 0, total;
    int fmt, set, e, nsel = 0, rc = 0, saved_any_format = 0;
    for (e = 0; e < b->neng; ++e)
        nsel += engine_selected(b, e);
    total = (size_t)(count_bits(b->o.sets) * count_bits(b->o.formats) * nsel *
                     (b->o.threads > 1 ? 2 : 1));
    b->res = calloc(total ? total : 1, sizeof *b->res);
    b->glres = calloc((size_t)(count_bits(b->o.sets) * count_bits(b->o.formats) * b->nours) + 1,
                      sizeof *b->glres);
    if (!content || !q || !b->res || !b->glres) {
        rc = cli_runtime_error("bench", "out of memory");
        goto done;
    }
    for (fmt = 0; fmt < BENCH_FMT_COUNT && rc == 0; ++fmt) {
        bench_texture tex;
        tool_backend_tex *file = NULL;
        if (!((b->o.formats >> fmt) & 1u)) continue;
        if (bench_texture_make(content, b->o.size, (bench_format)fmt, &tex) != 0) {
            rc = EXIT_RUNTIME;
            break;
        }
        rc = format_file(b, &tex, (bench_format)fmt, &file);
        for (set = 0; set < BENCH_SET_COUNT && rc == 0; ++set) {
            if (!((b->o.sets >> set) & 1u)) continue;
            bench_queries((bench_set)set, b->o.size, q, b->o.queries);
            /* The buffer about to be timed, once per set (every format
             * gets the same queries). */
            if (b->o.save && !saved_any_format &&
                bench_save_queries(b->o.save, (bench_set)set, q, b->o.queries) != 0) {
                rc = EXIT_RUNTIME;
                break;
            }
            if (measure(b, &tex, (bench_format)fmt, (bench_set)set, q, &done, total) != 0)
                rc = EXIT_RUNTIME;
            for (e = 0; e < b->nours && b->gl.ops && rc == 0; ++e) {
                bench_gl_result *g = &b->glres[b->ngl++];
                if (bench_gl_measure(&b->gl, &b->eng[e], e, &tex, (bench_set)set, (bench_format)fmt,
                                     q, b->o.queries, b->o.runs, g) != 0)
                    rc = cli_runtime_error("bench", "OpenGL %s: %s", b->eng[e].name, g->note);
            }
        }
        bench_texture_stats(&tex, stderr);
        if (file) tool_backend_release(&b->files, file);
        bench_texture_free(&tex);
        saved_any_format = 1;
    }
done:
    free(content);
    free(q);
    return rc;
}

/* OpenImageIO's store (its files in the texture's own format, under
 * --tmpdir; its TextureSystem's cache --cache-mb) and its rows' backends,
 * and the OpenGL backend. Returns 0, or EXIT_RUNTIME after reporting. */
static int open_backends(bench_run *b)
{
    char err[512];
    if (b->o.oiio || b->o.save || b->o.cache_mb > 0.0f) {
        oiio_ts_opts opts;
        if (!(b->store = tool_oiio_store_open_in(b->o.cache_mb, b->o.tmpdir, err, sizeof err)))
            return cli_runtime_error("bench", "%s", err);
        tool_oiio_store_native_formats(b->store);
        oiio_ts_opts_init(&opts);
        if (tool_backend_oiio_open(&b->files, b->store, &opts, err, sizeof err) != 0)
            return cli_runtime_error("bench", "%s", err);
    }
    if (b->o.oiio && bench_engines_open_oiio(b->eng, b->neng, b->store) != 0) return EXIT_RUNTIME;
    if (b->o.gl && tool_backend_gl_open(&b->gl, b->o.gl_device, err, sizeof err) != 0)
        return cli_runtime_error("bench", "OpenGL: %s", err);
    return 0;
}

/* --save's directory: made if missing (one level, as mkdir), else it must
 * be a directory. Returns 0, or EXIT_RUNTIME after reporting. */
static int make_save_dir(const char *dir)
{
    struct stat st;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return cli_runtime_error("bench", "--save: cannot create %s: %s", dir, strerror(errno));
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        return cli_runtime_error("bench", "--save: %s is not a directory", dir);
    return 0;
}

/* The engine table from --filters: the named registry entries (libsample
 * only: the twins come with them; no corners, the query sets have only
 * Jacobians). Returns 0, or EXIT_USAGE after reporting. */
static int make_engines(bench_run *b)
{
    tool_pick picks[MAX_ENGINES / 2];
    const tool_filter *f[MAX_ENGINES / 2];
    char err[160];
    int k, n = tool_picks_parse("bench", b->o.filters, bench_default_filters, 0, picks,
                                MAX_ENGINES / 2, err, sizeof err);
    if (n < 0) return cli_usage_error("bench", "--filters: %s", err);
    if (n == 0) return cli_usage_error("bench", "--filters names no filter");
    for (k = 0; k < n; ++k) f[k] = picks[k].f;
    b->nours = n;
    b->neng = bench_engines_of(f, n, b->eng, MAX_ENGINES);
    return b->neng < 0 ? cli_usage_error("bench", "--filters: too many") : 0;
}

int cmd_bench(int argc, char **argv)
{
    bench_run b;
    const char *tmp;
    char *command = NULL;
    double load[2] = {-1.0, -1.0};
    int i, rc;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);

    for (i = 1; i < argc; ++i)
        if (cli_is_help(argv[i])) {
            fputs(help, stdout);
            fputs(help_kinds, stdout);
            tool_picks_help(stdout, "  ", bench_default_filters, 0);
            fputs(help_tail, stdout);
            return EXIT_OK;
        }
    memset(&b, 0, sizeof b);
    b.o.size = 2048;
    b.o.queries = 262144;
    b.o.runs = 5;
    b.o.threads = ncpu > 0 ? (int)(ncpu < 1024 ? ncpu : 1024) : 1;
    b.o.batch = 256;
    b.o.oiio = 1;
    b.o.sets = (1u << BENCH_SET_COUNT) - 1;
    b.o.formats = (1u << BENCH_FMT_COUNT) - 1;
    b.o.filters = "all";
    b.o.frame = 256;
    if (parse_args(argc, argv, &b.o) != 0) return EXIT_USAGE;
    if (b.o.volume + b.o.env + (b.o.textures > 0 || b.o.nfiles > 0) > 1)
        return cli_usage_error("bench", "--volume, --env and --textures are different runs: give one");
    if (b.o.volume) {
        /* A volume of --size³ texels: 512³ float RGBA is already 2 GiB. */
        if (b.o.size_given && b.o.size > 512)
            return cli_usage_error("bench", "--volume: --size must be at most 512");
        tmp = b.o.tmpdir ? b.o.tmpdir : getenv("TMPDIR");
        return bench_volume(b.o.size_given ? b.o.size : 128, b.o.queries_given ? b.o.queries : 65536,
                            b.o.runs, b.o.frame, b.o.oiio, tmp && *tmp ? tmp : "/tmp");
    }
    if (b.o.nfiles) {
        if (b.o.textures && b.o.textures != b.o.nfiles)
            return cli_usage_error("bench", "--textures %d but %d --texture-file", b.o.textures, b.o.nfiles);
        b.o.textures = b.o.nfiles;
    }
    if (b.o.textures) {
        if (!(b.o.cache_mb > 0.0f)) return cli_usage_error("bench", "--textures needs --cache-mb");
        if (b.o.threads > 64) return cli_usage_error("bench", "--textures: at most 64 threads");
        if (!b.o.filters_given) b.o.filters = "trilinear";
    } else if (b.o.texsize) {
        return cli_usage_error("bench", "--texsize is an option of --textures");
    }
    if (make_engines(&b) != 0) return EXIT_USAGE;
    if (b.o.textures) {
        bench_cacheset_opts co;
        tmp = b.o.tmpdir ? b.o.tmpdir : getenv("TMPDIR");
        memset(&co, 0, sizeof co);
        co.textures = b.o.textures;
        co.texsize = b.o.texsize ? b.o.texsize : 4096;
        co.runs = b.o.runs;
        co.threads = b.o.threads;
        co.oiio = b.o.oiio;
        co.queries = b.o.queries_given ? b.o.queries : 65536;
        co.cache_mb = b.o.cache_mb;
        co.tmpdir = tmp && *tmp ? tmp : "/tmp";
        co.files = b.o.nfiles ? b.o.files : NULL;
        co.eng = b.eng;
        co.neng = b.neng;
        return bench_cacheset(&co);
    }
    if (b.o.env) {
        bench_env_opts eo;
        if (b.o.json || b.o.save || b.o.scalar || b.o.sets != (1u << BENCH_SET_COUNT) - 1 ||
            b.o.formats != (1u << BENCH_FMT_COUNT) - 1)
            return cli_usage_error("bench", "--env takes no --json, --save, --scalar, --sets or --formats");
        tmp = b.o.tmpdir ? b.o.tmpdir : getenv("TMPDIR");
        eo.size = b.o.size;
        eo.runs = b.o.runs;
        eo.threads = b.o.threads;
        eo.oiio = b.o.oiio;
        eo.queries = b.o.queries;
        eo.batch = b.o.batch;
        eo.filters = b.o.filters;
        eo.tmpdir = tmp && *tmp ? tmp : "/tmp";
        return bench_env(&eo);
    }
    for (i = 0; i < b.neng; ++i)
        if (b.o.scalar && !b.eng[i].oiio) b.eng[i].reference = 1;

    if (b.o.save && make_save_dir(b.o.save) != 0) return EXIT_RUNTIME;
    rc = open_backends(&b);
    if (rc == 0) {
        if (getloadavg(&load[0], 1) != 1) load[0] = -1.0;
        rc = run_all(&b);
    }
    if (getloadavg(&load[1], 1) != 1) load[1] = -1.0;
    if (rc == 0) {
        bench_report r;
        r.scalar = b.o.scalar;
        r.isa = sample_isa_name();
        r.load[0] = load[0];
        r.load[1] = load[1];
        command = join_args(argc, argv);
        r.engines = b.eng;
        r.engine_count = b.neng;
        r.results = b.res;
        r.count = b.nres;
        r.size = b.o.size;
        r.threads_max = b.o.threads;
        r.runs = b.o.runs;
        r.queries = b.o.queries;
        r.batch = b.o.batch;
        r.command = command ? command : "texsample bench";
        r.gl = b.glres;
        r.ngl = b.ngl;
        r.gl_driver = b.gl.driver;
        if (!b.o.json || strcmp(b.o.json, "-") != 0) bench_print_table(&r);
        if (b.o.json && bench_write_json(&r, b.o.json) != 0) rc = EXIT_RUNTIME;
        if (b.o.save) {
            bench_save sv = {b.o.save, b.o.sets, b.o.formats, (1u << b.nours) - 1u};
            if (bench_save_manifest(&sv, &r) != 0) rc = EXIT_RUNTIME;
        }
    }
    bench_engines_close(b.eng, b.neng);
    tool_backend_close(&b.files);
    tool_oiio_store_close(b.store);
    free(b.res);
    free(b.glres);
    tool_backend_close(&b.gl);
    free(command);
    return rc;
}
