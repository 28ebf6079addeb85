/*
 * For a program that links some of the bench's sources (queries.c,
 * engines.c, timing.c) but not OpenImageIO or textures.c: the definitions
 * they refer to, with every OIIO call failing ("not built with OIIO").
 * Included by exactly one translation unit of such a program (the probes
 * dev/perf_probe.c, tests/oracles/lean_footprint.c, tests/bench_timer.c).
 */
#ifndef BENCH_NO_OIIO_H
#define BENCH_NO_OIIO_H

#include "bench.h"

#include <stdio.h>
#include <string.h>

const char *const bench_format_names[BENCH_FMT_COUNT] = {"float", "half", "srgb8"};

void oiio_ts_opts_init(oiio_ts_opts *o) { memset(o, 0, sizeof *o); }

int oiio_ts_sample(oiio_ts *ts, oiio_ts_tex *t, const oiio_ts_opts *o, const sample_query *q, size_t n, float *rgba,
                   char *err, size_t errlen)
{
    (void)ts, (void)t, (void)o, (void)q, (void)n, (void)rgba;
    snprintf(err, errlen, "not built with OpenImageIO");
    return -1;
}

int oiio_ts_environment(oiio_ts *ts, oiio_ts_tex *t, const oiio_ts_opts *o, const sample_query3 *q, size_t n,
                        float *rgba, char *err, size_t errlen)
{
    (void)ts, (void)t, (void)o, (void)q, (void)n, (void)rgba;
    snprintf(err, errlen, "not built with OpenImageIO");
    return -1;
}

#endif /* BENCH_NO_OIIO_H */
