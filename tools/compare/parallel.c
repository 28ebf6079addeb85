/*
 * Rows over pthreads, handed out one at a time from a shared counter: the
 * horizon rows of the plane cost far more than the sky rows, so static
 * slices would leave a thread idle. A row's result depends only on the row,
 * so the output is the same at any thread count.
 */
#define _POSIX_C_SOURCE 200809L
#include "cmp_internal.h"
#include "cli.h"

#include <pthread.h>
#include <stdlib.h>
#include <time.h>

typedef struct rows_job {
    pthread_mutex_t lock;
    int next, done, rows;
    void (*fn)(void *ctx, int row);
    void *ctx;
    const char *label;
} rows_job;

static void *rows_worker(void *arg)
{
    rows_job *j = arg;
    for (;;) {
        int row;
        pthread_mutex_lock(&j->lock);
        row = j->next < j->rows ? j->next++ : -1;
        pthread_mutex_unlock(&j->lock);
        if (row < 0) return NULL;
        j->fn(j->ctx, row);
        pthread_mutex_lock(&j->lock);
        ++j->done;
        if (j->label && (j->done % 16 == 0 || j->done == j->rows))
            cli_progress(j->label, (size_t)j->done, (size_t)j->rows);
        pthread_mutex_unlock(&j->lock);
    }
}

void cmp_parallel_rows(int rows, int threads, void (*fn)(void *ctx, int row), void *ctx,
                       const char *label)
{
    rows_job j;
    pthread_t *tid = NULL;
    int k, started = 0;
    j.next = j.done = 0;
    j.rows = rows;
    j.fn = fn;
    j.ctx = ctx;
    j.label = label;
    if (pthread_mutex_init(&j.lock, NULL) != 0) {
        for (k = 0; k < rows; ++k) fn(ctx, k);
        return;
    }
    if (threads > 1) tid = malloc(sizeof *tid * (size_t)(threads - 1));
    for (k = 0; tid && k < threads - 1; ++k) {
        if (pthread_create(&tid[k], NULL, rows_worker, &j) != 0) break;
        ++started;
    }
    rows_worker(&j); /* the calling thread works too; fewer threads only cost time */
    for (k = 0; k < started; ++k) pthread_join(tid[k], NULL);
    free(tid);
    pthread_mutex_destroy(&j.lock);
}

double cmp_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
