/*
 * The filter configurations compare renders (issue 7): the OpenGL ladder
 * from no filtering to trilinear, GPU anisotropy, bicubic, the footprint
 * filters of DESIGN §7, and OpenImageIO's TextureSystem as the industry
 * reference. The nearest family keeps NEAREST magnification so that each
 * row shows one filter throughout.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

const cmp_config cmp_configs[] = {
    {"nearest", "nearest, no mips", SAMPLE_NEAREST, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE, 1, 0, 0, 0},
    {"bilinear", "bilinear, no mips", SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 1, 0, 0, 0},
    {"nmn", "nearest-mipmap-nearest", SAMPLE_NEAREST_MIPMAP_NEAREST, SAMPLE_NEAREST,
     SAMPLE_FOOTPRINT_NONE, 1, 0, 0, 0},
    {"trilinear", "trilinear", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 1,
     0, 0, 0},
    {"aniso16", "anisotropic x16", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
     SAMPLE_FOOTPRINT_ANISOTROPIC, 16, 0, 0, 0},
    {"bicubic", "bicubic (cubic_mipmap_linear)", SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_CUBIC,
     SAMPLE_FOOTPRINT_NONE, 1, 0, 0, 0},
    {"bn-jacobian", "Blinn-Newell, Jacobian", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
     SAMPLE_FOOTPRINT_BLINN_NEWELL, 1, 0, 0, 0},
    {"bn-corners", "Blinn-Newell, exact corners", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
     SAMPLE_FOOTPRINT_BLINN_NEWELL, 1, 1, 0, 0},
    /* Corner mode weighted by the screen-space area element, i.e. the
     * integral DESIGN §8 scores against (doc/footprint-filters.md). */
    {"bn-corners-area", "Blinn-Newell, exact corners, area-weighted", SAMPLE_LINEAR_MIPMAP_LINEAR,
     SAMPLE_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL, 1, 1, 0, SAMPLE_OPT_BN_AREA_WEIGHT},
    {"ewa", "EWA", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_EWA, 1, 0, 0, 0},
    /* OpenImageIO at its best: smartcubic interpolation, its EWA-like
     * anisotropic filter, same derivatives (oiio.c). */
    {"oiio", "OpenImageIO TextureSystem", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR,
     SAMPLE_FOOTPRINT_NONE, 16, 0, 1, 0},
};
const int cmp_config_count = (int)(sizeof cmp_configs / sizeof cmp_configs[0]);

int cmp_configs_parse(const char *list, int *idx, int max, char *bad, size_t badlen)
{
    unsigned char want[sizeof cmp_configs / sizeof cmp_configs[0]] = {0};
    const char *p = list;
    int k, n = 0;
    while (*p) {
        size_t len = strcspn(p, ",");
        int found = 0;
        if (len == 3 && strncmp(p, "all", 3) == 0) {
            memset(want, 1, sizeof want);
            found = 1;
        }
        for (k = 0; k < cmp_config_count && !found; ++k)
            if (strlen(cmp_configs[k].name) == len && strncmp(p, cmp_configs[k].name, len) == 0) {
                want[k] = 1;
                found = 1;
            }
        if (!found) {
            snprintf(bad, badlen, "%.*s", (int)(len < 64 ? len : 64), p);
            return -1;
        }
        p += len;
        if (*p == ',') ++p;
    }
    for (k = 0; k < cmp_config_count; ++k)
        if (want[k] && n < max) idx[n++] = k;
    return n;
}

void cmp_config_sampler(const cmp_config *c, const sample_sampler *scene, sample_sampler *out)
{
    *out = *scene;
    out->min_filter = c->min;
    out->mag_filter = c->mag;
    out->footprint = c->footprint;
    out->max_anisotropy = c->max_aniso;
    out->options |= c->options;
}
