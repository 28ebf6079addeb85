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

/* Write n bytes of data to the file `name` in `dir` (a failure is a
 * failed CHECK). */
static inline void cli_put(const char *dir, const char *name, const void *data, size_t n)
{
    char p[512];
    FILE *f;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    f = fopen(p, "wb");
    CHECK(f && fwrite(data, 1, n, f) == n, "write %s", p);
    if (f) fclose(f);
}

/* Run `texsample ARGS` (exe) in dir with a 10 s limit, its stdout and
 * stderr in out.txt and err.txt there; its exit status. */
static inline int cli_run_in(const char *dir, const char *exe, const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "cd %s && timeout 10 %s %s >out.txt 2>err.txt", dir, exe, args);
    return check_shell(cmd);
}

static inline void cli_remove_dir(const char *dir)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (check_shell(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

#endif
