/* The zone plate seen through a filter: a picture of where each filter
 * aliases, beside the measured curves. */
#include "freq.h"

#include <stdio.h>
#include <stdlib.h>

sample_status fq_zone_texture(sample_texture **out, float **texels, sample_error *err)
{
    sample_status st;
    *out = NULL;
    *texels = fq_zone_plate_texels(FQ_ZONE_N);
    if (!*texels) {
        if (err) {
            err->status = SAMPLE_E_OUT_OF_MEMORY;
            snprintf(err->message, sizeof err->message, "zone plate: out of memory");
        }
        return SAMPLE_E_OUT_OF_MEMORY;
    }
    st = fq_texture_create(*texels, FQ_ZONE_N, 1, out, err);
    if (st != SAMPLE_OK) {
        free(*texels);
        *texels = NULL;
    }
    return st;
}

float *fq_zone_render(const fq_backend *b, void *ctx, char *err, size_t errlen)
{
    size_t n = (size_t)FQ_ZONE_PIXELS * FQ_ZONE_PIXELS, k;
    sample_query *q = (sample_query *)malloc(n * sizeof *q);
    float *rgba = (float *)malloc(n * 4 * sizeof *rgba);
    double texels = 0.0;
    int x, y;
    if (!q || !rgba) {
        free(q);
        free(rgba);
        snprintf(err, errlen, "zone plate: out of memory");
        return NULL;
    }
    for (y = 0, k = 0; y < FQ_ZONE_PIXELS; ++y)
        for (x = 0; x < FQ_ZONE_PIXELS; ++x, ++k) {
            /* Pixel centres, an isotropic footprint of m texels. */
            q[k].s = (float)((x + 0.5) * FQ_ZONE_M / FQ_ZONE_N);
            q[k].t = (float)((y + 0.5) * FQ_ZONE_M / FQ_ZONE_N);
            q[k].dsdx = q[k].dtdy = (float)(FQ_ZONE_M / FQ_ZONE_N);
            q[k].dtdx = q[k].dsdy = 0.0f;
        }
    if (b->sample(ctx, q, n, rgba, &texels, err, errlen) != 0) {
        free(q);
        free(rgba);
        return NULL;
    }
    free(q);
    for (k = 0; k < n; ++k) {
        float v = 0.5f + 0.5f * rgba[4 * k];
        rgba[4 * k] = rgba[4 * k + 1] = rgba[4 * k + 2] = v;
        rgba[4 * k + 3] = 1.0f;
    }
    return rgba;
}
