/*
 * bench --env: environment lookups (doc/benchmarks.md, "Environment
 * maps"). libsample's lat-long map (sample_batch_latlong) and cube map
 * (sample_batch_cube) beside OpenImageIO's environment() on the same
 * lat-long map, for each filter of the registry that has an environment
 * meaning, on two query sets:
 *
 *   env-random      random directions, isotropic footprints of 2.5
 *                   equator texels of the lat-long map, random orientation:
 *                   every engine pays its cache misses alike;
 *   env-reflection  a mirror sphere's reflection frame (⌈√n⌉² pixels,
 *                   orthographic view along −z, the disc's pixels in
 *                   scanline order): R = 2(N·V)N − V with its exact screen
 *                   derivatives, from magnification at the centre to the
 *                   whole environment in a pixel at the rim.
 *
 * The lat-long map is size × size/2 texels of bench's synthetic content;
 * the cube map has faces of size/4 (the lat-long map's texel density at
 * the equator), each the synthetic content at that size. Timing, threads
 * and batches are bench's own (timing.c).
 */
#include "bench.h"
#include "cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { ENV_SETS = 2, ENV_MAX_ENGINES = 48 };
static const char *const env_set_names[ENV_SETS] = {"env-random", "env-reflection"};

/* splitmix64, as queries.c. */
static uint64_t next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double unit(uint64_t *state) { return (double)(next(state) >> 11) * (1.0 / 9007199254740992.0); }

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l, v[1] /= l, v[2] /= l;
}

/* Uniform directions (z uniform in [−1, 1], azimuth uniform), footprint
 * `angle` radians along two perpendicular tangents at a random rotation. */
static void random_set(double angle, sample_query3 *q, size_t n)
{
    uint64_t st = 5;
    size_t i;
    int a;
    for (i = 0; i < n; ++i) {
        double z = 2.0 * unit(&st) - 1.0, ph = 6.283185307179586 * unit(&st), r = sqrt(1.0 - z * z);
        double R[3] = {r * cos(ph), r * sin(ph), z}, up[3] = {0, 0, 1}, u[3], v[3], rot = 6.283185307179586 * unit(&st);
        if (fabs(z) > 0.9) up[0] = 1, up[2] = 0;
        cross(R, up, u);
        normalize(u);
        cross(R, u, v);
        for (a = 0; a < 3; ++a) {
            q[i].p[a] = (float)R[a];
            q[i].dpdx[a] = (float)(angle * (cos(rot) * u[a] + sin(rot) * v[a]));
            q[i].dpdy[a] = (float)(angle * (-sin(rot) * u[a] + cos(rot) * v[a]));
        }
    }
}

/* The mirror sphere: pixel (i, j) of a res × res view of the unit disc
 * sees N = (x, y, √(1 − x² − y²)), V = (0, 0, 1); R = 2 N_z N − V, and
 * dR/dx = 2(∂N_z N + N_z ∂N) with ∂N/∂x = (1, 0, −x/N_z)·(2/res). Pixels
 * within 2 % of the rim are left out (N_z → 0: the derivative is
 * unbounded). Repeats the frame if it holds fewer than n. */
static void reflection_set(sample_query3 *q, size_t n)
{
    int res = (int)ceil(sqrt((double)n)), i, j, a;
    double px = 2.0 / res;
    size_t k = 0, first;
    while (k < n) {
        first = k;
        for (j = 0; j < res && k < n; ++j)
            for (i = 0; i < res && k < n; ++i) {
                double x = -1.0 + (i + 0.5) * px, y = 1.0 - (j + 0.5) * px, rr = x * x + y * y, nz;
                double N[3], dN[2][3], R[3], dR[2][3];
                if (rr > 0.96) continue;
                nz = sqrt(1.0 - rr);
                N[0] = x, N[1] = y, N[2] = nz;
                dN[0][0] = px, dN[0][1] = 0.0, dN[0][2] = -x / nz * px;
                dN[1][0] = 0.0, dN[1][1] = -px, dN[1][2] = y / nz * px;
                for (a = 0; a < 3; ++a) R[a] = 2.0 * nz * N[a] - (a == 2);
                for (int d = 0; d < 2; ++d)
                    for (a = 0; a < 3; ++a) dR[d][a] = 2.0 * (dN[d][2] * N[a] + nz * dN[d][a]);
                for (a = 0; a < 3; ++a) {
                    q[k].p[a] = (float)R[a];
                    q[k].dpdx[a] = (float)dR[0][a];
                    q[k].dpdy[a] = (float)dR[1][a];
                }
                ++k;
            }
        if (k == first) break; /* cannot happen for res ≥ 1; no endless loop */
    }
}

/* The two maps from bench's content: lat-long size × size/2 (the top half
 * of the size² content), cube faces of size/4 (content at that size). */
static int make_maps(int size, sample_texture **ll, sample_texture **cube)
{
    float *c = bench_content(size), *f = bench_content(size / 4 > 0 ? size / 4 : 1);
    sample_image img = {size, size / 2, 4, SAMPLE_FORMAT_F32, c, 0}, faces[6];
    sample_mip_params mip;
    sample_error e;
    int k, rc = -1, n = size / 4 > 0 ? size / 4 : 1;
    *ll = *cube = NULL;
    sample_mip_params_init(&mip);
    mip.wrap_s = SAMPLE_WRAP_REPEAT;
    for (k = 0; k < 6; ++k) {
        faces[k].width = faces[k].height = n;
        faces[k].channels = 4;
        faces[k].format = SAMPLE_FORMAT_F32;
        faces[k].data = f;
        faces[k].row_stride = 0;
    }
    if (!c || !f) fprintf(stderr, "texsample bench: out of memory\n");
    else if (sample_texture_create(&img, &mip, ll, &e) != SAMPLE_OK ||
             sample_texture_create_cube(faces, &mip, cube, &e) != SAMPLE_OK)
        fprintf(stderr, "texsample bench: environment map: %s\n", e.message);
    else
        rc = 0;
    free(c);
    free(f);
    return rc;
}

