/*
 * PNG writer: 8-bit RGB, filter type 0 per row, zlib-compressed, written
 * through cli_write_file so an interrupted run leaves no truncated file.
 * compare writes its own PNGs rather than going through libsample_io so
 * that the comparison works in a build without OpenImageIO (the core has no
 * dependencies; zlib is the only one compare adds, tools/compare.cmake).
 */
#include "cmp_internal.h"
#include "cli.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* Append a chunk: length, type, data, CRC over type and data. */
static unsigned char *chunk(unsigned char *o, const char type[4], const unsigned char *data,
                            uint32_t len)
{
    uLong crc;
    put32(o, len);
    memcpy(o + 4, type, 4);
    if (len) memcpy(o + 8, data, len);
    crc = crc32(0L, o + 4, 4 + len);
    put32(o + 8 + len, (uint32_t)crc);
    return o + 12 + len;
}

int cmp_png_write(const char *path, const cmp_pic *p)
{
    static const unsigned char sig[8] = {137, 'P', 'N', 'G', '\r', '\n', 26, '\n'};
    size_t row = (size_t)p->w * 3 + 1, raw_len = row * (size_t)p->h;
    unsigned char *raw = malloc(raw_len), *z = NULL, *file = NULL, *o, ihdr[13];
    uLongf zlen = compressBound((uLong)raw_len);
    int j, rc = 1;
    if (!raw) return 1;
    for (j = 0; j < p->h; ++j) {
        raw[(size_t)j * row] = 0; /* filter: none */
        memcpy(raw + (size_t)j * row + 1, p->rgb + (size_t)j * (size_t)p->w * 3, row - 1);
    }
    z = malloc(zlen);
    if (!z || compress2(z, &zlen, raw, (uLong)raw_len, 6) != Z_OK) goto out;
    file = malloc(8 + 25 + 12 + zlen + 12);
    if (!file) goto out;
    memcpy(file, sig, 8);
    put32(ihdr, (uint32_t)p->w);
    put32(ihdr + 4, (uint32_t)p->h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    o = chunk(file + 8, "IHDR", ihdr, 13);
    o = chunk(o, "IDAT", z, (uint32_t)zlen);
    o = chunk(o, "IEND", NULL, 0);
    rc = cli_write_file(path, file, (size_t)(o - file)) ? 0 : 1;
out:
    free(raw);
    free(z);
    free(file);
    return rc;
}
