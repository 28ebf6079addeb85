// oiio_ts: the C wrapper around OpenImageIO 2.4's TextureSystem (oiio_ts.h).
// The only C++ in the tools; it stays a translation of the C API and nothing
// more, so that every decision about the comparison is visible in C.
#include "oiio_ts.h"

// Before OpenImageIO's headers, which otherwise declare Imath::V3f only.
#include <Imath/ImathVec.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <vector>

using namespace OIIO;

struct oiio_ts {
    TextureSystem *sys;
    std::vector<oiio_ts_tex *> opened; // freed with the system
};

// A TextureHandle is an opaque OIIO type; the C side only carries it around.
struct oiio_ts_tex {
    TextureSystem::TextureHandle *handle;
};

static void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

extern "C" void oiio_ts_opts_init(oiio_ts_opts *o)
{
    if (!o) return;
    o->mode = OIIO_TS_TRILINEAR;
    o->wrap_s = o->wrap_t = SAMPLE_WRAP_REPEAT;
    o->max_aniso = 16;
    o->conservative = 1;
}

// The OIIO wrap name of a libsample mode, or nullptr where OIIO has none.
// "black" reads 0 outside [0, 1] — CLAMP_TO_BORDER with a zero border.
static const char *wrap_oiio_name(sample_wrap w)
{
    switch (w) {
    case SAMPLE_WRAP_REPEAT: return "periodic";
    case SAMPLE_WRAP_MIRRORED_REPEAT: return "mirror";
    case SAMPLE_WRAP_CLAMP_TO_EDGE: return "clamp";
    case SAMPLE_WRAP_CLAMP_TO_BORDER: return "black";
    default: return nullptr;
    }
}

extern "C" int oiio_ts_wrap_supported(sample_wrap wrap)
{
    return wrap_oiio_name(wrap) != nullptr;
}

static const char *const mode_names[OIIO_TS_MODE_COUNT] = {
    "closest", "bilinear", "bicubic", "trilinear", "aniso",
};

// Each mode's (interpmode, mipmode), with the names oiio_ts_describe gives
// them: one table, so the description cannot drift from what is sampled.
static const struct {
    TextureOpt::InterpMode interp;
    TextureOpt::MipMode mip;
    const char *interp_name, *mip_name;
} mode_opts[OIIO_TS_MODE_COUNT] = {
    {TextureOpt::InterpClosest, TextureOpt::MipModeNoMIP, "InterpClosest", "MipModeNoMIP"},
    {TextureOpt::InterpBilinear, TextureOpt::MipModeNoMIP, "InterpBilinear", "MipModeNoMIP"},
    {TextureOpt::InterpBicubic, TextureOpt::MipModeNoMIP, "InterpBicubic", "MipModeNoMIP"},
    {TextureOpt::InterpBilinear, TextureOpt::MipModeTrilinear, "InterpBilinear",
     "MipModeTrilinear"},
    {TextureOpt::InterpBilinear, TextureOpt::MipModeAniso, "InterpBilinear", "MipModeAniso"},
};

extern "C" int oiio_ts_describe(const oiio_ts_opts *o, oiio_ts_textureopt *out)
{
    if (!o || !out || (unsigned)o->mode >= OIIO_TS_MODE_COUNT) return -1;
    out->swrap = wrap_oiio_name(o->wrap_s);
    out->twrap = wrap_oiio_name(o->wrap_t);
    if (!out->swrap || !out->twrap) return -1;
    out->interpmode = mode_opts[o->mode].interp_name;
    out->mipmode = mode_opts[o->mode].mip_name;
    out->anisotropic = o->max_aniso > 0 ? o->max_aniso : 1;
    out->conservative_filter = o->conservative != 0;
    return 0;
}

extern "C" const char *oiio_ts_mode_name(oiio_ts_mode mode)
{
    return (unsigned)mode < OIIO_TS_MODE_COUNT ? mode_names[mode] : "?";
}

extern "C" int oiio_ts_mode_parse(const char *name)
{
    for (int m = 0; name && m < OIIO_TS_MODE_COUNT; ++m)
        if (std::strcmp(name, mode_names[m]) == 0) return m;
    return -1;
}

