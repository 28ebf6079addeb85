/*
 * Texel addressing of environment maps (env_addr.c), the counterpart of
 * wrap.h for the kinds whose texels past an edge are not a wrap of the
 * same level: a cube map's faces, where they come from the adjacent face
 * (GL 4.6 §8.13.1, seamless), and a lat-long map's poles, where they come
 * from the other half of the map (doc/environment-maps.md).
 */
#ifndef SAMPLE_ENV_ADDR_H
#define SAMPLE_ENV_ADDR_H

#include "texel.h"

/* How a context addresses texels past a level's edge (sample_ctx.env). */
typedef enum ls_env_mode {
    LS_ENV_NONE = 0,    /* the sampler's wrap modes (wrap.h) */
    LS_ENV_CUBE = 1,    /* seamless cube faces */
    LS_ENV_LATLONG = 2, /* REPEAT in s, over the poles in t */
} ls_env_mode;

/* ctx_texel's `linear` for the reads of Blinn–Newell and EWA
 * (footprint.h, fp_span_texels): every wrap mode takes it as LINEAR's; a
 * cube map reads texels past an edge by the footprint rule (env_addr.c,
 * footprint_texel), not §8.13.1's. */
#define LS_ENV_READ_FOOTPRINT 2

/* Texel (i, j) (integral, finite; inside or outside the level) of face
 * `face` (cube) of level lv, decoded, as mode addresses it. `linear` is
 * ctx_texel's: for a cube map NEAREST (0) clamps to the face (its wrap is
 * CLAMP_TO_EDGE, §8.13.1), LINEAR and cubic (1) read the neighbouring
 * faces as §8.13.1 does, and the footprint filters
 * (LS_ENV_READ_FOOTPRINT) by the footprint rule. */
void ls_env_texel(const sample_texture *tex, int lv, int face, ls_env_mode mode, double i, double j, int linear,
                  float out[4]);

#endif /* SAMPLE_ENV_ADDR_H */
