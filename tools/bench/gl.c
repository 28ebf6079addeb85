/*
 * bench's OpenGL rows (bench.h): each libsample filter's sampler state on
 * an OpenGL driver through tools/backend.h. A GPU's sampling is fast and
 * its transfers are not, so the three are timed apart: the texture upload
 * once, and per pass the queries' upload, the draw and the read-back,
 * each to a glFinish (tools/backends/gl.c). The sampling speed is samples
 * per second of the draw alone, as bench's other rows count the filter
 * alone.
 */
#include "bench.h"
#include "../backend.h"

#include <stdlib.h>
#include <string.h>

int bench_gl_measure(struct tool_backend *gl, const bench_engine *e, int engine,
                     const bench_texture *t, bench_set set, bench_format fmt,
                     const sample_query *q, size_t n, int runs, bench_gl_result *out)
{
    tool_backend_times tt = {0, 0, 0};
    tool_backend_tex *x = NULL;
    float *rgba = malloc(n * 4 * sizeof *rgba);
    double *v = malloc(3 * (size_t)runs * sizeof *v);
    bench_timing up, rb;
    int r, rc;
    memset(out, 0, sizeof *out);
    out->set = set;
    out->format = fmt;
    out->engine = engine;
    if (!rgba || !v) {
        free(rgba);
        free(v);
        snprintf(out->note, sizeof out->note, "out of memory");
        return -1;
    }
    rc = tool_backend_prepare(gl, t->ours, &e->smp, &x, &tt, out->note, sizeof out->note);
    out->texture_upload_s = tt.upload;
    /* The warm-up pass: the driver compiles its sampling code on first use. */
    if (rc == 0) rc = tool_backend_sample(gl, x, q, n, rgba, NULL, NULL, out->note, sizeof out->note);
    for (r = 0; r < runs && rc == 0; ++r) {
        memset(&tt, 0, sizeof tt);
        rc = tool_backend_sample(gl, x, q, n, rgba, NULL, &tt, out->note, sizeof out->note);
        v[r] = tt.sample > 0.0 ? (double)n / tt.sample : 0.0;
        v[runs + r] = tt.upload;
        v[2 * runs + r] = tt.readback;
    }
    tool_backend_release(gl, x);
    if (rc == 0) {
        bench_timing_of(v, runs, &out->sampling);
        bench_timing_of(v + runs, runs, &up);
        bench_timing_of(v + 2 * runs, runs, &rb);
        out->query_upload_s = up.median;
        out->readback_s = rb.median;
    }
    free(rgba);
    free(v);
    if (rc == TOOL_BACKEND_NA) out->na = 1;
    return rc == 0 || rc == TOOL_BACKEND_NA ? 0 : -1;
}
