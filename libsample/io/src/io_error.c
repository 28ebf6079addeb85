/* Option defaults of libsample_io. */
#include "io_internal.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void sample_io_options_init(sample_io_options *o)
{
    memset(o, 0, sizeof *o);
    o->use_file_levels = 1;
}

void sample_io_write_options_init(sample_io_write_options *o)
{
    memset(o, 0, sizeof *o);
    o->type = SAMPLE_IO_TYPE_AUTO;
}

void sample_io_exr_options_init(sample_io_exr_options *o)
{
    memset(o, 0, sizeof *o);
    o->tile_w = o->tile_h = 64; /* maketx's default tile size */
    o->wrap_s = o->wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    o->type = SAMPLE_IO_TYPE_AUTO;
    o->alpha_channel = -1;
}

void io_extension(const char *path, char *ext, size_t ext_size)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    size_t k = 0;
    if (ext_size == 0) return;
    if (dot && (!slash || dot > slash))
        for (++dot; *dot && k + 1 < ext_size; ++dot) ext[k++] = (char)tolower((unsigned char)*dot);
    ext[k] = '\0';
}
