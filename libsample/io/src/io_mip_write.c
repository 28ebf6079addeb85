/* Mip-mapped files out (doc/io-and-colour.md, "Writing"): the checks every
 * mip-mapped writer shares, the level pixels in the file's type, and the
 * choice of writer by extension. OpenEXR goes through the OpenEXR library
 * (exr_mip.cpp), tiled TIFF through OpenImageIO (oiio_write.cpp); both
 * write a temporary file that io_tmp.c names and renames when complete. */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>

static int full_chain(int w, int h)
{
    int n = 1, m = w > h ? w : h;
    while (m > 1) m >>= 1, ++n;
    return n;
}

sample_status io_level_pixels(const sample_texture *tex, int k, sample_io_type type, const io_colour *col,
                              const char *cs, int half_clamp, size_t *overflows, void **out, sample_error *err)
{
    sample_texture_info inf;
    int w, h, i, j, c;
    size_t n, nc;
    float *buf;
    sample_texture_info_get(tex, &inf);
    sample_texture_level_size(tex, k, &w, &h);
    n = (size_t)w * (size_t)h;
    nc = (size_t)inf.channels;
    *out = NULL;
    if (!(buf = (float *)malloc(n * nc * sizeof(float))))
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate level %d (%d x %d) for writing", k, w, h);
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            float v[4];
            sample_texture_texel(tex, k, i, j, v);
            for (c = 0; c < (int)nc; ++c) buf[((size_t)j * (size_t)w + (size_t)i) * nc + (size_t)c] = v[c];
        }
    if (type == SAMPLE_IO_TYPE_U8 || type == SAMPLE_IO_TYPE_U16) {
        sample_status st = io_colour_apply(col, cs, 0, buf, n, (int)nc, err);
        if (st != SAMPLE_OK) {
            free(buf);
            return st;
        }
    }
    *overflows += io_quantize(buf, n * nc, type, half_clamp);
    *out = buf;
    return SAMPLE_OK;
}

/* What every mip-mapped writer refuses. */
static sample_status check(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                           sample_error *err)
{
    sample_texture_info inf;
    int c;
    if (!path || !*path || !tex)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "writing a mip-mapped file: no path or no texture");
    if (o->tile_w < 1 || o->tile_h < 1 || o->tile_w > 4096 || o->tile_h > 4096)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "tile size %d x %d: each side must be 1 to 4096",
                                o->tile_w, o->tile_h);
    if ((unsigned)o->type >= SAMPLE_IO_TYPE_COUNT)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "unknown pixel type %d", (int)o->type);
    sample_texture_info_get(tex, &inf);
    if (inf.levels > 1 && inf.levels != full_chain(inf.width, inf.height))
        return sample_error_set(err, SAMPLE_E_UNSUPPORTED,
                                "the texture has %d of its %d levels; a mip-mapped file holds all of them", inf.levels,
                                full_chain(inf.width, inf.height));
    if (o->alpha_channel >= inf.channels)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "alpha channel %d of a %d-channel texture",
                                o->alpha_channel, inf.channels);
    for (c = 0; o->channel_names && c < inf.channels; ++c)
        if (!o->channel_names[c] || !*o->channel_names[c])
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "channel %d has no name", c);
    return SAMPLE_OK;
}

sample_status io_mip_target(const char *path, sample_io_type type, int *tiff, sample_error *err)
{
    char ext[16];
    io_extension(path, ext, sizeof ext);
    *tiff = strcmp(ext, "tx") == 0 || strcmp(ext, "tif") == 0 || strcmp(ext, "tiff") == 0;
    if (!*tiff && strcmp(ext, "exr") != 0)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT,
                                "'%s': .%s files hold no mip levels; write .exr, .tx, .tif or .tiff", path, ext);
    if (!*tiff && (type == SAMPLE_IO_TYPE_U8 || type == SAMPLE_IO_TYPE_U16))
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT,
                                "'%s': OpenEXR has no 8- or 16-bit integer type; write .tx or .tif for those", path);
    return SAMPLE_OK;
}

/* The texels are in the config's scene_linear space; U8 and U16 store them
 * sRGB-encoded. The file is labelled with the space it holds
 * (io_colour_label_get: its own name, chromaticities where known). */
static sample_status write_levels(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                                  int tiff, io_env env, size_t *overflows, sample_error *err)
{
    sample_io_type type = o->type != SAMPLE_IO_TYPE_AUTO ? o->type
                          : o->use_float                 ? SAMPLE_IO_TYPE_FLOAT
                                                         : SAMPLE_IO_TYPE_HALF;
    const char *cs = "scene_linear";
    io_colour *col = NULL;
    io_colour_label label;
    io_tmp tmp;
    sample_status st = io_colour_open(o->ocio_config, &col, err);
    if (st != SAMPLE_OK) return st;
    if (type == SAMPLE_IO_TYPE_U8 || type == SAMPLE_IO_TYPE_U16) {
        cs = io_colour_srgb_name(col);
        if (!cs) st = sample_error_set(err, SAMPLE_E_COLOR, "the OCIO config has no sRGB colour space for 8/16-bit output");
    }
    if (st == SAMPLE_OK) io_colour_label_get(col, cs, &label);
    if (st == SAMPLE_OK && (st = io_tmp_create(path, &tmp, err)) == SAMPLE_OK) {
        st = tiff ? io_oiio_write_mip(path, tmp.write_path, tex, o, type, col, cs, &label, overflows, err)
                  : io_exr_write_mip(tmp.write_path, tex, o, &label, env, overflows, err);
        st = io_tmp_finish(st, &tmp, path, err);
    }
    io_colour_close(col);
    return st;
}

static sample_status write_mip(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                               int any_format, io_env env, sample_error *err)
{
    sample_io_exr_options defaults;
    size_t overflows = 0;
    sample_status st;
    int tiff = 0;
    if (!o) {
        sample_io_exr_options_init(&defaults);
        o = &defaults;
    }
    if ((st = check(path, tex, o, err)) != SAMPLE_OK) return st;
    if (!any_format) {
        if (o->type == SAMPLE_IO_TYPE_U8 || o->type == SAMPLE_IO_TYPE_U16)
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "OpenEXR has no 8- or 16-bit integer type");
    } else if ((st = io_mip_target(path, o->type, &tiff, err)) != SAMPLE_OK) {
        return st;
    }
    st = write_levels(path, tex, o, tiff, env, &overflows, err);
    if (o->half_overflows) *o->half_overflows = overflows;
    return st;
}

sample_status sample_io_write_mip_exr(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                                      sample_error *err)
{
    return write_mip(path, tex, o, 0, IO_ENV_NONE, err);
}

sample_status io_write_mip_env(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                               io_env env, sample_error *err)
{
    return write_mip(path, tex, o, 0, env, err);
}

sample_status sample_io_write_mip(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                                  sample_error *err)
{
    return write_mip(path, tex, o, 1, IO_ENV_NONE, err);
}
