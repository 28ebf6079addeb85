/*
 * The filters the benchmark measures: rows of the tools' filter registry
 * (tools/filters.h), each on libsample and, where the entry has one, on its
 * OpenImageIO twin. All wrap with REPEAT ("periodic"). bicubic-bspline is
 * the bicubic measured by default because the B-spline is OIIO's bicubic
 * kernel; Catmull–Rom reads the same 4 × 4 texels at the same cost.
 *
 * libsample's rows sample through its backend of tools/backend.h, the
 * interface every tool's rows share: one prepare, run and release per
 * batch (a sampler check and a small allocation beside a batch's
 * thousands of lookups), so the timed path stays sample_batch's.
 */
#include "bench.h"
#include "../backend.h"
#include "sample/testing.h"

#include <stdio.h>
#include <string.h>

/* libsample's backends: the fast path and the reference path (--scalar);
 * opened by bench_engines_of, before any timed thread runs, and kept for
 * the process. */
static tool_backend lib_fast, lib_ref;

const char *const bench_default_filters[] = {
    "nearest", "bilinear", "bicubic-bspline", "trilinear", "aniso16", "blinn-newell", "ewa", NULL,
};

int bench_engines_of(const tool_filter *const *filters, int count, bench_engine *out, int max)
{
    int k, n = 0;
    if (max < 2 * count) return -1;
    if ((!lib_fast.ops && tool_backend_libsample(&lib_fast, NULL) != 0) ||
        (!lib_ref.ops && tool_backend_libsample(&lib_ref, sample_batch_reference) != 0))
        return -1;
    memset(out, 0, (size_t)max * sizeof *out);
    for (k = 0; k < count; ++k) {
        bench_engine *e = &out[n++];
        e->name = tool_filter_name(filters[k]);
        sample_sampler_init(&e->smp);
        tool_filter_apply(filters[k], &e->smp);
        e->match = -1;
    }
    for (k = 0; k < count; ++k) {
        bench_engine *e;
        if (!filters[k]->oiio.twin) continue;
        out[k].match = n;
        e = &out[n++];
        e->name = out[k].name;
        e->oiio = 1;
        e->match = -1;
        oiio_ts_opts_init(&e->opts);
        tool_filter_oiio_opts(filters[k], &e->opts);
    }
    return n;
}

int bench_engines(bench_engine *out, int max)
{
    const tool_filter *f[sizeof bench_default_filters / sizeof bench_default_filters[0]];
    int n = 0;
    for (; bench_default_filters[n]; ++n)
        if (!(f[n] = tool_filter_by_name(bench_default_filters[n]))) return -1;
    return bench_engines_of(f, n, out, max);
}

/* A libsample row's batch through its backend. */
static int lib_batch(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
                     float *rgba, sample_stats *stats)
{
    tool_backend *b = e->reference ? &lib_ref : &lib_fast;
    tool_backend_tex *x = NULL;
    tool_backend_batch a;
    char err[256];
    int rc = (e->env ? tool_backend_prepare_env : tool_backend_prepare)(b, t->ours, &e->smp, &x, NULL,
                                                                        err, sizeof err);
    if (rc == 0) {
        tool_backend_batch_init(&a, n, e->env ? NULL : q, e->env ? q : NULL, rgba, stats);
        rc = tool_backend_run(b, x, &a, NULL, err, sizeof err);
        tool_backend_release(b, x);
    }
    if (rc == 0) return 0;
    fprintf(stderr, "texsample bench: %s: %s\n", e->name, err);
    return -1;
}

int bench_engine_run(const bench_engine *e, const bench_texture *t, oiio_ts *ts,
                     const void *q, size_t n, float *rgba, sample_stats *stats)
{
    char err[512];
    if (e->oiio) {
        /* OpenImageIO's rows read bench's own files in each format
         * (textures.c), which its backend (tools/backends/oiio.c, float
         * files only) does not write. */
        int rc = e->env ? oiio_ts_environment(ts, t->theirs, &e->opts, q, n, rgba, err, sizeof err)
                        : oiio_ts_sample(ts, t->theirs, &e->opts, q, n, rgba, err, sizeof err);
        if (rc == 0) return 0;
        fprintf(stderr, "texsample bench: OIIO %s%s: %s\n", e->env ? "environment " : "", e->name, err);
        return -1;
    }
    if (t->cached && !e->env) {
        /* bench --cache-mb: libsample's lookups through its texture system. */
        sample_batch_args a;
        sample_status st;
        memset(&a, 0, sizeof a);
        a.count = n;
        a.queries = q;
        a.rgba = rgba;
        a.stats = stats;
        st = t->cached(t->sys, t->ours, &e->smp, &a);
        if (st == SAMPLE_OK) return 0;
        fprintf(stderr, "texsample bench: %s: %s\n", e->name, sample_strerror(st));
        return -1;
    }
    return lib_batch(e, t, q, n, rgba, stats);
}
