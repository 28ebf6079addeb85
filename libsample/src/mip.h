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

/* One axis of a resampling step (mip.c): for each output texel its source
 * texels and weights. */
typedef struct mip_axis {
    int n_src, n_dst, taps; /* taps per output texel (unused ones weigh 0) */
    int *idx;               /* n_dst × taps source indices */
    float *w;               /* n_dst × taps weights, each row sums to 1 */
} mip_axis;

/* The taps of an axis of n_src → n_dst texels with kernel f, as
 * ls_mip_build makes them, but with the indices as they fall, past the
 * edges too (< 0, ≥ n_src): for a cube map, whose texels past a face edge
 * are on the adjacent face (cube.c). 0 when out of memory. Free with
 * ls_mip_axis_free. */
int ls_mip_axis_unwrapped(mip_axis *ax, int n_src, int n_dst, sample_mipgen f);
void ls_mip_axis_free(mip_axis *ax);

#endif /* SAMPLE_MIP_H */
