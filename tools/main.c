/* texsample: the libsample command-line program. */
#include "cli.h"
#include "commands.h"
#ifdef TEXSAMPLE_FRONT
#include "image_program.h"
#endif

#include <stdio.h>
#include <string.h>

/* The front program (tools/CMakeLists.txt) links libsample alone: the
 * commands that read or write image files run in the image program. */
#ifdef TEXSAMPLE_FRONT
#define IMAGE_COMMAND(fn) NULL
#else
#define IMAGE_COMMAND(fn) fn
#endif

static const struct {
    const char *name;
    cli_command_fn fn; /* NULL: run in the image program */
    const char *summary;
} commands[] = {
    {"lookup", cmd_lookup, "evaluate a query file against a texture (raw or image file)"},
    {"info", IMAGE_COMMAND(cmd_info), "describe a texture file and its pyramid"},
    {"mip", IMAGE_COMMAND(cmd_mip), "build a tiled, mip-mapped OpenEXR or TIFF file (like maketx)"},
    {"render", IMAGE_COMMAND(cmd_render), "reference renderer: teapot, plane, sphere, ... with exact Jacobians"},
    {"compare", IMAGE_COMMAND(cmd_compare), "aliasing comparison of every filter against the ground truth"},
    {"freq", IMAGE_COMMAND(cmd_freq), "frequency tests: pass-band and aliasing of each filter"},
    {"bench", IMAGE_COMMAND(cmd_bench), "speed, side by side with OpenImageIO's TextureSystem"},
};

static void usage(FILE *f)
{
    size_t k;
    fprintf(f, "usage: texsample COMMAND [options]   (texsample COMMAND --help for more)\n\n"
               "libsample %s, texture filtering and mipmap sampling.\n\nCommands:\n",
            SAMPLE_VERSION_STRING);
    for (k = 0; k < sizeof commands / sizeof commands[0]; ++k)
        fprintf(f, "  %-9s %s\n", commands[k].name, commands[k].summary);
    fprintf(f, "\nOptions take their value as the next argument or after '=' (--out FILE,\n"
               "--out=FILE); '--' ends the options, so that a file may start with '-'.\n"
               "Exit codes: 0 success, 1 runtime error, 2 usage error.\n");
}

static int run(size_t k, int argc, char **argv)
{
    int rc;
    argc = cli_args_prepare(commands[k].name, argc, argv);
#ifdef TEXSAMPLE_FRONT
    rc = commands[k].fn ? commands[k].fn(argc, argv) : image_program_run(argc, argv);
#else
    rc = commands[k].fn(argc, argv);
#endif
    if (cli_trace_options() && commands[k].fn) {
        char *help[] = {argv[0], "--help", NULL};
        commands[k].fn(2, help);
    }
    cli_args_free();
    return cli_usage_reported() ? EXIT_USAGE : rc;
}

int main(int argc, char **argv)
{
    size_t k;
    if (argc < 2) {
        usage(stderr);
        return EXIT_USAGE;
    }
    if (cli_is_help(argv[1]) || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("texsample %s\n", SAMPLE_VERSION_STRING);
        return EXIT_OK;
    }
    for (k = 0; k < sizeof commands / sizeof commands[0]; ++k)
        if (strcmp(argv[1], commands[k].name) == 0) return run(k, argc - 1, argv + 1);
    fprintf(stderr, "texsample: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return EXIT_USAGE;
}
