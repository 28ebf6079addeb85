/* texsample freq: not implemented yet. */
#include "cli.h"
#include "commands.h"

#include <stdio.h>

int cmd_freq(int argc, char **argv)
{
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("usage: texsample freq ...\n\nNot implemented yet.\n");
        return EXIT_OK;
    }
    return cli_runtime_error("freq", "not implemented yet");
}
