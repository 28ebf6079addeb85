/*
 * The filters the benchmark measures: rows of the tools' filter registry
 * (tools/filters.h), each on libsample and, where the entry has one, on its
 * OpenImageIO twin. All wrap with REPEAT ("periodic"). bicubic-bspline is
 * the bicubic measured by default because the B-spline is OIIO's bicubic
 * kernel; Catmull–Rom reads the same 4 × 4 texels at the same cost.
 */
#include "bench.h"
#include "sample/testing.h"

#include <stdio.h>
#include <string.h>

const char *const bench_default_filters[] = {
    "nearest", "bilinear", "bicubic-bspline", "trilinear", "aniso16", "blinn-newell", "ewa", NULL,
};

int bench_engines_of(const tool_filter *const *filters, int count, bench_engine *out, int max)
{
    int k, n = 0;
    if (max < 2 * count) return -1;
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

int bench_engine_run(const bench_engine *e, const bench_texture *t, oiio_ts *ts,
                     const void *q, size_t n, float *rgba, sample_stats *stats)
{
    if (e->env) {
        char err[512];
        sample_batch3_args a;
        sample_status st;
        if (e->oiio) {
            if (oiio_ts_environment(ts, t->theirs, &e->opts, q, n, rgba, err, sizeof err) == 0) return 0;
            fprintf(stderr, "texsample bench: OIIO environment %s: %s\n", e->name, err);
            return -1;
        }
        memset(&a, 0, sizeof a);
        a.count = n;
        a.queries = q;
        a.rgba = rgba;
        a.stats = stats;
        st = sample_batch_env(t->ours, &e->smp, &a);
        if (st == SAMPLE_OK) return 0;
        fprintf(stderr, "texsample bench: %s: %s\n", e->name, sample_strerror(st));
        return -1;
    }
    if (e->oiio) {
        char err[512];
        if (oiio_ts_sample(ts, t->theirs, &e->opts, q, n, rgba, err, sizeof err) != 0) {
            fprintf(stderr, "texsample bench: OIIO %s: %s\n", e->name, err);
            return -1;
        }
    } else {
        sample_batch_args a;
        sample_status st;
        memset(&a, 0, sizeof a);
        a.count = n;
        a.queries = q;
        a.rgba = rgba;
        a.stats = stats;
        if (t->cached)
            st = t->cached(t->sys, t->ours, &e->smp, &a);
        else
            st = (e->reference ? sample_batch_reference : sample_batch)(t->ours, &e->smp, &a);
        if (st != SAMPLE_OK) {
            fprintf(stderr, "texsample bench: %s: %s\n", e->name, sample_strerror(st));
            return -1;
        }
    }
    return 0;
}
