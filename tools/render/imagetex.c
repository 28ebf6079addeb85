/*
 * Image textures of scene files: read through libsample_io (any format
 * OpenImageIO reads, converted to linear by OpenColorIO), mip-mapped with
 * the texture's wrap modes. Without libsample_io in the build, a scene that
 * names an image is refused with a message instead.
 */
#include "rn_internal.h"

#include <stdint.h>
#include <stdio.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"

/* base_dir/file, or file alone when it is absolute or there is no base. */
static int resolve(const char *base_dir, const char *file, char *out, size_t outlen)
{
    int n = base_dir && base_dir[0] && file[0] != '/'
                ? snprintf(out, outlen, "%s/%s", base_dir, file)
                : snprintf(out, outlen, "%s", file);
    return n >= 0 && (size_t)n < outlen;
}

int image_load(rn_texture *t, const char *base_dir, double max_texels, double *texels, char *err,
               size_t errlen)
{
    char path[4096];
    sample_io_options o;
    sample_mip_params mip;
    sample_texture_info info;
    sample_error e;
    FILE *f;
    if (!resolve(base_dir, t->path, path, sizeof path)) {
        rn_seterr(err, errlen, "image texture '%s': path too long", t->path);
        return 0;
    }
    /* Checked here so that a missing file (e.g. a built-in scene whose
     * testimages/ file is absent) says so plainly, not as a decoder error. */
    if (!(f = fopen(path, "rb"))) {
        rn_seterr(err, errlen, "image texture '%s' not found (looked for '%s')", t->path, path);
        return 0;
    }
    fclose(f);
    sample_io_options_init(&o);
    o.colorspace = t->colorspace[0] ? t->colorspace : NULL;
    /* The scene's texel budget, as float RGBA bytes (sample_io's measure):
     * a file claiming more is refused before its pixels are decoded. */
    o.max_bytes = max_texels * 16.0 >= (double)SIZE_MAX ? SIZE_MAX
                  : max_texels >= 1.0              ? (size_t)(max_texels * 16.0)
                                                   : 1;
    sample_mip_params_init(&mip);
    mip.wrap_s = t->wrap_s;
    mip.wrap_t = t->wrap_t;
    if (sample_io_read_texture(path, &o, &mip, &t->tex, &e) != SAMPLE_OK) {
        t->tex = NULL;
        rn_seterr(err, errlen, "image texture '%s': %s", t->path, e.message);
        return 0;
    }
    sample_texture_info_get(t->tex, &info);
    *texels = (double)info.width * (double)info.height;
    return 1;
}

#else

int image_load(rn_texture *t, const char *base_dir, double max_texels, double *texels, char *err,
               size_t errlen)
{
    (void)base_dir;
    (void)max_texels;
    *texels = 0;
    rn_seterr(err, errlen, "image texture '%s': this build has no image support (libsample_io)",
              t->path);
    return 0;
}

#endif
