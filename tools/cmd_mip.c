/* texsample mip: image in, tiled mip-mapped OpenEXR or TIFF out (like maketx). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

static const char help[] =
    "usage: texsample mip INPUT OUTPUT.exr|.tx|.tif [options]\n\n"
    "Reads any image OpenImageIO reads, converts it to the scene-linear working\n"
    "space in float, multiplies straight alpha into the colour (OpenEXR's\n"
    "premultiplied colour, so transparent texels do not bleed), builds the full\n"
    "mip pyramid in float (levels max(1, w/2^k) x max(1, h/2^k)) and writes a\n"
    "tiled, mip-mapped file with the input's channel names (at most 4 channels):\n"
    "OpenEXR for .exr (ROUND_DOWN level sizes), TIFF for .tx/.tif/.tiff (maketx's\n"
    ".tx layout). Other extensions are refused: their formats hold no levels.\n\n"
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
    "  --format half|float|u8|u16    pixel type of OUTPUT (default half); u8 and u16 are\n"
    "                                sRGB-encoded, as maketx -d uint8, and need .tx/.tif\n"
    "  --half | --float              the same as --format half | --format float\n"
    "  --half-clamp                  half: values beyond +-65504 become +-65504, not +-inf\n"
    "                                (without it, a warning counts them)\n"
    "  --env cube|latlong            write an OpenEXR environment map (.exr only) that\n"
    "                                OpenImageIO reads as one: INPUT is a cube map (1:6,\n"
    "                                OpenEXR's stacked faces) or a lat-long map (2:1, or\n"
    "                                any shape its envmap attribute calls lat-long),\n"
    "                                resampled into the other layout by EWA over each new\n"
    "                                texel's footprint. Pyramids: cube across face edges,\n"
    "                                lat-long periodic in s (--wrap options are refused)\n"
    "  --env-size N                  the output's cube face side or lat-long height\n"
    "                                (default: lat-long width / 4, 2 x the face side)\n\n"
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
    int w = sample_wrap_parse(v);
    if (w < 0) return cli_usage_error(sub, "%s: unknown wrap mode '%s'", opt, v), -1;
    *out = (sample_wrap)w;
    return 0;
}

static int parse_format(const char *v, sample_io_type *t)
{
    static const struct {
        const char *name;
        sample_io_type type;
    } names[] = {{"half", SAMPLE_IO_TYPE_HALF}, {"float", SAMPLE_IO_TYPE_FLOAT}, {"u8", SAMPLE_IO_TYPE_U8},
                 {"uint8", SAMPLE_IO_TYPE_U8}, {"u16", SAMPLE_IO_TYPE_U16}, {"uint16", SAMPLE_IO_TYPE_U16}};
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; ++k)
        if (strcmp(v, names[k].name) == 0) {
            *t = names[k].type;
            return 1;
        }
    return 0;
}

/* --env: read an environment map, resample it into `to` where the layout
 * or size changes, write it with its layout's attributes. */
