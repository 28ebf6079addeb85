// OpenImageIO writers (OIIO 2.4 ImageOutput,
// https://openimageio.readthedocs.io/en/v2.4.x/imageoutput.html): one picture,
// or the levels of a texture as a tiled, mip-mapped TIFF.
#include "io_internal.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <memory>
#include <string>

using namespace OIIO;

extern "C" sample_status io_oiio_write(const char *final_path, const char *tmp_path, const void *px, io_ptype type,
                                       int w, int h, int nchan, const char *const *names, const io_colour_label *label,
                                       sample_error *err)
{
    static const TypeDesc types[] = {TypeDesc::UINT8, TypeDesc::UINT16, TypeDesc::HALF, TypeDesc::FLOAT};
    try {
        // The writer is chosen by the final name; the pixels go to the
        // temporary one (OIIO's open() takes any name once created).
        auto out = ImageOutput::create(final_path);
        if (!out) {
            std::string msg = OIIO::geterror();
            return sample_error_set(err, SAMPLE_E_UNSUPPORTED, "no image writer for '%s': %s", final_path, msg.c_str());
        }
        if (nchan == 4 && !names && !out->supports("alpha"))
            return sample_error_set(err, SAMPLE_E_UNSUPPORTED, "%s files cannot store alpha; write 3 channels",
                           out->format_name());
        ImageSpec spec(w, h, nchan, types[type]);
        if (names) {
            spec.channelnames.assign(names, names + nchan);
            spec.alpha_channel = -1; // named data channels are never alpha
        }
        // Store the values as given: no premultiplied/straight conversion.
        spec.attribute("oiio:UnassociatedAlpha", 1);
        if (label) {
            spec.attribute("oiio:ColorSpace", label->name);
            // OpenEXR's standard chromaticities attribute (OIIO passes a
            // float[8] "chromaticities" through). OIIO 2.4's OpenEXR writer
            // drops oiio:ColorSpace; later versions keep it.
            if (label->has_chromaticities)
                spec.attribute("chromaticities", TypeDesc(TypeDesc::FLOAT, 8), label->chromaticities);
        }
        if (!out->open(tmp_path, spec) || !out->write_image(types[type], px) || !out->close()) {
            std::string msg = out->geterror();
            return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path, msg.c_str());
        }
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory writing '%s'", final_path);
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path, e.what());
    }
}

// Every level of a texture as one tiled TIFF, level 0 first, each later level
// appended as a MIP level (ImageOutput::AppendMIPLevel), as maketx writes
// .tx files; the pixels come from io_level_pixels.
extern "C" sample_status io_oiio_write_mip(const char *final_path, const char *tmp_path, const sample_texture *tex,
                                           const sample_io_exr_options *o, sample_io_type type,
                                           const io_colour *col, const char *cs, const io_colour_label *label,
                                           size_t *overflows, sample_error *err)
{
    static const TypeDesc types[] = {TypeDesc::UINT8, TypeDesc::UINT16, TypeDesc::HALF, TypeDesc::FLOAT};
    static const char *const rgba[4] = {"R", "G", "B", "A"};
    const char *const *names = o->channel_names ? o->channel_names : rgba;
    sample_texture_info inf;
    sample_texture_info_get(tex, &inf);
    TypeDesc td = types[type - 1];
    try {
        auto out = ImageOutput::create(final_path);
        // OIIO 2.4's TIFF writer answers supports("mipmap") with false yet
        // appends MIP levels (reduced-resolution directories, as maketx
        // writes them); tiles are what it must have.
        if (!out || !out->supports("tiles"))
            return sample_error_set(err, SAMPLE_E_UNSUPPORTED, "no tiled mip-mapped writer for '%s'", final_path);
        size_t done = 0, total = 0, nc = (size_t)inf.channels, px_bytes = nc * td.size();
        for (int l = 0; l < inf.levels; ++l) {
            int lw, lh;
            sample_texture_level_size(tex, l, &lw, &lh);
            total += (size_t)((lh + o->tile_h - 1) / o->tile_h);
        }
        for (int l = 0; l < inf.levels; ++l) {
            int lw, lh;
            sample_texture_level_size(tex, l, &lw, &lh);
            ImageSpec spec(lw, lh, inf.channels, td);
            spec.tile_width = o->tile_w;
            spec.tile_height = o->tile_h;
            spec.channelnames.assign(names, names + inf.channels);
            spec.alpha_channel = o->alpha_channel;
            spec.attribute("compression", "zip");
            spec.attribute("textureformat", "Plain Texture");
            spec.attribute("wrapmodes", std::string(io_wrap_word(o->wrap_s)) + "," + io_wrap_word(o->wrap_t));
            spec.attribute("oiio:ColorSpace", label->name);
            // TIFF's ExtraSamples tag says associated (premultiplied) or
            // unassociated alpha; OIIO writes the former unless told.
            if (o->alpha_channel >= 0 && !o->premultiplied) spec.attribute("oiio:UnassociatedAlpha", 1);
            if (!out->open(tmp_path, spec, l == 0 ? ImageOutput::Create : ImageOutput::AppendSubimage))
                return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path, out->geterror().c_str());
            void *raw = nullptr;
            sample_status st = io_level_pixels(tex, l, type, col, cs, o->half_clamp, overflows, &raw, err);
            if (st != SAMPLE_OK) return st;
            std::unique_ptr<char, void (*)(void *)> px(static_cast<char *>(raw), std::free);
            for (int y = 0; y < lh; y += o->tile_h) {
                int y1 = y + o->tile_h < lh ? y + o->tile_h : lh;
                if (!out->write_tiles(0, lw, y, y1, 0, 1, td, px.get() + (size_t)y * (size_t)lw * px_bytes,
                                      (stride_t)px_bytes, (stride_t)((size_t)lw * px_bytes)))
                    return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path,
                                            out->geterror().c_str());
                if (o->progress) o->progress(o->progress_user, ++done, total);
            }
        }
        if (!out->close())
            return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path, out->geterror().c_str());
        return SAMPLE_OK;
    } catch (const std::bad_alloc &) {
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "out of memory writing '%s'", final_path);
    } catch (const std::exception &e) {
        return sample_error_set(err, SAMPLE_E_IO, "cannot write '%s': %s", final_path, e.what());
    }
}