extern "C" int oiio_ts_make_texture(const float *rgba, int w, int h, oiio_ts_format format,
                                    sample_wrap wrap_s, sample_wrap wrap_t, const char *out_path,
                                    char *err, size_t errlen)
{
    static const TypeDesc types[OIIO_TS_FORMAT_COUNT] = {TypeDesc::FLOAT, TypeDesc::HALF,
                                                         TypeDesc::UINT8};
    const char *ws = wrap_oiio_name(wrap_s), *wt = wrap_oiio_name(wrap_t);
    if (!rgba || w <= 0 || h <= 0 || !out_path || (unsigned)format >= OIIO_TS_FORMAT_COUNT) {
        set_err(err, errlen, "oiio_ts_make_texture: bad argument");
        return -1;
    }
    if (!ws || !wt) {
        set_err(err, errlen, std::string("OpenImageIO has no wrap mode like ") +
                                 sample_wrap_name(ws ? wrap_t : wrap_s));
        return -1;
    }
    try {
        // Wrap the caller's memory (no copy); make_texture only reads it.
        ImageSpec spec(w, h, 4, TypeDesc::FLOAT);
        ImageBuf src(spec, const_cast<float *>(rgba));
        ImageSpec config;
        config.format = types[format];
        config.tile_width = config.tile_height = 64; // maketx's default tile
        config.tile_depth = 1;
        config.attribute("wrapmodes", std::string(ws) + "," + wt);
        // Uncompressed: the benchmark measures filtering, not inflate.
        config.attribute("compression", "none");
        config.attribute("maketx:constant_color_detect", 0);
        config.attribute("maketx:opaque_detect", 0);
        config.attribute("maketx:monochrome_detect", 0);
        if (!ImageBufAlgo::make_texture(ImageBufAlgo::MakeTxTexture, src, out_path, config)) {
            set_err(err, errlen, "make_texture " + std::string(out_path) + ": " + OIIO::geterror());
            return -1;
        }
        // The file's format follows its extension, and OIIO 2.4's TIFF
        // writer (.tx, .tif) silently stores half as float: check what was
        // written rather than benchmark a different format than asked for.
        auto in = ImageInput::open(out_path);
        if (!in || in->spec().format != types[format]) {
            set_err(err, errlen, std::string(out_path) + ": the file format cannot hold " +
                                     types[format].c_str() + " texels (use .exr for half)");
            return -1;
        }
    } catch (const std::exception &e) {
        set_err(err, errlen, std::string("make_texture: ") + e.what());
        return -1;
    }
    return 0;
}

extern "C" oiio_ts *oiio_ts_create(double cache_mb)
{
    oiio_ts *ts = new (std::nothrow) oiio_ts;
    if (!ts) return nullptr;
    // Unshared: a tool's statistics and cache settings are its own.
    ts->sys = TextureSystem::create(false);
    if (!ts->sys) {
        delete ts;
        return nullptr;
    }
    // The default cache (256 MB in 2.4) would evict tiles of a 2048² float
    // texture's pyramid under random queries, and then the benchmark would
    // time file reads.
    float mb = cache_mb > 0.0 ? (float)cache_mb : 4096.0f;
    ts->sys->attribute("max_memory_MB", mb);
    return ts;
}

extern "C" void oiio_ts_destroy(oiio_ts *ts)
{
    if (!ts) return;
    for (oiio_ts_tex *t : ts->opened) delete t;
    // The system is unshared (oiio_ts_create), so the image cache it made
    // is its own: without teardown_imagecache OpenImageIO 2.4 leaves that
    // cache allocated (LeakSanitizer: ImageCache::create's aligned_malloc).
    TextureSystem::destroy(ts->sys, true);
    delete ts;
}

extern "C" void oiio_ts_stats_get(oiio_ts *ts, oiio_ts_stats *out)
{
    int i;
    long long ll;
    out->tiles_read = out->bytes_read = out->memory = out->peak_tiles = -1;
    if (!ts) return;
    // The TextureSystem answers its ImageCache's attributes.
    if (ts->sys->getattribute("stat:tiles_created", TypeDesc::INT, &i)) out->tiles_read = i;
    if (ts->sys->getattribute("stat:bytes_read", TypeDesc::INT64, &ll)) out->bytes_read = ll;
    if (ts->sys->getattribute("stat:cache_memory_used", TypeDesc::INT64, &ll)) out->memory = ll;
    if (ts->sys->getattribute("stat:tiles_peak", TypeDesc::INT, &i)) out->peak_tiles = i;
}

