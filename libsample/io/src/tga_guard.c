/*
 * A pre-flight check of Targa files, before OpenImageIO sees the bytes.
 * OpenImageIO 2.4's Targa reader drops the part of an RLE packet that runs
 * past the image, and looks colour-map indices up without comparing them
 * with the map's length; both read as plausible pixels, exit status 0. The
 * layout (Truevision TGA File Format Specification 2.0: an 18-byte header,
 * the image ID, the colour map, then the pixels; RLE packets of a header
 * byte, bit 7 run or raw, count in bits 0–6 plus one) lets us walk the
 * pixel stream once and refuse:
 *
 * - an RLE packet that holds more pixels than the image has left, or a
 *   stream that ends before the image is complete;
 * - a colour-map index outside [first entry, first entry + length).
 *
 * Targa has no magic number: a file is taken as Targa when its header is a
 * consistent one (image type 1, 2, 3, 9, 10 or 11, colour-map type 0 or 1
 * and 1 for the colour-mapped types, 8/15/16/24/32 bits per pixel, non-zero
 * size). No other format OpenImageIO reads starts that way (their magic
 * numbers put a byte other than 0 or 1 second).
 */
#include "io_internal.h"

#include <inttypes.h>

typedef struct tga_header {
    unsigned id_len, map_type, type, map_first, map_len, map_bits, width, height, bpp;
} tga_header;

static unsigned le16(const unsigned char *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }

static int parse(const unsigned char *p, size_t n, tga_header *h)
{
    unsigned t;
    if (n < 18) return 0;
    h->id_len = p[0], h->map_type = p[1], h->type = t = p[2];
    h->map_first = le16(p + 3), h->map_len = le16(p + 5), h->map_bits = p[7];
    h->width = le16(p + 12), h->height = le16(p + 14), h->bpp = p[16];
    if (!(t == 1 || t == 2 || t == 3 || t == 9 || t == 10 || t == 11) || h->map_type > 1) return 0;
    if ((t == 1 || t == 9) && h->map_type != 1) return 0;
    if (!(h->bpp == 8 || h->bpp == 15 || h->bpp == 16 || h->bpp == 24 || h->bpp == 32)) return 0;
    return h->width > 0 && h->height > 0;
}

static int is_tga(const unsigned char *p, size_t n)
{
    tga_header h;
    return parse(p, n, &h);
}

/* One pixel of `bytes` bytes; for colour-mapped images its index is checked
 * against the map. */
static sample_status pixel(io_src *s, const tga_header *h, unsigned bytes, uint64_t at, const char *what,
                           sample_error *err)
{
    uint32_t v;
    if (!io_src_uint(s, (int)bytes, 0, &v))
        return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: Targa pixel data ends at pixel %" PRIu64 " of %" PRIu64,
                                what, at, (uint64_t)h->width * h->height);
    if ((h->type == 1 || h->type == 9) && (v < h->map_first || v - h->map_first >= h->map_len))
        return sample_error_set(err, SAMPLE_E_CORRUPT,
                                "%s: Targa pixel %" PRIu64 " has colour-map index %" PRIu32
                                ", outside the map (entries %u to %d)",
                                what, at, v, h->map_first, (int)(h->map_first + h->map_len) - 1);
    return SAMPLE_OK;
}

static sample_status check(io_src *s, const char *what, sample_error *err)
{
    unsigned char p[18];
    tga_header h;
    uint64_t total, done = 0;
    unsigned bytes;
    int k, c;
    for (k = 0; k < 18; ++k) {
        if (!io_src_byte(s, &c)) return SAMPLE_OK;
        p[k] = (unsigned char)c;
    }
    if (!parse(p, 18, &h)) return SAMPLE_OK;
    bytes = (h.bpp + 7) / 8;
    total = (uint64_t)h.width * h.height;
    /* Only the colour-mapped images' indices are looked at, and only the
     * RLE images' packets: an uncompressed true-colour stream has nothing
     * to check but its length, which the reader checks itself. */
    if (h.type == 2 || h.type == 3) return SAMPLE_OK;
    if (!io_src_skip(s, h.id_len + (uint64_t)h.map_len * ((h.map_bits + 7) / 8)))
        return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: Targa colour map runs past the end of the file", what);
    while (done < total) {
        sample_status st;
        uint32_t head, n, i;
        if (h.type == 1) {
            if ((st = pixel(s, &h, bytes, done, what, err)) != SAMPLE_OK) return st;
            ++done;
            continue;
        }
        if (!io_src_uint(s, 1, 0, &head))
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                                    "%s: Targa RLE data ends at pixel %" PRIu64 " of %" PRIu64, what, done, total);
        n = (head & 0x7fu) + 1;
        if (n > total - done)
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                                    "%s: Targa RLE packet at pixel %" PRIu64 " holds %" PRIu32
                                    " pixels; the image has %" PRIu64 " left",
                                    what, done, n, total - done);
        for (i = 0; i < ((head & 0x80u) ? 1u : n); ++i)
            if ((st = pixel(s, &h, bytes, done + i, what, err)) != SAMPLE_OK) return st;
        done += n;
    }
    return SAMPLE_OK;
}

sample_status io_tga_guard_memory(const void *data, size_t size, sample_error *err)
{
    return io_src_preflight(NULL, data, size, 18, is_tga, 0, check, err);
}

sample_status io_tga_guard_file(const char *path, sample_error *err)
{
    return io_src_preflight(path, NULL, 0, 18, is_tga, 0, check, err);
}
