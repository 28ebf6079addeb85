/* An image file in, a mip-mapped file out, losing nothing on the way
 * (doc/io-and-colour.md, "texsample mip"): what maketx does, and what
 * `texsample mip` calls. */
#include "io_internal.h"

#include <string.h>

sample_status sample_io_make_mip(const char *in, const char *out, const sample_io_options *ro,
                                 const sample_mip_params *mip, const sample_io_exr_options *wo, sample_error *err)
{
    sample_io_options r;
    sample_io_exr_options w;
    sample_mip_params m;
    sample_io_file_info fi;
    const char *names[4];
    sample_texture *tex = NULL;
    sample_status st;
    int c, tiff;
    if (!in || !*in || !out || !*out)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_make_mip: no input or no output path");
    if (ro) r = *ro;
    else sample_io_options_init(&r);
    if (wo) w = *wo;
    else sample_io_exr_options_init(&w);
    if (mip) m = *mip;
    else sample_mip_params_init(&m);
    /* The output's name says its format; one that holds no levels is
     * refused before the input is read. */
    if ((st = io_mip_target(out, w.type, &tiff, err)) != SAMPLE_OK) return st;
    if (m.filter == SAMPLE_MIPGEN_NONE) m.filter = SAMPLE_MIPGEN_BOX;
    m.max_levels = 0;
    /* Every level from the base, in float, on premultiplied colour: a
     * level is never built from a re-quantised level above, and a
     * transparent texel's colour weighs nothing. */
    r.use_file_levels = 0;
    r.float_storage = 1;
    r.premultiply = 1;
    if ((st = sample_io_describe(in, &r, &fi, err)) != SAMPLE_OK) return st;
    /* Channels keep their names and count: more than a texture holds is
     * refused, not cut. */
    if (fi.channels > 4)
        return sample_error_set(err, SAMPLE_E_UNSUPPORTED,
                                "'%s' has %d channels (%s, %s, %s, %s, %s%s); a texture holds at most 4", in,
                                fi.channels, fi.channel_names[0], fi.channel_names[1], fi.channel_names[2],
                                fi.channel_names[3], fi.channel_names[4], fi.channels > 5 ? ", ..." : "");
    for (c = 0; c < fi.channels; ++c) names[c] = fi.channel_names[c][0] ? fi.channel_names[c] : "?";
    w.channel_names = names;
    w.alpha_channel = fi.alpha_channel;
    w.premultiplied = fi.alpha_channel >= 0; /* straight alpha is multiplied in on reading */
    w.wrap_s = m.wrap_s;
    w.wrap_t = m.wrap_t;
    if (!w.ocio_config) w.ocio_config = r.ocio_config;
    if ((st = sample_io_read_texture(in, &r, &m, &tex, err)) != SAMPLE_OK) return st;
    st = sample_io_write_mip(out, tex, &w, err);
    sample_texture_destroy(tex);
    return st;
}
