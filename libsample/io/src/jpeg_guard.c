/*
 * A pre-flight check of JPEG headers, before OpenImageIO sees the bytes.
 * OpenImageIO 2.4's JPEG reader takes an APP13 segment that starts with
 * "Photoshop 3.0\0" for an IPTC block and reads as many bytes as the block's
 * own 16-bit size field says, without comparing it with the segment's length
 * (JpgInput::jpeg_decode_iptc), so a corrupt size reads past the segment's
 * buffer (found by fuzz_io under AddressSanitizer). The markers before the
 * image data (ITU-T T.81 B.1: 0xFF, a code, a big-endian length that counts
 * itself, the payload) let us check what that reader will read against what
 * the segment holds, and refuse the file instead.
 */
#include "io_internal.h"

/* The IPTC block inside a Photoshop APP13 payload, as OIIO reads it:
 * "Photoshop 3.0\0", "8BIM", resource 0x0404, 4 bytes, a 16-bit size, the
 * IPTC data. */
enum { PS_NAME = 14, PS_HEAD = 26, PS_IPTC = 0x0404 };
static const char ps_name[PS_NAME + 1] = "Photoshop 3.0";

/* Whether OIIO's reading of an APP13 payload of n bytes (the first
 * min(n, PS_HEAD) in h) stays inside it: its strcmp with ps_name reads
 * past a payload that is a proper prefix of "Photoshop 3.0\0"; a matching
 * one must hold the whole block head and the IPTC size it claims. */
static int app13_inside(const unsigned char *h, size_t n)
{
    size_t k, m = n < PS_NAME ? n : PS_NAME;
    unsigned size;
    for (k = 0; k < m; ++k)
        if (h[k] != (unsigned char)ps_name[k]) return 1; /* strcmp stops inside */
    if (n < PS_HEAD) return 0;
    if (memcmp(h + PS_NAME, "8BIM", 4) != 0 || (h[18] << 8 | h[19]) != PS_IPTC) return 1;
    size = (unsigned)h[24] << 8 | h[25];
    return size <= n - PS_HEAD;
}

/* Markers, each its 0xFF and code, up to the start of the scan (SOS) or the
 * end (EOI); bounded by the data's length (each step reads at least one
 * byte). */
static sample_status check(io_src *s, const char *what, sample_error *err)
{
    for (;;) {
        int c, hi, lo;
        unsigned char h[PS_HEAD];
        size_t len, k, n;
        do {
            if (!io_src_byte(s, &c)) return SAMPLE_OK; /* truncated: the reader reports it */
        } while (c != 0xFF);
        do {
            if (!io_src_byte(s, &c)) return SAMPLE_OK;
        } while (c == 0xFF); /* fill bytes */
        if (c == 0xDA || c == 0xD9) return SAMPLE_OK; /* SOS, EOI: OIIO saves no markers past them */
        if (c == 0x01 || (c >= 0xD0 && c <= 0xD8) || c == 0x00) continue; /* no length */
        if (!io_src_byte(s, &hi) || !io_src_byte(s, &lo)) return SAMPLE_OK;
        len = (size_t)(hi << 8 | lo);
        if (len < 2) return SAMPLE_OK; /* libjpeg refuses it */
        len -= 2;
        if (c != 0xED) {
            if (!io_src_skip(s, len)) return SAMPLE_OK;
            continue;
        }
        if (len > s->size - s->pos)
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: JPEG APP13 segment is truncated", what);
        n = len < PS_HEAD ? len : PS_HEAD;
        for (k = 0; k < n; ++k) {
            if (!io_src_byte(s, &c)) return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: JPEG APP13 segment is truncated", what);
            h[k] = (unsigned char)c;
        }
        if (!app13_inside(h, len))
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                           "%s: JPEG APP13 (Photoshop IPTC) block claims more bytes than its %zu-byte segment", what,
                           len);
        if (!io_src_skip(s, len - n)) return SAMPLE_OK;
    }
}

static int is_jpeg(const unsigned char *p, size_t n) { return n >= 3 && p[0] == 0xFF && p[1] == 0xD8 && p[2] == 0xFF; }

/* The markers start after the SOI (FF D8). */
sample_status io_jpeg_guard_memory(const void *data, size_t size, sample_error *err)
{
    return io_src_preflight(NULL, data, size, 3, is_jpeg, 2, check, err);
}

sample_status io_jpeg_guard_file(const char *path, sample_error *err)
{
    return io_src_preflight(path, NULL, 0, 3, is_jpeg, 2, check, err);
}
