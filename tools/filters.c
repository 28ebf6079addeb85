/*
 * The filter registry (filters.h): one table of the filter configurations
 * every tool names, the old spellings, and the name → pick parsing that
 * compare, freq, bench and lookup share.
 */
#include "filters.h"

#include <string.h>

/* The footprint filters replace min_filter whenever λ > 0 (DESIGN §7);
 * trilinear stays their min filter so that the sampler is also valid
 * without them. The nearest family keeps NEAREST magnification so that a
 * row shows one filter throughout. bicubic-bspline uses the B-spline
 * because that is OpenImageIO's bicubic kernel (InterpBicubic), so the pair
 * reads the same 4 × 4 texels with the same weights. */
const tool_filter tool_filters[] = {
    {.label = "nearest, no mips",
     .min = SAMPLE_NEAREST, .mag = SAMPLE_NEAREST,
     .oiio = {.twin = 1, .mode = OIIO_TS_CLOSEST}},
    {.name = "bilinear", .label = "bilinear, no mips",
     .min = SAMPLE_LINEAR, .mag = SAMPLE_LINEAR,
     .oiio = {.twin = 1, .mode = OIIO_TS_BILINEAR}},
    {.name = "bicubic-bspline", .label = "bicubic B-spline, no mips",
     .min = SAMPLE_CUBIC, .mag = SAMPLE_CUBIC, .cubic = SAMPLE_CUBIC_BSPLINE,
     .oiio = {.twin = 1, .mode = OIIO_TS_BICUBIC}},
    {.label = "nearest-mipmap-nearest",
     .min = SAMPLE_NEAREST_MIPMAP_NEAREST, .mag = SAMPLE_NEAREST},
    {.name = "trilinear", .label = "trilinear",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .oiio = {.twin = 1, .mode = OIIO_TS_TRILINEAR}},
    /* The ratios GPUs offer below 16 (GL_TEXTURE_MAX_ANISOTROPY), so that
     * a driver's ladder can be read against libsample's. */
    {.name = "aniso2", .label = "anisotropic x2",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_ANISOTROPIC, .max_aniso = 2,
     .oiio = {.twin = 1, .mode = OIIO_TS_ANISO}},
    {.name = "aniso4", .label = "anisotropic x4",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_ANISOTROPIC, .max_aniso = 4,
     .oiio = {.twin = 1, .mode = OIIO_TS_ANISO}},
    {.name = "aniso16", .label = "anisotropic x16",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_ANISOTROPIC, .max_aniso = 16,
     .oiio = {.twin = 1, .mode = OIIO_TS_ANISO}},
    {.label = "cubic_mipmap_linear (Catmull-Rom)",
     .min = SAMPLE_CUBIC_MIPMAP_LINEAR, .mag = SAMPLE_CUBIC, .cubic = SAMPLE_CUBIC_CATMULL_ROM},
    {.label = "Blinn-Newell, Jacobian",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_BLINN_NEWELL},
    {.name = "blinn-newell-corners", .label = "Blinn-Newell, exact corners",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_BLINN_NEWELL, .corners = 1},
    /* Corner mode weighted by the screen-space area element, i.e. the
     * integral DESIGN §8 scores against (doc/footprint-filters.md). */
    {.name = "blinn-newell-corners-area", .label = "Blinn-Newell, exact corners, area-weighted",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_BLINN_NEWELL, .corners = 1,
     .options = SAMPLE_OPT_BN_AREA_WEIGHT},
    {.label = "EWA",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_EWA},
    /* EWA's ellipse by a lattice of Gaussian-weighted bilinear probes (Feline). */
    {.label = "Feline (EWA by bilinear probes)",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_FELINE},
    /* EWA with sharper radial kernels (doc/footprint-filters.md, "Radial
     * kernels"); the clamped row bounds Lanczos-3's ringing. */
    {.name = "ewa-lanczos2", .label = "EWA, Lanczos-2",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_EWA, .ewa_kernel = SAMPLE_EWA_LANCZOS2},
    {.name = "ewa-lanczos3", .label = "EWA, Lanczos-3",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_EWA, .ewa_kernel = SAMPLE_EWA_LANCZOS3},
    {.name = "ewa-lanczos3-clamp", .label = "EWA, Lanczos-3, clamped",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_EWA, .ewa_kernel = SAMPLE_EWA_LANCZOS3,
     .options = SAMPLE_OPT_EWA_CLAMP},
    {.name = "ewa-mitchell", .label = "EWA, Mitchell-Netravali",
     .min = SAMPLE_LINEAR_MIPMAP_LINEAR, .mag = SAMPLE_LINEAR,
     .footprint = SAMPLE_FOOTPRINT_EWA, .ewa_kernel = SAMPLE_EWA_MITCHELL},
};
const int tool_filter_count = (int)(sizeof tool_filters / sizeof tool_filters[0]);

