/* texsample render: not implemented yet (see the open issues). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>

int cmd_render(int argc, char **argv)
{
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("usage: texsample render ...\n\nNot implemented yet.\n");
        return EXIT_OK;
    }
    return cli_runtime_error("render", "not implemented yet");
}
