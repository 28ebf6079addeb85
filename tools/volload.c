/* Volumes from raw files (volload.h). */
#include "volload.h"
#include "cli.h"
#include "texload.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int vl_given(int argc, char **argv)
{
    int i;
    for (i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--volume") == 0 || strncmp(argv[i], "--volume=", 9) == 0) return 1;
    return 0;
}

int vl_source_flag(const char *sub, int argc, char **argv, int *i, vl_source *src)
{
    static const char *const names[3] = {"--w", "--h", "--d"};
    const char *v;
    int a;
    if (cli_opt(argc, argv, i, "--volume", &v)) return src->path = v, 1;
    if (cli_opt(argc, argv, i, "--levels", &v)) return src->levels = v, 1;
    for (a = 0; a < 3; ++a)
        if (cli_opt(argc, argv, i, names[a], &v)) {
            if (!cli_parse_int(v, &src->dims[a]) || src->dims[a] <= 0 || src->dims[a] > SAMPLE_MAX_SIZE) {
                cli_usage_error(sub, "%s needs a size from 1 to %d, not '%s'", names[a], SAMPLE_MAX_SIZE, v);
                return -1;
            }
            return 1;
        }
    return 0;
}

int vl_mipgen_flag(const char *sub, int argc, char **argv, int *i, sample_mip_params *mip)
{
    const char *v;
    int m;
    if (!cli_opt(argc, argv, i, "--mipgen", &v)) return 0;
    if ((m = sample_mipgen_parse(v)) < 0) return cli_usage_error(sub, "--mipgen: unknown kernel '%s'", v), -1;
    mip->filter = (sample_mipgen)m;
    return 1;
}

/* A raw volume has its size on the command line; an image file has it in
 * its header. */
static int vl_raw(const vl_source *src) { return src->dims[0] || src->dims[1] || src->dims[2]; }

int vl_source_check(const char *sub, const vl_source *src)
{
    if (!src->path) return cli_usage_error(sub, "--volume needs a file");
    if (vl_raw(src) && (!src->dims[0] || !src->dims[1] || !src->dims[2]))
        return cli_usage_error(sub, "a raw --volume needs all of --w, --h and --d");
    if (!vl_raw(src) && src->levels) return cli_usage_error(sub, "--levels is for raw volumes (--w, --h, --d)");
    return 0;
}

/* A volume image through libsample_io. */
static int load_image(const char *sub, const vl_source *src, const sample_mip_params *mip, sample_texture **out)
{
#ifdef TEXSAMPLE_HAVE_IO
    sample_error err;
    if (sample_io_read_volume(src->path, mip, out, &err) != SAMPLE_OK) return cli_runtime_error(sub, "%s", err.message), -1;
    return 0;
#elif defined(TEXSAMPLE_FRONT)
    (void)sub, (void)src, (void)mip, (void)out;
    return TL_IMAGE_PROGRAM;
#else
    (void)src, (void)mip, (void)out;
    return cli_runtime_error(sub, "this build has no image support (libsample_io); give a raw volume"), -1;
#endif
}

/* Read the raw float32 RGBA volume of dims at path into *data. */
static int read_volume(const char *sub, const char *path, const int dims[3], void **data)
{
    size_t size, want = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2] * 4 * sizeof(float);
    const char *why;
    if (!cli_read_file(path, data, &size, &why)) {
        cli_runtime_error(sub, "cannot read '%s': %s", path, why);
        return -1;
    }
    if (size != want) {
        cli_runtime_error(sub, "'%s' holds %zu bytes; %d x %d x %d float32 RGBA needs %zu", path, size, dims[0],
                          dims[1], dims[2], want);
        free(*data);
        *data = NULL;
        return -1;
    }
    return 0;
}

int vl_load(const char *sub, const vl_source *src, const sample_mip_params *mip, sample_texture **out)
{
    sample_volume lv[SAMPLE_MAX_LEVELS];
    void *data[SAMPLE_MAX_LEVELS] = {0};
    sample_error err;
    int count = 1, k, a, rc = -1;
    const int *dims = src->dims;
    if (!vl_raw(src)) return load_image(sub, src, mip, out);
    if (read_volume(sub, src->path, dims, &data[0]) != 0) return -1;
    memset(lv, 0, sizeof lv);
    lv[0] = (sample_volume){dims[0], dims[1], dims[2], 4, SAMPLE_FORMAT_F32, data[0], 0, 0};
    for (k = 1; src->levels && k < SAMPLE_MAX_LEVELS; ++k) {
        char name[4096];
        int d[3];
        FILE *f;
        if (lv[k - 1].width == 1 && lv[k - 1].height == 1 && lv[k - 1].depth == 1) break;
        for (a = 0; a < 3; ++a) d[a] = dims[a] >> k > 0 ? dims[a] >> k : 1;
        snprintf(name, sizeof name, "%s.%d.raw", src->levels, k);
        if (!(f = fopen(name, "rb"))) break;
        fclose(f);
        if (read_volume(sub, name, d, &data[k]) != 0) goto done;
        lv[k] = (sample_volume){d[0], d[1], d[2], 4, SAMPLE_FORMAT_F32, data[k], 0, 0};
        count = k + 1;
    }
    if ((src->levels ? sample_texture_create_3d_levels(lv, count, out, &err)
                     : sample_texture_create_3d(&lv[0], mip, out, &err)) != SAMPLE_OK) {
        cli_runtime_error(sub, "%s", err.message);
        goto done;
    }
    rc = 0;
done:
    for (k = 0; k < SAMPLE_MAX_LEVELS; ++k) free(data[k]);
    return rc;
}

void vl_print_texture(const sample_texture *tex, const char *origin)
{
    sample_texture_info inf;
    int k, w, h, d;
    sample_texture_info_get(tex, &inf);
    printf("texture\nkind      %s\nsize      %d x %d x %d\nformat    %s\nchannels  %d\nlevels    %d (%s)\n"
           "bytes     %zu\n",
           sample_texture_kind_name(inf.kind), inf.width, inf.height, inf.depth, sample_format_name(inf.format),
           inf.channels, inf.levels, origin, inf.bytes);
    for (k = 0; sample_texture_level_size3(tex, k, &w, &h, &d); ++k) printf("  level %2d  %d x %d x %d\n", k, w, h, d);
}
