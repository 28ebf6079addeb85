/*
 * The filters the benchmark measures: rows of the tools' filter registry
 * (tools/filters.h), each on libsample and, where the entry has one, on its
 * OpenImageIO twin. All wrap with REPEAT ("periodic"). bicubic-bspline is
 * the bicubic measured by default because the B-spline is OIIO's bicubic
 * kernel; Catmull–Rom reads the same 4 × 4 texels at the same cost.
 *
 * Every row samples through its backend of tools/backend.h, the interface
 * every tool's rows share: libsample's (sample_batch; with --cache-mb, its
 * texture system's batch) and OpenImageIO's TextureSystem, which reads its
 * own file of the texture in the texture's format. A row is prepared once
 * per timed measurement (OpenImageIO's file written and read through,
 * outside the clock) and then asked one run per batch, so the timed path
 * stays sample_batch's and TextureSystem::texture's.
 */
#include "bench.h"
#include "../backend.h"
#include "sample/testing.h"

#include <stdio.h>
#include <stdlib.h>
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

int bench_engines_open_oiio(bench_engine *e, int n, tool_oiio_store *store)
{
    char err[256];
    int k;
    for (k = 0; k < n; ++k) {
        if (!e[k].oiio || e[k].backend) continue;
        if (!(e[k].backend = malloc(sizeof *e[k].backend))) {
            fprintf(stderr, "texsample bench: out of memory\n");
            return -1;
        }
        if (tool_backend_oiio_open(e[k].backend, store, &e[k].opts, err, sizeof err) != 0) {
            free(e[k].backend);
            e[k].backend = NULL;
            fprintf(stderr, "texsample bench: OIIO %s: %s\n", e[k].name, err);
            return -1;
        }
    }
    return 0;
}

void bench_engines_close(bench_engine *e, int n)
{
    int k;
    for (k = 0; k < n; ++k) {
        if (!e[k].backend) continue;
        tool_backend_close(e[k].backend);
        free(e[k].backend);
        e[k].backend = NULL;
    }
}

/* What an engine's rows sample through: OpenImageIO's backend; for
 * libsample, the texture system's (--cache-mb) or libsample's own (the
 * fast or, with --scalar, the reference path). */
static tool_backend *backend_of(const bench_engine *e, const bench_texture *t,
                                const sample_texture **tex)
{
    *tex = t->ours;
    if (e->oiio) return e->backend;
    if (t->cached && !e->env) {
        *tex = t->cached;
        return t->cached_backend;
    }
    return e->reference ? &lib_ref : &lib_fast;
}

static const char *row_label(const bench_engine *e) { return e->oiio ? "OIIO " : ""; }

int bench_row_prepare(const bench_engine *e, const bench_texture *t, bench_row *out)
{
    const sample_texture *tex;
    char err[512];
    int rc = -1;
    out->x = NULL;
    if (!(out->b = backend_of(e, t, &tex)) || !out->b->ops)
        snprintf(err, sizeof err, "OpenImageIO is not measured in this run");
    else if (e->oiio && t->file)
        rc = tool_backend_oiio_prepare_file(out->b, t->file, &e->smp, &out->x, err, sizeof err);
    else
        rc = (e->env ? tool_backend_prepare_env : tool_backend_prepare)(out->b, tex, &e->smp, &out->x,
                                                                         NULL, err, sizeof err);
    if (rc == 0) return 0;
    fprintf(stderr, "texsample bench: %s%s%s: %s\n", row_label(e), e->env ? "environment " : "", e->name,
            err);
    out->b = NULL;
    return -1;
}

int bench_row_run(const bench_engine *e, const bench_row *r, const void *q, size_t n, float *rgba,
                  sample_stats *stats)
{
    tool_backend_batch a;
    char err[512];
    tool_backend_batch_init(&a, n, e->env ? NULL : q, e->env ? q : NULL, rgba, stats);
    if (tool_backend_run(r->b, r->x, &a, NULL, err, sizeof err) == 0) return 0;
    fprintf(stderr, "texsample bench: %s%s%s: %s\n", row_label(e), e->env ? "environment " : "", e->name,
            err);
    return -1;
}

void bench_row_release(bench_row *r)
{
    if (r->b) tool_backend_release(r->b, r->x);
    r->b = NULL;
    r->x = NULL;
}

int bench_engine_run(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
                     float *rgba, sample_stats *stats)
{
    bench_row r;
    int rc;
    if (bench_row_prepare(e, t, &r) != 0) return -1;
    rc = bench_row_run(e, &r, q, n, rgba, stats);
    bench_row_release(&r);
    return rc;
}
