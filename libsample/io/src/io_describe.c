/* What an image file holds, from its headers (doc/io-and-colour.md,
 * "Describing"): the memory used is that of the headers, never the pixels,
 * so `texsample info` on a file claiming 65536 × 65536 costs what its
 * header costs. The reader's own plan (io_read_plan) says what a texture
 * read from it would be. */
#include "io_internal.h"

#include <stdio.h>
#include <string.h>

void io_file_info_fill(const io_reader_info *inf, const io_plan *p, sample_io_file_info *info)
{
    int c;
    memset(info, 0, sizeof *info);
    snprintf(info->format, sizeof info->format, "%s", inf->format);
    snprintf(info->pixel_type, sizeof info->pixel_type, "%s", inf->pixel_type);
    snprintf(info->compression, sizeof info->compression, "%s", inf->compression);
    snprintf(info->wrapmodes, sizeof info->wrapmodes, "%s", inf->wrapmodes);
    snprintf(info->textureformat, sizeof info->textureformat, "%s", inf->textureformat);
    info->has_wrap = inf->wrapmodes[0] && io_wrapmodes_parse(inf->wrapmodes, &info->wrap_s, &info->wrap_t);
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
    snprintf(info->colorspace_used, sizeof info->colorspace_used, "%s", p->colorspace);
    info->colorspace_from_rule = p->colorspace_from_rule;
    info->colorspace_unknown = p->colorspace_unknown;
    info->texture_format = p->format;
    info->texture_channels = p->nchan;
    info->texture_file_levels = 1;
}

/* How many of the file's levels follow libsample's level rule: the prefix
 * sample_io_read_texture keeps. */
static int file_levels_kept(const sample_io_file_info *info, const sample_io_options *o)
{
    int k, kept = 1;
    for (k = 1; o->use_file_levels && k < info->levels; ++k) {
        int w = info->width >> k > 0 ? info->width >> k : 1, h = info->height >> k > 0 ? info->height >> k : 1;
        if (info->level_width[k] != w || info->level_height[k] != h) break;
        kept = k + 1;
    }
    return kept;
}

sample_status sample_io_describe(const char *path, const sample_io_options *o, sample_io_file_info *info,
                                 sample_error *err)
{
    sample_io_options defaults;
    io_reader *r = NULL;
    io_reader_info inf;
    io_colour *col = NULL;
    io_plan p;
    int level_w[SAMPLE_MAX_LEVELS] = {0}, level_h[SAMPLE_MAX_LEVELS] = {0}, k;
    sample_status st;
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
    for (k = 0; st == SAMPLE_OK && k < inf.nlevels && k < SAMPLE_MAX_LEVELS; ++k)
        st = io_reader_level_size(r, k, &level_w[k], &level_h[k], err);
    io_reader_close(r);
    if (st == SAMPLE_OK && (inf.width <= 0 || inf.height <= 0 || inf.channels <= 0))
        st = sample_error_set(err, SAMPLE_E_CORRUPT, "image claims %d x %d pixels with %d channels", inf.width,
                              inf.height, inf.channels);
    if (st == SAMPLE_OK) st = io_colour_open(o->ocio_config, &col, err);
    if (st == SAMPLE_OK) st = io_read_plan(col, &inf, o, &p, err);
    io_colour_close(col);
    if (st != SAMPLE_OK) return st;
    io_file_info_fill(&inf, &p, info);
    memcpy(info->level_width, level_w, sizeof level_w);
    memcpy(info->level_height, level_h, sizeof level_h);
    info->texture_file_levels = file_levels_kept(info, o);
    return st;
}
