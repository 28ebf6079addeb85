/* What an image file holds, from its headers (doc/io-and-colour.md,
 * "Describing"): the memory used is that of the headers, never the pixels,
 * so `texsample info` on a file claiming 65536 × 65536 costs what its
 * header costs. The reader's own plan (io_read_plan) says what a texture
 * read from it would be. */
#include "io_internal.h"

#include <stdio.h>
#include <string.h>

/* Copy the file's side of the reader's info. */
static void file_side(const io_reader_info *inf, sample_io_file_info *info)
{
    int c;
    snprintf(info->format, sizeof info->format, "%s", inf->format);
    snprintf(info->pixel_type, sizeof info->pixel_type, "%s", inf->pixel_type);
    snprintf(info->compression, sizeof info->compression, "%s", inf->compression);
    snprintf(info->wrapmodes, sizeof info->wrapmodes, "%s", inf->wrapmodes);
    snprintf(info->colorspace, sizeof info->colorspace, "%s", inf->colorspace);
    for (c = 0; c < SAMPLE_IO_NAMED_CHANNELS; ++c)
        snprintf(info->channel_names[c], sizeof info->channel_names[c], "%s", inf->channel_names[c]);
    info->width = inf->width;
    info->height = inf->height;
    info->channels = inf->channels;
    info->alpha_channel = inf->alpha_channel;
    info->straight_alpha = inf->straight_alpha;
    info->levels = inf->nlevels;
    info->tile_width = inf->tile_w;
    info->tile_height = inf->tile_h;
}

/* The texture's side: the plan, and how many of the file's levels follow
 * libsample's level rule (the prefix sample_io_read_texture keeps). */
static sample_status texture_side(const io_reader_info *inf, const sample_io_options *o,
                                  sample_io_file_info *info, sample_error *err)
{
    io_colour *col = NULL;
    io_plan p;
    int k;
    sample_status st = io_colour_open(o->ocio_config, &col, err);
    if (st == SAMPLE_OK) st = io_read_plan(col, inf, o, &p, err);
    if (st == SAMPLE_OK) {
        snprintf(info->colorspace_used, sizeof info->colorspace_used, "%s", p.colorspace);
        info->colorspace_from_rule = !o->colorspace && !(inf->colorspace[0] && io_colour_known(col, inf->colorspace));
        info->texture_format = p.format;
        info->texture_channels = p.nchan;
        info->texture_file_levels = 1;
        for (k = 1; o->use_file_levels && k < info->levels; ++k) {
            int w = inf->width >> k > 0 ? inf->width >> k : 1, h = inf->height >> k > 0 ? inf->height >> k : 1;
            if (info->level_width[k] != w || info->level_height[k] != h) break;
            info->texture_file_levels = k + 1;
        }
    }
    io_colour_close(col);
    return st;
}

sample_status sample_io_describe(const char *path, const sample_io_options *o, sample_io_file_info *info,
                                 sample_error *err)
{
    sample_io_options defaults;
    io_reader *r = NULL;
    io_reader_info inf;
    sample_status st;
    int k;
    if (!info) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_describe: info is NULL");
    memset(info, 0, sizeof *info);
    if (!o) {
        sample_io_options_init(&defaults);
        o = &defaults;
    }
    if ((st = sample_io_check_regular_file(path, "image", err)) != SAMPLE_OK ||
        (st = io_preflight(path, NULL, 0, err)) != SAMPLE_OK || (st = io_reader_open(path, NULL, 0, NULL, &r, err)) != SAMPLE_OK)
        return st;
    io_reader_info_get(r, &inf);
    file_side(&inf, info);
    for (k = 0; st == SAMPLE_OK && k < info->levels; ++k)
        st = io_reader_level_size(r, k, &info->level_width[k], &info->level_height[k], err);
    io_reader_close(r);
    if (st == SAMPLE_OK && (inf.width <= 0 || inf.height <= 0 || inf.channels <= 0))
        st = sample_error_set(err, SAMPLE_E_CORRUPT, "image claims %d x %d pixels with %d channels", inf.width,
                              inf.height, inf.channels);
    if (st == SAMPLE_OK) st = texture_side(&inf, o, info, err);
    return st;
}