static int run_env(const char *sub, const char *in, const char *outp, int to, int size, const sample_io_options *o,
                   const sample_mip_params *mip, const sample_io_exr_options *x)
{
    sample_texture *src = NULL, *dst = NULL;
    sample_texture_info inf;
    sample_error err;
    sample_status st;
    char ext[16];
    const char *dot = strrchr(outp, '.');
    snprintf(ext, sizeof ext, "%s", dot ? dot + 1 : "");
    if (strcmp(ext, "exr") != 0 && strcmp(ext, "EXR") != 0)
        return cli_usage_error(sub, "--env writes OpenEXR (.exr): the envmap attribute is OpenEXR's, not '%s'", outp);
    if ((st = sample_io_read_env(in, o, mip, &src, &err)) != SAMPLE_OK) return cli_runtime_error(sub, "%s", err.message);
    sample_texture_info_get(src, &inf);
    if ((int)inf.kind != to || size)
        st = sample_io_env_convert(src, (sample_texture_kind)to, size, mip, &dst, &err);
    if (st == SAMPLE_OK) st = sample_io_write_env(outp, dst ? dst : src, x, &err);
    sample_texture_destroy(src);
    sample_texture_destroy(dst);
    return st == SAMPLE_OK ? EXIT_OK : cli_runtime_error(sub, "%s", err.message);
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
    sample_error err;
    size_t overflows = 0;
    sample_status st;
    int i, env = -1, env_size = 0, wrap_given = 0;
    sample_io_options_init(&o);
    sample_io_exr_options_init(&x);
    sample_mip_params_init(&mip);
    x.type = SAMPLE_IO_TYPE_HALF;
    for (i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            printf("%s", help);
            return EXIT_OK;
        }
        if (cli_opt(argc, argv, &i, "--filter", &v)) {
            int m = sample_mipgen_parse(v);
            if (m < 0 || m == SAMPLE_MIPGEN_NONE)
                return cli_usage_error(sub, "--filter: expected box, lanczos3 or kaiser, not '%s'", v);
            mip.filter = (sample_mipgen)m;
        } else if (cli_opt(argc, argv, &i, "--wrap", &v)) {
            if (parse_wrap(sub, "--wrap", v, &mip.wrap_s) != 0) return EXIT_USAGE;
            wrap_given = 1;
            mip.wrap_t = mip.wrap_s;
        } else if (cli_opt(argc, argv, &i, "--wrap-s", &v)) {
            if (parse_wrap(sub, "--wrap-s", v, &mip.wrap_s) != 0) return EXIT_USAGE;
            wrap_given = 1;
        } else if (cli_opt(argc, argv, &i, "--wrap-t", &v)) {
            if (parse_wrap(sub, "--wrap-t", v, &mip.wrap_t) != 0) return EXIT_USAGE;
            wrap_given = 1;
        } else if (cli_opt(argc, argv, &i, "--colorspace", &v)) {
            o.colorspace = v;
        } else if (cli_opt(argc, argv, &i, "--ocio", &v)) {
            /* The input is decoded into this config's scene_linear space,
             * and the output names that space. */
            o.ocio_config = x.ocio_config = v;
        } else if (cli_opt(argc, argv, &i, "--tile", &v)) {
            int n;
            if (!cli_parse_int(v, &n) || n < 1 || n > 4096)
                return cli_usage_error(sub, "--tile needs a size from 1 to 4096, not '%s'", v);
            x.tile_w = x.tile_h = n;
        } else if (cli_opt(argc, argv, &i, "--format", &v)) {
            if (!parse_format(v, &x.type))
                return cli_usage_error(sub, "--format: expected half, float, u8 or u16, not '%s'", v);
        } else if (cli_opt(argc, argv, &i, "--half", NULL)) {
            x.type = SAMPLE_IO_TYPE_HALF;
        } else if (cli_opt(argc, argv, &i, "--float", NULL)) {
            x.type = SAMPLE_IO_TYPE_FLOAT;
        } else if (cli_opt(argc, argv, &i, "--half-clamp", NULL)) {
            x.half_clamp = 1;
        } else if (cli_opt(argc, argv, &i, "--env", &v)) {
            if (strcmp(v, "cube") == 0) env = SAMPLE_TEXTURE_CUBE;
            else if (strcmp(v, "latlong") == 0) env = SAMPLE_TEXTURE_2D;
            else return cli_usage_error(sub, "--env: expected cube or latlong, not '%s'", v);
        } else if (cli_opt(argc, argv, &i, "--env-size", &v)) {
            if (!cli_parse_int(v, &env_size) || env_size < 1 || env_size > 16384)
                return cli_usage_error(sub, "--env-size needs a size from 1 to 16384, not '%s'", v);
        } else if (argv[i][0] != '-' && !in) {
            in = argv[i];
        } else if (argv[i][0] != '-' && !outp) {
            outp = argv[i];
        } else if (argv[i][0] == '-') {
            return cli_usage_error(sub, "unknown option '%s'", argv[i]);
        } else {
            return cli_usage_error(sub, "unexpected argument '%s' (one INPUT, one OUTPUT)", argv[i]);
        }
    }
    if (!in || !outp) return cli_usage_error(sub, "an input image and an output file are required");
    if (env_size && env < 0) return cli_usage_error(sub, "--env-size needs --env");
    if (env >= 0 && wrap_given)
        return cli_usage_error(sub, "--env: an environment map's edges are its layout's (no --wrap)");
    if (env >= 0) {
        /* As for a plain texture: float, straight alpha multiplied in. */
        o.float_storage = 1;
        o.premultiply = 1;
        return run_env(sub, in, outp, env, env_size, &o, &mip, &x);
    }
    x.progress = progress;
    x.half_overflows = &overflows;
    /* A wrong output name or type is the command line's fault: exit 2. */
    if ((st = sample_io_make_mip(in, outp, &o, &mip, &x, &err)) != SAMPLE_OK)
        return st == SAMPLE_E_INVALID_ARGUMENT ? cli_usage_error(sub, "%s", err.message)
                                               : cli_runtime_error(sub, "%s", err.message);
    if (overflows)
        fprintf(stderr, "texsample mip: warning: %zu value%s beyond +-65504 became %s in half%s\n", overflows,
                overflows == 1 ? "" : "s", x.half_clamp ? "+-65504" : "+-inf",
                x.half_clamp ? "" : " (--float keeps them, --half-clamp clamps them)");
    return EXIT_OK;
#else
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("%s", help);
        return EXIT_OK;
    }
    return cli_runtime_error(sub, "this build has no image support (libsample_io)");
#endif
}
