/*
 * Pyramid building (mip.c, DESIGN §6).
 */
#ifndef SAMPLE_MIP_H
#define SAMPLE_MIP_H

#include "texel.h"

/* Fill levels 1 … of a texture whose level 0 is loaded (DESIGN §6).
 * On failure the extra levels are freed and tex->nlevels is back to 1. */
sample_status ls_mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err);

/* Most bytes of scratch ls_mip_build holds for a texture w texels wide
 * with kernel f: O(w), whatever the height (doc/mip-and-lod.md, "Memory"). */
size_t ls_mip_scratch_bytes(int w, sample_mipgen f);

#endif /* SAMPLE_MIP_H */
