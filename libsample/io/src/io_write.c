/* Pictures out: colour conversion from the working space, quantization and
 * the temporary-file-then-rename protocol (doc/io-and-colour.md, "Writing"). */
#include "io_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static sample_status check_size(const char *path, int w, int h, sample_error *err)
{
    if (!path || !*path) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "no output path");
    if (w > SAMPLE_MAX_SIZE || h > SAMPLE_MAX_SIZE)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "%d x %d image: the largest side is %d", w, h, SAMPLE_MAX_SIZE);
    if (w <= 0 || h <= 0) return sample_error_set(err, SAMPLE_E_BAD_SIZE, "cannot write a %d x %d image", w, h);
    return SAMPLE_OK;
}

static sample_io_type auto_type(const char *path)
{
    char ext[16];
    io_extension(path, ext, sizeof ext);
    if (strcmp(ext, "exr") == 0) return SAMPLE_IO_TYPE_HALF;
    if (strcmp(ext, "hdr") == 0) return SAMPLE_IO_TYPE_FLOAT;
    return SAMPLE_IO_TYPE_U8;
}

/* Clamp to [0, 1], round to nearest; NaN → 0 (a comparison with NaN is
 * false, so the first test sends it to 0). */
static double unorm(float v, double maxcode)
{
    double x = v > 0.0f ? (v < 1.0f ? (double)v : 1.0) : 0.0;
    return floor(x * maxcode + 0.5);
}

size_t io_quantize(float *buf, size_t n, sample_io_type type, int half_clamp)
{
    unsigned char *b = (unsigned char *)buf;
    size_t i, overflows = 0;
    for (i = 0; i < n; ++i) {
        float f;
        memcpy(&f, b + 4 * i, 4);
        if (type == SAMPLE_IO_TYPE_U8) {
            b[i] = (unsigned char)unorm(f, 255.0);
        } else if (type == SAMPLE_IO_TYPE_U16) {
            uint16_t v = (uint16_t)unorm(f, 65535.0);
            memcpy(b + 2 * i, &v, 2);
        } else if (type == SAMPLE_IO_TYPE_HALF) {
            uint16_t v = sample_float_to_half(f);
            /* Rounded to ±inf from a finite value: beyond half's largest,
             * 65504 (IEEE 754 binary16). */
            if ((v & 0x7fffu) == 0x7c00u && isfinite(f)) {
                ++overflows;
                if (half_clamp) v = (uint16_t)((v & 0x8000u) | 0x7bffu);
            }
            memcpy(b + 2 * i, &v, 2);
        }
    }
    return overflows;
}

sample_status sample_io_write_image_ex(const char *path, const float *rgba, int w, int h, int channels_to_write,
                                       const sample_io_write_options *o, sample_error *err)
{
    sample_io_write_options defaults;
    sample_io_type type;
    const char *cs;
    io_colour *col = NULL;
    io_colour_label label;
    float *buf = NULL;
    size_t n, i;
    io_tmp tmp;
    sample_status st = check_size(path, w, h, err);
    int c;
    if (st != SAMPLE_OK) return st;
    if (!rgba) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "no pixels to write to '%s'", path);
    if (channels_to_write != 3 && channels_to_write != 4)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "channels_to_write is %d; it must be 3 or 4", channels_to_write);
    if (!o) {
        sample_io_write_options_init(&defaults);
        o = &defaults;
    }
    if ((unsigned)o->type >= SAMPLE_IO_TYPE_COUNT)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "unknown pixel type %d", (int)o->type);
    type = o->type == SAMPLE_IO_TYPE_AUTO ? auto_type(path) : o->type;
    st = io_colour_open(o->ocio_config, &col, err);
    if (st != SAMPLE_OK) return st;
    cs = o->colorspace;
    if (!cs && (type == SAMPLE_IO_TYPE_HALF || type == SAMPLE_IO_TYPE_FLOAT)) cs = "scene_linear";
    if (!cs) cs = io_colour_srgb_name(col);
    st = cs ? io_colour_require(col, cs, err)
            : sample_error_set(err, SAMPLE_E_COLOR, "the OCIO config has no sRGB colour space for 8/16-bit files");
    if (st != SAMPLE_OK) goto done;
    io_colour_label_get(col, cs, &label);
    n = (size_t)w * (size_t)h;
    if (!(buf = malloc(n * (size_t)channels_to_write * sizeof(float)))) {
        st = sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a %d x %d image", w, h);
        goto done;
    }
    for (i = 0; i < n; ++i)
        for (c = 0; c < channels_to_write; ++c) buf[i * (size_t)channels_to_write + (size_t)c] = rgba[4 * i + (size_t)c];
    st = io_colour_apply(col, cs, 0, buf, n, channels_to_write, err);
    if (st != SAMPLE_OK) goto done;
    io_quantize(buf, n * (size_t)channels_to_write, type, 0);
    st = io_tmp_create(path, &tmp, err);
    if (st != SAMPLE_OK) goto done;
    /* sample_io_type U8 … FLOAT are io_ptype IO_U8 … IO_FLOAT plus one. */
    st = io_oiio_write(path, tmp.write_path, buf, (io_ptype)(type - 1), w, h, channels_to_write, NULL, &label, err);
    st = io_tmp_finish(st, &tmp, path, err);
done:
    free(buf);
    io_colour_close(col);
    return st;
}

sample_status sample_io_write_image(const char *path, const float *rgba, int w, int h, int channels_to_write,
                                    const char *colorspace, sample_error *err)
{
    sample_io_write_options o;
    sample_io_write_options_init(&o);
    o.colorspace = colorspace;
    return sample_io_write_image_ex(path, rgba, w, h, channels_to_write, &o, err);
}

sample_status sample_io_write_channels(const char *path, const float *data, int w, int h, int nchannels,
                                       const char *const *names, sample_error *err)
{
    io_tmp tmp;
    int a, b;
    sample_status st = check_size(path, w, h, err);
    if (st != SAMPLE_OK) return st;
    if (!data || !names) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "no pixels or no channel names for '%s'", path);
    if (nchannels < 1 || nchannels > 1024)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "%d channels: from 1 to 1024 can be written", nchannels);
    /* OpenEXR channel names must be unique and non-empty (OpenEXR file
     * layout, "Channel list"). */
    for (a = 0; a < nchannels; ++a) {
        if (!names[a] || !*names[a]) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "channel %d has no name", a);
        for (b = 0; b < a; ++b)
            if (strcmp(names[a], names[b]) == 0)
                return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "channel name '%s' is used twice", names[a]);
    }
    st = io_tmp_create(path, &tmp, err);
    if (st != SAMPLE_OK) return st;
    st = io_oiio_write(path, tmp.write_path, data, IO_FLOAT, w, h, nchannels, names, NULL, err);
    return io_tmp_finish(st, &tmp, path, err);
}
