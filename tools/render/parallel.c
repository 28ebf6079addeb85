/*
 * A tiny row-parallel loop over pthreads, shared by the renderer and
 * texsample compare (render.h). Rows are handed out one at a time from a
 * shared counter (load balance on scenes where some rows are sky and some
 * teapot, or the plane's horizon rows that cost far more than the rest);
 * since each row's result depends only on the row, the output is identical
 * at any thread count.
 */
#include "rn_internal.h"

#include <pthread.h>
#include <stdlib.h>

typedef struct rows_job {
    pthread_mutex_t lock;
    int next, done, rows;
    void (*fn)(void *ctx, int row);
    void *ctx;
    render_progress_fn progress;
    const char *what;
} rows_job;

static void *rows_worker(void *arg)
{
    rows_job *j = arg;
    for (;;) {
        int row;
        pthread_mutex_lock(&j->lock);
        row = j->next < j->rows ? j->next++ : -1;
        pthread_mutex_unlock(&j->lock);
        if (row < 0) break;
        j->fn(j->ctx, row);
        pthread_mutex_lock(&j->lock);
        ++j->done;
        if (j->progress && (j->done % 8 == 0 || j->done == j->rows))
            j->progress(j->what, (size_t)j->done, (size_t)j->rows);
        pthread_mutex_unlock(&j->lock);
    }
    return NULL;
}

int render_parallel_rows(int rows, int threads, void (*fn)(void *ctx, int row), void *ctx,
                         render_progress_fn progress, const char *what)
{
    rows_job j;
    pthread_t *tid = NULL;
    int k, started = 0, ok = 1;
    j.next = 0;
    j.done = 0;
    j.rows = rows;
    j.fn = fn;
    j.ctx = ctx;
    j.progress = progress;
    j.what = what ? what : "rows";
    if (pthread_mutex_init(&j.lock, NULL) != 0) {
        for (k = 0; k < rows; ++k) fn(ctx, k);
        return 0;
    }
    if (threads > 1) tid = malloc(sizeof *tid * (size_t)(threads - 1));
    if (tid)
        for (k = 0; k < threads - 1; ++k) {
            if (pthread_create(&tid[k], NULL, rows_worker, &j) != 0) {
                ok = 0;
                break;
            }
            ++started;
        }
    rows_worker(&j); /* the calling thread works too; fewer threads only cost time */
    for (k = 0; k < started; ++k) pthread_join(tid[k], NULL);
    free(tid);
    pthread_mutex_destroy(&j.lock);
    return ok;
}
