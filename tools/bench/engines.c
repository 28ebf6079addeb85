/*
 * The filters the benchmark measures, and how each maps to OpenImageIO's
 * TextureSystem where it has a twin. All wrap with REPEAT ("periodic").
 * bicubic uses the cubic B-spline because that is OIIO's bicubic kernel;
 * Catmull–Rom reads the same 4 × 4 texels at the same cost.
 */
#include "bench.h"
#include "sample/testing.h"

#include <stdio.h>
#include <string.h>

typedef struct engine_def {
    const char *name;
    sample_filter min, mag;
    sample_footprint footprint;
    int oiio_mode; /* the OIIO twin's mode, or −1 */
} engine_def;

static const engine_def defs[] = {
    {"nearest", SAMPLE_NEAREST, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE, OIIO_TS_CLOSEST},
    {"bilinear", SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, OIIO_TS_BILINEAR},
    {"bicubic", SAMPLE_CUBIC, SAMPLE_CUBIC, SAMPLE_FOOTPRINT_NONE, OIIO_TS_BICUBIC},
    {"trilinear", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE,
     OIIO_TS_TRILINEAR},
    {"aniso16", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_ANISOTROPIC,
     OIIO_TS_ANISO},
    {"blinn-newell", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL,
     -1},
    {"ewa", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_EWA, -1},
};
enum { NDEFS = sizeof defs / sizeof defs[0] };

int bench_engines(bench_engine *out, int max)
{
    int k, n = 0, twin[NDEFS];
    if (max < 2 * NDEFS) return -1;
    memset(out, 0, (size_t)max * sizeof *out);
    for (k = 0; k < NDEFS; ++k) {
        bench_engine *e = &out[n++];
        e->name = defs[k].name;
        sample_sampler_init(&e->smp);
        e->smp.min_filter = defs[k].min;
        e->smp.mag_filter = defs[k].mag;
        e->smp.footprint = defs[k].footprint;
        e->smp.cubic = SAMPLE_CUBIC_BSPLINE;
        e->smp.max_anisotropy = 16.0f;
        e->match = -1;
    }
    for (k = 0; k < NDEFS; ++k) {
        bench_engine *e;
        twin[k] = -1;
        if (defs[k].oiio_mode < 0) continue;
        twin[k] = n;
        e = &out[n++];
        e->name = defs[k].name;
        e->oiio = 1;
        e->match = -1;
        oiio_ts_opts_init(&e->opts);
        e->opts.mode = (oiio_ts_mode)defs[k].oiio_mode;
        e->opts.max_aniso = 16;
    }
    for (k = 0; k < NDEFS; ++k) out[k].match = twin[k];
    return n;
}

int bench_engine_run(const bench_engine *e, const bench_texture *t, oiio_ts *ts,
                     const sample_query *q, size_t n, float *rgba, sample_stats *stats)
{
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
        if ((st = (e->reference ? sample_batch_reference : sample_batch)(t->ours, &e->smp, &a)) != SAMPLE_OK) {
            fprintf(stderr, "texsample bench: %s: %s\n", e->name, sample_strerror(st));
            return -1;
        }
    }
    return 0;
}
