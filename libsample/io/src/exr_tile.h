/*
 * The texture system's direct OpenEXR tile reader (exr_tile.c): one file
 * tile of one mip level decoded by the OpenEXR core C library (OpenEXR 3.1
 * <OpenEXR/openexr.h>) straight into a caller's buffer, as the cache's
 * tiles lay texels out (doc/texture-system.md, "Files").
 */
#ifndef SAMPLE_IO_EXR_TILE_H
#define SAMPLE_IO_EXR_TILE_H

#include "io_internal.h"

typedef struct io_exr_tile io_exr_tile;

/* Open `path` to read the tiles of `tex` (its levels as the texture system
 * describes the file, tiles 2^log2 texels a side), channels [0,
 * plan->nchan) as plan->read_as. *out stays NULL (status SAMPLE_OK) when
 * the file is not one this reader takes — not OpenEXR, several parts,
 * deep, not MIPMAP_LEVELS with ROUND_DOWN, other tile sizes or level
 * sizes, channels not exactly a prefix of R, G, B, A of one type (half or
 * float), a read_as the core library cannot produce exactly — and the
 * caller uses io_reader (the rule of exr_read.cpp). */
sample_status io_exr_tile_open(const char *path, const sample_texture *tex, int log2, const io_plan *plan,
                               io_exr_tile **out, sample_error *err);

/* Tile (tx, ty) of level lv, w × h texels (the tile's size inside the
 * level: the file must agree), into dst: texel (i, j) at dst + j × line +
 * i × pixel, channel c at c × 2 (half) or c × 4 (float) bytes within it.
 * A tile the file lacks or cannot decode is SAMPLE_E_CORRUPT with a
 * message naming the file, the level and the tile. One call at a time
 * per x (its decoding pipeline is reused; texsys_cache.c holds the
 * file's io_lock). */
sample_status io_exr_tile_read(io_exr_tile *x, int lv, int tx, int ty, int w, int h, unsigned char *dst,
                               size_t pixel, size_t line, sample_error *err);

void io_exr_tile_close(io_exr_tile *x); /* accepts NULL */

#endif
