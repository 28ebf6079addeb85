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
 * texture3d() (tools/oiio/oiio_volume.h) reads the same base level from a
 * volume TIFF and filters it only by InterpClosest or a trilinear blend
 * (no mip levels, no footprint): its two rows are the twins of nearest and
 * bilinear (LINEAR without mips), timed alike, with the largest difference
 * from libsample's values over both sets; the mip and footprint rows have
 * no twin, and the table says so.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, getpid */
#include "bench.h"
#include "cli.h"
#include "commands.h"
#include "oiio_volume.h"
#include "render/render.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define VOL_BATCH 256
#define VOL_MAX_RUNS 101

static const char *const vol_filters[] = {"nearest", "bilinear", "trilinear", "aniso16",
                                          "blinn-newell", "ewa", NULL};

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

/* An engine: n queries into n × 4 floats (stats: NULL, or n entries the
 * engine fills if it counts texels); 1 on success. */
typedef struct vol_engine {
    const render_scene *sc;
    sample_sampler smp; /* libsample */
    oiio_vol *oiio;     /* OpenImageIO when not NULL */
    int linear;
} vol_engine;

static int engine_run(const vol_engine *e, const sample_query3 *q, size_t n, float *rgba,
                      sample_stats *st)
{
    if (e->oiio)
        return oiio_vol_sample(e->oiio, e->linear, SAMPLE_WRAP_CLAMP_TO_EDGE, q, n, rgba, NULL, 0) == 0;
    return render_scene_solid_sample(e->sc, 0, &e->smp, q, n, rgba, st);
}

/* One engine over one set: the untimed pass (texels per sample, the values
 * into out when not NULL), then `runs` timed passes. */
static int time_set(const vol_engine *e, const sample_query3 *q, size_t n, int runs, double *rate,
                    double *texels, float *out)
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
            ok = engine_run(e, q + i, m, rgba, pass < 0 && !e->oiio ? st : NULL);
            if (pass < 0 && !e->oiio)
                for (k = 0; k < m; ++k) sum += st[k].texels;
            if (pass < 0 && out) memcpy(out + 4 * i, rgba, sizeof *rgba * 4 * m);
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
    *texels = e->oiio ? -1.0 : sum / (double)n;
    return 0;
}

/* The volume's base level as OpenImageIO's file `path`, opened; NULL with
 * the reason in why. The caller removes the file once it is closed. */
static oiio_vol *oiio_volume(const sample_texture *tex, const char *path, char *why, size_t len)
{
    sample_texture_info info;
    float *px;
    oiio_vol *v = NULL;
    int i, j, k;
    size_t at = 0;
    sample_texture_info_get(tex, &info);
    px = malloc(sizeof *px * 4 * (size_t)info.width * (size_t)info.height * (size_t)info.depth);
    if (!px) {
        snprintf(why, len, "out of memory");
        return NULL;
    }
    for (k = 0; k < info.depth; ++k)
        for (j = 0; j < info.height; ++j)
            for (i = 0; i < info.width; ++i, at += 4) sample_texture_texel_layer(tex, 0, k, i, j, px + at);
    if (oiio_vol_write(px, info.width, info.height, info.depth, path, why, len) == 0)
        v = oiio_vol_open(path, why, len);
    free(px);
    return v;
}

/* Largest |a − b| over n RGBA results. */
static double max_diff(const float *a, const float *b, size_t n)
{
    double m = 0.0;
    size_t k;
    for (k = 0; k < 4 * n; ++k)
        if (fabs((double)a[k] - (double)b[k]) > m) m = fabs((double)a[k] - (double)b[k]);
    return m;
}

static void print_row(const char *name, const vol_row *r, const char *note)
{
    char tx[2][16];
    int s;
    for (s = 0; s < 2; ++s) {
        if (r->texels[s] < 0) snprintf(tx[s], sizeof tx[s], "-");
        else snprintf(tx[s], sizeof tx[s], "%.1f", r->texels[s]);
    }
    printf("%-16s %14.2f %10s %14.2f %10s  %s\n", name, r->rate[0] * 1e-6, tx[0], r->rate[1] * 1e-6,
           tx[1], note);
}

