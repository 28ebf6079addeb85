/*
 * The byte source the header pre-flights read (exr_guard.c, jpeg_guard.c,
 * tiff_guard.c, tga_guard.c):
 * a memory buffer or an open file, with its total size, read one byte at a
 * time and never past the end.
 */
#include "io_internal.h"

int io_src_byte(io_src *s, int *c)
{
    if (s->pos >= s->size) return 0;
    if (s->mem) {
        *c = s->mem[s->pos];
    } else {
        int v = fgetc(s->f);
        if (v == EOF) return 0;
        *c = v;
    }
    s->pos++;
    return 1;
}

int io_src_skip(io_src *s, uint64_t n)
{
    if (n > s->size - s->pos) return 0;
    s->pos += n;
    return s->mem ? 1 : fseek(s->f, (long)s->pos, SEEK_SET) == 0;
}

int io_src_seek(io_src *s, uint64_t pos)
{
    if (pos > s->size) return 0;
    s->pos = pos;
    return s->mem ? 1 : fseek(s->f, (long)pos, SEEK_SET) == 0;
}

int io_src_uint(io_src *s, int nbytes, int big_endian, uint32_t *v)
{
    int k, c;
    *v = 0;
    for (k = 0; k < nbytes; ++k) {
        if (!io_src_byte(s, &c)) return 0;
        if (big_endian) *v = *v << 8 | (uint32_t)c;
        else *v |= (uint32_t)c << (8 * k);
    }
    return 1;
}

int io_src_file(io_src *s, FILE *f)
{
    long end;
    memset(s, 0, sizeof *s);
    if (fseek(f, 0, SEEK_END) != 0 || (end = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) return 0;
    s->f = f;
    s->size = (uint64_t)end;
    return 1;
}

void io_src_memory(io_src *s, const void *data, size_t size)
{
    memset(s, 0, sizeof *s);
    s->mem = (const unsigned char *)data;
    s->size = size;
}

sample_status io_src_preflight(const char *path, const void *data, size_t size, size_t nmagic,
                               int (*is_format)(const unsigned char *p, size_t n), uint64_t start,
                               sample_status (*check)(io_src *s, const char *what, sample_error *err),
                               sample_error *err)
{
    io_src s;
    unsigned char magic[32];
    sample_status st = SAMPLE_OK;
    FILE *f;
    if (!path) {
        if (!is_format((const unsigned char *)data, size) || start > size) return SAMPLE_OK;
        io_src_memory(&s, data, size);
        s.pos = start;
        return check(&s, "image in memory", err);
    }
    f = fopen(path, "rb");
    if (!f) return SAMPLE_OK; /* the reader reports unreadable files */
    if (nmagic <= sizeof magic && fread(magic, 1, nmagic, f) == nmagic && is_format(magic, nmagic) &&
        io_src_file(&s, f) && io_src_skip(&s, start))
        st = check(&s, path, err);
    fclose(f);
    return st;
}
