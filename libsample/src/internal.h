/*
 * Every internal header of libsample, for the tests that reach inside the
 * library. The library's own files include only the modules they use
 * (doc/architecture.md draws the layers):
 *
 *   base.h      public API, vector types, portable maths, macros
 *   texel.h     storage and texel decode (texture.c, color.c)
 *   wrap.h      texel addressing (wrap.c)
 *   cube.h      cube-map faces and their coordinates (cube.c)
 *   env_addr.h  environment maps' addressing past edges (env_addr.c)
 *   latlong.h   lat-long maps' direction → (s, t) (latlong.c)
 *   ctx.h       the per-batch context, texel reads through the wraps
 *   kernels.h   the kernel tables per instruction set (isa.c, reference.c)
 *   recon.h     reconstruction on one level (reconstruct.c)
 *   lod.h       level of detail and level choice (lod.c)
 *   mip.h       pyramid building (mip.c)
 *   aniso.h     the anisotropic filter (footprint_aniso.c)
 *   footprint.h Blinn–Newell and EWA (footprint_*.c)
 *   filter.h    the filters of one query (filter.c)
 */
#ifndef SAMPLE_INTERNAL_H
#define SAMPLE_INTERNAL_H

#include "base.h"
#include "texel.h"
#include "wrap.h"
#include "cube.h"
#include "env_addr.h"
#include "latlong.h"
#include "ctx.h"
#include "kernels.h"
#include "recon.h"
#include "lod.h"
#include "mip.h"
#include "aniso.h"
#include "footprint.h"
#include "filter.h"

#endif /* SAMPLE_INTERNAL_H */