extern "C" oiio_ts_tex *oiio_ts_open(oiio_ts *ts, const char *path, char *err, size_t errlen)
{
    if (!ts || !path) {
        set_err(err, errlen, "oiio_ts_open: bad argument");
        return nullptr;
    }
    TextureSystem::TextureHandle *h = ts->sys->get_texture_handle(ustring(path));
    // A handle is made for any name; reading the header is what fails for a
    // missing or unreadable file.
    ImageSpec spec;
    if (!h || !ts->sys->good(h) || !ts->sys->get_imagespec(h, nullptr, 0, spec)) {
        std::string msg = ts->sys->geterror();
        set_err(err, errlen, std::string(path) + ": " + (msg.empty() ? "cannot open" : msg));
        return nullptr;
    }
    // Handles live as long as the TextureSystem, and so does this record.
    try {
        ts->opened.reserve(ts->opened.size() + 1); // so push_back cannot throw
        oiio_ts_tex *t = new oiio_ts_tex{h};
        ts->opened.push_back(t);
        return t;
    } catch (const std::bad_alloc &) {
        set_err(err, errlen, "out of memory");
        return nullptr;
    }
}

extern "C" int oiio_ts_sample(oiio_ts *ts, oiio_ts_tex *tex, const oiio_ts_opts *o,
                              const sample_query *q, size_t count, float *rgba, char *err,
                              size_t errlen)
{
    if (!ts || !tex || !o || (count && (!q || !rgba)) || (unsigned)o->mode >= OIIO_TS_MODE_COUNT) {
        set_err(err, errlen, "oiio_ts_sample: bad argument");
        return -1;
    }
    const char *ws = wrap_oiio_name(o->wrap_s), *wt = wrap_oiio_name(o->wrap_t);
    if (!ws || !wt) {
        set_err(err, errlen, std::string("OpenImageIO has no wrap mode like ") +
                                 sample_wrap_name(ws ? o->wrap_t : o->wrap_s));
        return -1;
    }
    // Built from the description, so that what bench --save records is
    // what OIIO gets.
    oiio_ts_textureopt d;
    oiio_ts_describe(o, &d); // cannot fail: mode and wraps checked above
    TextureOpt opt;
    opt.swrap = TextureOpt::decode_wrapmode(d.swrap);
    opt.twrap = TextureOpt::decode_wrapmode(d.twrap);
    opt.anisotropic = d.anisotropic;
    opt.conservative_filter = d.conservative_filter != 0;
    opt.interpmode = mode_opts[o->mode].interp;
    opt.mipmode = mode_opts[o->mode].mip;
    // The calling thread's record (OIIO keeps one per thread), fetched once
    // per call rather than once per lookup.
    TextureSystem::Perthread *pt = ts->sys->get_perthread_info();
    for (size_t i = 0; i < count; ++i) {
        const sample_query &k = q[i];
        float *out = rgba + 4 * i;
        if (!ts->sys->texture(tex->handle, pt, opt, k.s, k.t, k.dsdx, k.dtdx, k.dsdy, k.dtdy, 4,
                              out)) {
            set_err(err, errlen, "texture lookup failed: " + ts->sys->geterror());
            return -1;
        }
    }
    return 0;
}

extern "C" int oiio_ts_environment(oiio_ts *ts, oiio_ts_tex *tex, const oiio_ts_opts *o,
                                   const sample_query3 *q, size_t count, float *rgba, char *err,
                                   size_t errlen)
{
    if (!ts || !tex || !o || (count && (!q || !rgba)) || (unsigned)o->mode >= OIIO_TS_MODE_COUNT) {
        set_err(err, errlen, "oiio_ts_environment: bad argument");
        return -1;
    }
    TextureOpt opt;
    opt.anisotropic = o->max_aniso;
    opt.conservative_filter = o->conservative != 0;
    opt.interpmode = mode_opts[o->mode].interp;
    opt.mipmode = mode_opts[o->mode].mip;
    TextureSystem::Perthread *pt = ts->sys->get_perthread_info();
    for (size_t i = 0; i < count; ++i) {
        const sample_query3 &k = q[i];
        Imath::V3f R(k.p[0], k.p[1], k.p[2]), dx(k.dpdx[0], k.dpdx[1], k.dpdx[2]),
            dy(k.dpdy[0], k.dpdy[1], k.dpdy[2]);
        if (!ts->sys->environment(tex->handle, pt, opt, R, dx, dy, 4, rgba + 4 * i)) {
            set_err(err, errlen, "environment lookup failed: " + ts->sys->geterror());
            return -1;
        }
    }
    return 0;
}
