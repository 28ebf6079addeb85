/*
 * What the environment-map tests share (test_cube.c, test_latlong.c):
 * random texels, the test cube and lat-long map, direction queries and the
 * filters of the continuity paths.
 */
#ifndef SAMPLE_TEST_ENV_TEST_H
#define SAMPLE_TEST_ENV_TEST_H

#include "check.h"
#include "internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

static inline uint32_t rnd_u32_of(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

static inline float rnd(uint32_t *s) { return (float)(rnd_u32_of(s) >> 8) * (1.0f / 16777216.0f); }

/* Texel value of face f, texel (i, j), channel c of an n-sized test cube:
 * distinct exact floats. */
static inline float tval(int f, int i, int j, int c, int n) { return (float)(((f * n + j) * n + i) * 4 + c) / 4096.0f; }

/* A float RGBA cube of n × n faces holding tval, levels by mip (NULL: base only). */
static inline sample_texture *make_cube(int n, const sample_mip_params *mip)
{
    sample_image faces[6];
    float *d = (float *)malloc((size_t)6 * n * n * 4 * sizeof(float));
    sample_texture *tex = NULL;
    sample_error err;
    int f, i, j, c;
    for (f = 0; f < 6; ++f) {
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i)
                for (c = 0; c < 4; ++c) d[(((size_t)f * n + j) * n + i) * 4 + c] = tval(f, i, j, c, n);
        faces[f] = (sample_image){n, n, 4, SAMPLE_FORMAT_F32, d + (size_t)f * n * n * 4, 0};
    }
    if (sample_texture_create_cube(faces, mip, &tex, &err) != SAMPLE_OK) fprintf(stderr, "%s\n", err.message);
    free(d);
    return tex;
}

static inline sample_query3 q_dir(const float r[3])
{
    sample_query3 q;
    memset(&q, 0, sizeof q);
    memcpy(q.p, r, sizeof q.p);
    return q;
}

/* The filters the continuity test runs (mag and min filter, footprint)
 * and the bound on one step through a corner (doc/environment-maps.md,
 * "How the tests check it"): LINEAR's 2 × 2 block meets the edge bound
 * there too (§8.13.1's corner texel); trilinear and anisotropic step where
 * λ changes with the face (measured 0.044, 0.047); bicubic's 4 × 4 reads
 * §8.13.1's corner texels (0.057); Blinn–Newell and EWA read each face
 * with its own footprint and step no more than LINEAR (0.024). */
static const struct {
    const char *name;
    sample_filter mag, min;
    sample_footprint fp;
    double corner_bound;
} cont_filters[] = {
    {"linear", SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 0.05},
    {"trilinear", SAMPLE_LINEAR, SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_NONE, 0.05},
    {"cubic", SAMPLE_CUBIC, SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_NONE, 0.08},
    {"aniso", SAMPLE_LINEAR, SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_ANISOTROPIC, 0.06},
    {"blinn-newell", SAMPLE_LINEAR, SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL, 0.035},
    {"ewa", SAMPLE_LINEAR, SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_FOOTPRINT_EWA, 0.035},
};
#define CONT_FILTERS ((int)(sizeof cont_filters / sizeof cont_filters[0]))

/* The sampler of cont_filters[fi]. */
static inline void cont_sampler(int fi, sample_sampler *s)
{
    sample_sampler_init(s);
    s->mag_filter = cont_filters[fi].mag;
    s->min_filter = cont_filters[fi].min;
    s->footprint = cont_filters[fi].fp;
    s->max_anisotropy = 8.0f;
}


/* The direction of lat-long position (s, t) (latlong.h inverted):
 * φ = 2π(s − ½), θ = π(½ − t); −x = sin φ cos θ, z = cos φ cos θ,
 * y = sin θ. */
static inline void latlong_dir(double s, double t, double r[3])
{
    const double pi = 3.14159265358979323846;
    double phi = 2.0 * pi * (s - 0.5), theta = pi * (0.5 - t);
    r[0] = -sin(phi) * cos(theta);
    r[1] = sin(theta);
    r[2] = cos(phi) * cos(theta);
}

#define LW 8
#define LH 4
static float ll_data[LH][LW][4];

static inline sample_texture *make_latlong(void)
{
    sample_image im = {LW, LH, 4, SAMPLE_FORMAT_F32, ll_data, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    uint32_t seed = 11;
    int i, j, c;
    for (j = 0; j < LH; ++j)
        for (i = 0; i < LW; ++i)
            for (c = 0; c < 4; ++c) ll_data[j][i][c] = rnd(&seed);
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "lat-long texture");
    return tex;
}


/* The largest change a continuity path's step (0.015 texel) may make, on
 * random texels in [0, 1]: the gradient of a bilinear interpolant of such
 * texels is at most 1 per texel, bicubic's about 1.5. */
#define CONT_BOUND 0.05

#endif /* SAMPLE_TEST_ENV_TEST_H */