int bench_volume(int size, size_t queries, int runs, int frame, int oiio, const char *tmpdir)
{
    render_scene *sc = NULL;
    sample_query3 *q[2] = {NULL, NULL};
    float *ours[2][2] = {{NULL, NULL}, {NULL, NULL}}, *theirs[2] = {NULL, NULL};
    size_t n[2] = {queries, 0};
    char err[512], why[512] = "--no-oiio", path[1100] = "";
    vol_engine e;
    oiio_vol *ov = NULL;
    int f, s, twin, rc = EXIT_RUNTIME;
    if (runs > VOL_MAX_RUNS) runs = VOL_MAX_RUNS;
    if (teapot_scene(size, frame, &sc, err, sizeof err) != 0) {
        cli_runtime_error("bench", "%s", err);
        return EXIT_RUNTIME;
    }
    q[0] = malloc(sizeof *q[0] * queries);
    q[1] = malloc(sizeof *q[1] * (size_t)frame * (size_t)frame);
    for (s = 0; s < 2; ++s) {
        size_t m = s ? (size_t)frame * (size_t)frame : queries;
        theirs[s] = malloc(sizeof *theirs[s] * 4 * m);
        ours[0][s] = malloc(sizeof *ours[0][s] * 4 * m);
        ours[1][s] = malloc(sizeof *ours[1][s] * 4 * m);
        if (!theirs[s] || !ours[0][s] || !ours[1][s]) q[s] = NULL;
    }
    if (!q[0] || !q[1]) {
        cli_runtime_error("bench", "out of memory for the queries");
        goto done;
    }
    random_queries(size, q[0], n[0]);
    n[1] = teapot_queries(sc, frame, q[1]);
    snprintf(path, sizeof path, "%s/bench_volume_%ld.tif", tmpdir, (long)getpid());
    if (oiio) ov = oiio_volume(render_scene_texture(sc, 0), path, why, sizeof why);
    printf("3D texture %d x %d x %d float RGBA (box pyramid), 1 thread, median of %d runs\n"
           "random: %zu queries, 2.5 x 2.5-10 texels at random angles; teapot: the carved\n"
           "teapot's %d x %d frame, %zu queries\n\n",
           size, size, size, runs, n[0], frame, frame, n[1]);
    printf("%-16s %14s %10s %14s %10s\n", "filter", "random Msmp/s", "texels", "teapot Msmp/s",
           "texels");
    memset(&e, 0, sizeof e);
    e.sc = sc;
    for (f = 0; vol_filters[f]; ++f) {
        const tool_filter *tf = tool_filter_by_name(vol_filters[f]);
        vol_row row;
        if (!tf) continue;
        twin = f < 2 ? f : -1; /* nearest ~ closest, bilinear ~ linear */
        sample_sampler_init(&e.smp);
        tool_filter_apply(tf, &e.smp);
        for (s = 0; s < 2; ++s)
            if (time_set(&e, q[s], n[s], runs, &row.rate[s], &row.texels[s],
                         twin >= 0 ? ours[twin][s] : NULL) != 0) {
                cli_runtime_error("bench", "%s: sample_batch_3d failed", vol_filters[f]);
                goto done;
            }
        print_row(vol_filters[f], &row, twin >= 0 ? "" : "(no OIIO twin: texture3d has no mip levels)");
    }
    for (twin = 0; twin < 2; ++twin) {
        const char *name = twin ? "oiio linear" : "oiio closest";
        vol_row row;
        char note[96];
        if (!ov) {
            printf("%-16s not run: %s\n", name, why);
            continue;
        }
        e.oiio = ov;
        e.linear = twin;
        for (s = 0; s < 2; ++s)
            if (time_set(&e, q[s], n[s], runs, &row.rate[s], &row.texels[s], theirs[s]) != 0) {
                cli_runtime_error("bench", "%s: OpenImageIO's texture3d failed", name);
                goto done;
            }
        snprintf(note, sizeof note, "(twin of %s: largest difference %.2g)", vol_filters[twin],
                 fmax(max_diff(theirs[0], ours[twin][0], n[0]), max_diff(theirs[1], ours[twin][1], n[1])));
        print_row(name, &row, note);
    }
    rc = EXIT_OK;
done:
    oiio_vol_close(ov);
    if (oiio) remove(path); /* written even when OIIO would not read it */
    free(q[0]);
    free(q[1]);
    for (s = 0; s < 2; ++s) {
        free(theirs[s]);
        free(ours[0][s]);
        free(ours[1][s]);
    }
    render_scene_destroy(sc);
    return rc;
}
