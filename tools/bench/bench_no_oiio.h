/*
 * For a program that links some of the bench's sources (queries.c,
 * engines.c, timing.c) but not OpenImageIO, tools/backends/oiio.c or
 * textures.c: the definitions they refer to, with every OIIO call failing
 * ("not built with OIIO").
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

int tool_backend_oiio_open(tool_backend *b, tool_oiio_store *store, const oiio_ts_opts *opts, char *err,
                           size_t errlen)
{
    (void)store, (void)opts;
    memset(b, 0, sizeof *b);
    snprintf(err, errlen, "not built with OpenImageIO");
    return TOOL_BACKEND_ERROR;
}

int tool_backend_oiio_prepare_file(tool_backend *b, const char *path, const sample_sampler *smp,
                                   tool_backend_tex **out, char *err, size_t errlen)
{
    (void)b, (void)path, (void)smp, (void)out;
    snprintf(err, errlen, "not built with OpenImageIO");
    return TOOL_BACKEND_ERROR;
}

#endif /* BENCH_NO_OIIO_H */
