/*
 * One configuration over a view, for any engine (a backend of
 * tools/backend.h that serves many threads: backends.c). Each row is split into batches of pixels that share a texture
 * (and, for the corner mode, have valid corners), because sample_batch() is
 * the primary entry point and validates once per call (sample.h §3); the
 * time spent inside the engine's calls is summed per row so ns/sample does
 * not depend on the thread count.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

double cmp_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct run_job {
    const cmp_view *v;
    int corners;
    cmp_batch_fn fn;
    void *ctx;
    int stats;
    float *rgba;
    double *row_seconds; /* per row: time inside sample_batch */
    double *row_texels;  /* per row: texels read */
    size_t *row_queries;
    unsigned char *row_failed; /* per row, so that no two threads write one flag */
} run_job;

void cmp_fill_untextured(const cmp_view *v, float *rgba)
{
    size_t n = (size_t)v->w * (size_t)v->h, px;
    int k;
    for (px = 0; px < n; ++px) {
        if (v->tex[px] >= 0) continue;
        for (k = 0; k < 4; ++k)
            /* A surface without texture shades as white in RENDER_SHADE_TEXTURE. */
            rgba[px * 4 + (size_t)k] = v->tex[px] == -2 ? v->background[k] : 1.0f;
    }
}

/* The distinct texture indices of a row, in first-seen order. */
static int row_textures(const int *tex, int w, int *list)
{
    int i, k, n = 0;
    for (i = 0; i < w; ++i) {
        if (tex[i] < 0) continue;
        for (k = 0; k < n && list[k] != tex[i]; ++k) {}
        if (k == n) list[n++] = tex[i];
    }
    return n;
}

static void run_row(void *ctx, int j)
{
    run_job *jb = ctx;
    const cmp_view *v = jb->v;
    size_t base = (size_t)j * (size_t)v->w;
    const int *tex = v->tex + base;
    int *list = malloc(sizeof *list * (size_t)v->w), *pix = malloc(sizeof *pix * (size_t)v->w);
    size_t *gpx = malloc(sizeof *gpx * (size_t)v->w);
    sample_query *q = malloc(sizeof *q * (size_t)v->w);
    sample_query3 *q3 = v->q3 ? malloc(sizeof *q3 * (size_t)v->w) : NULL;
    sample_quad *quad = malloc(sizeof *quad * (size_t)v->w);
    sample_stats *st = malloc(sizeof *st * (size_t)v->w);
    float *out = malloc(sizeof *out * 4 * (size_t)v->w);
    int nt, t, group, i, k;
    double secs = 0.0, texels = 0.0;
    size_t queries = 0;
    if (!list || !pix || !gpx || !q || !quad || !st || !out || (v->q3 && !q3)) {
        jb->row_failed[j] = 1;
        goto done;
    }
    nt = row_textures(tex, v->w, list);
    for (t = 0; t < nt; ++t)
        /* Two groups of pixels: 0 with the Jacobian only, 1 with exact corners (corner mode only). */
        for (group = 0; group < 2; ++group) {
            int n = 0, three = list[t] == v->env_tex || cmp_view_3d(v, list[t]);
            double t0;
            for (i = 0; i < v->w; ++i) {
                int with = jb->corners && v->quad_ok[base + (size_t)i];
                if (tex[i] != list[t] || with != group) continue;
                if (three) q3[n] = v->q3[base + (size_t)i];
                else q[n] = v->q[base + (size_t)i];
                if (with) quad[n] = v->quad[base + (size_t)i];
                gpx[n] = base + (size_t)i;
                pix[n++] = i;
            }
            if (n == 0) continue;
            t0 = cmp_now();
            if (jb->fn(jb->ctx, list[t], gpx, three ? NULL : q, three ? q3 : NULL, group ? quad : NULL,
                       (size_t)n, out, jb->stats ? st : NULL) != 0) {
                jb->row_failed[j] = 1;
                goto done;
            }
            secs += cmp_now() - t0;
            for (i = 0; i < n; ++i) {
                for (k = 0; k < 4; ++k)
                    jb->rgba[(base + (size_t)pix[i]) * 4 + (size_t)k] = out[(size_t)i * 4 + (size_t)k];
                if (jb->stats) texels += st[i].texels;
            }
            queries += (size_t)n;
        }
done:
    jb->row_seconds[j] = secs;
    jb->row_texels[j] = texels;
    jb->row_queries[j] = queries;
    free(list);
    free(pix);
    free(gpx);
    free(q);
    free(q3);
    free(quad);
    free(st);
    free(out);
}

int cmp_run(const cmp_view *v, int corners, cmp_batch_fn fn, void *ctx, int stats, int threads,
            int runs, cmp_result *r)
{
    run_job jb;
    size_t n = (size_t)v->w * (size_t)v->h;
    double *wall = NULL, *ns = NULL;
    int j, run, failed = 0;
    if (runs < 1) runs = 1;
    memset(r, 0, sizeof *r);
    memset(&jb, 0, sizeof jb);
    jb.v = v;
    jb.corners = corners;
    jb.fn = fn;
    jb.ctx = ctx;
    jb.stats = stats;
    jb.rgba = r->rgba = malloc(n * 4 * sizeof *r->rgba);
    jb.row_seconds = calloc((size_t)v->h, sizeof *jb.row_seconds);
    jb.row_texels = calloc((size_t)v->h, sizeof *jb.row_texels);
    jb.row_queries = calloc((size_t)v->h, sizeof *jb.row_queries);
    jb.row_failed = calloc((size_t)v->h, 1);
    wall = malloc(sizeof *wall * (size_t)runs);
    ns = malloc(sizeof *ns * (size_t)runs);
    if (!r->rgba || !jb.row_seconds || !jb.row_texels || !jb.row_queries || !jb.row_failed ||
        !wall || !ns) {
        failed = 1;
    } else {
        cmp_fill_untextured(v, r->rgba);
        /* Every run writes the same values into the same image (the engines
         * are deterministic); only the clock differs. */
        for (run = 0; run < runs && !failed; ++run) {
            double t0 = cmp_now(), secs = 0.0, texels = 0.0;
            render_parallel_rows(v->h, threads, run_row, &jb, NULL, NULL);
            wall[run] = cmp_now() - t0;
            r->queries = 0;
            for (j = 0; j < v->h; ++j) {
                secs += jb.row_seconds[j];
                texels += jb.row_texels[j];
                r->queries += jb.row_queries[j];
                failed |= jb.row_failed[j];
            }
            ns[run] = r->queries ? 1e9 * secs / (double)r->queries : 0.0;
            r->texels = !stats ? -1.0 : r->queries ? texels / (double)r->queries : 0.0;
        }
        if (!failed) {
            r->runs = runs;
            r->seconds = cmp_median(wall, runs);
            r->ns_per_sample = cmp_median(ns, runs);
        }
    }
    free(jb.row_seconds);
    free(jb.row_texels);
    free(jb.row_queries);
    free(jb.row_failed);
    free(wall);
    free(ns);
    if (failed) cmp_result_free(r);
    return failed;
}

void cmp_result_free(cmp_result *r)
{
    free(r->rgba);
    r->rgba = NULL;
}
