/* Blinn–Newell pyramid-weighted quadrilateral (DESIGN §7). Placeholder. */
#include "internal.h"

uint32_t fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st)
{
    (void)corners;
    return sample_gl(c, q, call_bias, out, dds, ddt, st);
}
