/*
 * A pre-flight check of TIFF files, before OpenImageIO sees the bytes.
 * libtiff, through OpenImageIO 2.4, reads a file whose strip table ends
 * before the image does by allocating the whole claimed image and filling
 * the missing strips with zeros: a 1 KB file claiming 32768 × 32768 costs
 * gigabytes, and a strip whose offset points past the end of the file reads
 * as black without an error. The image file directories (TIFF 6.0, section
 * 2: header, IFD entries of tag, type, count, value-or-offset; section 3
 * and 15: StripOffsets/StripByteCounts, TileOffsets/TileByteCounts,
 * RowsPerStrip, PlanarConfiguration) say how much data the image needs and
 * where it is, so the claim can be checked against the file before any
 * pixel is allocated:
 *
 * - the strip (tile) table has an entry for every strip (tile) the image
 *   needs;
 * - every strip lies inside the file and holds at least one byte;
 * - uncompressed strips hold at least the bytes their rows need.
 *
 * Compressed data cannot be bounded by its size; the reader's byte budget
 * (sample_io_options.max_bytes) bounds it. BigTIFF (version 43) passes
 * untouched.
 */
#include "io_internal.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

enum {
    TAG_WIDTH = 256, TAG_HEIGHT = 257, TAG_BITS = 258, TAG_COMPRESSION = 259, TAG_STRIP_OFFSETS = 273,
    TAG_SAMPLES = 277, TAG_ROWS_PER_STRIP = 278, TAG_STRIP_COUNTS = 279, TAG_PLANAR = 284, TAG_TILE_WIDTH = 322,
    TAG_TILE_LENGTH = 323, TAG_TILE_OFFSETS = 324, TAG_TILE_COUNTS = 325
};
/* A chain of image directories is followed this far (a .tx file holds one
 * per mip level: 17 at most); a longer one, or a cycle, is left to libtiff. */
enum { TIFF_MAX_IFDS = 64 };

typedef struct tiff_entry {
    int present;
    uint32_t type, count, field; /* field: the raw value-or-offset word */
    unsigned char raw[4];        /* its bytes, for values stored inline */
} tiff_entry;

typedef struct tiff_ifd {
    tiff_entry width, height, bits, compression, samples, rows, planar, tile_w, tile_h, offsets, counts;
    int tiled;
} tiff_ifd;

static uint32_t type_size(uint32_t type)
{
    switch (type) {
    case 1: case 2: case 6: case 7: return 1; /* BYTE, ASCII, SBYTE, UNDEFINED */
    case 3: case 8: return 2;                 /* SHORT, SSHORT */
    case 4: case 9: case 11: case 13: return 4; /* LONG, SLONG, FLOAT, IFD */
    default: return 8;                        /* RATIONAL, DOUBLE, ... */
    }
}

/* Element `index` of an entry of SHORT or LONG type (other types: 0). */
static int entry_value(io_src *s, int be, const tiff_entry *e, uint32_t index, uint32_t *v)
{
    uint32_t size = type_size(e->type);
    *v = 0;
    if (size != 2 && size != 4 && size != 1) return 1;
    if ((uint64_t)e->count * size <= 4) {
        const unsigned char *p = e->raw + index * size;
        uint32_t k;
        for (k = 0; k < size; ++k) *v = be ? *v << 8 | p[k] : *v | (uint32_t)p[k] << (8 * k);
        return 1;
    }
    return io_src_seek(s, (uint64_t)e->field + (uint64_t)index * size) && io_src_uint(s, (int)size, be, v);
}

static uint32_t single(io_src *s, int be, const tiff_entry *e, uint32_t dflt)
{
    uint32_t v;
    return e->present && e->count >= 1 && entry_value(s, be, e, 0, &v) ? v : dflt;
}

static tiff_entry *slot_for(tiff_ifd *d, uint32_t tag)
{
    switch (tag) {
    case TAG_WIDTH: return &d->width;
    case TAG_HEIGHT: return &d->height;
    case TAG_BITS: return &d->bits;
    case TAG_COMPRESSION: return &d->compression;
    case TAG_SAMPLES: return &d->samples;
    case TAG_ROWS_PER_STRIP: return &d->rows;
    case TAG_PLANAR: return &d->planar;
    case TAG_TILE_WIDTH: return &d->tile_w;
    case TAG_TILE_LENGTH: return &d->tile_h;
    case TAG_STRIP_OFFSETS: case TAG_TILE_OFFSETS: return &d->offsets;
    case TAG_STRIP_COUNTS: case TAG_TILE_COUNTS: return &d->counts;
    default: return NULL;
    }
}

/* Read the entries of the directory at s's position; *next gets the next
 * directory's offset. 0: the directory itself is cut short. */
static int read_ifd(io_src *s, int be, tiff_ifd *d, uint32_t *next)
{
    uint32_t n, k;
    memset(d, 0, sizeof *d);
    if (!io_src_uint(s, 2, be, &n)) return 0;
    for (k = 0; k < n; ++k) {
        uint32_t tag, type, count;
        unsigned char raw[4];
        int c, b;
        tiff_entry *e;
        if (!io_src_uint(s, 2, be, &tag) || !io_src_uint(s, 2, be, &type) || !io_src_uint(s, 4, be, &count)) return 0;
        for (b = 0; b < 4; ++b) {
            if (!io_src_byte(s, &c)) return 0;
            raw[b] = (unsigned char)c;
        }
        if (!(e = slot_for(d, tag))) continue;
        e->present = 1;
        e->type = type;
        e->count = count;
        memcpy(e->raw, raw, 4);
        e->field = be ? (uint32_t)raw[0] << 24 | (uint32_t)raw[1] << 16 | (uint32_t)raw[2] << 8 | raw[3]
                      : (uint32_t)raw[3] << 24 | (uint32_t)raw[2] << 16 | (uint32_t)raw[1] << 8 | raw[0];
        if (tag == TAG_TILE_OFFSETS || tag == TAG_TILE_COUNTS) d->tiled = 1;
    }
    return io_src_uint(s, 4, be, next);
}

