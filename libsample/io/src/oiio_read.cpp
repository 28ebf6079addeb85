// OpenImageIO: open an image file or an in-memory file and read its levels
// (OIIO 2.4 ImageInput, https://openimageio.readthedocs.io/en/v2.4.x/imageinput.html).
#include "io_internal.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

using namespace OIIO;

struct io_reader {
    std::unique_ptr<Filesystem::IOMemReader> proxy; // must outlive `in`'s use of it
    std::unique_ptr<ImageInput> in;
    io_reader_info info;
};

static io_ptype native_type(TypeDesc t)
{
    switch (t.basetype) {
    case TypeDesc::UINT8: return IO_U8;
    case TypeDesc::UINT16: return IO_U16;
    case TypeDesc::HALF: return IO_HALF;
    default: return IO_FLOAT; // float, double, 32-bit ints, signed types
    }
}

static TypeDesc oiio_type(io_ptype t)
{
    switch (t) {
    case IO_U8: return TypeDesc::UINT8;
    case IO_U16: return TypeDesc::UINT16;
    case IO_HALF: return TypeDesc::HALF;
    default: return TypeDesc::FLOAT;
    }
}

// Open from memory with one named format: OIIO 2.4 readers take the proxy
// through set_ioproxy() and, for those that look for it there, the
// "oiio:ioproxy" configuration hint (imageio.h, ImageInput::open).
static std::unique_ptr<ImageInput> open_memory(const std::string &format, Filesystem::IOMemReader *proxy,
                                               ImageSpec config, bool *unsupported)
{
    auto in = ImageInput::create(format);
    *unsupported = false;
    if (!in) return nullptr;
    if (!in->supports("ioproxy")) {
        *unsupported = true;
        return nullptr;
    }
    proxy->seek(0);
    void *ptr = proxy;
    config.attribute("oiio:ioproxy", TypeDesc::PTR, &ptr);
    in->set_ioproxy(proxy);
    ImageSpec spec;
    if (!in->open("memory." + format, spec, config)) {
        (void)in->geterror(); // drop the message so it does not pile up
        return nullptr;
    }
    return in;
}

static sample_status open_input(io_reader *r, const char *path, const void *data, size_t size,
                                const char *hint, sample_error *err)
{
    // Keep the file's values: OIIO would otherwise premultiply unassociated
    // alpha (PNG, TGA) on read, which changes 8-bit colour irreversibly.
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    if (path) {
        r->in = ImageInput::open(path, &config);
        if (r->in) return SAMPLE_OK;
        std::string msg = OIIO::geterror();
        FILE *f = std::fopen(path, "rb");
        if (!f) return sample_error_set(err, SAMPLE_E_IO, "cannot open '%s': %s", path, std::strerror(errno));
        std::fclose(f);
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read image '%s': %s", path, msg.c_str());
    }
    r->proxy.reset(new Filesystem::IOMemReader(data, size));
    bool unsupported = false;
    if (hint && *hint) {
        // The hint names the reader: "png", ".png" or "name.png".
        std::string h(hint);
        size_t dot = h.rfind('.');
        std::string ext = dot == std::string::npos ? h : h.substr(dot + 1);
        r->in = open_memory(ext, r->proxy.get(), config, &unsupported);
        if (r->in) return SAMPLE_OK;
        if (unsupported)
            return sample_error_set(err, SAMPLE_E_UNSUPPORTED, "the reader for '%s' cannot read from memory", hint);
        return sample_error_set(err, SAMPLE_E_CORRUPT, "not a readable '%s' image (%zu bytes in memory)", hint, size);
    }
    // No hint: every reader that can read memory, in OIIO's order.
    std::string formats;
    OIIO::getattribute("input_format_list", formats);
    for (const std::string &f : Strutil::splits(formats, ",")) {
        r->in = open_memory(f, r->proxy.get(), config, &unsupported);
        if (r->in) return SAMPLE_OK;
    }
    return sample_error_set(err, SAMPLE_E_CORRUPT, "no image reader recognises these %zu bytes", size);
}

