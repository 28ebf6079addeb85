/* Texture sources shared by the subcommands. */
#include "texload.h"
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

void tl_source_init(tl_source *src) { memset(src, 0, sizeof *src); }

int tl_source_given(const tl_source *src) { return src->raw || src->image; }

int tl_source_flag(const char *sub, int argc, char **argv, int *i, tl_source *src)
{
    const char *v;
    int *size;
    if (cli_opt(argc, argv, i, "--raw", &v)) return src->raw = v, 1;
    if (cli_opt(argc, argv, i, "--image", &v)) return src->image = v, 1;
    if (cli_opt(argc, argv, i, "--levels", &v)) return src->levels = v, 1;
    if (cli_opt(argc, argv, i, "--colorspace", &v)) return src->colorspace = v, 1;
    if (cli_opt(argc, argv, i, "--w", &v)) size = &src->w;
    else if (cli_opt(argc, argv, i, "--h", &v)) size = &src->h;
    else return 0;
    if (!cli_parse_int(v, size) || *size <= 0 || *size > SAMPLE_MAX_SIZE) {
        cli_usage_error(sub, "%s needs a size from 1 to %d, not '%s'", size == &src->w ? "--w" : "--h",
                        SAMPLE_MAX_SIZE, v);
        return -1;
    }
    return 1;
}

/* Read one raw float32 RGBA level of w × h into *data (a cube map's level:
 * `faces` = 6 faces of w × w, h = 6w). */
static int read_raw(const char *sub, const char *path, int w, int h, int faces, void **data)
{
    size_t size, want = (size_t)w * (size_t)h * 4 * sizeof(float);
    const char *why;
    if (!cli_read_file(path, data, &size, &why)) {
        cli_runtime_error(sub, "cannot read '%s': %s", path, why);
        return -1;
    }
    if (size != want) {
        if (faces == 6)
            cli_runtime_error(sub, "'%s' holds %zu bytes; six %d x %d faces of float32 RGBA need %zu", path, size, w,
                              w, want);
        else
            cli_runtime_error(sub, "'%s' holds %zu bytes; %d x %d float32 RGBA needs %zu", path, size, w, h, want);
        free(*data);
        *data = NULL;
        return -1;
    }
    return 0;
}

/* The images of level k of a raw texture: one w × h image, or for a cube
 * map six n × n faces, which a raw file holds one after the other — read
 * as one n × 6n image. */
static int raw_images(const tl_source *src, void *data, int k, sample_image *im)
{
    const int w = src->w >> k > 0 ? src->w >> k : 1, h = src->h >> k > 0 ? src->h >> k : 1;
    int f, faces = src->cube ? 6 : 1;
    for (f = 0; f < faces; ++f) {
        im[f].width = w;
        im[f].height = h;
        im[f].channels = 4;
        im[f].format = SAMPLE_FORMAT_F32;
        im[f].row_stride = 0;
        im[f].data = (const float *)data + (size_t)f * w * h * 4;
    }
    return faces;
}

static int load_raw(const char *sub, tl_source *src, const sample_mip_params *mip, sample_texture **out)
{
    sample_image lv[6 * SAMPLE_MAX_LEVELS];
    void *data[SAMPLE_MAX_LEVELS] = {0};
    int count = 1, k, rc = -1, faces = src->cube ? 6 : 1;
    sample_error err;
    sample_status st;
    if (src->cube) {
        if (src->size <= 0) return cli_usage_error(sub, "--cube needs --size"), -1;
        src->w = src->h = src->size;
    }
    if (src->w <= 0 || src->h <= 0) return cli_usage_error(sub, "--raw needs --w and --h"), -1;
    if (read_raw(sub, src->raw, src->w, faces * src->h, faces, &data[0]) != 0) return -1;
    memset(lv, 0, sizeof lv);
    raw_images(src, data[0], 0, lv);
    if (src->levels) {
        /* As many PREFIX.k.raw as exist, in order. */
        for (k = 1; k < SAMPLE_MAX_LEVELS; ++k) {
            char path[4096];
            FILE *f;
            int w = src->w >> k > 0 ? src->w >> k : 1, h = src->h >> k > 0 ? src->h >> k : 1;
            if (w == 1 && h == 1 && (lv[faces * (k - 1)].width == 1 && lv[faces * (k - 1)].height == 1)) break;
            snprintf(path, sizeof path, "%s.%d.raw", src->levels, k);
            if (!(f = fopen(path, "rb"))) break;
            fclose(f);
            if (read_raw(sub, path, w, faces * h, faces, &data[k]) != 0) goto done;
            raw_images(src, data[k], k, lv + faces * k);
            count = k + 1;
        }
        st = src->cube ? sample_texture_create_cube_levels(lv, count, out, &err)
                       : sample_texture_create_levels(lv, count, out, &err);
    } else {
        st = src->cube ? sample_texture_create_cube(lv, mip, out, &err) : sample_texture_create(&lv[0], mip, out, &err);
    }
    if (st != SAMPLE_OK) {
        cli_runtime_error(sub, "%s", err.message);
        goto done;
    }
    rc = 0;
done:
    for (k = 0; k < SAMPLE_MAX_LEVELS; ++k) free(data[k]);
    return rc;
}

#ifdef TEXSAMPLE_HAVE_IO
void tl_warn_colorspace(const char *sub, const char *path, const sample_io_file_info *file)
{
    if (file->colorspace_unknown)
        fprintf(stderr, "texsample %s: warning: '%s' names colour space '%s', which the OCIO config does not "
                "know; decoded as '%s' (name its space with --colorspace)\n",
                sub, path, file->colorspace, file->colorspace_used);
}
#endif

int tl_load(const char *sub, tl_source *src, const sample_mip_params *mip, sample_texture **out)
{
    *out = NULL;
    if (src->raw) return load_raw(sub, src, mip, out);
#ifdef TEXSAMPLE_HAVE_IO
    {
        sample_io_options opt;
        sample_io_file_info file;
        sample_error err;
        sample_io_options_init(&opt);
        opt.colorspace = src->colorspace;
        opt.file_info = &file;
        opt.mip_wrap_from_file = src->wrap_from_file;
        if (sample_io_read_texture(src->image, &opt, mip, out, &err) != SAMPLE_OK) {
            cli_runtime_error(sub, "%s", err.message);
            return -1;
        }
        tl_warn_colorspace(sub, src->image, &file);
        src->has_wrap = file.has_wrap;
        src->wrap_s = file.wrap_s;
        src->wrap_t = file.wrap_t;
        return 0;
    }
#elif defined(TEXSAMPLE_FRONT)
    (void)mip;
    return TL_IMAGE_PROGRAM;
#else
    return cli_runtime_error(sub, "this build has no image support (libsample_io); use --raw"), -1;
#endif
}
