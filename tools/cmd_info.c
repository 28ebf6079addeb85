/* texsample info: describe a texture and its pyramid. */
#include "cli.h"
#include "commands.h"
#include "texload.h"

#include <stdio.h>

static const char help[] =
    "usage: texsample info (--image FILE | --raw FILE --w W --h H [--levels PREFIX])\n"
    "                      [--colorspace NAME] [--mipgen box|lanczos3|kaiser|none]\n\n"
    "Prints the size, channels, storage format and every mip level of a texture.\n";

int cmd_info(int argc, char **argv)
{
    const char *sub = "info", *v;
    tl_source src;
    sample_mip_params mip;
    sample_texture *tex;
    sample_texture_info inf;
    int i, k;
    tl_source_init(&src);
    sample_mip_params_init(&mip);
    for (i = 1; i < argc; ++i) {
        int r;
        if (cli_is_help(argv[i])) {
            printf("%s", help);
            return EXIT_OK;
        }
        if ((r = tl_source_flag(sub, argc, argv, &i, &src)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--mipgen", &v)) {
            int m = v ? sample_mipgen_parse(v) : -1;
            if (m < 0) return cli_usage_error(sub, "--mipgen: unknown kernel '%s'", v ? v : "");
            mip.filter = (sample_mipgen)m;
            continue;
        }
        if (argv[i][0] != '-' && !src.image && !src.raw) {
            src.image = argv[i];
            continue;
        }
        return cli_usage_error(sub, "unknown option '%s'", argv[i]);
    }
    if (!tl_source_given(&src)) return cli_usage_error(sub, "a texture is required (--image or --raw)");
    if (tl_load(sub, &src, &mip, &tex) != 0) return EXIT_RUNTIME;
    sample_texture_info_get(tex, &inf);
    printf("size      %d x %d\nchannels  %d\nformat    %s\nlevels    %d\nbytes     %zu\n", inf.width, inf.height,
           inf.channels, sample_format_name(inf.format), inf.levels, inf.bytes);
    for (k = 0; k < inf.levels; ++k) {
        int w, h;
        sample_texture_level_size(tex, k, &w, &h);
        printf("  level %2d  %d x %d\n", k, w, h);
    }
    sample_texture_destroy(tex);
    return EXIT_OK;
}
