// The texture system's one question to OpenImageIO that libsample_io's
// image reader does not ask (doc/texture-system.md, "Cube maps and
// volumes"): is a file a volume as sample_io_read_volume reads one — an
// image with a z extent of its own (ImageSpec::depth > 1), or several
// subimages (a multi-page TIFF, a multi-part OpenEXR) of one size?
#include "io_internal.h"

#include <OpenImageIO/imageio.h>

using namespace OIIO;

extern "C" int io_ts_probe_volume(const char *path); // texsys_internal.h

extern "C" int io_ts_probe_volume(const char *path)
{
    try {
        auto in = ImageInput::open(path);
        if (!in) {
            (void)OIIO::geterror(); // not an image: sample_texsys_open says so
            return 0;
        }
        const ImageSpec spec = in->spec();
        int volume = spec.depth > 1;
        if (!volume && in->seek_subimage(1, 0))
            volume = in->spec().width == spec.width && in->spec().height == spec.height && in->spec().depth <= 1;
        in->close();
        return volume;
    } catch (...) {
        return 0;
    }
}
