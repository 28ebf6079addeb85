/* Shared command-line plumbing for texsample's subcommands. */
#ifndef TEXSAMPLE_CLI_H
#define TEXSAMPLE_CLI_H

#include "sample/sample.h"

#include <stddef.h>

/* Exit codes of every subcommand. */
enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2 };

/* A subcommand: returns one of the exit codes above. */
typedef int (*cli_command_fn)(int argc, char **argv);

/* Print "texsample SUB: message" to stderr and return EXIT_USAGE / EXIT_RUNTIME. */
int cli_usage_error(const char *sub, const char *fmt, ...);
int cli_runtime_error(const char *sub, const char *fmt, ...);

/* Was a usage error reported (cli_usage_error)? main.c then exits with
 * EXIT_USAGE whatever the command returned. */
int cli_usage_reported(void);

/* Before subcommand `sub` parses argv (argv[0] is its name): "--" ends the
 * options; it is removed, and each later argument starting with '-' is
 * given as "./ARG", the same file, so that no command takes an operand for
 * an option. Returns the new argc. cli_args_free frees what it made. */
int cli_args_prepare(const char *sub, int argc, char **argv);
void cli_args_free(void);

/* Is argv[*i] the option `name` ("--name", or "--name=VALUE" when it takes
 * a value)? If it takes a value (val non-NULL), *val gets VALUE or
 * argv[*i+1] (and *i advances). A missing or empty value, or a value given
 * to an option that takes none, is a usage error: reported, naming the
 * option, and the program exits with EXIT_USAGE (options are parsed before
 * any work). */
int cli_opt(int argc, char **argv, int *i, const char *name, const char **val);
int cli_is_help(const char *arg);
/* TEXSAMPLE_TRACE_OPTIONS=1 (tests/cli_options.c): cli_opt prints every
 * option name it is asked about on stderr, and main.c runs the command a
 * second time with --help. Given an option it does not know, a command
 * asks about each of its own before reporting it, and each must be in its
 * help. */
int cli_trace_options(void);

/* Strict number parsing: whole string, finite. Return 0 on failure. */
int cli_parse_int(const char *s, int *out);
int cli_parse_float(const char *s, float *out);
/* "r,g,b,a" (or a single value for all four). */
int cli_parse_float4(const char *s, float out[4]);

/* The sampler flags shared by lookup, render and compare:
 *   --wrap-s/--wrap-t/--wrap, --min, --mag, --border, --cubic, --cubic-clamp,
 *   --lod-bias, --min-lod, --max-lod, --base-level, --max-level,
 *   --filter none|aniso|blinn-newell|ewa or a filter registry name
 *   (tools/filters.h), --aniso N,
 *   --nearest-level-floor, --legacy-switchover
 * Returns 1 if argv[*i] was one of them (consumed), 0 if not, −1 on a bad
 * value (already reported). */
int cli_sampler_flag(const char *sub, int argc, char **argv, int *i, sample_sampler *s);
/* The help text for those flags, on stdout (the registry's names
 * generated). */
void cli_sampler_help_print(void);

/* Whole-file read: only a regular file is read (a FIFO or a device is
 * refused at once, never waited on). On failure (0) *why says why
 * ("Is a directory", "No such file or directory", ...). Whole-file write
 * goes to FILE.tmp, then renames, so a failed write leaves no truncated
 * file; on failure (0) errno says why. */
int cli_read_file(const char *path, void **data, size_t *size, const char **why);
int cli_write_file(const char *path, const void *data, size_t size);

/* Progress on stderr for long work ("render 42%"); silent unless stderr is a
 * terminal or force is set. done == total ends the line. */
void cli_progress(const char *what, size_t done, size_t total);

#endif