/* Bytes one uncompressed strip (tile) k holds at least, from its rows. */
static uint64_t strip_need(uint64_t row_bytes, uint32_t rows, uint32_t h, uint64_t per_plane, uint64_t k)
{
    uint64_t first = (k % per_plane) * rows;
    uint64_t n = first < h ? (h - first < rows ? h - first : rows) : 0;
    return row_bytes * n;
}

static sample_status check_ifd(io_src *s, int be, const tiff_ifd *d, int index, const char *what, sample_error *err)
{
    const char *unit = d->tiled ? "tile" : "strip";
    uint32_t w = single(s, be, &d->width, 0), h = single(s, be, &d->height, 0);
    uint32_t spp = single(s, be, &d->samples, 1), bps = single(s, be, &d->bits, 1);
    uint32_t comp = single(s, be, &d->compression, 1), planar = single(s, be, &d->planar, 1);
    uint64_t planes = planar == 2 ? spp : 1, per_plane, needed, row_bytes, k, need;
    uint32_t rows, tw = 0;
    /* What libtiff refuses by itself (no size, no table) is left to it. */
    if (!w || !h || !spp || !bps || !d->offsets.present) return SAMPLE_OK;
    if (d->tiled) {
        uint32_t th = single(s, be, &d->tile_h, 0);
        tw = single(s, be, &d->tile_w, 0);
        if (!tw || !th) return SAMPLE_OK;
        per_plane = ((uint64_t)w + tw - 1) / tw * (((uint64_t)h + th - 1) / th);
        rows = th; /* each tile holds all its rows, the edge tiles too */
        row_bytes = ((uint64_t)tw * bps * (planar == 2 ? 1 : spp) + 7) / 8;
    } else {
        rows = single(s, be, &d->rows, UINT32_MAX);
        if (rows == 0 || rows > h) rows = h;
        per_plane = ((uint64_t)h + rows - 1) / rows;
        row_bytes = ((uint64_t)w * bps * (planar == 2 ? 1 : spp) + 7) / 8;
    }
    needed = per_plane * planes;
    if (d->offsets.count < needed || (d->counts.present && d->counts.count < needed))
        return sample_error_set(err, SAMPLE_E_CORRUPT,
                                "%s: TIFF image %d claims %" PRIu32 " x %" PRIu32 " but its %s table has %" PRIu32
                                " entries of the %" PRIu64 " it needs",
                                what, index, w, h, unit,
                                d->offsets.count < needed ? d->offsets.count : d->counts.count, needed);
    for (k = 0; k < needed; ++k) {
        uint32_t off, cnt = 0;
        if (!entry_value(s, be, &d->offsets, (uint32_t)k, &off) ||
            (d->counts.present && !entry_value(s, be, &d->counts, (uint32_t)k, &cnt)))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: TIFF image %d's %s table lies past the end of the file",
                                    what, index, unit);
        if (!d->counts.present) continue;
        if (cnt == 0 || off == 0 || off > s->size || cnt > s->size - off)
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                                    "%s: TIFF image %d's %s %" PRIu64 " (%" PRIu32 " bytes at offset %" PRIu32
                                    ") is not inside the %" PRIu64 "-byte file",
                                    what, index, unit, k, cnt, off, s->size);
        need = d->tiled ? row_bytes * rows : strip_need(row_bytes, rows, h, per_plane, k);
        if (comp == 1 && cnt < need)
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                                    "%s: uncompressed TIFF image %d's %s %" PRIu64 " holds %" PRIu32
                                    " bytes; its rows need %" PRIu64,
                                    what, index, unit, k, cnt, need);
    }
    return SAMPLE_OK;
}

static sample_status check(io_src *s, const char *what, sample_error *err)
{
    int c0, c1, be, n;
    uint32_t magic, next;
    if (!io_src_byte(s, &c0) || !io_src_byte(s, &c1)) return SAMPLE_OK;
    be = c0 == 'M';
    if (!io_src_uint(s, 2, be, &magic) || magic != 42 || !io_src_uint(s, 4, be, &next)) return SAMPLE_OK;
    for (n = 0; n < TIFF_MAX_IFDS && next != 0; ++n) {
        tiff_ifd d;
        sample_status st;
        if (!io_src_seek(s, next) || !read_ifd(s, be, &d, &next))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: TIFF image directory %d lies past the end of the file",
                                    what, n);
        if ((st = check_ifd(s, be, &d, n, what, err)) != SAMPLE_OK) return st;
    }
    return SAMPLE_OK;
}

static int is_tiff(const unsigned char *p, size_t n)
{
    return n >= 4 && ((p[0] == 'I' && p[1] == 'I' && p[2] == 42 && p[3] == 0) ||
                      (p[0] == 'M' && p[1] == 'M' && p[2] == 0 && p[3] == 42));
}

sample_status io_tiff_guard_memory(const void *data, size_t size, sample_error *err)
{
    return io_src_preflight(NULL, data, size, 4, is_tiff, 0, check, err);
}

sample_status io_tiff_guard_file(const char *path, sample_error *err)
{
    return io_src_preflight(path, NULL, 0, 4, is_tiff, 0, check, err);
}
