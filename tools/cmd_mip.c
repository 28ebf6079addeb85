/* texsample mip: not implemented yet (see the open issues). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>

int cmd_mip(int argc, char **argv)
{
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("usage: texsample mip ...\n\nNot implemented yet.\n");
        return EXIT_OK;
    }
    return cli_runtime_error("mip", "not implemented yet");
}
