/*
 * perf_probe: the developer's timing probe (the step tables of
 * doc/history/performance-passes*.md were measured with it). One filter,
 * one of bench's query sets, one format: the best 1-thread CPU time of
 * several passes over the queries (warm-up excluded), in batches of 256, and a hash of the
 * results, so that a change can be timed and shown to keep the bits.
 * Built and run by dev/perf_probe.sh; not part of the product build.
 *
 *   perf_probe FILTER SET FORMAT [QUERIES [RUNS]]
 *   (FILTER, SET, FORMAT as `texsample bench` names them; env PB_SCALAR=1:
 *   the reference path, PB_SIZE: texture side, default 2048; PB_TILE=b:
 *   the texture held in tiles of 2^b texels a side, as a tile cache holds
 *   it (sample_texture_tiled_copy; b = 6: OpenImageIO's 64²); PB_BATCH:
 *   queries per sample_batch call, default 256 — 16 is the texture
 *   system's chunk)
 */
#define _GNU_SOURCE
#include "probe_util.h"
#include "sample/testing.h"

static int find(const char *const *names, int n, const char *want)
{
    int k;
    for (k = 0; k < n; ++k)
        if (!strcmp(names[k], want)) return k;
    return -1;
}

int main(int argc, char **argv)
{
    const char *filt = argc > 1 ? argv[1] : "trilinear", *set = argc > 2 ? argv[2] : "minify",
               *fmt = argc > 3 ? argv[3] : "float";
    size_t n = argc > 4 ? strtoul(argv[4], NULL, 10) : 65536, i, nt;
    int runs = argc > 5 ? atoi(argv[5]) : 5, size = getenv("PB_SIZE") ? atoi(getenv("PB_SIZE")) : 2048;
    bench_engine eng[32];
    int ne = bench_engines(eng, 32), ei = -1, si, fi, k;
    float *content, *out;
    void *data = NULL;
    sample_image img;
    sample_texture *tex;
    sample_query *q;
    sample_sampler smp;
    double best;
    uint32_t h = 0;

    for (k = 0; k < ne; ++k)
        if (!eng[k].oiio && !strcmp(eng[k].name, filt)) ei = k;
    si = find(bench_set_names, BENCH_SET_COUNT, set);
    fi = find(bench_format_names, BENCH_FMT_COUNT, fmt);
    if (ei < 0 || si < 0 || fi < 0 || n == 0 || n > PROBE_MAX_QUERIES || runs < 1 || size < 1 ||
        size > PROBE_MAX_SIZE) {
        fprintf(stderr, "usage: perf_probe FILTER SET FORMAT [QUERIES [RUNS]]\n");
        return 2;
    }
    nt = (size_t)size * (size_t)size * 4;
    content = probe_noise(size);
    q = malloc(n * sizeof *q);
    out = malloc(n * 4 * sizeof *out);
    if (!content || !q || !out) return 1;
    img = (sample_image){size, size, 4, SAMPLE_FORMAT_F32, content, 0};
    if (fi == BENCH_FMT_F16) {
        uint16_t *p = malloc(nt * sizeof *p);
        if (!p) return 1;
        for (i = 0; i < nt; ++i) p[i] = sample_float_to_half(content[i]);
        img.data = data = p;
        img.format = SAMPLE_FORMAT_F16;
    } else if (fi == BENCH_FMT_SRGB8) {
        uint8_t *p = malloc(nt);
        if (!p) return 1;
        for (i = 0; i < nt; ++i) p[i] = (uint8_t)(content[i] * 255.0f);
        img.data = data = p;
        img.format = SAMPLE_FORMAT_SRGB8;
    }
    if (!(tex = probe_texture(&img))) return 1;
    if (getenv("PB_TILE")) {
        sample_texture *tiled;
        sample_error err;
        if (sample_texture_tiled_copy(tex, atoi(getenv("PB_TILE")), &tiled, &err) != SAMPLE_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        sample_texture_destroy(tex);
        tex = tiled;
    }
    if (getenv("PB_BATCH")) probe_batch = strtoul(getenv("PB_BATCH"), NULL, 10);
    if (probe_batch < 1) probe_batch = 1;
    bench_queries((bench_set)si, size, q, n);
    smp = eng[ei].smp;
    best = probe_time_batches(getenv("PB_SCALAR") ? sample_batch_reference : sample_batch, tex, &smp, q, n, runs,
                              out);
    if (best < 0.0) return 1;
    for (i = 0; i < n * 4; ++i) {
        uint32_t u;
        memcpy(&u, &out[i], sizeof u);
        h = probe_mix(h ^ u);
    }
    printf("%-12s %-8s %-6s %7.2f M/s  hash %08x\n", filt, set, fmt, (double)n / best / 1e6, h);
    sample_texture_destroy(tex);
    free(data);
    free(content);
    free(q);
    free(out);
    return 0;
}
