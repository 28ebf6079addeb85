/* Image file → libsample texture: storage format, colour, levels
 * (doc/io-and-colour.md, "Reading"). */
#include "io_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Where the levels come from: the direct OpenEXR reader (tiled mip-mapped
 * EXR, exr_read.cpp) when exr is set, else OpenImageIO. Both have the same
 * interface, so the plan, the budget and the level loop are shared. */
typedef struct io_source {
    io_exr_tiled *exr;
    io_reader *oiio;
} io_source;

static void src_info(const io_source *s, io_reader_info *inf)
{
    if (s->exr) io_exr_tiled_info_get(s->exr, inf);
    else io_reader_info_get(s->oiio, inf);
}

static sample_status src_level_size(io_source *s, int k, int *w, int *h, sample_error *err)
{
    return s->exr ? io_exr_tiled_level_size(s->exr, k, w, h, err) : io_reader_level_size(s->oiio, k, w, h, err);
}

static sample_status src_read(io_source *s, int k, io_ptype type, int nchan, void *dst, sample_error *err)
{
    return s->exr ? io_exr_tiled_read(s->exr, k, type, nchan, dst, err)
                  : io_reader_read(s->oiio, k, type, nchan, dst, err);
}

/* Names of sRGB spaces in common configs, tried in order where "sRGB" is
 * meant (our shipped config has the first; ACES configs have the others). */
static const char *const srgb_names[] = {"srgb", "sRGB", "srgb_texture", "sRGB - Texture",
                                         "Utility - sRGB - Texture"};

const char *io_colour_srgb_name(const io_colour *col)
{
    size_t k;
    for (k = 0; k < sizeof srgb_names / sizeof srgb_names[0]; ++k)
        if (io_colour_known(col, srgb_names[k])) return srgb_names[k];
    return NULL;
}

/* OpenImageIO's own names for what the rule below assumes anyway: "sRGB"
 * for 8- and 16-bit PNG, JPEG and TIFF, "Linear" (OpenEXR, whether or not
 * the file names a space) or "linear" (Radiance HDR) for half and float.
 * A config that spells these spaces otherwise (ACES: "sRGB - Texture")
 * decodes them the same, so they are not reported as unknown. */
static int oiio_generic_name(const char *name, io_ptype native)
{
    if (native == IO_HALF || native == IO_FLOAT) return strcmp(name, "Linear") == 0 || strcmp(name, "linear") == 0;
    return strcmp(name, "sRGB") == 0;
}

/* The source colour space into p->colorspace; p->colorspace_from_rule and
 * p->colorspace_unknown say how it was found. */
static sample_status choose_colorspace(const io_colour *col, const sample_io_options *o,
                                       const io_reader_info *inf, io_plan *p, sample_error *err)
{
    if (o->colorspace) {
        p->colorspace = o->colorspace;
        return io_colour_require(col, o->colorspace, err);
    }
    /* Metadata the config does not know (OIIO writes names like
     * "GammaCorrected1.8") falls through to the rule rather than failing:
     * files carry all sorts of names. The caller is told (file_info), so
     * that a program can say which name was not known and what was used. */
    if (inf->colorspace[0]) {
        if (io_colour_known(col, inf->colorspace)) {
            p->colorspace = inf->colorspace;
            return SAMPLE_OK;
        }
        p->colorspace_unknown = !oiio_generic_name(inf->colorspace, inf->native);
    }
    p->colorspace_from_rule = 1;
    if (inf->native == IO_HALF || inf->native == IO_FLOAT) {
        p->colorspace = "scene_linear";
        return SAMPLE_OK;
    }
    if ((p->colorspace = io_colour_srgb_name(col)) != NULL) return SAMPLE_OK;
    return sample_error_set(err, SAMPLE_E_COLOR, "the OCIO config has no sRGB colour space for 8/16-bit data; "
                                        "name the file's colour space explicitly");
}

/* Storage rule (doc/io-and-colour.md): keep the file's precision, unless
 * the options ask for float or for premultiplication (which needs the
 * colour linear and in half or float). */
