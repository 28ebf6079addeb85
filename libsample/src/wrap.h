/*
 * Texel addressing (wrap.c): the single function that maps an integral
 * texel index to a texel of the level or to the border colour, for every
 * wrap mode (DESIGN §3, GL 4.6 §8.14.2 table 8.20).
 */
#ifndef SAMPLE_WRAP_H
#define SAMPLE_WRAP_H

#include "base.h"

/* Wrap modes that transform the coordinate before indexing (GL_CLAMP and the
 * EXT mirror-clamps) do it here: s → s', normalized, for an axis of n texels.
 * Other modes return s unchanged. NaN must be rejected before. */
float ls_wrap_coord(sample_wrap mode, float s, int n);

/* Whether `mode` transforms the coordinate (ls_wrap_coord) before indexing:
 * legacy CLAMP and the EXT mirror-clamps (DESIGN §3). A predicate, so that
 * nothing depends on the enum's numeric order. */
static inline int wrap_transforms_coord(sample_wrap mode)
{
    switch (mode) {
    case SAMPLE_WRAP_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER:
        return 1;
    default:
        return 0;
    }
}

/* The single addressing function (DESIGN §3): integral index i (a double so
 * that any float coordinate's floor is exact) on an axis of n texels → a
 * texel index in [0, n), or −1 for "border colour". `linear` selects the
 * LINEAR/footprint rule of legacy CLAMP (clamp to [−1, n]) instead of the
 * NEAREST rule (clamp to [0, n−1]). */
int ls_wrap_index(sample_wrap mode, double i, int n, int linear);

#endif /* SAMPLE_WRAP_H */
