/* Anisotropic filtering (DESIGN §7). Placeholder: trilinear until implemented. */
#include "internal.h"

uint32_t fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    return sample_gl(c, q, call_bias, out, dds, ddt, st);
}
