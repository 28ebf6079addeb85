/* Enum names as the command line spells them, and status strings. */
#include "base.h"

#include <stdarg.h>
#include <stdio.h>

#define COUNT_OF(a) (sizeof(a) / sizeof((a)[0]))

static const char *const status_names[] = {
    [SAMPLE_OK] = "success",
    [SAMPLE_E_INVALID_ARGUMENT] = "invalid argument",
    [SAMPLE_E_BAD_SIZE] = "bad size",
    [SAMPLE_E_TOO_LARGE] = "too large",
    [SAMPLE_E_OUT_OF_MEMORY] = "out of memory",
    [SAMPLE_E_UNSUPPORTED] = "unsupported",
    [SAMPLE_E_IO] = "input/output error",
    [SAMPLE_E_CORRUPT] = "corrupt or malformed data",
    [SAMPLE_E_COLOR] = "colour conversion failed",
};
_Static_assert(COUNT_OF(status_names) == SAMPLE_STATUS_COUNT, "status_names");

static const char *const wrap_names[] = {
    [SAMPLE_WRAP_REPEAT] = "repeat",
    [SAMPLE_WRAP_MIRRORED_REPEAT] = "mirrored_repeat",
    [SAMPLE_WRAP_CLAMP_TO_EDGE] = "clamp_to_edge",
    [SAMPLE_WRAP_CLAMP_TO_BORDER] = "clamp_to_border",
    [SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE] = "mirror_clamp_to_edge",
    [SAMPLE_WRAP_CLAMP] = "clamp",
    [SAMPLE_WRAP_MIRROR_CLAMP] = "mirror_clamp",
    [SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER] = "mirror_clamp_to_border",
};
_Static_assert(COUNT_OF(wrap_names) == SAMPLE_WRAP_COUNT, "wrap_names");

static const char *const filter_names[] = {
    [SAMPLE_NEAREST] = "nearest",
    [SAMPLE_LINEAR] = "linear",
    [SAMPLE_NEAREST_MIPMAP_NEAREST] = "nearest_mipmap_nearest",
    [SAMPLE_LINEAR_MIPMAP_NEAREST] = "linear_mipmap_nearest",
    [SAMPLE_NEAREST_MIPMAP_LINEAR] = "nearest_mipmap_linear",
    [SAMPLE_LINEAR_MIPMAP_LINEAR] = "linear_mipmap_linear",
    [SAMPLE_CUBIC] = "cubic",
    [SAMPLE_CUBIC_MIPMAP_NEAREST] = "cubic_mipmap_nearest",
    [SAMPLE_CUBIC_MIPMAP_LINEAR] = "cubic_mipmap_linear",
};
_Static_assert(COUNT_OF(filter_names) == SAMPLE_FILTER_COUNT, "filter_names");

static const char *const cubic_names[] = {
    [SAMPLE_CUBIC_CATMULL_ROM] = "catmull-rom",
    [SAMPLE_CUBIC_BSPLINE] = "bspline",
    [SAMPLE_CUBIC_MITCHELL] = "mitchell",
};
_Static_assert(COUNT_OF(cubic_names) == SAMPLE_CUBIC_COUNT, "cubic_names");

static const char *const footprint_names[] = {
    [SAMPLE_FOOTPRINT_NONE] = "none",
    [SAMPLE_FOOTPRINT_ANISOTROPIC] = "aniso",
    [SAMPLE_FOOTPRINT_BLINN_NEWELL] = "blinn-newell",
    [SAMPLE_FOOTPRINT_EWA] = "ewa",
    [SAMPLE_FOOTPRINT_FELINE] = "feline",
};
_Static_assert(COUNT_OF(footprint_names) == SAMPLE_FOOTPRINT_COUNT, "footprint_names");

static const char *const ewa_kernel_names[] = {
    [SAMPLE_EWA_GAUSSIAN] = "gaussian",
    [SAMPLE_EWA_LANCZOS2] = "lanczos2",
    [SAMPLE_EWA_LANCZOS3] = "lanczos3",
    [SAMPLE_EWA_MITCHELL] = "mitchell",
};
_Static_assert(COUNT_OF(ewa_kernel_names) == SAMPLE_EWA_KERNEL_COUNT, "ewa_kernel_names");

