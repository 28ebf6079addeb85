// OpenEXR: tiled, mip-mapped writer (OpenEXR 3.1 Imf tiled API; file layout
// per "Technical Introduction to OpenEXR", Tiles and Multi-resolution:
// MIPMAP_LEVELS with ROUND_DOWN gives level k = max(1, ⌊w/2^k⌋) ×
// max(1, ⌊h/2^k⌋), libsample's level rule, down to 1 × 1). The checks and
// the level pixels are io_mip_write.c's.
#include "io_internal.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfEnvmapAttribute.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTileDescription.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <cstdlib>
#include <memory>
#include <string>

extern "C" sample_status io_exr_write_mip(const char *tmp_path, const sample_texture *tex,
                                          const sample_io_exr_options *o, const io_colour_label *label,
                                          io_env env, size_t *overflows, sample_error *err)
{
    static const char *const rgba[4] = {"R", "G", "B", "A"};
    const char *const *names = o->channel_names ? o->channel_names : rgba;
    sample_texture_info inf;
    sample_texture_info_get(tex, &inf);
    bool use_float = o->type == SAMPLE_IO_TYPE_FLOAT || (o->type == SAMPLE_IO_TYPE_AUTO && o->use_float);
    sample_io_type type = use_float ? SAMPLE_IO_TYPE_FLOAT : SAMPLE_IO_TYPE_HALF;
    try {
        Imf::PixelType pt = use_float ? Imf::FLOAT : Imf::HALF;
        Imf::Header hdr(inf.width, inf.height);
        hdr.setTileDescription(Imf::TileDescription((unsigned)o->tile_w, (unsigned)o->tile_h,
                                                    inf.levels > 1 ? Imf::MIPMAP_LEVELS : Imf::ONE_LEVEL,
                                                    Imf::ROUND_DOWN));
        for (int c = 0; c < inf.channels; ++c) hdr.channels().insert(names[c], Imf::Channel(pt));
        hdr.compression() = Imf::ZIP_COMPRESSION; // maketx's default, lossless
        std::string wrap = std::string(io_wrap_word(o->wrap_s)) + "," + io_wrap_word(o->wrap_t);
        // An environment map says so twice: OpenEXR's envmap attribute
        // (ImfEnvmap.h) and the textureformat string OpenImageIO's
        // TextureSystem reads; a lat-long map as maketx --envlatl labels it
        // (y up, periodic in s, clamped in t).
        if (env == IO_ENV_LATLONG) {
            Imf::addEnvmap(hdr, Imf::ENVMAP_LATLONG);
            hdr.insert("textureformat", Imf::StringAttribute("LatLong Environment"));
            hdr.insert("oiio:updirection", Imf::StringAttribute("y"));
            wrap = "periodic,clamp";
            hdr.insert("oiio:sampleborder", Imf::IntAttribute(0));
        } else if (env == IO_ENV_CUBE) {
            Imf::addEnvmap(hdr, Imf::ENVMAP_CUBE);
            hdr.insert("textureformat", Imf::StringAttribute("CubeFace Environment"));
            hdr.insert("oiio:sampleborder", Imf::IntAttribute(0));
        }
        hdr.insert("wrapmodes", Imf::StringAttribute(wrap));
        // OpenEXR defines colour as premultiplied by alpha; a writer handed
        // straight colour says so rather than leaving a reader to guess.
        if (o->alpha_channel >= 0)
            hdr.insert("libsample:alpha", Imf::StringAttribute(o->premultiplied ? "premultiplied" : "straight"));
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
        size_t bytes = use_float ? 4 : 2, nc = (size_t)inf.channels;
        for (int l = 0; l < out.numLevels(); ++l) {
            int lw = out.levelWidth(l);
            void *raw = nullptr;
            sample_status st = io_level_pixels(tex, l, type, nullptr, nullptr, o->half_clamp, overflows, &raw, err);
            if (st != SAMPLE_OK) return st;
            std::unique_ptr<char, void (*)(void *)> px(static_cast<char *>(raw), std::free);
            Imf::FrameBuffer fb;
            for (size_t c = 0; c < nc; ++c)
                fb.insert(names[c], Imf::Slice(pt, px.get() + c * bytes, nc * bytes, (size_t)lw * nc * bytes));
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
