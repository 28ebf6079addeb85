/*
 * Timed passes over a query set on 1 … N threads. The threads take tiles
 * of up to BENCH_TILE_BATCHES consecutive batches from a shared counter, first
 * come first served, as a renderer's workers take tiles of a frame: the
 * coherent set stays coherent within a tile (16 scanlines of the default
 * `plane`), and a thread that drew the cheap part of the frame takes more
 * of it. (Fixed contiguous halves, the first version, left one thread idle
 * on `plane`, whose half near the horizon costs many times the other:
 * doc/benchmarks.md.) Each tile is handed to the engine in batches.
 * The threads are a pool made once per measurement, as a renderer keeps
 * its workers: a pass releases them together (a barrier) and ends when the
 * last slice is done (a second barrier), and the clock spans exactly that.
 * Creating and joining threads inside every pass (the first version) put
 * 0.1–0.3 ms of thread start-up into passes of 1–2 ms for the fastest
 * filters, which measured the harness rather than the engine's scaling
 * (doc/benchmarks.md). Waking a sleeping worker through a condition
 * variable, the second version, still cost tens of microseconds at each
 * end of a pass (2 threads / 1 thread 1.7 instead of 2.0 for nearest at
 * 65,536 queries), so the pool waits as OpenMP's and TBB's do: a worker
 * polls for the next pass, and the caller for the end of this one, for
 * up to BENCH_SPIN_NS before sleeping on the condition variable.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>

/* Batches per tile: at most 16 (4,096 queries at the default 256), and
 * few enough that every thread gets at least 8 tiles of a pass (a short
 * --quick run too), at least one. */
#define BENCH_TILE_BATCHES 16
#define BENCH_TILES_PER_THREAD 8
/* How long a waiting thread polls before it sleeps: longer than a pass of
 * the fastest filters, short against a measurement. */
#define BENCH_SPIN_NS 2000000L

typedef struct pool pool;

typedef struct job {
    const bench_engine *e;
    const bench_row *row; /* the engine's row on the texture, prepared once */
    const void *q;      /* n queries of qsize bytes */
    size_t qsize;
    float *rgba;
    size_t n, batch, tile;
    int failed;
    unsigned seen; /* the last timed run this worker took part in */
    pool *p;
} job;

/* Pass number `gen` releases workers 1 … threads − 1; each decrements
 * `busy` when its tiles are done; `quit` sends them home. `gen` and `quit`
 * change only under `mu`, and the worker that brings `busy` to 0 signals
 * under `mu`, so a thread that polled in vain and then sleeps (it tests
 * again under `mu` first) cannot miss its wake-up. */
struct pool {
    pthread_mutex_t mu;
    pthread_cond_t go, done;
    atomic_uint gen;
    atomic_int busy, quit;
    atomic_size_t next; /* the pass's next tile's first query */
};

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void cpu_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/* Polls `ready` for up to BENCH_SPIN_NS; nonzero if it became true. The
 * clock is read every 256 polls, not on every one. */
static int spin_until(int (*ready)(const void *), const void *arg)
{
    double limit = now() + 1e-9 * (double)BENCH_SPIN_NS;
    unsigned k;
    for (k = 1;; ++k) {
        if (ready(arg)) return 1;
        if (k % 256 == 0 && now() > limit) return 0;
        cpu_relax();
    }
}

/* A worker's next pass has begun (or the pool is closing). */
static int next_pass(const void *jv)
{
    const job *j = jv;
    return atomic_load_explicit(&j->p->gen, memory_order_acquire) != j->seen ||
           atomic_load_explicit(&j->p->quit, memory_order_relaxed);
}

/* Every worker has finished the pass. */
static int pass_done(const void *pv)
{
    return atomic_load_explicit(&((pool *)pv)->busy, memory_order_acquire) == 0;
}

/* Tiles until the pass's queries are all taken. */
static void run_tiles(job *j)
{
    const size_t tile = j->tile;
    size_t lo;
    while (!j->failed && (lo = atomic_fetch_add_explicit(&j->p->next, tile, memory_order_relaxed)) < j->n) {
        size_t i, hi = j->n - lo < tile ? j->n : lo + tile;
        for (i = lo; i < hi && !j->failed; i += j->batch) {
            size_t m = hi - i < j->batch ? hi - i : j->batch;
            if (bench_row_run(j->e, j->row, (const char *)j->q + i * j->qsize, m, j->rgba + 4 * i, NULL) != 0)
                j->failed = 1;
        }
    }
}

static void *worker(void *arg)
{
    job *j = arg;
    pool *p = j->p;
    for (;;) {
        if (!spin_until(next_pass, j)) {
            pthread_mutex_lock(&p->mu);
            while (!next_pass(j)) pthread_cond_wait(&p->go, &p->mu);
            pthread_mutex_unlock(&p->mu);
        }
        if (atomic_load_explicit(&p->quit, memory_order_relaxed)) break;
        j->seen = atomic_load_explicit(&p->gen, memory_order_acquire);
        run_tiles(j);
        /* Release: the caller that sees busy == 0 sees this thread's
         * results and `failed`. */
        if (atomic_fetch_sub_explicit(&p->busy, 1, memory_order_acq_rel) == 1) {
            pthread_mutex_lock(&p->mu);
            pthread_cond_signal(&p->done);
            pthread_mutex_unlock(&p->mu);
        }
    }
    return NULL;
}

/* One pass (the calling thread works too); returns seconds, or −1 on
 * failure. */
