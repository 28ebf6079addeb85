/*
 * Rendered images to files, through libsample_io (temporary file and
 * rename, so a failed write leaves nothing behind): the picture as linear
 * float OpenEXR or sRGB 8-bit PNG, the per-pixel buffers as one float
 * OpenEXR with named channels. Without libsample_io in the build both
 * refuse with a message.
 */
#include "rn_internal.h"

#include <stdlib.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

/* "Z" and the "N." layer are the names OpenEXR viewers know for depth and
 * normals; the rest are render_image's buffers in their order. */
const char *const render_buffer_names[RENDER_BUFFER_CHANNELS] = {
    "s", "t", "dsdx", "dtdx", "dsdy", "dtdy", "lod", "texels", "Z", "N.X", "N.Y", "N.Z",
    "object", "prim"};

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

int render_output_kind(const char *path)
{
    return ends_with(path, ".exr") ? 1 : ends_with(path, ".png") ? 2 : 0;
}

#ifdef TEXSAMPLE_HAVE_IO

int render_image_write(const render_image *img, const char *path, char *err, size_t errlen)
{
    sample_io_write_options o;
    sample_error e;
    int kind = render_output_kind(path);
    if (!kind) {
        rn_seterr(err, errlen, "'%s': the image is .exr or .png", path);
        return -1;
    }
    /* .exr keeps the reference values unrounded (float, not the half that
     * sample_io picks by default); .png is sRGB by sample_io's rule. */
    sample_io_write_options_init(&o);
    if (kind == 1) o.type = SAMPLE_IO_TYPE_FLOAT;
    if (sample_io_write_image_ex(path, img->rgba, img->width, img->height, kind == 1 ? 4 : 3, &o,
                                 &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "%s", e.message);
        return -1;
    }
    return 0;
}

int render_image_write_buffers(const render_image *img, const char *path, char *err,
                               size_t errlen)
{
    enum { N = RENDER_BUFFER_CHANNELS };
    size_t n = (size_t)img->width * (size_t)img->height, k;
    sample_error e;
    sample_status st;
    float *b;
    if (render_output_kind(path) != 1) {
        rn_seterr(err, errlen, "'%s': the buffers are an .exr file", path);
        return -1;
    }
    if (!img->st || !img->jacobian || !img->lod || !img->texels || !img->depth || !img->normal ||
        !img->id) {
        rn_seterr(err, errlen, "the image was rendered without all of its buffers");
        return -1;
    }
    if (!(b = malloc(n * N * sizeof *b))) {
        rn_seterr(err, errlen, "out of memory for the buffers of a %d x %d image", img->width,
                  img->height);
        return -1;
    }
    for (k = 0; k < n; ++k) {
        float *o = b + N * k;
        memcpy(o, img->st + 2 * k, 2 * sizeof *o);
        memcpy(o + 2, img->jacobian + 4 * k, 4 * sizeof *o);
        o[6] = img->lod[k];
        o[7] = img->texels[k];
        o[8] = img->depth[k];
        memcpy(o + 9, img->normal + 3 * k, 3 * sizeof *o);
        memcpy(o + 12, img->id + 2 * k, 2 * sizeof *o);
    }
    st = sample_io_write_channels(path, b, img->width, img->height, N, render_buffer_names, &e);
    free(b);
    if (st != SAMPLE_OK) {
        rn_seterr(err, errlen, "%s", e.message);
        return -1;
    }
    return 0;
}

#else

int render_image_write(const render_image *img, const char *path, char *err, size_t errlen)
{
    (void)img;
    rn_seterr(err, errlen, "cannot write '%s': this build has no image output (libsample_io)", path);
    return -1;
}

int render_image_write_buffers(const render_image *img, const char *path, char *err,
                               size_t errlen)
{
    return render_image_write(img, path, err, errlen);
}

#endif