/* The engines: each filter on the lat-long map, on the cube map, and its
 * OIIO twin (lat-long) when OIIO runs. */
static int env_engines(const char *filters, int oiio, bench_engine *out, int max)
{
    tool_pick picks[16];
    const tool_filter *f[16];
    bench_engine base[32];
    char err[256];
    int n = tool_picks_parse("bench", filters ? filters : "all", bench_default_filters, 0, picks, 16, err,
                             sizeof err), k, m, e = 0;
    if (n < 0) return cli_usage_error("bench", "--filters: %s", err), -1;
    for (k = m = 0; k < n; ++k)
        if (!picks[k].oiio) f[m++] = picks[k].f;
    if ((n = bench_engines_of(f, m, base, 32)) < 0) return cli_usage_error("bench", "--filters: too many"), -1;
    for (k = 0; k < m && e + 3 <= max; ++k) {
        out[e] = base[k];
        out[e++].env = BENCH_ENV_LATLONG;
        out[e] = base[k];
        out[e++].env = BENCH_ENV_CUBE;
        if (oiio && base[k].match >= 0) {
            out[e] = base[base[k].match];
            out[e++].env = BENCH_ENV_LATLONG;
        }
    }
    return e;
}

int bench_env(const bench_env_opts *o)
{
    bench_engine eng[ENV_MAX_ENGINES];
    sample_texture *ll = NULL, *cube = NULL;
    sample_query3 *q = malloc(o->queries * sizeof *q);
    tool_oiio_store *store = NULL;
    bench_texture tl = {.ours = NULL}, tc = {.ours = NULL};
    bench_row held = {NULL, NULL};
    char err[512];
    int neng = env_engines(o->filters, o->oiio, eng, ENV_MAX_ENGINES), set, e, rc = EXIT_OK;
    if (neng < 0) {
        free(q);
        return EXIT_USAGE;
    }
    if (!q || make_maps(o->size, &ll, &cube) != 0) {
        free(q);
        sample_texture_destroy(ll);
        sample_texture_destroy(cube);
        return cli_runtime_error("bench", "cannot build the environment maps");
    }
    tl.ours = ll;
    tc.ours = cube;
    /* OpenImageIO's rows read its lat-long map, which its backend writes
     * from ll (sample_io_write_env: the same texels and pyramid). */
    if (o->oiio && (!(store = tool_oiio_store_open_in(0.0, o->tmpdir, err, sizeof err)) ||
                    bench_engines_open_oiio(eng, neng, store) != 0)) {
        if (!store) fprintf(stderr, "texsample bench: %s\n", err);
        rc = cli_runtime_error("bench", "OpenImageIO's environment map could not be made (--no-oiio leaves it out)");
    }
    /* One OpenImageIO row held for the whole run, so that each timed
     * measurement's prepare finds the map's file by the texture it holds
     * (tools/backends/oiio.c) instead of reading the map's texels again. */
    for (e = 0; e < neng && rc == EXIT_OK && store; ++e)
        if (eng[e].oiio) {
            if (bench_row_prepare(&eng[e], &tl, &held) != 0)
                rc = cli_runtime_error("bench", "OpenImageIO's environment map could not be made (--no-oiio "
                                                "leaves it out)");
            break;
        }
    printf("environment maps: lat-long %d x %d, cube %d x %d faces; %zu queries a set, median of %d runs, samples/s\n",
           o->size, o->size / 2, o->size / 4 > 0 ? o->size / 4 : 1, o->size / 4 > 0 ? o->size / 4 : 1, o->queries,
           o->runs);
    printf("  %-16s %-26s %-8s %12s %12s\n", "set", "filter", "map", "1 thread", "threads");
    for (set = 0; set < ENV_SETS && rc == EXIT_OK; ++set) {
        if (set == 0) random_set(2.5 * 6.283185307179586 / o->size, q, o->queries);
        else reflection_set(q, o->queries);
        for (e = 0; e < neng && rc == EXIT_OK; ++e) {
            const bench_texture *t = eng[e].env == BENCH_ENV_CUBE ? &tc : &tl;
            bench_timing one, all;
            char label[64];
            if (bench_time(&eng[e], t, q, o->queries, 1, o->runs, o->batch, &one) != 0 ||
                bench_time(&eng[e], t, q, o->queries, o->threads, o->runs, o->batch, &all) != 0) {
                rc = cli_runtime_error("bench", "%s on %s failed", eng[e].name, env_set_names[set]);
                break;
            }
            snprintf(label, sizeof label, "%s%s", eng[e].oiio ? "oiio-" : "", eng[e].name);
            printf("  %-16s %-26s %-8s %12.0f %12.0f\n", env_set_names[set], label,
                   eng[e].env == BENCH_ENV_CUBE ? "cube" : "latlong", one.median, all.median);
        }
    }
    bench_row_release(&held);
    bench_engines_close(eng, neng);
    tool_oiio_store_close(store);
    sample_texture_destroy(ll);
    sample_texture_destroy(cube);
    free(q);
    return rc;
}
