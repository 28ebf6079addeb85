/*
 * The standard query sets. Random sets draw (s, t) uniformly over the
 * texture and rotate the footprint by a random angle, so that every
 * engine pays for cache misses the same way; the plane set is what a
 * renderer really sends — neighbouring pixels, neighbouring texels — and
 * its shuffled copy separates the cost of filtering from that of memory.
 */
#include "bench.h"

#include <math.h>

const char *const bench_set_names[BENCH_SET_COUNT] = {
    [BENCH_SET_MAGNIFY] = "magnify",
    [BENCH_SET_MINIFY] = "minify",
    [BENCH_SET_ANISO] = "aniso8",
    [BENCH_SET_PLANE] = "plane",
    [BENCH_SET_SHUFFLED] = "plane-shuffled",
};

const unsigned bench_set_seeds[] = {
    [BENCH_SET_MAGNIFY] = 1,
    [BENCH_SET_MINIFY] = 2,
    [BENCH_SET_ANISO] = 3,
    [BENCH_SET_PLANE] = 0,
    [BENCH_SET_SHUFFLED] = 4,
};
_Static_assert(sizeof bench_set_seeds / sizeof bench_set_seeds[0] == BENCH_SET_COUNT, "one seed per set");

/* splitmix64 (Steele, Lea, Flood 2014): a fixed sequence on every platform. */
static uint64_t next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1) with 24 bits, exactly representable in float. */
static float unit(uint64_t *state) { return (float)(next(state) >> 40) / 16777216.0f; }

/* An ellipse footprint with semi-axes `major`, `minor` (base texels) at a
 * random angle: the Jacobian columns are the images of the screen x and y
 * unit steps, here the two (scaled, rotated) principal axes. */
static void random_set(float major, float minor, int size, uint64_t seed, sample_query *q,
                       size_t n)
{
    uint64_t st = seed;
    const double two_pi = 6.283185307179586;
    size_t i;
    for (i = 0; i < n; ++i) {
        double a = two_pi * unit(&st), c = cos(a), s = sin(a);
        double M = (double)major / size, m = (double)minor / size;
        q[i].s = unit(&st);
        q[i].t = unit(&st);
        q[i].dsdx = (float)(M * c);
        q[i].dtdx = (float)(M * s);
        q[i].dsdy = (float)(-m * s);
        q[i].dtdy = (float)(m * c);
    }
}

/* Step: a camera at height 1 over the plane y = 0 looks along +z with a
 * 90° horizontal field of view (focal length f = W/2 pixels); the horizon
 * is 8 pixels above the image, so the top rows are strongly minified and
 * anisotropic and the bottom rows about one texel per pixel. Pixel (x, y)
 * (centre x + ½, y + ½) sees the ray (p, −r, 1) with p = (x + ½ − W/2)/f
 * and r = (y + ½ + 8)/f, which meets the plane at z = 1/r, x = p/r. The
 * texture repeats every L = 4 units: s = ½ + p/(rL), t = 1/(rL). Its exact
 * Jacobian (∂r/∂y = ∂p/∂x = 1/f):
 *   ∂s/∂x = 1/(f r L),  ∂s/∂y = −p/(f r² L),  ∂t/∂x = 0,  ∂t/∂y = −1/(f r² L). */
static void plane_set(sample_query *q, size_t n)
{
    int W = (int)ceil(sqrt((double)n));
    double f = W / 2.0, L = 4.0;
    size_t i;
    for (i = 0; i < n; ++i) {
        int x = (int)(i % (size_t)W), y = (int)(i / (size_t)W);
        double p = (x + 0.5 - W / 2.0) / f, r = (y + 0.5 + 8.0) / f;
        q[i].s = (float)(0.5 + p / (r * L));
        q[i].t = (float)(1.0 / (r * L));
        q[i].dsdx = (float)(1.0 / (f * r * L));
        q[i].dtdx = 0.0f;
        q[i].dsdy = (float)(-p / (f * r * r * L));
        q[i].dtdy = (float)(-1.0 / (f * r * r * L));
    }
}

void bench_queries(bench_set set, int size, sample_query *q, size_t n)
{
    size_t i;
    switch (set) {
    case BENCH_SET_MAGNIFY: random_set(0.25f, 0.25f, size, bench_set_seeds[set], q, n); break;
    case BENCH_SET_MINIFY: random_set(2.5f, 2.5f, size, bench_set_seeds[set], q, n); break;
    case BENCH_SET_ANISO: random_set(12.0f, 1.5f, size, bench_set_seeds[set], q, n); break;
    case BENCH_SET_PLANE: plane_set(q, n); break;
    case BENCH_SET_SHUFFLED: {
        /* Fisher–Yates with a fixed seed; the modulo bias of a 64-bit draw
         * over n < 2^32 is immaterial here. */
        uint64_t st = bench_set_seeds[set];
        plane_set(q, n);
        for (i = n; i > 1; --i) {
            size_t j = (size_t)(next(&st) % i);
            sample_query tmp = q[i - 1];
            q[i - 1] = q[j];
            q[j] = tmp;
        }
        break;
    }
    default: break;
    }
}