/* What the tools called these before they shared this table. "bicubic"
 * was bench's B-spline without mips (OpenImageIO's bicubic) and compare's
 * Catmull–Rom cubic_mipmap_linear; it stays with the first, the meaning
 * bicubic has beside bilinear, and the alias note says so. */
const tool_filter_alias tool_filter_aliases[] = {
    {"bicubic", "bicubic-bspline"},
    {"nmn", "nearest_mipmap_nearest"},
    {"blinn_newell", "blinn-newell"},
    {"bn-jacobian", "blinn-newell"},
    {"bn-corners", "blinn-newell-corners"},
    {"bn-corners-area", "blinn-newell-corners-area"},
    {"oiio", "oiio-aniso16"},
    {"oiio_trilinear", "oiio-trilinear"},
    {"oiio_aniso", "oiio-aniso16"},
};
const int tool_filter_alias_count = (int)(sizeof tool_filter_aliases / sizeof tool_filter_aliases[0]);

static const char oiio_prefix[] = "oiio-";
static const char gl_prefix[] = "gl-";

/* Picks are ranked libsample, OIIO, OpenGL (pick_rank): three per entry. */
#define PICK_KINDS 3

const char *tool_filter_name(const tool_filter *f)
{
    if (f->name) return f->name;
    return f->footprint != SAMPLE_FOOTPRINT_NONE ? sample_footprint_name(f->footprint)
                                                 : sample_filter_name(f->min);
}

void tool_filter_apply(const tool_filter *f, sample_sampler *s)
{
    s->min_filter = f->min;
    s->mag_filter = f->mag;
    s->footprint = f->footprint;
    s->cubic = f->cubic;
    s->ewa_kernel = f->ewa_kernel;
    s->max_anisotropy = f->max_aniso > 0.0f ? f->max_aniso : 1.0f;
    s->options |= f->options;
}

void tool_filter_oiio_opts(const tool_filter *f, oiio_ts_opts *o)
{
    o->mode = f->oiio.mode;
    if (f->max_aniso > 0.0f) o->max_aniso = (int)f->max_aniso;
}

int tool_filter_gl_twin(const tool_filter *f)
{
    return f->min <= SAMPLE_LINEAR_MIPMAP_LINEAR && f->mag <= SAMPLE_LINEAR &&
           (f->footprint == SAMPLE_FOOTPRINT_NONE || f->footprint == SAMPLE_FOOTPRINT_ANISOTROPIC) &&
           f->options == 0 && !f->corners;
}

/* Does pick p name something that exists (an entry, or a twin it has)? */
static int pick_exists(const tool_pick *p)
{
    if (p->oiio) return p->f->oiio.twin;
    if (p->gl) return tool_filter_gl_twin(p->f);
    return 1;
}

/* A canonical name (no alias) → pick. */
static int find_canonical(const char *name, tool_pick *out)
{
    int oiio = strncmp(name, oiio_prefix, sizeof oiio_prefix - 1) == 0, k;
    int gl = strncmp(name, gl_prefix, sizeof gl_prefix - 1) == 0;
    const char *base = oiio ? name + sizeof oiio_prefix - 1 : gl ? name + sizeof gl_prefix - 1 : name;
    for (k = 0; k < tool_filter_count; ++k)
        if (strcmp(tool_filter_name(&tool_filters[k]), base) == 0) {
            out->f = &tool_filters[k];
            out->oiio = oiio;
            out->gl = gl;
            return pick_exists(out) ? 0 : -1;
        }
    return -1;
}

int tool_pick_find(const char *name, tool_pick *out, const char **canonical)
{
    int k;
    if (!name) return -1;
    if (find_canonical(name, out) == 0) return 0;
    for (k = 0; k < tool_filter_alias_count; ++k)
        if (strcmp(tool_filter_aliases[k].alias, name) == 0) {
            if (find_canonical(tool_filter_aliases[k].name, out) != 0) return -1;
            if (canonical) *canonical = tool_filter_aliases[k].name;
            return 1;
        }
    return -1;
}

int tool_pick_read(const char *sub, const char *name, tool_pick *out)
{
    const char *canonical = NULL;
    int r = tool_pick_find(name, out, &canonical);
    if (r == 1) fprintf(stderr, "texsample %s: '%s' is read as '%s'\n", sub, name, canonical);
    return r < 0 ? -1 : 0;
}

const tool_filter *tool_filter_by_name(const char *name)
{
    tool_pick p;
    return tool_pick_find(name, &p, NULL) >= 0 && !p.oiio && !p.gl ? p.f : NULL;
}

