/* texsample bench: not implemented yet (see the open issues). */
#include "cli.h"
#include "commands.h"

#include <stdio.h>

int cmd_bench(int argc, char **argv)
{
    if (argc > 1 && cli_is_help(argv[1])) {
        printf("usage: texsample bench ...\n\nNot implemented yet.\n");
        return EXIT_OK;
    }
    return cli_runtime_error("bench", "not implemented yet");
}
