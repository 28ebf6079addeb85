// OpenEXR: tiled, mip-mapped writer (OpenEXR 3.1 Imf tiled API; file layout
// per "Technical Introduction to OpenEXR", Tiles and Multi-resolution:
// MIPMAP_LEVELS with ROUND_DOWN gives level k = max(1, ⌊w/2^k⌋) ×
// max(1, ⌊h/2^k⌋), libsample's level rule, down to 1 × 1).
#include "io_internal.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

static int full_chain(int w, int h)
{
    int n = 1, m = w > h ? w : h;
    while (m > 1) m >>= 1, ++n;
    return n;
}

extern "C" sample_status io_exr_write_mip(const char *tmp_path, const sample_texture *tex,
                                          const sample_io_exr_options *o, const io_colour_label *label,
                                          sample_error *err)
{
    static const char *const names[4] = {"R", "G", "B", "A"};
    sample_texture_info inf;
    sample_texture_info_get(tex, &inf);
    bool mipmapped = inf.levels > 1;
    if (mipmapped && inf.levels != full_chain(inf.width, inf.height))
        return sample_error_set(err, SAMPLE_E_UNSUPPORTED,
                       "the texture has %d of its %d levels; a mip-mapped OpenEXR file holds all of them", inf.levels,
                       full_chain(inf.width, inf.height));
    try {
        Imf::PixelType pt = o->use_float ? Imf::FLOAT : Imf::HALF;
        Imf::Header hdr(inf.width, inf.height);
        hdr.setTileDescription(Imf::TileDescription((unsigned)o->tile_w, (unsigned)o->tile_h,
                                                    mipmapped ? Imf::MIPMAP_LEVELS : Imf::ONE_LEVEL,
                                                    Imf::ROUND_DOWN));
        for (int c = 0; c < inf.channels; ++c) hdr.channels().insert(names[c], Imf::Channel(pt));
        hdr.compression() = Imf::ZIP_COMPRESSION; // maketx's default, lossless
        std::string wrap = std::string(io_wrap_word(o->wrap_s)) + "," + io_wrap_word(o->wrap_t);
        hdr.insert("wrapmodes", Imf::StringAttribute(wrap));
        // The working space by its own name (OpenImageIO reads it back as
        // oiio:ColorSpace) and, where known, OpenEXR's standard
        // chromaticities (absent, a reader assumes Rec.709).
        if (label) {
            hdr.insert("oiio:ColorSpace", Imf::StringAttribute(label->name));
            if (label->has_chromaticities) {
                const float *c = label->chromaticities;
                Imf::addChromaticities(hdr, Imf::Chromaticities(Imath::V2f(c[0], c[1]), Imath::V2f(c[2], c[3]),
                                                                Imath::V2f(c[4], c[5]), Imath::V2f(c[6], c[7])));
            }
        }
        Imf::TiledOutputFile out(tmp_path, hdr);

        size_t done = 0, total = 0;
        for (int l = 0; l < out.numLevels(); ++l) total += (size_t)out.numYTiles(l);
        size_t bytes = o->use_float ? 4 : 2, nc = (size_t)inf.channels;
        for (int l = 0; l < out.numLevels(); ++l) {
            int lw = out.levelWidth(l), lh = out.levelHeight(l);
            std::vector<unsigned char> px((size_t)lw * (size_t)lh * nc * bytes);
            for (int j = 0; j < lh; ++j)
                for (int i = 0; i < lw; ++i) {
                    float v[4];
                    sample_texture_texel(tex, l, i, j, v);
                    unsigned char *p = px.data() + (((size_t)j * (size_t)lw + (size_t)i) * nc) * bytes;
                    for (size_t c = 0; c < nc; ++c) {
                        if (o->use_float) {
                            std::memcpy(p + 4 * c, &v[c], 4);
                        } else {
                            uint16_t hv = sample_float_to_half(v[c]);
                            std::memcpy(p + 2 * c, &hv, 2);
                        }
                    }
                }
            Imf::FrameBuffer fb;
            for (size_t c = 0; c < nc; ++c)
                fb.insert(names[c], Imf::Slice(pt, reinterpret_cast<char *>(px.data() + c * bytes), nc * bytes,
                                               (size_t)lw * nc * bytes));
            out.setFrameBuffer(fb);
            for (int ty = 0; ty < out.numYTiles(l); ++ty) {
                out.writeTiles(0, out.numXTiles(l) - 1, ty, ty, l);
                if (o->progress) o->progress(o->progress_user, ++done, total);
            }
        }
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory writing a mip-mapped OpenEXR file");
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_IO, "cannot write the OpenEXR file: %s", e.what());
    }
}
