/*
 * texsample bench --volume: 3D texture lookups (doc/volumes.md,
 * "Benchmarks"). The volume is the wood of compare's solid scene baked at
 * --size³ texels (float RGBA, box pyramid); two query sets:
 *
 *   random  (s, t, r) uniform in the volume, the Jacobian's columns two
 *           random orthogonal directions of 2.5 and 2.5–10 texels (a
 *           surface patch cutting the volume at any angle, 1:1 to 4:1);
 *   teapot  the carved teapot's frame: every pixel of a --frame² picture
 *           of that scene on the teapot, its surface point and exact
 *           dP/dx, dP/dy (render_scene_solid_query), in scanline order.
 *
 * Each filter of the registry named below is timed on one thread over
 * sample_batch_3d calls of 256 queries: the median of --runs passes after
 * an untimed one, and the texels read per sample. OpenImageIO's
 * texture3d() reads volume files and filters their base level only (no
 * mip levels, no footprint), so no row of it does what these rows do; the
 * table says so rather than time a different filter.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "bench.h"
#include "cli.h"
#include "commands.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define VOL_BATCH 256
#define VOL_MAX_RUNS 101

static const char *const vol_filters[] = {"nearest", "trilinear", "aniso16", "blinn-newell", "ewa",
                                          NULL};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static uint64_t splitmix(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static double unit01(uint64_t *x) { return (double)(splitmix(x) >> 11) * (1.0 / 9007199254740992.0); }

/* A random unit vector (uniform on the sphere). */
static void random_dir(uint64_t *x, double d[3])
{
    double z = 2.0 * unit01(x) - 1.0, a = 2.0 * 3.14159265358979323846 * unit01(x);
    double r = sqrt(1.0 - z * z);
    d[0] = r * cos(a);
    d[1] = r * sin(a);
    d[2] = z;
}

static void random_queries(int size, sample_query3 *q, size_t n)
{
    uint64_t x = 0x5eed3d0000000001ull;
    size_t i;
    int k;
    for (i = 0; i < n; ++i) {
        double u[3], v[3], w[3], len, a = 2.5 / size, b = a * (1.0 + 3.0 * unit01(&x));
        random_dir(&x, u);
        random_dir(&x, w);
        /* v: w without its u component, normalized (redrawn if parallel). */
        len = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
        for (k = 0; k < 3; ++k) v[k] = w[k] - len * u[k];
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(len > 1e-3)) {
            --i;
            continue;
        }
        for (k = 0; k < 3; ++k) {
            q[i].p[k] = (float)unit01(&x);
            q[i].dpdx[k] = (float)(a * u[k]);
            q[i].dpdy[k] = (float)(b * v[k] / len);
        }
    }
}

/* The wood teapot of compare's solid scene, the wood baked at size³. */
static int teapot_scene(int size, int frame, render_scene **sc, char *err, size_t errlen)
{
    char json[1024];
    snprintf(json, sizeof json,
             "{\"camera\":{\"eye\":[6.5,-8.5,5.2],\"look\":[0.2,0,1.4],\"up\":[0,0,1],\"fov\":33},"
             "\"textures\":[{\"name\":\"wood\",\"type\":\"wood\",\"freq\":2,\"amount\":3,"
             "\"solid\":{\"min\":[-3.1,-2.1,-0.1],\"max\":[3.5,2.1,3.2],\"size\":%d,\"samples\":1}}],"
             "\"materials\":[{\"name\":\"wood\",\"texture\":\"wood\"}],"
             "\"objects\":[{\"type\":\"teapot\",\"material\":\"wood\"}]}",
             size);
    return render_scene_parse(json, strlen(json), frame, frame, sc, err, errlen);
}

/* The teapot frame's queries (scanline order); returns how many. */
static size_t teapot_queries(const render_scene *sc, int frame, sample_query3 *q)
{
    size_t n = 0;
    int i, j;
    for (j = 0; j < frame; ++j)
        for (i = 0; i < frame; ++i) {
            render_hit h;
            if (render_scene_hit(sc, i + 0.5, j + 0.5, &h) &&
                render_scene_solid_query(sc, render_scene_material_texture(sc, h.material), &h, &q[n]))
                ++n;
        }
    return n;
}

typedef struct vol_row {
    double rate[2], texels[2]; /* per set: median samples/s, texels per sample */
} vol_row;

