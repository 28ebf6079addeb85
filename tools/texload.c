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

/* Read one raw float32 RGBA level of w × h into *data. */
static int read_raw(const char *sub, const char *path, int w, int h, void **data)
{
    size_t size, want = (size_t)w * (size_t)h * 4 * sizeof(float);
    const char *why;
    if (!cli_read_file(path, data, &size, &why)) {
        cli_runtime_error(sub, "cannot read '%s': %s", path, why);
        return -1;
    }
    if (size != want) {
        cli_runtime_error(sub, "'%s' holds %zu bytes; %d x %d float32 RGBA needs %zu", path, size, w, h, want);
        free(*data);
        *data = NULL;
        return -1;
    }
    return 0;
}

static int load_raw(const char *sub, const tl_source *src, const sample_mip_params *mip, sample_texture **out)
{
    sample_image lv[SAMPLE_MAX_LEVELS];
    void *data[SAMPLE_MAX_LEVELS] = {0};
    int count = 1, k, rc = -1;
    sample_error err;
    if (src->w <= 0 || src->h <= 0) return cli_usage_error(sub, "--raw needs --w and --h"), -1;
    if (read_raw(sub, src->raw, src->w, src->h, &data[0]) != 0) return -1;
    memset(lv, 0, sizeof lv);
    lv[0].width = src->w;
    lv[0].height = src->h;
    lv[0].channels = 4;
    lv[0].format = SAMPLE_FORMAT_F32;
    lv[0].data = data[0];
    if (src->levels) {
        /* As many PREFIX.k.raw as exist, in order. */
        for (k = 1; k < SAMPLE_MAX_LEVELS; ++k) {
            char path[4096];
            FILE *f;
            int w = src->w >> k > 0 ? src->w >> k : 1, h = src->h >> k > 0 ? src->h >> k : 1;
            if (w == 1 && h == 1 && (lv[k - 1].width == 1 && lv[k - 1].height == 1)) break;
            snprintf(path, sizeof path, "%s.%d.raw", src->levels, k);
            if (!(f = fopen(path, "rb"))) break;
            fclose(f);
            if (read_raw(sub, path, w, h, &data[k]) != 0) goto done;
            lv[k] = lv[0];
            lv[k].width = w;
            lv[k].height = h;
            lv[k].data = data[k];
            count = k + 1;
        }
        if (sample_texture_create_levels(lv, count, out, &err) != SAMPLE_OK) {
            cli_runtime_error(sub, "%s", err.message);
            goto done;
        }
    } else if (sample_texture_create(&lv[0], mip, out, &err) != SAMPLE_OK) {
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
