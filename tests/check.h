/*
 * A tiny test harness (after lcms2's testbed): CHECK(cond, fmt, ...) records
 * a failure with its location and keeps going; RUN(fn) runs one test
 * function; check_skip(why) records a part that cannot run here (a tool it
 * needs is missing); check_finish() prints "N passed, N failed" and returns
 * the exit code: 1 on any failure, else CHECK_SKIP_CODE if a part was
 * skipped, else 0. Header-only: each test program includes it once.
 */
#ifndef SAMPLE_TEST_CHECK_H
#define SAMPLE_TEST_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static int check_pass_count, check_fail_count, check_case_failed, check_skip_count;

/* The exit code of a test that could not run everything it checks because
 * a tool or library it needs is missing: automake's convention, which
 * ctest reports as "Skipped" where the test's registration sets
 * SKIP_RETURN_CODE 77 (doc/testing.md, "Skipped, not passed"). A failure
 * elsewhere in the program still exits 1. */
#define CHECK_SKIP_CODE 77

#define CHECK(cond, ...)                                                        \
    do {                                                                        \
        if (!(cond)) {                                                          \
            if (check_fail_count + check_case_failed < 50) {                    \
                fprintf(stderr, "%s:%d: CHECK(%s) failed: ", __FILE__, __LINE__, #cond); \
                fprintf(stderr, __VA_ARGS__);                                   \
                fputc('\n', stderr);                                            \
            }                                                                   \
            check_case_failed++;                                                \
        }                                                                       \
    } while (0)

/* |a − b| ≤ tol, NaN never close. */
#define CHECK_NEAR(a, b, tol)                                                   \
    CHECK(fabs((double)(a) - (double)(b)) <= (double)(tol), "%s = %.9g, expected %.9g (tol %.3g)", #a, \
          (double)(a), (double)(b), (double)(tol))

#define CHECK_EQF(a, b)                                                         \
    CHECK((float)(a) == (float)(b), "%s = %.9g, expected exactly %.9g", #a, (double)(a), (double)(b))

#define RUN(fn)                                                                 \
    do {                                                                        \
        int check_skips_before = check_skip_count;                              \
        check_case_failed = 0;                                                  \
        fn();                                                                   \
        if (check_case_failed) {                                                \
            fprintf(stderr, "FAIL %s (%d checks)\n", #fn, check_case_failed);   \
            check_fail_count++;                                                 \
        } else if (check_skip_count == check_skips_before) {                    \
            check_pass_count++;                                                 \
        }                                                                       \
    } while (0)

/* The part of the current test that cannot run here, and why; the rest of
 * the program still runs and is still checked. */
static inline void check_skip(const char *why)
{
    printf("SKIP: %s\n", why);
    check_skip_count++;
}

static int check_finish(void)
{
    if (check_skip_count)
        printf("%d passed, %d failed, %d skipped\n", check_pass_count, check_fail_count, check_skip_count);
    else
        printf("%d passed, %d failed\n", check_pass_count, check_fail_count);
    return check_fail_count ? 1 : check_skip_count ? CHECK_SKIP_CODE : 0;
}

/* The whole file at `path`, NUL-terminated, in a malloc'd buffer (the
 * caller frees it); NULL if it cannot be read. *len (if non-NULL) gets the
 * bytes read, 0 on failure. The test programs read their tools' outputs
 * with it. */
static inline void *check_slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    long n;
    char *s = NULL;
    if (len) *len = 0;
    if (!f) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
        (s = malloc((size_t)n + 1)) != NULL) {
        size_t got = fread(s, 1, (size_t)n, f);
        s[got] = '\0';
        if (len) *len = got;
    }
    fclose(f);
    return s;
}

/* check_slurp of the file `name` in the folder `dir`. */
static inline char *check_slurp_in(const char *dir, const char *name)
{
    char path[4096];
    if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path) return NULL;
    return (char *)check_slurp(path, NULL);
}

/* Run a shell command; its exit status, or −1 if it did not exit. */
static inline int check_shell(const char *cmd)
{
    int st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

#endif
