/*
 * oiio_volume: OpenImageIO's 3D texture lookup, TextureSystem::texture3d(),
 * behind a C API, for bench --volume (doc/volumes.md, "Benchmarks").
 *
 * What OIIO 2.4 does with a volume (texturesys.cpp, texture3d.cpp): the
 * point P goes through the file's world-to-local matrix if it has one (a
 * TIFF written here has none: P is (s, t, r) in [0, 1]³, texel centres at
 * (i + ½)/w as libsample's), then texture3d_lookup_nomip on the base level
 * whatever the mip mode — InterpClosest reads one texel, the other
 * interpolation modes a trilinear blend of 8 — and the derivatives are not
 * used. So OIIO has twins of libsample's NEAREST and LINEAR without mip
 * levels, and of no mip or footprint filter.
 *
 * Which files it reads as volumes: Field3D and OpenVDB (read-only
 * plugins), and TIFF volumes where its reader takes the ImageDepth tag.
 * OIIO 2.4 as Debian 12 ships it writes no volume TIFF (the writer drops
 * the depth) and reads one as its first slice (depth 1, the TileDepth
 * kept), so here oiio_vol_open refuses the file with that message.
 */
#ifndef TEXSAMPLE_OIIO_VOLUME_H
#define TEXSAMPLE_OIIO_VOLUME_H

#include "sample/sample.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct oiio_vol oiio_vol; /* a volume file open in a private TextureSystem */

/* Write w × h × d float RGBA texels (x fastest, then y, then z = slice r)
 * as a tiled (16 × 16 × 16), uncompressed TIFF with that depth
 * (ImageSpec::depth: the ImageDepth and TileDepth tags). Returns 0, or −1
 * with a message in err. */
int oiio_vol_write(const float *rgba, int w, int h, int d, const char *path, char *err,
                   size_t errlen);
/* Open the file in a TextureSystem of its own; NULL with a message if it
 * cannot be read. */
oiio_vol *oiio_vol_open(const char *path, char *err, size_t errlen);
void oiio_vol_close(oiio_vol *v); /* accepts NULL */
/* texture3d() at each query's p (the derivatives are passed on; OIIO does
 * not use them) into n × 4 floats: linear 0 InterpClosest, 1
 * InterpBilinear (trilinear within the base level); `wrap` on all three
 * axes (REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER with a
 * black border; −1 for the others). Returns 0, or −1 with a message. */
int oiio_vol_sample(oiio_vol *v, int linear, sample_wrap wrap, const sample_query3 *q, size_t n,
                    float *rgba, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif /* TEXSAMPLE_OIIO_VOLUME_H */