static const char *const mipgen_names[] = {
    [SAMPLE_MIPGEN_NONE] = "none",
    [SAMPLE_MIPGEN_BOX] = "box",
    [SAMPLE_MIPGEN_LANCZOS3] = "lanczos3",
    [SAMPLE_MIPGEN_KAISER] = "kaiser",
};
_Static_assert(COUNT_OF(mipgen_names) == SAMPLE_MIPGEN_COUNT, "mipgen_names");

static const char *const format_names[] = {
    [SAMPLE_FORMAT_F32] = "float",
    [SAMPLE_FORMAT_F16] = "half",
    [SAMPLE_FORMAT_UNORM8] = "unorm8",
    [SAMPLE_FORMAT_SRGB8] = "srgb8",
};
_Static_assert(COUNT_OF(format_names) == SAMPLE_FORMAT_COUNT, "format_names");

static const char *const kind_names[] = {
    [SAMPLE_TEXTURE_2D] = "2d",
    [SAMPLE_TEXTURE_CUBE] = "cube",
    [SAMPLE_TEXTURE_3D] = "3d",
};
_Static_assert(COUNT_OF(kind_names) == SAMPLE_TEXTURE_KIND_COUNT, "kind_names");

static const char *name_of(const char *const *names, size_t n, int v)
{
    return (v >= 0 && (size_t)v < n) ? names[v] : "unknown";
}

static int parse_in(const char *const *names, size_t n, const char *s)
{
    size_t k;
    if (!s) return -1;
    for (k = 0; k < n; ++k)
        if (strcmp(names[k], s) == 0) return (int)k;
    return -1;
}

const char *sample_strerror(sample_status s) { return name_of(status_names, COUNT_OF(status_names), (int)s); }
const char *sample_wrap_name(sample_wrap v) { return name_of(wrap_names, COUNT_OF(wrap_names), (int)v); }
const char *sample_filter_name(sample_filter v) { return name_of(filter_names, COUNT_OF(filter_names), (int)v); }
const char *sample_cubic_name(sample_cubic v) { return name_of(cubic_names, COUNT_OF(cubic_names), (int)v); }
const char *sample_footprint_name(sample_footprint v) { return name_of(footprint_names, COUNT_OF(footprint_names), (int)v); }
const char *sample_ewa_kernel_name(sample_ewa_kernel v)
{
    return name_of(ewa_kernel_names, COUNT_OF(ewa_kernel_names), (int)v);
}
const char *sample_mipgen_name(sample_mipgen v) { return name_of(mipgen_names, COUNT_OF(mipgen_names), (int)v); }
const char *sample_format_name(sample_format v) { return name_of(format_names, COUNT_OF(format_names), (int)v); }
const char *sample_texture_kind_name(sample_texture_kind v) { return name_of(kind_names, COUNT_OF(kind_names), (int)v); }

int sample_wrap_parse(const char *s)
{
    /* GL's own spelling of the EXT mode is accepted too. */
    if (s && strcmp(s, "mirror_clamp_ext") == 0) return SAMPLE_WRAP_MIRROR_CLAMP;
    return parse_in(wrap_names, COUNT_OF(wrap_names), s);
}
int sample_filter_parse(const char *s) { return parse_in(filter_names, COUNT_OF(filter_names), s); }
int sample_cubic_parse(const char *s)
{
    if (s && strcmp(s, "catmull_rom") == 0) return SAMPLE_CUBIC_CATMULL_ROM;
    return parse_in(cubic_names, COUNT_OF(cubic_names), s);
}
int sample_footprint_parse(const char *s)
{
    if (s && (strcmp(s, "anisotropic") == 0)) return SAMPLE_FOOTPRINT_ANISOTROPIC;
    if (s && (strcmp(s, "blinn_newell") == 0)) return SAMPLE_FOOTPRINT_BLINN_NEWELL;
    return parse_in(footprint_names, COUNT_OF(footprint_names), s);
}
int sample_ewa_kernel_parse(const char *s) { return parse_in(ewa_kernel_names, COUNT_OF(ewa_kernel_names), s); }
int sample_mipgen_parse(const char *s) { return parse_in(mipgen_names, COUNT_OF(mipgen_names), s); }

sample_status sample_error_vset(sample_error *err, sample_status status, const char *fmt, va_list ap)
{
    if (err) {
        int n;
        err->status = status;
        n = vsnprintf(err->message, sizeof err->message, fmt, ap);
        if (n < 0) snprintf(err->message, sizeof err->message, "%s", sample_strerror(status));
    }
    return status;
}

sample_status sample_error_set(sample_error *err, sample_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    sample_error_vset(err, status, fmt, ap);
    va_end(ap);
    return status;
}
