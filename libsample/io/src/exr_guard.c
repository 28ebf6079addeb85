/*
 * A pre-flight check of OpenEXR headers, before OpenImageIO and OpenEXR see
 * the bytes. OpenEXR 3.1 allocates an attribute's value at the size the file
 * claims before it reads it, so a corrupt size field in a few hundred bytes
 * of input makes it allocate gigabytes (found by fuzz_io). The header layout
 * (OpenEXR "File Layout": magic, version, then per part attributes as
 * name\0 type\0 int32-size value, ended by an empty name) lets us check every
 * claimed size against the bytes that actually exist.
 */
#include "io_internal.h"

#include <stdio.h>
#include <string.h>

/* A null-terminated string of at most `max` characters; *len gets its length. */
static int src_string(io_src *s, size_t max, char *buf, size_t *len)
{
    size_t n = 0;
    int c;
    for (;;) {
        if (!io_src_byte(s, &c)) return 0;
        if (c == 0) break;
        if (n >= max) return 0;
        if (n + 1 < 64) buf[n] = (char)c;
        ++n;
    }
    buf[n < 64 ? n : 63] = '\0';
    *len = n;
    return 1;
}

/* Parts and attributes are bounded so that a header cannot make us loop
 * for long either (real files have tens of attributes). */
enum { EXR_MAX_PARTS = 1024, EXR_MAX_ATTRIBUTES = 100000 };

static sample_status check(io_src *s, const char *what, sample_error *err)
{
    unsigned char head[8];
    int c, k, parts = 0, attrs = 0;
    unsigned version;
    size_t name_max;
    for (k = 0; k < 8; ++k) {
        if (!io_src_byte(s, &c)) return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR header is truncated", what);
        head[k] = (unsigned char)c;
    }
    version = (unsigned)head[4] | (unsigned)head[5] << 8 | (unsigned)head[6] << 16 | (unsigned)head[7] << 24;
    /* Long names (bit 10) allow 255 characters, else 31. */
    name_max = (version & 0x400u) ? 255 : 31;
    for (;;) {
        char name[64], type[64];
        size_t nlen, tlen;
        int32_t size;
        unsigned char b[4];
        if (!src_string(s, name_max, name, &nlen))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR attribute name is truncated or too long", what);
        if (nlen == 0) {
            /* End of a part's header; multi-part files (bit 12) end the list
             * of headers with one more empty header. */
            ++parts;
            if (!(version & 0x1000u) || parts >= EXR_MAX_PARTS) return SAMPLE_OK;
            if (s->pos < s->size && (s->mem ? s->mem[s->pos] == 0 : 0)) return SAMPLE_OK;
            if (!s->mem) {
                int next;
                long at = ftell(s->f);
                next = fgetc(s->f);
                if (next == 0 || next == EOF) return SAMPLE_OK;
                if (fseek(s->f, at, SEEK_SET) != 0) return SAMPLE_OK;
            }
            continue;
        }
        if (++attrs > EXR_MAX_ATTRIBUTES)
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR header has too many attributes", what);
        if (!src_string(s, name_max, type, &tlen))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR attribute '%s' has a bad type name", what, name);
        for (k = 0; k < 4; ++k) {
            if (!io_src_byte(s, &c))
                return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR attribute '%s' is truncated", what, name);
            b[k] = (unsigned char)c;
        }
        size = (int32_t)((uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24);
        if (size < 0 || (uint64_t)size > s->size - s->pos)
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                           "%s: OpenEXR attribute '%s' (%s) claims %ld bytes but only %llu remain", what, name,
                           type, (long)size, (unsigned long long)(s->size - s->pos));
        if (!io_src_skip(s, (uint64_t)size))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "%s: OpenEXR attribute '%s' is truncated", what, name);
    }
}

static int is_exr(const unsigned char *p, size_t n)
{
    return n >= 4 && p[0] == 0x76 && p[1] == 0x2f && p[2] == 0x31 && p[3] == 0x01;
}

sample_status io_exr_guard_memory(const void *data, size_t size, sample_error *err)
{
    return io_src_preflight(NULL, data, size, 4, is_exr, 0, check, err);
}

sample_status io_exr_guard_file(const char *path, sample_error *err)
{
    return io_src_preflight(path, NULL, 0, 4, is_exr, 0, check, err);
}
