/*
 * The byte source the header pre-flights read (exr_guard.c, jpeg_guard.c):
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