/* One filter over one set: texels per sample, then `runs` timed passes. */
static int time_set(const render_scene *sc, const sample_sampler *smp, const sample_query3 *q,
                    size_t n, int runs, double *rate, double *texels)
{
    float *rgba = malloc(sizeof *rgba * 4 * VOL_BATCH);
    sample_stats *st = malloc(sizeof *st * VOL_BATCH);
    double t[VOL_MAX_RUNS], sum = 0.0;
    size_t i, k;
    int r, pass, ok = rgba && st;
    for (pass = -1; ok && pass < runs; ++pass) {
        double t0 = now_s();
        for (i = 0; ok && i < n; i += VOL_BATCH) {
            size_t m = n - i < VOL_BATCH ? n - i : VOL_BATCH;
            ok = render_scene_solid_sample(sc, 0, smp, q + i, m, rgba, pass < 0 ? st : NULL);
            if (pass < 0)
                for (k = 0; k < m; ++k) sum += st[k].texels;
        }
        if (pass >= 0) t[pass] = now_s() - t0;
    }
    free(rgba);
    free(st);
    if (!ok) return -1;
    /* Median by insertion sort (runs ≤ VOL_MAX_RUNS). */
    for (r = 1; r < runs; ++r)
        for (pass = r; pass > 0 && t[pass - 1] > t[pass]; --pass) {
            double s = t[pass];
            t[pass] = t[pass - 1];
            t[pass - 1] = s;
        }
    *rate = (double)n / (runs % 2 ? t[runs / 2] : 0.5 * (t[runs / 2 - 1] + t[runs / 2]));
    *texels = sum / (double)n;
    return 0;
}

int bench_volume(int size, size_t queries, int runs, int frame)
{
    render_scene *sc = NULL;
    sample_query3 *q[2] = {NULL, NULL};
    size_t n[2] = {queries, 0};
    char err[512];
    int f, s, rc = EXIT_RUNTIME;
    if (runs > VOL_MAX_RUNS) runs = VOL_MAX_RUNS;
    if (teapot_scene(size, frame, &sc, err, sizeof err) != 0) {
        cli_runtime_error("bench", "%s", err);
        return EXIT_RUNTIME;
    }
    q[0] = malloc(sizeof *q[0] * queries);
    q[1] = malloc(sizeof *q[1] * (size_t)frame * (size_t)frame);
    if (!q[0] || !q[1]) {
        cli_runtime_error("bench", "out of memory for the queries");
        goto done;
    }
    random_queries(size, q[0], n[0]);
    n[1] = teapot_queries(sc, frame, q[1]);
    printf("3D texture %d x %d x %d float RGBA (box pyramid), 1 thread, median of %d runs\n"
           "random: %zu queries, 2.5 x 2.5-10 texels at random angles; teapot: the carved\n"
           "teapot's %d x %d frame, %zu queries\n\n",
           size, size, size, runs, n[0], frame, frame, n[1]);
    printf("%-16s %14s %10s %14s %10s\n", "filter", "random Msmp/s", "texels", "teapot Msmp/s",
           "texels");
    for (f = 0; vol_filters[f]; ++f) {
        const tool_filter *tf = tool_filter_by_name(vol_filters[f]);
        sample_sampler smp;
        vol_row row;
        if (!tf) continue;
        sample_sampler_init(&smp);
        tool_filter_apply(tf, &smp);
        for (s = 0; s < 2; ++s)
            if (n[s] == 0) {
                row.rate[s] = row.texels[s] = 0.0;
            } else if (time_set(sc, &smp, q[s], n[s], runs, &row.rate[s], &row.texels[s]) != 0) {
                cli_runtime_error("bench", "%s: sample_batch_3d failed", vol_filters[f]);
                goto done;
            }
        printf("%-16s %14.2f %10.1f %14.2f %10.1f\n", vol_filters[f], row.rate[0] * 1e-6,
               row.texels[0], row.rate[1] * 1e-6, row.texels[1]);
    }
    printf("%-16s %s\n", "oiio texture3d",
           "not run: OpenImageIO's texture3d() filters a volume file's base level only\n"
           "                 (closest or linear: no mip levels, no footprint), so it has\n"
           "                 no twin of these rows; nor does this build write volume files");
    rc = EXIT_OK;
done:
    free(q[0]);
    free(q[1]);
    render_scene_destroy(sc);
    return rc;
}
