// oiio_volume: TextureSystem::texture3d() behind a C API (oiio_volume.h).
// A translation of the C API and nothing more, as oiio_ts.cpp.
#include "oiio_volume.h"

#include <Imath/ImathVec.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>
#include <memory>
#include <new>
#include <string>

using namespace OIIO;

struct oiio_vol {
    TextureSystem *sys;
    TextureSystem::TextureHandle *handle;
};

static void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) std::snprintf(err, errlen, "%s", msg.c_str());
}

// A volume TIFF: OpenImageIO 2.4's TIFF writer leaves out the ImageDepth
// tag (its volumes are read-only), so the file is written here, as the
// TIFF 6.0 specification (tiles, section 15) with SGI's ImageDepth (32997)
// and TileDepth (32998) tags that libtiff and OIIO's reader take: little
// endian, uncompressed, contiguous float RGBA, tiles of 16 × 16 × d texels
// ordered x fastest then y, padded with zeros past the right and bottom.
namespace {
struct ifd_entry {
    uint16_t tag, type;
    uint32_t count, value;
};
void put16(std::vector<unsigned char> &b, uint16_t v)
{
    b.push_back((unsigned char)(v & 255));
    b.push_back((unsigned char)(v >> 8));
}
void put32(std::vector<unsigned char> &b, uint32_t v)
{
    put16(b, (uint16_t)(v & 65535));
    put16(b, (uint16_t)(v >> 16));
}
} // namespace

extern "C" int oiio_vol_write(const float *rgba, int w, int h, int d, const char *path, char *err,
                              size_t errlen)
{
    const int T = 16, tx = (w + T - 1) / T, ty = (h + T - 1) / T;
    const uint64_t tile_bytes = (uint64_t)T * T * (uint64_t)d * 16u;
    const uint64_t data = 8, total = data + tile_bytes * (uint64_t)tx * (uint64_t)ty;
    if (w < 1 || h < 1 || d < 1 || total + 4096 > 0xffffffffu) {
        set_err(err, errlen, "oiio_vol_write: a volume of 1 to 4 GiB");
        return -1;
    }
    std::vector<unsigned char> ifd;
    const uint32_t ntiles = (uint32_t)(tx * ty), extra = (uint32_t)total;
    // Arrays after the IFD: BitsPerSample[4], SampleFormat[4], offsets, counts.
    const ifd_entry e0[] = {{256, 4, 1, (uint32_t)w},   {257, 4, 1, (uint32_t)h},
                            {258, 3, 4, 0},             {259, 3, 1, 1},
                            {262, 3, 1, 2},             {277, 3, 1, 4},
                            {284, 3, 1, 1},             {322, 4, 1, (uint32_t)T},
                            {323, 4, 1, (uint32_t)T},   {324, 4, ntiles, 0},
                            {325, 4, ntiles, 0},        {338, 3, 1, 2},
                            {339, 3, 4, 0},             {32997, 4, 1, (uint32_t)d},
                            {32998, 4, 1, (uint32_t)d}};
    const uint32_t n = sizeof e0 / sizeof e0[0];
    const uint32_t arrays = extra + 2 + 12 * n + 4;
    const uint32_t bits_at = arrays, fmt_at = arrays + 8, off_at = arrays + 16,
                   cnt_at = off_at + 4 * ntiles;
    put16(ifd, (uint16_t)n);
    for (const ifd_entry &e : e0) {
        uint32_t v = e.value;
        if (e.tag == 258) v = bits_at;
        if (e.tag == 339) v = fmt_at;
        if (e.tag == 324) v = ntiles == 1 ? (uint32_t)data : off_at;
        if (e.tag == 325) v = ntiles == 1 ? (uint32_t)tile_bytes : cnt_at;
        put16(ifd, e.tag);
        put16(ifd, e.type);
        put32(ifd, e.count);
        // A SHORT value sits in the low half of the field (little endian).
        put32(ifd, v);
    }
    put32(ifd, 0); // no next IFD
    for (int k = 0; k < 4; ++k) put16(ifd, 32);
    for (int k = 0; k < 4; ++k) put16(ifd, 3); // IEEE float
    for (uint32_t k = 0; k < ntiles; ++k) put32(ifd, (uint32_t)(data + tile_bytes * k));
    for (uint32_t k = 0; k < ntiles; ++k) put32(ifd, (uint32_t)tile_bytes);
    std::FILE *f = std::fopen(path, "wb");
    if (!f) {
        set_err(err, errlen, std::string("cannot write ") + path);
        return -1;
    }
    std::vector<unsigned char> head;
    head.push_back('I');
    head.push_back('I');
    put16(head, 42);
    put32(head, extra);
    bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
    std::vector<float> tile((size_t)T * T * (size_t)d * 4);
    for (int j0 = 0; ok && j0 < ty; ++j0)
        for (int i0 = 0; ok && i0 < tx; ++i0) {
            std::fill(tile.begin(), tile.end(), 0.0f);
            for (int k = 0; k < d; ++k)
                for (int j = 0; j < T && j0 * T + j < h; ++j)
                    for (int i = 0; i < T && i0 * T + i < w; ++i)
                        std::memcpy(&tile[(((size_t)k * T + j) * T + i) * 4],
                                    rgba + (((size_t)k * h + (size_t)(j0 * T + j)) * w + (size_t)(i0 * T + i)) * 4,
                                    16);
            ok = std::fwrite(tile.data(), 1, tile.size() * 4, f) == tile.size() * 4;
        }
    ok = ok && std::fwrite(ifd.data(), 1, ifd.size(), f) == ifd.size();
    ok = (std::fclose(f) == 0) && ok;
    if (!ok) {
        std::remove(path);
        set_err(err, errlen, std::string("cannot write ") + path);
        return -1;
    }
    return 0;
}

