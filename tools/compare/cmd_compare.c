/* texsample compare: not implemented yet (see the open issues). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>

int cmd_compare(int argc, char **argv)
{
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("usage: texsample compare ...\n\nNot implemented yet.\n");
        return EXIT_OK;
    }
    return cli_runtime_error("compare", "not implemented yet");
}