static double pass(job *jobs, pool *p, int threads)
{
    double t0 = now(), t1;
    int k, failed = 0;
    atomic_store_explicit(&p->next, 0, memory_order_relaxed);
    atomic_store_explicit(&p->busy, threads - 1, memory_order_relaxed);
    pthread_mutex_lock(&p->mu);
    /* Release: a worker that sees the new `gen` sees `next` and `busy`. */
    atomic_fetch_add_explicit(&p->gen, 1, memory_order_release);
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->mu);
    run_tiles(&jobs[0]);
    if (!spin_until(pass_done, p)) {
        pthread_mutex_lock(&p->mu);
        while (!pass_done(p)) pthread_cond_wait(&p->done, &p->mu);
        pthread_mutex_unlock(&p->mu);
    }
    t1 = now();
    for (k = 0; k < threads; ++k) failed |= jobs[k].failed;
    return failed ? -1.0 : t1 - t0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

void bench_timing_of(double *v, int n, bench_timing *out)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    out->runs = n;
    out->min = v[0];
    out->max = v[n - 1];
    out->median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct bench_timer {
    bench_row row;
    job *jobs;
    pthread_t *tid;
    float *rgba;
    double *sps; /* samples per second of each timed pass */
    int threads, runs, done, started;
    size_t n;
    pool p;
};

static void timer_stop(bench_timer *tm)
{
    int k;
    pthread_mutex_lock(&tm->p.mu);
    atomic_store_explicit(&tm->p.quit, 1, memory_order_relaxed);
    pthread_cond_broadcast(&tm->p.go);
    pthread_mutex_unlock(&tm->p.mu);
    for (k = 1; k < tm->started; ++k) pthread_join(tm->tid[k], NULL);
    pthread_mutex_destroy(&tm->p.mu);
    pthread_cond_destroy(&tm->p.go);
    pthread_cond_destroy(&tm->p.done);
    bench_row_release(&tm->row);
    free(tm->rgba);
    free(tm->jobs);
    free(tm->tid);
    free(tm->sps);
    free(tm);
}

bench_timer *bench_timer_open(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
                              int threads, int runs, size_t batch)
{
    bench_timer *tm;
    size_t batches, tile;
    int k;

    if (runs < 1 || threads < 1 || batch < 1 || !(tm = calloc(1, sizeof *tm))) return NULL;
    tm->threads = threads;
    tm->runs = runs;
    tm->n = n;
    tm->started = 1;
    atomic_init(&tm->p.gen, 0u);
    atomic_init(&tm->p.busy, 0);
    atomic_init(&tm->p.quit, 0);
    atomic_init(&tm->p.next, 0u);
    pthread_mutex_init(&tm->p.mu, NULL);
    pthread_cond_init(&tm->p.go, NULL);
    pthread_cond_init(&tm->p.done, NULL);
    tm->rgba = malloc(n * 4 * sizeof *tm->rgba);
    tm->jobs = calloc((size_t)threads, sizeof *tm->jobs);
    tm->tid = calloc((size_t)threads, sizeof *tm->tid);
    tm->sps = calloc((size_t)runs, sizeof *tm->sps);
    if (!tm->rgba || !tm->jobs || !tm->tid || !tm->sps || bench_row_prepare(e, t, &tm->row) != 0) goto fail;
    batches = n / ((size_t)threads * BENCH_TILES_PER_THREAD * batch);
    tile = batch * (batches < 1 ? 1 : batches > BENCH_TILE_BATCHES ? BENCH_TILE_BATCHES : batches);
    for (k = 0; k < threads; ++k) {
        job *j = &tm->jobs[k];
        j->e = e;
        j->row = &tm->row;
        j->q = q;
        j->qsize = e->env ? sizeof(sample_query3) : sizeof(sample_query);
        j->rgba = tm->rgba;
        j->batch = batch;
        j->n = n;
        j->tile = tile;
        j->p = &tm->p;
    }
    /* A pool that cannot be made whole is not the measurement asked for:
     * fail rather than time fewer threads. */
    for (; tm->started < threads; ++tm->started)
        if (pthread_create(&tm->tid[tm->started], NULL, worker, &tm->jobs[tm->started]) != 0) goto fail;
    /* The warm-up pass: it faults in the result pages and, for OIIO, reads
     * every tile into the cache. */
    if (pass(tm->jobs, &tm->p, threads) < 0.0) goto fail;
    return tm;
fail:
    timer_stop(tm);
    return NULL;
}

int bench_timer_pass(bench_timer *tm)
{
    double s;
    if (tm->done >= tm->runs || (s = pass(tm->jobs, &tm->p, tm->threads)) < 0.0) return -1;
    tm->sps[tm->done++] = (double)tm->n / (s > 0.0 ? s : 1e-9);
    return 0;
}

int bench_timer_close(bench_timer *tm, bench_timing *out)
{
    int rc = -1;
    if (!tm) return -1;
    if (tm->done == tm->runs) {
        bench_timing_of(tm->sps, tm->runs, out);
        rc = 0;
    }
    timer_stop(tm);
    return rc;
}

int bench_time(const bench_engine *e, const bench_texture *t, const void *q, size_t n,
               int threads, int runs, size_t batch, bench_timing *out)
{
    bench_timer *tm = bench_timer_open(e, t, q, n, threads, runs, batch);
    int r;
    if (!tm) return -1;
    for (r = 0; r < runs; ++r)
        if (bench_timer_pass(tm) != 0) break;
    return bench_timer_close(tm, out);
}
