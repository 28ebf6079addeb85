/* What the command-line tests (tests/cli_*.c) share: reading what a run of
 * texsample left in their scratch folder, and removing the folder. */
#ifndef SAMPLE_TEST_CLI_UTIL_H
#define SAMPLE_TEST_CLI_UTIL_H

#include "check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Does the file `name` in `dir` hold `text`? Says what it holds if not. */
static inline int cli_holds(const char *dir, const char *name, const char *text)
{
    char *s = check_slurp_in(dir, name);
    int r = s && strstr(s, text) != NULL;
    if (!r) printf("  %s: wanted \"%s\", got \"%s\"\n", name, text, s ? s : "(nothing)");
    free(s);
    return r;
}

static inline void cli_remove_dir(const char *dir)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (check_shell(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

#endif
