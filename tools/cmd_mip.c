/* texsample mip: image in, tiled mip-mapped OpenEXR out (like maketx). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

static const char help[] =
    "usage: texsample mip INPUT OUTPUT.exr [options]\n\n"
    "Reads any image OpenImageIO reads, converts it to the scene-linear working\n"
    "space, builds the full mip pyramid (levels max(1, w/2^k) x max(1, h/2^k))\n"
    "and writes a tiled, mip-mapped OpenEXR file (ROUND_DOWN level sizes).\n\n"
    "Options:\n"
    "  --filter box|lanczos3|kaiser  down-sampling kernel (default box)\n"
    "  --wrap MODE                   both axes: what the kernel reads past the edges,\n"
    "  --wrap-s MODE, --wrap-t MODE  also stored as the file's wrapmodes attribute\n"
    "                                (repeat, mirrored_repeat, clamp_to_edge, clamp_to_border, ...;\n"
    "                                default clamp_to_edge)\n"
    "  --colorspace NAME             colour space of INPUT (default: file metadata, else\n"
    "                                8/16-bit = sRGB, half/float = linear)\n"
    "  --ocio CONFIG                 OpenColorIO config (default: $OCIO, else libsample's)\n"
    "  --tile N                      tile size N x N (default 64)\n"
    "  --half | --float              pixel type of OUTPUT (default --half)\n\n"
    "Progress goes to stderr when it is a terminal (or TEXSAMPLE_PROGRESS is set).\n"
    "Exit codes: 0 success, 1 runtime error, 2 usage error.\n";

#ifdef TEXSAMPLE_HAVE_IO
static void progress(void *user, size_t done, size_t total)
{
    (void)user;
    cli_progress("mip", done, total);
}

static int parse_wrap(const char *sub, const char *opt, const char *v, sample_wrap *out)
{
    int w = v ? sample_wrap_parse(v) : -1;
    if (w < 0) return cli_usage_error(sub, "%s: unknown wrap mode '%s'", opt, v ? v : ""), -1;
    *out = (sample_wrap)w;
    return 0;
}
#endif

int cmd_mip(int argc, char **argv)
{
    const char *sub = "mip";
#ifdef TEXSAMPLE_HAVE_IO
    const char *in = NULL, *outp = NULL, *v;
    sample_io_options o;
    sample_io_exr_options x;
    sample_mip_params mip;
    sample_texture *tex;
    sample_error err;
    int i;
    sample_io_options_init(&o);
    sample_io_exr_options_init(&x);
    sample_mip_params_init(&mip);
    /* The pyramid is always rebuilt with the kernel asked for. */
    o.use_file_levels = 0;
    for (i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            printf("%s", help);
            return EXIT_OK;
        }
        if (cli_opt(argc, argv, &i, "--filter", &v)) {
            int m = v ? sample_mipgen_parse(v) : -1;
            if (m < 0 || m == SAMPLE_MIPGEN_NONE)
                return cli_usage_error(sub, "--filter: expected box, lanczos3 or kaiser, not '%s'", v ? v : "");
            mip.filter = (sample_mipgen)m;
        } else if (cli_opt(argc, argv, &i, "--wrap", &v)) {
            if (parse_wrap(sub, "--wrap", v, &mip.wrap_s) != 0) return EXIT_USAGE;
            mip.wrap_t = mip.wrap_s;
        } else if (cli_opt(argc, argv, &i, "--wrap-s", &v)) {
            if (parse_wrap(sub, "--wrap-s", v, &mip.wrap_s) != 0) return EXIT_USAGE;
        } else if (cli_opt(argc, argv, &i, "--wrap-t", &v)) {
            if (parse_wrap(sub, "--wrap-t", v, &mip.wrap_t) != 0) return EXIT_USAGE;
        } else if (cli_opt(argc, argv, &i, "--colorspace", &v)) {
            if (!v) return cli_usage_error(sub, "--colorspace needs a name");
            o.colorspace = v;
        } else if (cli_opt(argc, argv, &i, "--ocio", &v)) {
            if (!v) return cli_usage_error(sub, "--ocio needs a config file");
            o.ocio_config = v;
        } else if (cli_opt(argc, argv, &i, "--tile", &v)) {
            int n;
            if (!v || !cli_parse_int(v, &n) || n < 1 || n > 4096)
                return cli_usage_error(sub, "--tile needs a size from 1 to 4096, not '%s'", v ? v : "");
            x.tile_w = x.tile_h = n;
        } else if (strcmp(argv[i], "--half") == 0) {
            x.use_float = 0;
        } else if (strcmp(argv[i], "--float") == 0) {
            x.use_float = 1;
        } else if (argv[i][0] != '-' && !in) {
            in = argv[i];
        } else if (argv[i][0] != '-' && !outp) {
            outp = argv[i];
        } else {
            return cli_usage_error(sub, "unexpected argument '%s'", argv[i]);
        }
    }
    if (!in || !outp) return cli_usage_error(sub, "an input image and an output file are required");
    x.wrap_s = mip.wrap_s;
    x.ocio_config = o.ocio_config;
    x.wrap_t = mip.wrap_t;
    x.progress = progress;
    if (sample_io_read_texture(in, &o, &mip, &tex, &err) != SAMPLE_OK)
        return cli_runtime_error(sub, "%s", err.message);
    if (sample_io_write_mip_exr(outp, tex, &x, &err) != SAMPLE_OK) {
        sample_texture_destroy(tex);
        return cli_runtime_error(sub, "%s", err.message);
    }
    sample_texture_destroy(tex);
    return EXIT_OK;
#else
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("%s", help);
        return EXIT_OK;
    }
    return cli_runtime_error(sub, "this build has no image support (libsample_io)");
#endif
}