static void plan_storage(const io_colour *col, const io_reader_info *inf, const sample_io_options *o, io_plan *p)
{
    int linear = io_colour_is_linear(col, p->colorspace);
    p->alpha = inf->alpha_channel >= 0 && inf->alpha_channel < p->nchan ? inf->alpha_channel : -1;
    p->premultiply = o->premultiply && inf->straight_alpha && p->alpha >= 0;
    if (o->float_storage) {
        p->read_as = IO_FLOAT, p->format = SAMPLE_FORMAT_F32, p->convert = !linear;
        return;
    }
    switch (inf->native) {
    case IO_U8:
        if (linear && !p->premultiply) {
            p->read_as = IO_U8, p->format = SAMPLE_FORMAT_UNORM8, p->convert = 0;
        } else if (p->nchan != 2 && !p->premultiply && io_colour_is_srgb(col, p->colorspace)) {
            /* The core decodes SRGB8 exactly; its channel 1 of a 2-channel
             * texture would be decoded as colour, but here it is alpha. */
            p->read_as = IO_U8, p->format = SAMPLE_FORMAT_SRGB8, p->convert = 0;
        } else {
            /* Half keeps 8-bit codes of any curve to better than 1/2048. */
            p->read_as = IO_FLOAT, p->format = SAMPLE_FORMAT_F16, p->convert = !linear;
        }
        break;
    case IO_HALF:
        p->read_as = linear && !p->premultiply ? IO_HALF : IO_FLOAT;
        p->format = SAMPLE_FORMAT_F16;
        p->convert = !linear;
        break;
    default:
        /* 16-bit integers become float: half's 11-bit significand would
         * lose 5 of their 16 bits. */
        p->read_as = IO_FLOAT, p->format = SAMPLE_FORMAT_F32, p->convert = !linear;
        break;
    }
}

sample_status io_read_plan(const io_colour *col, const io_reader_info *inf, const sample_io_options *o, io_plan *p,
                           sample_error *err)
{
    sample_status st;
    memset(p, 0, sizeof *p);
    p->nchan = inf->channels < 4 ? inf->channels : 4;
    st = choose_colorspace(col, o, inf, p, err);
    if (st == SAMPLE_OK) plan_storage(col, inf, o, p);
    return st;
}

/* Level k's size under libsample's rule. */
static void rule_size(int w, int h, int k, int *lw, int *lh)
{
    *lw = (w >> k) > 0 ? w >> k : 1;
    *lh = (h >> k) > 0 ? h >> k : 1;
}

/* Levels libsample builds from a w × h base with `mip` (1: none). */
static int built_levels(int w, int h, const sample_mip_params *mip)
{
    int n = 1, m = w > h ? w : h;
    if (!mip || mip->filter == SAMPLE_MIPGEN_NONE) return 1;
    while (m > 1) m >>= 1, ++n;
    return mip->max_levels > 0 && mip->max_levels < n ? mip->max_levels : n;
}

/* How many of the file's levels follow libsample's ROUND_DOWN chain (a file
 * written with ROUND_UP sizes matches only at level 0; then the pyramid is
 * rebuilt). Also enforces the byte budget: every level the texture will
 * hold, read from the file or built from its base (`build` levels in all),
 * counted as float. */
static sample_status count_levels(io_source *r, const io_reader_info *inf, const io_plan *p, int wanted, int build,
                                  size_t max_bytes, int *count, sample_error *err)
{
    size_t total = 0;
    int k;
    *count = 0;
    for (k = 0; k < wanted; ++k) {
        int w, h, rw, rh;
        sample_status st = src_level_size(r, k, &w, &h, err);
        if (st != SAMPLE_OK) return st;
        rule_size(inf->width, inf->height, k, &rw, &rh);
        if (w != rw || h != rh) break;
        total += (size_t)w * (size_t)h * (size_t)p->nchan * sizeof(float);
        if (total > max_bytes) break;
        *count = k + 1;
        if (w == 1 && h == 1) break;
    }
    for (k = *count; *count == 1 && k < build; ++k) {
        int w, h;
        rule_size(inf->width, inf->height, k, &w, &h);
        total += (size_t)w * (size_t)h * (size_t)p->nchan * sizeof(float);
    }
    if (total > max_bytes)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE,
                                "%d x %d x %d image: its levels need more than the %zu-byte limit (max_bytes)",
                                inf->width, inf->height, p->nchan, max_bytes);
    return SAMPLE_OK;
}

/* Colour times alpha, on linear values (OpenEXR's premultiplied colour,
 * "Technical Introduction to OpenEXR", Premultiplied vs. Un-Premultiplied
 * Color Channels). */
static void premultiply(float *px, size_t n, int nchan, int alpha)
{
    size_t i;
    int c;
    for (i = 0; i < n; ++i, px += nchan)
        for (c = 0; c < nchan; ++c)
            if (c != alpha) px[c] *= px[alpha];
}

