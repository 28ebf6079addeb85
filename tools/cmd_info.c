/* texsample info: what a file holds, and what libsample makes of it. */
#include "cli.h"
#include "commands.h"
#include "lookup_volume.h"
#include "texload.h"

#include <stdio.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

static const char help[] =
    "usage: texsample info (FILE | --image FILE | --raw FILE --w W --h H [--levels PREFIX])\n"
    "                      [--colorspace NAME] [--mipgen box|lanczos3|kaiser|none]\n\n"
    "For an image file, two parts, as `iinfo -v` and then the texture:\n"
    "  file     what the file holds, from its headers (no pixel is read): reader,\n"
    "           size, channels and their names, pixel type, alpha, the mip levels\n"
    "           stored, tiles, wrap modes, colour space, compression;\n"
    "  texture  what libsample builds from it: storage format, channels, colour\n"
    "           space decoded from, every level (from the file, or built with\n"
    "           --mipgen) and its bytes.\n"
    "For --raw, the texture part only.\n\n"
    "Options:\n"
    "  --image FILE            image file (any format OpenImageIO reads)\n"
    "  --raw FILE --w W --h H  raw float32 RGBA texels; --levels PREFIX adds PREFIX.k.raw\n"
    "  --colorspace NAME       colour space of the image (default: its metadata, else the rule)\n"
    "  --mipgen KERNEL         kernel for levels the file does not hold (default box; none: base only)\n"
    "Exit codes: 0 success, 1 runtime error, 2 usage error.\n";

/* The texture part, shared by both sources: levels follow the rule
 * max(1, w >> k) × max(1, h >> k). */
static void print_texture(int w, int h, int channels, sample_format f, int levels, const char *origin)
{
    size_t bytes = 0;
    int k;
    for (k = 0; k < levels; ++k) {
        int lw = w >> k > 0 ? w >> k : 1, lh = h >> k > 0 ? h >> k : 1;
        bytes += (size_t)lw * (size_t)lh * (size_t)channels * sample_format_bytes(f);
    }
    printf("format    %s\nchannels  %d\nlevels    %d (%s)\nbytes     %zu\n", sample_format_name(f), channels, levels,
           origin, bytes);
    for (k = 0; k < levels; ++k)
        printf("  level %2d  %d x %d\n", k, w >> k > 0 ? w >> k : 1, h >> k > 0 ? h >> k : 1);
}

#ifdef TEXSAMPLE_HAVE_IO
static int levels_built(int w, int h, const sample_mip_params *mip)
{
    int n = 1, m = w > h ? w : h;
    if (mip->filter == SAMPLE_MIPGEN_NONE) return 1;
    while (m > 1) m >>= 1, ++n;
    return n;
}

static const char *or_none(const char *s, const char *none) { return s[0] ? s : none; }

static int info_image(const char *sub, const tl_source *src, const sample_mip_params *mip)
{
    sample_io_options o;
    sample_io_file_info fi;
    sample_error err;
    int k, levels;
    sample_io_options_init(&o);
    o.colorspace = src->colorspace;
    if (sample_io_describe(src->image, &o, &fi, &err) != SAMPLE_OK) return cli_runtime_error(sub, "%s", err.message);
    tl_warn_colorspace(sub, src->image, &fi);
    printf("file      %s\nreader    %s\nsize      %d x %d\npixels    %s\nchannels  %d (", src->image, fi.format,
           fi.width, fi.height, fi.pixel_type, fi.channels);
    for (k = 0; k < fi.channels && k < SAMPLE_IO_NAMED_CHANNELS; ++k)
        printf("%s%s", k ? ", " : "", or_none(fi.channel_names[k], "?"));
    printf("%s)\n", fi.channels > SAMPLE_IO_NAMED_CHANNELS ? ", ..." : "");
    if (fi.alpha_channel >= 0)
        printf("alpha     channel %d, %s\n", fi.alpha_channel, fi.straight_alpha ? "straight" : "premultiplied");
    else
        printf("alpha     none\n");
    printf("levels    %d in the file\n", fi.levels);
    for (k = 0; k < fi.levels; ++k) printf("  level %2d  %d x %d\n", k, fi.level_width[k], fi.level_height[k]);
    if (fi.tile_width > 0) printf("tiles     %d x %d\n", fi.tile_width, fi.tile_height);
    else printf("tiles     none (scanlines)\n");
    printf("wrapmodes %s\ncolorspace %s\ncompression %s\n", or_none(fi.wrapmodes, "(not stated)"),
           or_none(fi.colorspace, "(not stated)"), or_none(fi.compression, "(not stated)"));
    printf("texture\ncolorspace %s (%s%s)\n", fi.colorspace_used,
           src->colorspace ? "--colorspace" : fi.colorspace_from_rule ? "the rule: 8/16-bit sRGB, half/float linear"
                                                                       : "the file's",
           fi.colorspace_unknown ? "; the OCIO config does not know the file's" : "");
    levels = fi.texture_file_levels > 1 ? fi.texture_file_levels : levels_built(fi.width, fi.height, mip);
    print_texture(fi.width, fi.height, fi.texture_channels, fi.texture_format, levels,
                  fi.texture_file_levels > 1 ? "from the file"
                  : levels > 1               ? sample_mipgen_name(mip->filter)
                                             : "base only");
    return EXIT_OK;
}
#endif

int cmd_info(int argc, char **argv)
{
    const char *sub = "info", *v;
    tl_source src;
    sample_mip_params mip;
    sample_texture *tex;
    sample_texture_info inf;
    int i;
    if (vl_given(argc, argv)) return cmd_info_volume(argc, argv);
    tl_source_init(&src);
    sample_mip_params_init(&mip);
    for (i = 1; i < argc; ++i) {
        int r;
        if (cli_is_help(argv[i])) {
            printf("%s%s", help, info_volume_help);
            return EXIT_OK;
        }
        if ((r = tl_source_flag(sub, argc, argv, &i, &src)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--mipgen", &v)) {
            int m = sample_mipgen_parse(v);
            if (m < 0) return cli_usage_error(sub, "--mipgen: unknown kernel '%s'", v);
            mip.filter = (sample_mipgen)m;
            continue;
        }
        if (argv[i][0] != '-' && !src.image && !src.raw) {
            src.image = argv[i];
            continue;
        }
        if (argv[i][0] != '-') return cli_usage_error(sub, "unexpected argument '%s' (one texture)", argv[i]);
        return cli_usage_error(sub, "unknown option '%s'", argv[i]);
    }
    if (!tl_source_given(&src)) return cli_usage_error(sub, "a texture is required (--image or --raw)");
#ifdef TEXSAMPLE_HAVE_IO
    if (!src.raw) return info_image(sub, &src, &mip);
#endif
    if (tl_load(sub, &src, &mip, &tex) != 0) return EXIT_RUNTIME;
    sample_texture_info_get(tex, &inf);
    printf("texture\nsize      %d x %d\n", inf.width, inf.height);
    print_texture(inf.width, inf.height, inf.channels, inf.format, inf.levels,
                  src.levels ? "from the files" : inf.levels > 1 ? sample_mipgen_name(mip.filter) : "base only");
    sample_texture_destroy(tex);
    return EXIT_OK;
}
