/* Running the image program (image_program.h). execv(3) rather than
 * dlopen: the image program is an ordinary program that can be run and
 * debugged by itself, its libraries are loaded only when it starts, and the
 * exit code, signals and standard streams pass through unchanged. */
#define _POSIX_C_SOURCE 200809L
#include "image_program.h"
#include "cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Where the image program is, relative to the directory of this program
 * (found through /proc/self/exe, proc(5), so that a program run from $PATH
 * or through a symbolic link finds its own install): beside it in the build
 * tree, else where the install puts it. */
static const char *const image_program_rel[] = {TEXSAMPLE_IMAGE_PROGRAM, TEXSAMPLE_IMAGE_FROM_BINDIR};
enum { IMAGE_PROGRAM_PLACES = sizeof image_program_rel / sizeof image_program_rel[0] };

int image_program_run(int argc, char **argv)
{
    char self[4096], path[IMAGE_PROGRAM_PLACES][4096 + 64];
    char **args;
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    char *slash;
    int k;
    if (n <= 0)
        return cli_runtime_error(argv[0], "cannot find this program's path (/proc/self/exe): %s", strerror(errno));
    self[n] = '\0';
    slash = strrchr(self, '/');
    if (slash) *slash = '\0';
    for (k = 0; k < IMAGE_PROGRAM_PLACES; ++k) {
        snprintf(path[k], sizeof path[k], "%s/%s", self, image_program_rel[k]);
        if (access(path[k], X_OK) == 0) break;
    }
    if (k == IMAGE_PROGRAM_PLACES)
        return cli_runtime_error(argv[0], "'%s' reads and writes image files, and its program is not installed "
                                 "(looked for '%s' and '%s')", argv[0], path[0], path[1]);
    args = (char **)calloc((size_t)argc + 2, sizeof *args);
    if (!args) return cli_runtime_error(argv[0], "out of memory");
    args[0] = path[k];
    memcpy(args + 1, argv, (size_t)argc * sizeof *args);
    fflush(NULL);
    execv(path[k], args);
    free(args);
    return cli_runtime_error(argv[0], "cannot run '%s': %s", path[k], strerror(errno));
}
