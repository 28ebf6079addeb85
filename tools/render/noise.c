/*
 * Gradient noise (Perlin 1985, "An Image Synthesizer"; the improved
 * interpolant and gradient set of Perlin 2002) and turbulence. The
 * permutation is drawn from a seed with a fixed LCG, so textures are the
 * same on every machine. With a period p the lattice wraps every p cells,
 * which makes a texture built from it tile seamlessly at s, t ∈ [0, 1].
 */
#include "rn_internal.h"

void noise_init(rn_noise *n, uint32_t seed, int period)
{
    uint32_t x = seed * 2654435761u + 12345u;
    int k;
    for (k = 0; k < 256; ++k) n->perm[k] = (unsigned char)k;
    for (k = 255; k > 0; --k) { /* Fisher–Yates */
        int j;
        unsigned char t;
        x = x * 1664525u + 1013904223u;
        j = (int)((x >> 8) % (uint32_t)(k + 1));
        t = n->perm[k];
        n->perm[k] = n->perm[j];
        n->perm[j] = t;
    }
    for (k = 0; k < 256; ++k) n->perm[256 + k] = n->perm[k];
    n->period = period > 0 && period <= 256 ? period : 0;
}

static double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
static double lerp(double t, double a, double b) { return a + t * (b - a); }

/* Dot product with one of Perlin's 12 edge gradients (16 with repeats). */
static double grad(int h, double x, double y, double z)
{
    double u, v;
    h &= 15;
    u = h < 8 ? x : y;
    v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

/* Lattice index reduced to [0, 256), or to [0, period) when periodic. */
static int cell(const rn_noise *n, double f, int add)
{
    int m = n->period ? n->period : 256;
    double r = fmod(f, (double)m);
    int i;
    if (r < 0) r += m;
    i = ((int)r + add) % m;
    return i;
}

double noise3(const rn_noise *n, double x, double y, double z)
{
    const unsigned char *p = n->perm;
    double fx, fy, fz, u, v, w;
    int X0, Y0, Z0, X1, Y1, Z1, A, B, AA, AB, BA, BB, A1, B1, AA1, AB1, BA1, BB1;
    if (!(fabs(x) < 1e9 && fabs(y) < 1e9 && fabs(z) < 1e9)) return 0.0;
    fx = floor(x); fy = floor(y); fz = floor(z);
    X0 = cell(n, fx, 0); Y0 = cell(n, fy, 0); Z0 = cell(n, fz, 0);
    X1 = cell(n, fx, 1); Y1 = cell(n, fy, 1); Z1 = cell(n, fz, 1);
    x -= fx; y -= fy; z -= fz;
    u = fade(x); v = fade(y); w = fade(z);
    A = p[X0] + Y0; B = p[X1] + Y0;
    A1 = p[X0] + Y1; B1 = p[X1] + Y1;
    AA = p[A] + Z0; AB = p[A1] + Z0; BA = p[B] + Z0; BB = p[B1] + Z0;
    AA1 = p[A] + Z1; AB1 = p[A1] + Z1; BA1 = p[B] + Z1; BB1 = p[B1] + Z1;
    return lerp(w,
                lerp(v, lerp(u, grad(p[AA], x, y, z), grad(p[BA], x - 1, y, z)),
                     lerp(u, grad(p[AB], x, y - 1, z), grad(p[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(p[AA1], x, y, z - 1), grad(p[BA1], x - 1, y, z - 1)),
                     lerp(u, grad(p[AB1], x, y - 1, z - 1), grad(p[BB1], x - 1, y - 1, z - 1))));
}

double turbulence3(const rn_noise *n, double x, double y, double z, int octaves)
{
    double sum = 0.0, f = 1.0;
    int k;
    for (k = 0; k < octaves; ++k) {
        sum += fabs(noise3(n, x * f, y * f, z * f)) / f;
        f *= 2.0;
    }
    return sum;
}
