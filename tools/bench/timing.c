/*
 * Timed passes over a query set on 1 … N threads. Each thread takes a
 * contiguous slice of the queries (so the coherent set stays coherent per
 * thread, as a renderer's tiles would) and calls the engine in batches.
 * The clock spans thread creation to the last join: what a caller waiting
 * for the whole set would see.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"

#include <pthread.h>
#include <stdlib.h>
#include <time.h>

typedef struct job {
    const bench_engine *e;
    const bench_texture *t;
    oiio_ts *ts;
    const sample_query *q;
    float *rgba;
    size_t lo, hi, batch;
    int failed;
    int running; /* has a thread of its own this pass */
} job;

static void run_slice(job *j)
{
    size_t i;
    for (i = j->lo; i < j->hi && !j->failed; i += j->batch) {
        size_t m = j->hi - i < j->batch ? j->hi - i : j->batch;
        if (bench_engine_run(j->e, j->t, j->ts, j->q + i, m, j->rgba + 4 * i, NULL) != 0)
            j->failed = 1;
    }
}

static void *worker(void *arg)
{
    run_slice(arg);
    return NULL;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One pass; returns seconds, or −1 on failure. */
static double pass(job *jobs, pthread_t *tid, int threads)
{
    double t0 = now(), t1;
    int k, failed = 0;
    for (k = 1; k < threads; ++k) {
        jobs[k].running = pthread_create(&tid[k], NULL, worker, &jobs[k]) == 0;
        /* No thread: run the slice here rather than lose it; the timing
         * shows it by being slower, and the pass still covers every query. */
        if (!jobs[k].running) run_slice(&jobs[k]);
    }
    run_slice(&jobs[0]);
    for (k = 1; k < threads; ++k)
        if (jobs[k].running) pthread_join(tid[k], NULL);
    t1 = now();
    for (k = 0; k < threads; ++k) failed |= jobs[k].failed;
    return failed ? -1.0 : t1 - t0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int bench_time(const bench_engine *e, const bench_texture *t, oiio_ts *ts,
               const sample_query *q, size_t n, int threads, int runs, size_t batch,
               bench_timing *out)
{
    float *rgba = malloc(n * 4 * sizeof *rgba);
    job *jobs = calloc((size_t)threads, sizeof *jobs);
    pthread_t *tid = calloc((size_t)threads, sizeof *tid);
    double *sps = calloc((size_t)runs, sizeof *sps);
    int r, k, rc = -1;

    if (!rgba || !jobs || !tid || !sps || runs < 1 || threads < 1) goto done;
    for (k = 0; k < threads; ++k) {
        job *j = &jobs[k];
        j->e = e;
        j->t = t;
        j->ts = ts;
        j->q = q;
        j->rgba = rgba;
        j->batch = batch;
        j->lo = n * (size_t)k / (size_t)threads;
        j->hi = n * (size_t)(k + 1) / (size_t)threads;
    }
    /* Run 0 is the warm-up: it faults in the result pages and, for OIIO,
     * reads every tile into the cache. */
    for (r = -1; r < runs; ++r) {
        double s = pass(jobs, tid, threads);
        if (s < 0.0) goto done;
        if (r >= 0) sps[r] = (double)n / (s > 0.0 ? s : 1e-9);
    }
    qsort(sps, (size_t)runs, sizeof *sps, cmp_double);
    out->runs = runs;
    out->min = sps[0];
    out->max = sps[runs - 1];
    out->median = runs % 2 ? sps[runs / 2] : 0.5 * (sps[runs / 2 - 1] + sps[runs / 2]);
    rc = 0;
done:
    free(rgba);
    free(jobs);
    free(tid);
    free(sps);
    return rc;
}
