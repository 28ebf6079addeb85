// OpenEXR: direct reader of tiled, mip-mapped files (OpenEXR 3.1 Imf
// multi-part API, which reads single-part files too). Only the layout our
// writer (exr_mip.cpp) and maketx produce is taken: one tiled part,
// MIPMAP_LEVELS, ROUND_DOWN (libsample's level rule), half or float
// channels named R, G, B, A (a prefix of them). Anything else returns "not
// mine" and io_read.c reads it through OpenImageIO as before.
#include "io_internal.h"

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfTiledInputPart.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>

// A file held in memory as an Imf::IStream. The bytes are the caller's and
// outlive the reader (sample_io_read_memory holds them for the whole call).
namespace {
class MemIStream : public Imf::IStream {
  public:
    MemIStream(const void *data, size_t size)
        : Imf::IStream("image in memory"), data_(static_cast<const char *>(data)), size_(size), pos_(0)
    {
    }
    // Imf's contract: copy n bytes or throw; return whether more remain.
    bool read(char c[], int n) override
    {
        if (n < 0 || pos_ > size_ || (uint64_t)n > size_ - pos_) throw Iex::InputExc("unexpected end of the OpenEXR data");
        std::memcpy(c, data_ + pos_, (size_t)n);
        pos_ += (uint64_t)n;
        return pos_ < size_;
    }
    uint64_t tellg() override { return pos_; }
    // Seeking past the end is allowed (a bad offset table); reading there throws.
    void seekg(uint64_t pos) override { pos_ = pos; }

  private:
    const char *data_;
    uint64_t size_, pos_;
};

std::atomic<unsigned long> direct_reads{0};
} // namespace

struct io_exr_tiled {
    // Declaration order is destruction order reversed: the part refers to
    // the file, the file to the stream.
    std::unique_ptr<Imf::IStream> stream;
    std::unique_ptr<Imf::MultiPartInputFile> file;
    std::unique_ptr<Imf::TiledInputPart> part;
    int nchan;
    Imf::PixelType type;
    io_reader_info info;
};

static const char *const rgba_names[4] = {"R", "G", "B", "A"};

