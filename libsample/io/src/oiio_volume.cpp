// OpenImageIO: a volume image's slices (doc/volumes.md, "Files"): the
// subimages of a multi-page TIFF or a multi-part OpenEXR, or the z extent
// of an image that has one (ImageSpec::depth > 1, a TIFF with the
// ImageDepth tag; OIIO 2.4 ImageInput::read_image reads every z).
#include "io_internal.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>

using namespace OIIO;

// Refuse before allocating: the library's per-side limit, and its texel
// byte limit (16 GiB) on the float RGBA copy.
static sample_status check_size(const char *path, int w, int h, long d, int nch, sample_error *err)
{
    if (w <= 0 || h <= 0 || d <= 0 || w > SAMPLE_MAX_SIZE || h > SAMPLE_MAX_SIZE || d > SAMPLE_MAX_SIZE)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "'%s': volume %d x %d x %ld is outside 1 ... %d per side",
                                path, w, h, d, SAMPLE_MAX_SIZE);
    if ((double)w * h * (double)d * nch * sizeof(float) > (double)((uint64_t)1 << 34))
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "'%s': volume %d x %d x %ld of %d channels is over 16 GiB",
                                path, w, h, d, nch);
    return SAMPLE_OK;
}

static sample_status read_slices(ImageInput *in, const char *path, io_volume *v, sample_error *err)
{
    const ImageSpec spec = in->spec();
    const int nch = spec.nchannels < 4 ? spec.nchannels : 4;
    long d = spec.depth > 1 ? spec.depth : 0;
    sample_status st;
    size_t slice;
    if (nch < 1) return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s' has no channels", path);
    if (!d)
        while (d <= SAMPLE_MAX_SIZE && in->seek_subimage((int)d, 0)) ++d;
    if ((st = check_size(path, spec.width, spec.height, d, nch, err)) != SAMPLE_OK) return st;
    slice = (size_t)spec.width * spec.height * nch;
    v->data = static_cast<float *>(std::malloc(slice * (size_t)d * sizeof(float)));
    if (!v->data)
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "'%s': no memory for a %d x %d x %ld volume", path,
                                spec.width, spec.height, d);
    v->width = spec.width;
    v->height = spec.height;
    v->depth = (int)d;
    v->channels = nch;
    if (spec.depth > 1) {
        if (!in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, v->data))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s': %s", path, in->geterror().c_str());
        return SAMPLE_OK;
    }
    for (long k = 0; k < d; ++k) {
        if (!in->seek_subimage((int)k, 0))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s': slice %ld cannot be read", path, k);
        const ImageSpec &s = in->spec();
        if (s.width != spec.width || s.height != spec.height || s.depth > 1 || s.nchannels < nch)
            return sample_error_set(err, SAMPLE_E_CORRUPT,
                                    "'%s': slice %ld is %d x %d with %d channels; slice 0 is %d x %d with %d", path,
                                    k, s.width, s.height, s.nchannels, spec.width, spec.height, spec.nchannels);
        if (!in->read_image((int)k, 0, 0, nch, TypeDesc::FLOAT, v->data + (size_t)k * slice))
            return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s': slice %ld: %s", path, k, in->geterror().c_str());
    }
    return SAMPLE_OK;
}

extern "C" sample_status io_oiio_read_volume(const char *path, io_volume *v, sample_error *err)
{
    std::memset(v, 0, sizeof *v);
    try {
        auto in = ImageInput::open(path);
        if (!in)
            return sample_error_set(err, SAMPLE_E_CORRUPT, "cannot read image '%s': %s", path,
                                    OIIO::geterror().c_str());
        sample_status st = read_slices(in.get(), path, v, err);
        if (st != SAMPLE_OK) {
            std::free(v->data);
            v->data = nullptr;
        }
        return st;
    } catch (const std::bad_alloc &) {
        std::free(v->data);
        v->data = nullptr;
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "'%s': out of memory", path);
    } catch (const std::exception &e) {
        std::free(v->data);
        v->data = nullptr;
        return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s': %s", path, e.what());
    }
}