sample_status io_plan_apply(const io_colour *col, const io_plan *p, void *buf, size_t n, sample_error *err)
{
    unsigned char *b = (unsigned char *)buf;
    size_t values = n * (size_t)p->nchan, i;
    sample_status st = SAMPLE_OK;
    if (p->convert) st = io_colour_apply(col, p->colorspace, 1, (float *)buf, n, p->nchan, err);
    if (st == SAMPLE_OK && p->premultiply) premultiply((float *)buf, n, p->nchan, p->alpha);
    if (st == SAMPLE_OK && p->read_as == IO_FLOAT && p->format == SAMPLE_FORMAT_F16) {
        /* Narrow in place: half i (bytes 2i, 2i+1) never overwrites a float
         * not yet read (bytes 4j.. for j ≥ i). */
        for (i = 0; i < values; ++i) {
            float f;
            uint16_t hv;
            memcpy(&f, b + 4 * i, 4);
            hv = sample_float_to_half(f);
            memcpy(b + 2 * i, &hv, 2);
        }
    }
    return st;
}

/* Read level k into a fresh buffer in the texture's storage format. */
static sample_status read_level(io_source *r, const io_colour *col, const io_plan *p, int k, int w, int h,
                                void **out, sample_error *err)
{
    size_t n = (size_t)w * (size_t)h, values = n * (size_t)p->nchan;
    size_t bytes = values * (p->read_as == IO_U8 ? 1 : p->read_as == IO_HALF ? 2 : 4);
    unsigned char *buf = malloc(bytes ? bytes : 1);
    sample_status st;
    *out = NULL;
    if (!buf) return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate %zu bytes for level %d", bytes, k);
    st = src_read(r, k, p->read_as, p->nchan, buf, err);
    if (st == SAMPLE_OK) st = io_plan_apply(col, p, buf, n, err);
    if (st != SAMPLE_OK) {
        free(buf);
        return st;
    }
    *out = buf;
    return SAMPLE_OK;
}

/* What the file says and what the plan made of it (sample_io.h). */
static sample_status file_info(io_source *r, const io_reader_info *inf, const io_plan *p, sample_io_file_info *info,
                               sample_error *err)
{
    int k;
    sample_status st = SAMPLE_OK;
    io_file_info_fill(inf, p, info);
    for (k = 0; st == SAMPLE_OK && k < info->levels && k < SAMPLE_MAX_LEVELS; ++k)
        st = src_level_size(r, k, &info->level_width[k], &info->level_height[k], err);
    return st;
}

/* *fallback is set (and nothing read) when the direct reader was given a
 * file whose colour space needs an OCIO conversion: OIIO's path does that. */
static sample_status read_texture(io_source *r, const io_colour *shared, const sample_io_options *o,
                                  const sample_mip_params *mip, sample_texture **out, int *fallback,
                                  sample_error *err)
{
    sample_io_options defaults;
    io_reader_info inf;
    io_colour *col = NULL;
    io_plan p;
    sample_image lv[SAMPLE_MAX_LEVELS];
    void *data[SAMPLE_MAX_LEVELS] = {0};
    sample_mip_params file_mip;
    sample_wrap ws = SAMPLE_WRAP_REPEAT, wt = SAMPLE_WRAP_REPEAT;
    int count = 0, k, has_wrap;
    sample_status st;
    if (!o) {
        sample_io_options_init(&defaults);
        o = &defaults;
    }
    *fallback = 0;
    src_info(r, &inf);
    if (inf.width > SAMPLE_MAX_SIZE || inf.height > SAMPLE_MAX_SIZE)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "image is %d x %d; the largest texture side is %d", inf.width,
                       inf.height, SAMPLE_MAX_SIZE);
    if (inf.width <= 0 || inf.height <= 0 || inf.channels <= 0)
        return sample_error_set(err, SAMPLE_E_CORRUPT, "image claims %d x %d pixels with %d channels", inf.width,
                       inf.height, inf.channels);
    has_wrap = inf.wrapmodes[0] && io_wrapmodes_parse(inf.wrapmodes, &ws, &wt);
    st = shared ? SAMPLE_OK : io_colour_open(o->ocio_config, &col, err);
    if (shared) col = (io_colour *)(uintptr_t)shared;
    if (st == SAMPLE_OK) st = io_read_plan(col, &inf, o, &p, err);
    if (st == SAMPLE_OK && o->file_info) st = file_info(r, &inf, &p, o->file_info, err);
    if (has_wrap && o->mip_wrap_from_file && mip) {
        file_mip = *mip;
        file_mip.wrap_s = ws;
        file_mip.wrap_t = wt;
        mip = &file_mip;
    }
    /* The direct reader reads the file's type as it is: conversions go
     * through OpenImageIO's path. */
    if (st == SAMPLE_OK && r->exr && (p.convert || p.read_as != inf.native)) {
        *fallback = 1;
        if (!shared) io_colour_close(col);
        return SAMPLE_OK;
    }
    if (st == SAMPLE_OK) {
        st = count_levels(r, &inf, &p, o->use_file_levels ? inf.nlevels : 1, built_levels(inf.width, inf.height, mip),
                          o->max_bytes ? o->max_bytes : SAMPLE_IO_DEFAULT_MAX_BYTES, &count, err);
        if (st == SAMPLE_OK && o->file_info) o->file_info->texture_file_levels = count;
    }
    memset(lv, 0, sizeof lv);
    for (k = 0; st == SAMPLE_OK && k < count; ++k) {
        rule_size(inf.width, inf.height, k, &lv[k].width, &lv[k].height);
        lv[k].channels = p.nchan;
        lv[k].format = p.format;
        st = read_level(r, col, &p, k, lv[k].width, lv[k].height, &data[k], err);
        lv[k].data = data[k];
    }
    if (st == SAMPLE_OK)
        st = count > 1 ? sample_texture_create_levels(lv, count, out, err) : sample_texture_create(&lv[0], mip, out, err);
    for (k = 0; k < SAMPLE_MAX_LEVELS; ++k) free(data[k]);
    if (!shared) io_colour_close(col);
    return st;
}

