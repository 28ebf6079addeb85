/*
 * Pyramid building (mip.c, DESIGN §6).
 */
#ifndef SAMPLE_MIP_H
#define SAMPLE_MIP_H

#include "texel.h"

/* Fill levels 1 … of a texture whose level 0 is loaded (DESIGN §6).
 * On failure the extra levels are freed and tex->nlevels is back to 1. */
sample_status ls_mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err);

#endif /* SAMPLE_MIP_H */
