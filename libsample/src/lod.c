/*
 * Level of detail and level selection (DESIGN §5; OpenGL 4.6 core
 * §8.14.1 "Scale Factor and Level of Detail", §8.14.2, §8.14.3 "Mipmapping").
 * lod_log2_rho, lod_lambda_base, lod_lambda and lod_select, called for
 * every query of the fast path, are static inline in internal.h.
 */
#include "lod.h"

void ls_lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac)
{
    double p = (double)c->base + (lambda > 0.0f ? (double)lambda : 0.0);
    if (p >= (double)c->maxlev) {
        *l0 = *l1 = c->maxlev;
        *frac = 0.0f;
        return;
    }
    *l0 = (int)floor(p);
    *l1 = *l0 + 1;
    *frac = (float)(p - floor(p));
}
