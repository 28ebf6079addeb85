/*
 * What the developer's probes (dev/perf_probe.c, tests/oracles/lean_footprint.c) share: the
 * bench sources they link without OIIO (bench_no_oiio.h; the probes time
 * libsample only), the clock, the texture and the timed loop of
 * sample_batch calls. Header-only: each probe is one translation unit
 * (dev/perf_probe.sh builds it; CMake builds both, tests/probes.cmake and
 * tests/oracles.cmake).
 */
#ifndef PROBE_UTIL_H
#define PROBE_UTIL_H

#include "bench_no_oiio.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The most queries and the largest texture side a probe takes: the
 * buffers' byte counts (n × 16, side² × 16) then cannot overflow. */
#define PROBE_MAX_QUERIES ((size_t)1 << 26)
#define PROBE_MAX_SIZE 16384

static double probe_cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint32_t probe_mix(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

/* The probes' texture content: size² RGBA of uniform noise in [0, 1]
 * (every mip level different from its neighbours). NULL if out of memory. */
static float *probe_noise(int size)
{
    size_t nt = (size_t)size * (size_t)size * 4, i;
    float *c = malloc(nt * sizeof *c);
    if (c)
        for (i = 0; i < nt; ++i) c[i] = (float)(probe_mix((uint32_t)i) & 0xffff) / 65535.0f;
    return c;
}

/* img as the bench makes its textures (a box pyramid, REPEAT); NULL after
 * printing the error. */
static sample_texture *probe_texture(const sample_image *img)
{
    sample_mip_params mip;
    sample_texture *tex;
    sample_error err;
    sample_mip_params_init(&mip);
    mip.wrap_s = mip.wrap_t = SAMPLE_WRAP_REPEAT;
    if (sample_texture_create(img, &mip, &tex, &err) == SAMPLE_OK) return tex;
    fprintf(stderr, "%s\n", err.message);
    return NULL;
}

/* Queries per sample_batch call in probe_time_batches: the bench's 256,
 * or what a probe sets (perf_probe's PB_BATCH: 16 is the texture
 * system's chunk, TS_CHUNK in libsample/io/src/texsys_internal.h). */
static size_t probe_batch = 256;

/* A batch entry point: sample_batch, or sample_batch_reference. */
typedef sample_status (*probe_batch_fn)(const sample_texture *, const sample_sampler *, const sample_batch_args *);

/* The best CPU time of `runs` passes (after one untimed warm-up) of
 * `batch` over the n queries in batches of probe_batch (256, as the bench
 * calls sample_batch); −1 if a call fails. */
static double probe_time_batches(probe_batch_fn batch, const sample_texture *tex, const sample_sampler *smp,
                                 const sample_query *q, size_t n, int runs, float *out)
{
    double best = 1e30;
    int r;
    for (r = 0; r <= runs; ++r) {
        double t0 = probe_cpu_now(), t;
        size_t b;
        for (b = 0; b < n; b += probe_batch) {
            sample_batch_args a;
            memset(&a, 0, sizeof a);
            a.count = n - b < probe_batch ? n - b : probe_batch;
            a.queries = q + b;
            a.rgba = out + 4 * b;
            if (batch(tex, smp, &a) != SAMPLE_OK) return -1.0;
        }
        t = probe_cpu_now() - t0;
        if (r > 0 && t < best) best = t;
    }
    return best;
}

#endif /* PROBE_UTIL_H */