extern "C" oiio_vol *oiio_vol_open(const char *path, char *err, size_t errlen)
{
    oiio_vol *v = new (std::nothrow) oiio_vol;
    if (!v) return nullptr;
    v->sys = TextureSystem::create(false);
    v->handle = v->sys ? v->sys->get_texture_handle(ustring(path)) : nullptr;
    const ImageSpec *spec = v->handle ? v->sys->imagespec(v->handle, nullptr, 0) : nullptr;
    if (!spec || spec->depth < 2) {
        // OIIO 2.4's TIFF reader takes the TileDepth tag but not ImageDepth
        // (the spec comes back with depth 1), so a TIFF volume reads as
        // its first slice; say so rather than time a 2D lookup.
        set_err(err, errlen, std::string("OpenImageIO reads ") + path +
                                 (spec ? " with depth " + std::to_string(spec->depth) +
                                             " (tile depth " + std::to_string(spec->tile_depth) +
                                             "), not as a volume"
                                       : ": " + (v->sys ? v->sys->geterror() : std::string())));
        oiio_vol_close(v);
        return nullptr;
    }
    return v;
}

extern "C" void oiio_vol_close(oiio_vol *v)
{
    if (!v) return;
    if (v->sys) TextureSystem::destroy(v->sys);
    delete v;
}

extern "C" int oiio_vol_sample(oiio_vol *v, int linear, sample_wrap wrap, const sample_query3 *q,
                               size_t n, float *rgba, char *err, size_t errlen)
{
    const char *name = wrap == SAMPLE_WRAP_REPEAT            ? "periodic"
                       : wrap == SAMPLE_WRAP_MIRRORED_REPEAT ? "mirror"
                       : wrap == SAMPLE_WRAP_CLAMP_TO_EDGE   ? "clamp"
                       : wrap == SAMPLE_WRAP_CLAMP_TO_BORDER ? "black"
                                                             : nullptr;
    if (!v || !name || (n && (!q || !rgba))) {
        set_err(err, errlen, name ? "oiio_vol_sample: bad argument"
                                  : "OpenImageIO has no wrap mode like this one");
        return -1;
    }
    TextureOpt opt;
    opt.swrap = opt.twrap = opt.rwrap = TextureOpt::decode_wrapmode(name);
    opt.interpmode = linear ? TextureOpt::InterpBilinear : TextureOpt::InterpClosest;
    opt.mipmode = TextureOpt::MipModeNoMIP;
    TextureSystem::Perthread *pt = v->sys->get_perthread_info();
    const Imath::V3f dz(0.0f, 0.0f, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        const sample_query3 &k = q[i];
        if (!v->sys->texture3d(v->handle, pt, opt, Imath::V3f(k.p[0], k.p[1], k.p[2]),
                               Imath::V3f(k.dpdx[0], k.dpdx[1], k.dpdx[2]),
                               Imath::V3f(k.dpdy[0], k.dpdy[1], k.dpdy[2]), dz, 4, rgba + 4 * i)) {
            set_err(err, errlen, "texture3d lookup failed: " + v->sys->geterror());
            return -1;
        }
    }
    return 0;
}