const char *tool_pick_name(const tool_pick *p, char *buf, size_t len)
{
    snprintf(buf, len, "%s%s", p->oiio ? oiio_prefix : p->gl ? gl_prefix : "", tool_filter_name(p->f));
    return buf;
}

const char *tool_pick_label(const tool_pick *p, char *buf, size_t len)
{
    snprintf(buf, len, "%s%s", p->oiio ? "OpenImageIO " : p->gl ? "OpenGL " : "", p->f->label);
    return buf;
}

int tool_pick_allowed(const tool_pick *p, unsigned accept)
{
    if (p->oiio) return (accept & TOOL_PICK_OIIO) != 0;
    if (p->gl) return (accept & TOOL_PICK_GL) != 0;
    return !p->f->corners || (accept & TOOL_PICK_CORNERS) != 0;
}

/* Registry order, libsample picks first, then OIIO's, then OpenGL's: the
 * order of every tool's rows. */
static int pick_rank(const tool_pick *p)
{
    return (int)(p->f - tool_filters) + (p->oiio ? tool_filter_count : p->gl ? 2 * tool_filter_count : 0);
}

/* The pick of rank k (pick_rank's inverse). */
static tool_pick pick_of_rank(int k)
{
    tool_pick p;
    p.f = &tool_filters[k % tool_filter_count];
    p.oiio = k / tool_filter_count == 1;
    p.gl = k / tool_filter_count == 2;
    return p;
}

int tool_picks_parse(const char *sub, const char *list, const char *const *defaults,
                     unsigned accept, tool_pick *out, int max, char *err, size_t errlen)
{
    unsigned char want[PICK_KINDS * sizeof tool_filters / sizeof tool_filters[0]] = {0};
    const char *p = list;
    int k, n = 0;
    if (!list || !*list) {
        snprintf(err, errlen, "needs a list of names");
        return -1;
    }
    while (*p) {
        size_t len = strcspn(p, ",");
        char name[TOOL_FILTER_NAME_MAX];
        tool_pick pk;
        if (len == 0 || len >= sizeof name) {
            snprintf(err, errlen, "unknown name '%.*s'", (int)(len < 64 ? len : 64), p);
            return -1;
        }
        memcpy(name, p, len);
        name[len] = '\0';
        if (strcmp(name, "all") == 0) {
            /* The defaults this tool can run here (OIIO may be off). */
            for (k = 0; defaults[k]; ++k)
                if (find_canonical(defaults[k], &pk) == 0 && tool_pick_allowed(&pk, accept))
                    want[pick_rank(&pk)] = 1;
        } else if (tool_pick_read(sub, name, &pk) < 0) {
            snprintf(err, errlen, "unknown name '%s'", name);
            return -1;
        } else if (!tool_pick_allowed(&pk, accept)) {
            snprintf(err, errlen, "'%s' cannot run here (%s)", name,
                     pk.oiio ? "no OpenImageIO here: not built with it, or --no-oiio"
                     : pk.gl ? "no OpenGL here: not built with EGL, or this tool has no GL rows"
                             : "it needs the exact footprint corners");
            return -1;
        } else {
            want[pick_rank(&pk)] = 1;
        }
        p += len;
        if (*p == ',') ++p;
    }
    for (k = 0; k < PICK_KINDS * tool_filter_count; ++k) {
        if (!want[k]) continue;
        if (n == max) {
            snprintf(err, errlen, "at most %d names", max);
            return -1;
        }
        out[n++] = pick_of_rank(k);
    }
    return n;
}

/* Is pick p among the names in defaults? */
static int is_default(const tool_pick *p, const char *const *defaults)
{
    tool_pick d;
    int k;
    for (k = 0; defaults[k]; ++k)
        if (find_canonical(defaults[k], &d) == 0 && pick_rank(&d) == pick_rank(p)) return 1;
    return 0;
}

void tool_picks_help(FILE *out, const char *indent, const char *const *defaults, unsigned accept)
{
    char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
    int k, w = 0;
    for (k = 0; k < PICK_KINDS * tool_filter_count; ++k) {
        tool_pick p = pick_of_rank(k);
        int len;
        if (!pick_exists(&p) || !tool_pick_allowed(&p, accept)) continue;
        len = (int)strlen(tool_pick_name(&p, name, sizeof name));
        if (len > w) w = len;
    }
    for (k = 0; k < PICK_KINDS * tool_filter_count; ++k) {
        tool_pick p = pick_of_rank(k);
        if (!pick_exists(&p) || !tool_pick_allowed(&p, accept)) continue;
        fprintf(out, "%s%c %-*s  %s\n", indent, is_default(&p, defaults) ? '*' : ' ', w,
                tool_pick_name(&p, name, sizeof name), tool_pick_label(&p, label, sizeof label));
    }
}