// OpenImageIO's names for OpenEXR's compression methods (its OpenEXR
// reader's "compression" attribute), in Imf::Compression's order.
static const char *compression_name(Imf::Compression c)
{
    static const char *const names[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
    return (unsigned)c < sizeof names / sizeof names[0] ? names[c] : "";
}

// Channels exactly a prefix of R, G, B, A, all of one type (half or float):
// the sets our writer and maketx write for 1–4 channel textures, read by
// OIIO in the same order. Other sets (layers, Y/RY/BY, extra AOVs) go to
// OIIO, whose channel ordering rules we do not repeat here.
static bool plain_rgba(const Imf::ChannelList &cl, int *nchan, Imf::PixelType *type)
{
    int n = 0;
    for (Imf::ChannelList::ConstIterator it = cl.begin(); it != cl.end(); ++it) ++n;
    if (n < 1 || n > 4) return false;
    for (int c = 0; c < n; ++c) {
        const Imf::Channel *ch = cl.findChannel(rgba_names[c]);
        if (!ch || ch->xSampling != 1 || ch->ySampling != 1) return false;
        if (ch->type != Imf::HALF && ch->type != Imf::FLOAT) return false;
        if (c == 0) *type = ch->type;
        else if (ch->type != *type) return false;
    }
    *nchan = n;
    return true;
}

// Is part 0 of `file` a layout we read directly? Fills nchan and type.
static bool eligible(const Imf::MultiPartInputFile &file, int *nchan, Imf::PixelType *type)
{
    if (file.parts() != 1) return false;
    const Imf::Header &h = file.header(0);
    if (!h.hasTileDescription()) return false;
    if (h.hasType() && h.type() != Imf::TILEDIMAGE) return false; // deep tiles
    const Imf::TileDescription &td = h.tileDescription();
    if (td.mode != Imf::MIPMAP_LEVELS || td.roundingMode != Imf::ROUND_DOWN) return false;
    // Opening the part sizes its tile buffers and level tables from these
    // numbers; absurd ones are left to OIIO's reader, which reports them
    // as before, rather than allocated here first.
    const Imath::Box2i &dw = h.dataWindow();
    int64_t w = (int64_t)dw.max.x - dw.min.x + 1, hh = (int64_t)dw.max.y - dw.min.y + 1;
    if (w < 1 || hh < 1 || w > SAMPLE_MAX_SIZE || hh > SAMPLE_MAX_SIZE) return false;
    if (td.xSize < 1 || td.ySize < 1 || td.xSize > SAMPLE_MAX_SIZE || td.ySize > SAMPLE_MAX_SIZE) return false;
    return plain_rgba(h.channels(), nchan, type);
}

extern "C" sample_status io_exr_tiled_open(const char *path, const void *data, size_t size, io_exr_tiled **out,
                                           sample_error *err)
{
    *out = nullptr;
    // Only OpenEXR bytes are worth opening (the magic number, as exr_guard.c).
    static const unsigned char magic[4] = {0x76, 0x2f, 0x31, 0x01};
    unsigned char head[4];
    if (path) {
        FILE *f = std::fopen(path, "rb");
        if (!f) return SAMPLE_OK; // OIIO reports unreadable files
        size_t got = std::fread(head, 1, 4, f);
        std::fclose(f);
        if (got != 4 || std::memcmp(head, magic, 4) != 0) return SAMPLE_OK;
    } else if (size < 4 || std::memcmp(data, magic, 4) != 0) {
        return SAMPLE_OK;
    }
    try {
        std::unique_ptr<io_exr_tiled> x(new io_exr_tiled);
        if (path) x->stream.reset(new Imf::StdIFStream(path));
        else x->stream.reset(new MemIStream(data, size));
        // Single-threaded decoding: no global thread pool is started on the
        // caller's behalf (sample_io.h promises no global state).
        x->file.reset(new Imf::MultiPartInputFile(*x->stream, 0));
        if (!eligible(*x->file, &x->nchan, &x->type)) return SAMPLE_OK;
        x->part.reset(new Imf::TiledInputPart(*x->file, 0));
        io_reader_info &inf = x->info;
        std::memset(&inf, 0, sizeof inf);
        inf.width = x->part->levelWidth(0);
        inf.height = x->part->levelHeight(0);
        inf.channels = x->nchan;
        inf.nlevels = x->part->numLevels();
        inf.alpha_channel = x->nchan == 4 ? 3 : -1;
        inf.native = x->type == Imf::HALF ? IO_HALF : IO_FLOAT;
        // OpenEXR colour is premultiplied by alpha (the format's rule).
        inf.straight_alpha = 0;
        for (int c = 0; c < x->nchan; ++c) std::snprintf(inf.channel_names[c], sizeof inf.channel_names[c], "%s", rgba_names[c]);
        // What OpenImageIO's OpenEXR reader reports of the same file, so
        // that sample_io_file_info reads alike on both paths.
        const Imf::Header &h = x->file->header(0);
        std::snprintf(inf.format, sizeof inf.format, "openexr");
        std::snprintf(inf.pixel_type, sizeof inf.pixel_type, "%s", x->type == Imf::HALF ? "half" : "float");
        std::snprintf(inf.compression, sizeof inf.compression, "%s", compression_name(h.compression()));
        inf.tile_w = (int)h.tileDescription().xSize;
        inf.tile_h = (int)h.tileDescription().ySize;
        // The metadata OIIO's reader reports too: a colour space named in
        // the file (oiio:ColorSpace, as sample_io_write_mip_exr writes it;
        // without one OIIO 2.4 says linear, and the rule decides alike)
        // and the wrap modes. A space that needs converting goes to OIIO
        // (io_read.c).
        if (auto *a = h.findTypedAttribute<Imf::StringAttribute>("oiio:ColorSpace"))
            std::snprintf(inf.colorspace, sizeof inf.colorspace, "%s", a->value().c_str());
        if (auto *a = h.findTypedAttribute<Imf::StringAttribute>("wrapmodes"))
            std::snprintf(inf.wrapmodes, sizeof inf.wrapmodes, "%s", a->value().c_str());
        // OIIO's reader calls a mip-mapped file (all this reader takes) a
        // plain texture unless it says otherwise, and turns the envmap
        // attribute into textureformat.
        std::snprintf(inf.textureformat, sizeof inf.textureformat, "Plain Texture");
        if (auto *a = h.findTypedAttribute<Imf::StringAttribute>("textureformat"))
            std::snprintf(inf.textureformat, sizeof inf.textureformat, "%s", a->value().c_str());
        if (Imf::hasEnvmap(h))
            std::snprintf(inf.textureformat, sizeof inf.textureformat, "%s",
                          Imf::envmap(h) == Imf::ENVMAP_CUBE ? "CubeFace Environment" : "LatLong Environment");
        *out = x.release();
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory opening an OpenEXR file");
    } catch (...) {
        // A header Imf cannot parse: leave the file to OIIO, which reports
        // it as the reader always has.
        return SAMPLE_OK;
    }
}

extern "C" void io_exr_tiled_info_get(const io_exr_tiled *x, io_reader_info *info) { *info = x->info; }

extern "C" sample_status io_exr_tiled_level_size(io_exr_tiled *x, int k, int *w, int *h, sample_error *err)
{
    if (k < 0 || k >= x->info.nlevels) return sample_error_set(err, SAMPLE_E_CORRUPT, "no mip level %d in the file", k);
    try {
        *w = x->part->levelWidth(k);
        *h = x->part->levelHeight(k);
        return SAMPLE_OK;
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read mip level %d: %s", k, e.what());
    }
}

extern "C" sample_status io_exr_tiled_read(io_exr_tiled *x, int k, io_ptype type, int nchan, void *dst,
                                           sample_error *err)
{
    io_ptype native = x->type == Imf::HALF ? IO_HALF : IO_FLOAT;
    // io_read.c asks for the native type (linear data is stored as read);
    // anything else is a caller bug, not a file problem.
    if (type != native || nchan < 1 || nchan > x->nchan)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "direct OpenEXR read: unsupported request");
    try {
        size_t bytes = x->type == Imf::HALF ? 2 : 4, nc = (size_t)nchan;
        Imath::Box2i dw = x->part->dataWindowForLevel(k);
        Imf::FrameBuffer fb;
        // Row 0 is the data window's min y, the file's first row, as OIIO.
        for (size_t c = 0; c < nc; ++c)
            fb.insert(rgba_names[c], Imf::Slice::Make(x->type, static_cast<char *>(dst) + c * bytes, dw,
                                                      nc * bytes, (size_t)x->part->levelWidth(k) * nc * bytes));
        x->part->setFrameBuffer(fb);
        x->part->readTiles(0, x->part->numXTiles(k) - 1, 0, x->part->numYTiles(k) - 1, k);
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory reading level %d", k);
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read the tiles of level %d: %s", k, e.what());
    } catch (...) {
        return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read the tiles of level %d", k);
    }
}

extern "C" void io_exr_tiled_close(io_exr_tiled *x) { delete x; }

extern "C" void io_exr_direct_count(void) { direct_reads.fetch_add(1, std::memory_order_relaxed); }

extern "C" unsigned long io_exr_direct_reads(void) { return direct_reads.load(std::memory_order_relaxed); }
