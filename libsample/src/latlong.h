/*
 * Lat-long (equirectangular) environment maps (latlong.c,
 * doc/environment-maps.md): a 2D texture sampled by direction, with
 * OpenImageIO's convention for lat-long files whose up direction is +y
 * (its vector_to_latlong with y_is_up, the orientation maketx --envlatl
 * output declares):
 *
 *   s = atan2(−x, z) / 2π + ½,   t = ½ − atan2(y, √(x² + z²)) / π
 *
 * so +y (up) is row 0 (t = 0), −y is t = 1, +z is s = ½, +x is s = ¼
 * and −x is s = ¾; s = 0 = 1 is the −z half-plane (the seam).
 */
#ifndef SAMPLE_LATLONG_H
#define SAMPLE_LATLONG_H

#include "base.h"

/* atan2(y, x) in [−π, π] from IEEE operations alone (no libm: the same
 * bits on every machine, as portable_math.h's functions), within a few
 * units of 2^−53 of π; atan2(0, 0) = 0. */
double ls_atan2(double y, double x);

/* The 2D query of a lat-long lookup: (s, t) above, and the Jacobian of
 * (s, t) by the chain rule through the exact derivatives of the two
 * angles. ∂s grows without bound towards the poles (∝ 1/√(x² + z²)) and
 * is held at ±FLT_MAX, so that λ clamps and the footprint filters' texel
 * cap applies; on the poles' axis itself it is 0, its limit along the
 * derivative's own direction. Returns 0, or −1 for the zero direction.
 * The query must be finite. */
int ls_latlong_query(const sample_query3 *q, sample_query *out);

#endif /* SAMPLE_LATLONG_H */
