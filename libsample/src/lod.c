/*
 * Level of detail and level selection (DESIGN §5; OpenGL 4.6 core
 * §8.14.1 "Scale Factor and Level of Detail", §8.14.2, §8.14.3 "Mipmapping").
 * lod_lambda and lod_select, called for every query of the fast path, are
 * static inline in internal.h.
 */
#include "internal.h"

float lod_lambda_base(const sample_ctx *c, const sample_query *q)
{
    /* ρ = max{ √((∂u/∂x)² + (∂v/∂x)²), √((∂u/∂y)² + (∂v/∂y)²) } (eq. 8.9),
     * u = s·w_t, v = t·h_t with w_t × h_t the size of level_base. In double:
     * a 1e20 Jacobian squared overflows float, and λ must still be right. */
    const struct sample_level *L = &c->tex->level[c->base];
    double ux = (double)q->dsdx * L->w, vx = (double)q->dtdx * L->h;
    double uy = (double)q->dsdy * L->w, vy = (double)q->dtdy * L->h;
    double px = ux * ux + vx * vx, py = uy * uy + vy * vy;
    double p = px > py ? px : py;
    /* log2 ρ = ½ log2 ρ²; p = 0 gives −inf (magnification). */
    return (float)(0.5 * log2(p));
}

void lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac)
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
