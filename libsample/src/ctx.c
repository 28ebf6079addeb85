/*
 * The per-batch context (ctx.h).
 */
#include "ctx.h"

void ls_ctx_init(sample_ctx *c, const sample_texture *tex, const sample_sampler *smp,
              const struct isa_kernels *k)
{
    c->tex = tex;
    c->smp = smp;
    memcpy(c->border, smp->border_color, sizeof c->border);
    /* level_base and q (§8.14.3): base clamped to the levels present (an
     * OpenGL texture would be incomplete; we read the last level instead),
     * q = min(level_max, last level). */
    c->base = smp->base_level < tex->nlevels ? smp->base_level : tex->nlevels - 1;
    c->maxlev = smp->max_level < tex->nlevels - 1 ? smp->max_level : tex->nlevels - 1;
    if (c->maxlev < c->base) c->maxlev = c->base;
    c->isa = k;
    c->env = LS_ENV_NONE;
    c->face = 0;
    c->q3 = NULL;
    c->tiles = NULL;
}
