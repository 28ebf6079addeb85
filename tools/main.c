/* texsample: the libsample command-line program. */
#include "cli.h"
#include "commands.h"

#include <stdio.h>
#include <string.h>

static const struct {
    const char *name;
    cli_command_fn fn;
    const char *summary;
} commands[] = {
    {"lookup", cmd_lookup, "evaluate a query file against a texture (raw or image file)"},
    {"info", cmd_info, "describe a texture file and its pyramid"},
    {"mip", cmd_mip, "build a tiled, mip-mapped OpenEXR file (like maketx)"},
    {"render", cmd_render, "reference renderer: teapot, plane, sphere, ... with exact Jacobians"},
    {"compare", cmd_compare, "aliasing comparison of every filter against the ground truth"},
    {"freq", cmd_freq, "frequency tests: pass-band and aliasing of each filter"},
    {"bench", cmd_bench, "speed, side by side with OpenImageIO's TextureSystem"},
};

static void usage(FILE *f)
{
    size_t k;
    fprintf(f, "usage: texsample COMMAND [options]   (texsample COMMAND --help for more)\n\n"
               "libsample %s, texture filtering and mipmap sampling.\n\nCommands:\n",
            SAMPLE_VERSION_STRING);
    for (k = 0; k < sizeof commands / sizeof commands[0]; ++k)
        fprintf(f, "  %-9s %s\n", commands[k].name, commands[k].summary);
    fprintf(f, "\nExit codes: 0 success, 1 runtime error, 2 usage error.\n");
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
        if (strcmp(argv[1], commands[k].name) == 0) return commands[k].fn(argc - 1, argv + 1);
    fprintf(stderr, "texsample: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return EXIT_USAGE;
}
