// OpenImageIO: write one picture (OIIO 2.4 ImageOutput,
// https://openimageio.readthedocs.io/en/v2.4.x/imageoutput.html).
#include "io_internal.h"

#include <OpenImageIO/imageio.h>

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
