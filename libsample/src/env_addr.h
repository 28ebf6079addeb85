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

/* Texel (i, j) (integral, finite; inside or outside the level) of face
 * `face` (cube) of level lv, decoded, as mode addresses it. `linear` is
 * ctx_texel's: for a cube map NEAREST (0) clamps to the face (its wrap is
 * CLAMP_TO_EDGE, §8.13.1) and LINEAR and cubic read the neighbouring
 * faces (the footprint filters read each face on its own:
 * ls_env_face_clip). */
void ls_env_texel(const sample_texture *tex, int lv, int face, ls_env_mode mode, double i, double j, int linear,
                  float out[4]);

/* The part inside an n × n cube face of texels ilo … ilo + ncol − 1 of a
 * footprint filter's walk row j (a row of the face, or a column when the
 * walk is by columns): none if the row is outside the face, else the span
 * cut to [0, n). Returns the texels kept and moves *ilo to the first.
 * Blinn–Newell and EWA read a cube map face by face, each face's texels
 * with that face's own footprint (footprint_common.c, ls_fp_cube_read),
 * so a walk reads only its own face. */
static inline double ls_env_face_clip(double n, double j, double *ilo, double ncol)
{
    double lo = *ilo, hi = *ilo + ncol - 1.0;
    if (!(j >= 0.0 && j < n)) return 0.0;
    if (lo < 0.0) lo = 0.0;
    if (hi > n - 1.0) hi = n - 1.0;
    *ilo = lo;
    return hi >= lo ? hi - lo + 1.0 : 0.0;
}

#endif /* SAMPLE_ENV_ADDR_H */
