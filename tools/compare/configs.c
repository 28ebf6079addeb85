/*
 * The filter configurations compare renders: rows of the tools' filter
 * registry (tools/filters.h). By default the OpenGL ladder from no
 * filtering to trilinear, GPU anisotropy, cubic, the footprint filters of
 * DESIGN §7 in both Blinn–Newell modes, and OpenImageIO's TextureSystem as
 * the industry reference.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

const char *const cmp_default_configs[] = {
    "nearest", "bilinear", "nearest_mipmap_nearest", "trilinear", "aniso16",
    "cubic_mipmap_linear", "blinn-newell", "blinn-newell-corners", "blinn-newell-corners-area",
    "ewa", "oiio-aniso16", NULL,
};

int cmp_configs_parse(const char *list, unsigned accept, cmp_config *out, int max, char *err,
                      size_t errlen)
{
    tool_pick picks[CMP_MAX_CONFIGS];
    int k, n = tool_picks_parse("compare", list, cmp_default_configs, accept, picks,
                                max < CMP_MAX_CONFIGS ? max : CMP_MAX_CONFIGS, err, errlen);
    for (k = 0; k < n; ++k) {
        out[k].pick = picks[k];
        out[k].tb = NULL;
        tool_pick_name(&picks[k], out[k].name, sizeof out[k].name);
        tool_pick_label(&picks[k], out[k].label, sizeof out[k].label);
    }
    return n;
}

void cmp_config_sampler(const cmp_config *c, const sample_sampler *scene, sample_sampler *out)
{
    *out = *scene;
    if (c->pick.f) tool_filter_apply(c->pick.f, out);
}