/* Direct OpenEXR first (tiled mip-mapped files), else OpenImageIO. */
static sample_status read_source(const char *path, const void *data, size_t size, const char *hint,
                                 const io_colour *col, const sample_io_options *o, const sample_mip_params *mip, sample_texture **out,
                                 sample_error *err)
{
    io_source s = {NULL, NULL};
    int fallback = 0;
    sample_status st = io_exr_tiled_open(path, data, size, &s.exr, err);
    if (st != SAMPLE_OK) return st;
    if (s.exr) {
        st = read_texture(&s, col, o, mip, out, &fallback, err);
        io_exr_tiled_close(s.exr);
        s.exr = NULL;
        if (st != SAMPLE_OK || !fallback) {
            if (st == SAMPLE_OK) io_exr_direct_count();
            return st;
        }
    }
    st = io_reader_open(path, data, size, hint, &s.oiio, err);
    if (st != SAMPLE_OK) return st;
    st = read_texture(&s, col, o, mip, out, &fallback, err);
    io_reader_close(s.oiio);
    return st;
}

/* The header pre-flights (exr_guard.c, jpeg_guard.c, tiff_guard.c,
 * tga_guard.c), each a no-op on other formats, on a file (path) or bytes. */
sample_status io_preflight(const char *path, const void *data, size_t size, sample_error *err)
{
    static sample_status (*const on_file[])(const char *, sample_error *) = {
        io_exr_guard_file, io_jpeg_guard_file, io_tiff_guard_file, io_tga_guard_file};
    static sample_status (*const on_memory[])(const void *, size_t, sample_error *) = {
        io_exr_guard_memory, io_jpeg_guard_memory, io_tiff_guard_memory, io_tga_guard_memory};
    size_t k;
    for (k = 0; k < sizeof on_file / sizeof on_file[0]; ++k) {
        sample_status st = path ? on_file[k](path, err) : on_memory[k](data, size, err);
        if (st != SAMPLE_OK) return st;
    }
    return SAMPLE_OK;
}

sample_status sample_io_read_texture(const char *path, const sample_io_options *o, const sample_mip_params *mip,
                                     sample_texture **out, sample_error *err)
{
    sample_status st;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_texture: out is NULL");
    *out = NULL;
    if (!path || !*path) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_texture: no path");
    if ((st = sample_io_check_regular_file(path, "image", err)) != SAMPLE_OK) return st;
    if ((st = io_preflight(path, NULL, 0, err)) != SAMPLE_OK) return st;
    return read_source(path, NULL, 0, NULL, NULL, o, mip, out, err);
}

sample_status sample_io_read_memory(const void *data, size_t size, const char *format_hint,
                                    const sample_io_options *o, const sample_mip_params *mip,
                                    sample_texture **out, sample_error *err)
{
    sample_status st;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_memory: out is NULL");
    *out = NULL;
    if (!data && size) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_memory: data is NULL");
    if (size == 0) return sample_error_set(err, SAMPLE_E_CORRUPT, "sample_io_read_memory: the file is empty");
    if ((st = io_preflight(NULL, data, size, err)) != SAMPLE_OK) return st;
    return read_source(NULL, data, size, format_hint, NULL, o, mip, out, err);
}

sample_status io_read_texture_col(const char *path, const io_colour *col, const sample_io_options *o,
                                  const sample_mip_params *mip, sample_texture **out, sample_error *err)
{
    sample_status st;
    *out = NULL;
    if ((st = sample_io_check_regular_file(path, "image", err)) != SAMPLE_OK) return st;
    if ((st = io_preflight(path, NULL, 0, err)) != SAMPLE_OK) return st;
    return read_source(path, NULL, 0, NULL, col, o, mip, out, err);
}
