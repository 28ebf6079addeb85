/*
 * Every option a texsample command accepts is in its --help. Given an
 * option it does not know, a command asks the shared parser (cli_opt,
 * tools/cli.c) about each of its own in turn before it reports the unknown
 * one; TEXSAMPLE_TRACE_OPTIONS=1 prints those names, then the command's
 * --help, and each name must appear in that help as a whole word.
 *
 *   cli_options TEXSAMPLE
 */
#define _XOPEN_SOURCE 700
#include "check.h"
#include "cli_util.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const commands[] = {"lookup", "info", "mip", "render", "compare", "freq", "bench"};

/* Does `text` hold `word` not followed by a letter, digit or '-'? */
static int has_word(const char *text, const char *word)
{
    size_t n = strlen(word);
    const char *p;
    for (p = strstr(text, word); p; p = strstr(p + 1, word))
        if (!isalnum((unsigned char)p[n]) && p[n] != '-' && p[n] != '_') return 1;
    return 0;
}

int main(int argc, char **argv)
{
    char tmpl[] = "/tmp/texsample_options_XXXXXX", cmd[8192], file[64];
    size_t c, len = 0;
    if (argc < 2) return 2;
    if (!mkdtemp(tmpl)) return 1;
    /* All at once: each image command loads OpenImageIO (about 0.3 s).
     * Traced, a command also prints its --help after the options. */
    for (c = 0; c < sizeof commands / sizeof commands[0]; ++c)
        len += (size_t)snprintf(cmd + len, sizeof cmd - len,
                                "(TEXSAMPLE_TRACE_OPTIONS=1 %s %s --no-such-option >%s/%s.help 2>%s/%s.trace;"
                                " echo $? >%s/%s.rc) & ",
                                argv[1], commands[c], tmpl, commands[c], tmpl, commands[c], tmpl, commands[c]);
    snprintf(cmd + len, sizeof cmd - len, "wait");
    CHECK(len < sizeof cmd - 8 && check_shell(cmd) == 0, "the commands ran");
    for (c = 0; c < sizeof commands / sizeof commands[0]; ++c) {
        const char *name = commands[c];
        char *trace, *help, *rc, *line;
        int asked = 0, missing = 0;
        snprintf(file, sizeof file, "%s.trace", name);
        trace = check_slurp_in(tmpl, file);
        snprintf(file, sizeof file, "%s.help", name);
        help = check_slurp_in(tmpl, file);
        snprintf(file, sizeof file, "%s.rc", name);
        rc = check_slurp_in(tmpl, file);
        CHECK(rc && strcmp(rc, "2\n") == 0, "%s: an unknown option is a usage error (exit %s)", name, rc ? rc : "?");
        if (!trace || !help) {
            CHECK(0, "%s: outputs read", name);
        } else {
            for (line = strtok(trace, "\n"); line; line = strtok(NULL, "\n")) {
                const char *opt;
                if (strncmp(line, "texsample: option ", 18) != 0) continue;
                opt = line + 18;
                ++asked;
                if (!has_word(help, opt)) {
                    printf("  %s --help does not name %s\n", name, opt);
                    ++missing;
                }
            }
            CHECK(asked > 0, "%s asks about its options", name);
            CHECK(missing == 0, "%s: all %d options in --help (%d missing)", name, asked, missing);
        }
        free(trace);
        free(help);
        free(rc);
    }
    cli_remove_dir(tmpl);
    return check_finish();
}
