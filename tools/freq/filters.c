/* The engine's filter configurations under test (DESIGN §9, issue 8) and
 * the backend that runs them through sample_batch. */
#include "freq.h"

#include <stdio.h>
#include <stdlib.h>

/* What distinguishes one configuration; everything else is OpenGL's
 * initial sampler state with REPEAT on both axes. */
typedef struct lib_config {
    sample_filter min, mag;
    sample_footprint footprint;
    float max_aniso;
} lib_config;

typedef struct lib_ctx {
    const sample_texture *tex;
    sample_sampler smp;
} lib_ctx;

static void *lib_prepare(const fq_backend *b, const sample_texture *tex, const float *texels,
                         int n, int channels, char *err, size_t errlen)
{
    const lib_config *cfg = (const lib_config *)b->config;
    lib_ctx *c = (lib_ctx *)malloc(sizeof *c);
    (void)texels;
    (void)n;
    (void)channels;
    if (!c) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    c->tex = tex;
    sample_sampler_init(&c->smp);
    c->smp.wrap_s = c->smp.wrap_t = SAMPLE_WRAP_REPEAT;
    c->smp.min_filter = cfg->min;
    c->smp.mag_filter = cfg->mag;
    c->smp.footprint = cfg->footprint;
    c->smp.max_anisotropy = cfg->max_aniso;
    return c;
}

static int lib_sample(void *ctx, const sample_query *q, size_t count, float *rgba,
                      double *texels, char *err, size_t errlen)
{
    lib_ctx *c = (lib_ctx *)ctx;
    sample_batch_args a = {0};
    sample_status st;
    size_t i;
    /* Stats are collected in the timed call: their cost is the same small
     * per-query store for every libsample filter (doc §5). */
    sample_stats *stats = (sample_stats *)malloc(count * sizeof *stats);
    if (!stats) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    a.count = count;
    a.queries = q;
    a.rgba = rgba;
    a.stats = stats;
    st = sample_batch(c->tex, &c->smp, &a);
    if (st != SAMPLE_OK) {
        snprintf(err, errlen, "sample_batch: %s", sample_strerror(st));
        free(stats);
        return -1;
    }
    for (i = 0; i < count; ++i) *texels += stats[i].texels;
    free(stats);
    return 0;
}

static void lib_release(void *ctx) { free(ctx); }

static const lib_config cfg_nearest = {SAMPLE_NEAREST, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE, 1};
static const lib_config cfg_bilinear = {SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 1};
static const lib_config cfg_nmn = {SAMPLE_NEAREST_MIPMAP_NEAREST, SAMPLE_NEAREST,
                                   SAMPLE_FOOTPRINT_NONE, 1};
static const lib_config cfg_trilinear = {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
                                         SAMPLE_FOOTPRINT_NONE, 1};
static const lib_config cfg_cubic = {SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_CUBIC,
                                     SAMPLE_FOOTPRINT_NONE, 1};
/* The footprint filters replace min_filter when λ > 0; trilinear stays the
 * min filter so that the sampler is also valid without them. */
static const lib_config cfg_aniso = {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
                                     SAMPLE_FOOTPRINT_ANISOTROPIC, 16};
static const lib_config cfg_bn = {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
                                  SAMPLE_FOOTPRINT_BLINN_NEWELL, 1};
static const lib_config cfg_ewa = {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
                                   SAMPLE_FOOTPRINT_EWA, 1};

#define LIB(nm, lb, cfg) {nm, lb, lib_prepare, lib_sample, lib_release, &cfg, 1}

const fq_backend fq_libsample_backends[] = {
    LIB("nearest", "nearest (no mips)", cfg_nearest),
    LIB("bilinear", "bilinear (no mips)", cfg_bilinear),
    LIB("nearest_mipmap_nearest", "nearest_mipmap_nearest", cfg_nmn),
    LIB("trilinear", "trilinear", cfg_trilinear),
    LIB("cubic_mipmap_linear", "cubic_mipmap_linear (Catmull-Rom)", cfg_cubic),
    LIB("aniso16", "anisotropic x16", cfg_aniso),
    LIB("blinn_newell", "Blinn-Newell", cfg_bn),
    LIB("ewa", "EWA", cfg_ewa),
};
const int fq_libsample_backend_count =
    (int)(sizeof fq_libsample_backends / sizeof fq_libsample_backends[0]);
