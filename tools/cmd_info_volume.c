/* texsample info --volume: what libsample makes of a raw volume (its
 * levels, each w x h x d, and bytes; doc/volumes.md). */
#include "cli.h"
#include "lookup_volume.h"

#include <stdio.h>

const char info_volume_help[] =
    "\nVolumes (3D textures):\n"
    "  texsample info --volume FILE --w W --h H --d D [--levels PREFIX] [--mipgen KERNEL]\n"
    "                          raw float32 RGBA, x fastest, then y, then z; prints the\n"
    "                          texture's kind, size w x h x d (depth) and every level\n"
    "  texsample info --volume FILE [--mipgen KERNEL]\n"
    "                          the same of a volume image (TIFF pages or OpenEXR parts\n"
    "                          as slices, or a volumetric TIFF)\n";

int cmd_info_volume(int argc, char **argv)
{
    const char *sub = "info";
    vl_source src = {NULL, NULL, {0, 0, 0}};
    sample_mip_params mip;
    sample_texture *tex;
    sample_texture_info inf;
    int i, r;
    sample_mip_params_init(&mip);
    for (i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            printf("%s", info_volume_help + 1);
            return EXIT_OK;
        }
        if ((r = vl_source_flag(sub, argc, argv, &i, &src)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if ((r = vl_mipgen_flag(sub, argc, argv, &i, &mip)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (argv[i][0] != '-') return cli_usage_error(sub, "unexpected argument '%s' (one texture)", argv[i]);
        return cli_usage_error(sub, "unknown option '%s' (with --volume)", argv[i]);
    }
    if (vl_source_check(sub, &src) != 0) return EXIT_USAGE;
    if (vl_load(sub, &src, &mip, &tex) != 0) return EXIT_RUNTIME;
    sample_texture_info_get(tex, &inf);
    if (!src.dims[0]) printf("file      %s\n", src.path);
    vl_print_texture(tex, src.levels ? "from the files" : inf.levels > 1 ? sample_mipgen_name(mip.filter) : "base only");
    sample_texture_destroy(tex);
    return EXIT_OK;
}