extern "C" sample_status io_reader_open(const char *path, const void *data, size_t size,
                                        const char *format_hint, io_reader **out, sample_error *err)
{
    *out = nullptr;
    try {
        std::unique_ptr<io_reader> r(new io_reader);
        sample_status st = open_input(r.get(), path, data, size, format_hint, err);
        if (st != SAMPLE_OK) return st;
        const ImageSpec &spec = r->in->spec();
        io_reader_info &inf = r->info;
        std::memset(&inf, 0, sizeof inf);
        inf.width = spec.width;
        inf.height = spec.height;
        inf.channels = spec.nchannels;
        inf.alpha_channel = spec.alpha_channel;
        inf.native = native_type(spec.format);
        std::string cs = spec.get_string_attribute("oiio:ColorSpace");
        std::snprintf(inf.colorspace, sizeof inf.colorspace, "%s", cs.c_str());
        // With the oiio:UnassociatedAlpha hint (open_input) the readers of
        // formats that store straight alpha leave it so and say so here.
        inf.straight_alpha = spec.alpha_channel >= 0 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
        std::snprintf(inf.format, sizeof inf.format, "%s", r->in->format_name());
        std::snprintf(inf.pixel_type, sizeof inf.pixel_type, "%s", spec.format.c_str());
        std::snprintf(inf.compression, sizeof inf.compression, "%s",
                      spec.get_string_attribute("compression").c_str());
        std::snprintf(inf.wrapmodes, sizeof inf.wrapmodes, "%s", spec.get_string_attribute("wrapmodes").c_str());
        std::snprintf(inf.textureformat, sizeof inf.textureformat, "%s",
                      spec.get_string_attribute("textureformat").c_str());
        inf.tile_w = spec.tile_width;
        inf.tile_h = spec.tile_height;
        for (int c = 0; c < spec.nchannels && c < SAMPLE_IO_NAMED_CHANNELS; ++c)
            std::snprintf(inf.channel_names[c], sizeof inf.channel_names[c], "%s", spec.channel_name(c).c_str());
        if (spec.depth != 1)
            return sample_error_set(err, SAMPLE_E_UNSUPPORTED, "volume images (depth %d) are not textures", spec.depth);
        // Mip levels of subimage 0, as maketx and `texsample mip` store them.
        inf.nlevels = 1;
        while (inf.nlevels < SAMPLE_MAX_LEVELS && r->in->seek_subimage(0, inf.nlevels)) inf.nlevels++;
        r->in->seek_subimage(0, 0);
        *out = r.release();
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory opening an image");
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read image: %s", e.what());
    }
}

extern "C" void io_reader_info_get(const io_reader *r, io_reader_info *info) { *info = r->info; }

extern "C" sample_status io_reader_level_size(io_reader *r, int k, int *w, int *h, sample_error *err)
{
    try {
        if (!r->in->seek_subimage(0, k))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot seek to mip level %d: %s", k, r->in->geterror().c_str());
        *w = r->in->spec().width;
        *h = r->in->spec().height;
        return SAMPLE_OK;
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read mip level %d: %s", k, e.what());
    }
}

extern "C" sample_status io_reader_read(io_reader *r, int k, io_ptype type, int nchan, void *dst,
                                        sample_error *err)
{
    try {
        // Only a false return is a failure: OIIO 2.4's TIFF reader leaves
        // a pending error holding just the file name after reading a valid
        // maketx .tx, so has_error() after success says nothing. What the
        // readers make up without failing is caught before they run
        // (tiff_guard.c, tga_guard.c).
        bool ok = r->in->read_image(0, k, 0, nchan, oiio_type(type), dst);
        if (!ok) {
            std::string msg = r->in->geterror();
            return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read pixels of level %d: %s", k,
                           msg.empty() ? "unknown error" : msg.c_str());
        }
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory reading level %d", k);
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read pixels of level %d: %s", k, e.what());
    }
}

extern "C" sample_status io_reader_read_tiles(io_reader *r, int k, int x0, int y0, int x1, int y1, io_ptype type,
                                              int nchan, void *dst, sample_error *err)
{
    try {
        // The explicit-subimage form is OIIO 2.4's thread-safe one
        // (ImageInput::read_tiles): the region is whole tiles, ending at
        // the level's edge.
        if (r->in->read_tiles(0, k, x0, x1, y0, y1, 0, 1, 0, nchan, oiio_type(type), dst)) return SAMPLE_OK;
        std::string msg = r->in->geterror();
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read the tile at (%d, %d) of level %d: %s", x0, y0, k,
                                msg.empty() ? "unknown error" : msg.c_str());
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory reading a tile of level %d", k);
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read a tile of level %d: %s", k, e.what());
    }
}

extern "C" void io_reader_close(io_reader *r)
{
    if (!r) return;
    try {
        if (r->in) r->in->close();
    } catch (...) {
        // Closing a reader that failed mid-way may throw; nothing to report.
    }
    delete r;
}
