/* Shared command-line plumbing. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"
#include "filters.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

/* The subcommand being parsed (cli_args_prepare), for the parser's own
 * messages, and whether a usage error was reported (main.c then exits 2,
 * whichever code the command returns: a texture source without its size
 * is found to be a usage error only where the texture is loaded). */
static const char *current = "texsample";
static int usage_reported;
/* The "./-name" strings cli_args_prepare made, freed by cli_args_free. */
static char **made;
static int made_count;

static int report(int code, const char *sub, const char *fmt, va_list ap)
{
    fprintf(stderr, "texsample %s: ", sub);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    return code;
}

int cli_usage_error(const char *sub, const char *fmt, ...)
{
    va_list ap;
    int r;
    va_start(ap, fmt);
    r = report(EXIT_USAGE, sub, fmt, ap);
    va_end(ap);
    fprintf(stderr, "Try 'texsample %s --help'.\n", sub);
    usage_reported = 1;
    return r;
}

int cli_usage_reported(void) { return usage_reported; }

int cli_runtime_error(const char *sub, const char *fmt, ...)
{
    va_list ap;
    int r;
    va_start(ap, fmt);
    r = report(EXIT_RUNTIME, sub, fmt, ap);
    va_end(ap);
    return r;
}

int cli_is_help(const char *a) { return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0; }

int cli_args_prepare(const char *sub, int argc, char **argv)
{
    int i, k;
    current = sub;
    for (i = 1; i < argc && strcmp(argv[i], "--") != 0; ++i) {
    }
    if (i == argc) return argc;
    /* Operands after "--" that look like options are given as "./NAME",
     * the same file (POSIX utility syntax guideline 10: "--" ends the
     * options; every later argument is an operand). */
    made = (char **)calloc((size_t)argc, sizeof *made);
    for (k = i + 1; k < argc; ++k) {
        char *a = argv[k];
        if (a[0] == '-' && made) {
            char *b = (char *)malloc(strlen(a) + 3);
            if (b) {
                memcpy(b, "./", 2);
                strcpy(b + 2, a);
                made[made_count++] = b;
                a = b;
            }
        }
        argv[k - 1] = a;
    }
    argv[argc - 1] = NULL;
    return argc - 1;
}

void cli_args_free(void)
{
    int k;
    for (k = 0; k < made_count; ++k) free(made[k]);
    free(made);
    made = NULL;
    made_count = 0;
}

int cli_trace_options(void)
{
    static int trace = -1;
    if (trace < 0) {
        const char *e = getenv("TEXSAMPLE_TRACE_OPTIONS");
        trace = e && *e && strcmp(e, "0") != 0;
    }
    return trace;
}

int cli_opt(int argc, char **argv, int *i, const char *name, const char **val)
{
    const char *a = argv[*i];
    size_t n = strlen(name);
    if (cli_trace_options()) fprintf(stderr, "texsample: option %s\n", name);
    if (strncmp(a, name, n) != 0 || (a[n] != '\0' && a[n] != '=')) return 0;
    if (!val) {
        if (a[n] == '\0') return 1;
        cli_usage_error(current, "option %s takes no value ('%s')", name, a);
        exit(EXIT_USAGE);
    }
    if (a[n] == '=' && a[n + 1] != '\0') {
        *val = a + n + 1;
        return 1;
    }
    if (a[n] == '\0' && *i + 1 < argc) {
        *val = argv[++*i];
        return 1;
    }
    /* Options are parsed before any work, so there is nothing to undo. */
    cli_usage_error(current, "option %s needs a value", name);
    exit(EXIT_USAGE);
}

int cli_parse_int(const char *s, int *out)
{
    char *end;
    long v;
    if (!s || !*s) return 0;
    errno = 0;
    v = strtol(s, &end, 10);
    if (*end || errno || v < -2147483647L || v > 2147483647L) return 0;
    *out = (int)v;
    return 1;
}

int cli_parse_float(const char *s, float *out)
{
    char *end;
    double v;
    if (!s || !*s) return 0;
    v = strtod(s, &end);
    if (*end || !isfinite(v) || fabs(v) > 3.0e38) return 0;
    *out = (float)v;
    return 1;
}

int cli_parse_float4(const char *s, float out[4])
{
    char buf[256], *p, *save = NULL;
    int n = 0;
    if (!s || strlen(s) >= sizeof buf) return 0;
    strcpy(buf, s);
    for (p = strtok_r(buf, ",", &save); p; p = strtok_r(NULL, ",", &save)) {
        if (n >= 4 || !cli_parse_float(p, &out[n])) return 0;
        ++n;
    }
    if (n == 1) out[1] = out[2] = out[3] = out[0];
    return n == 1 || n == 4;
}

static const char sampler_help[] =
    "Sampler state (named after OpenGL sampler parameters):\n"
    "  --wrap-s MODE, --wrap-t MODE, --wrap MODE (both)\n"
    "        repeat | mirrored_repeat | clamp_to_edge | clamp_to_border |\n"
    "        mirror_clamp_to_edge | clamp | mirror_clamp | mirror_clamp_to_border\n"
    "  --mag nearest|linear|cubic               (default linear)\n"
    "  --min nearest|linear|nearest_mipmap_nearest|linear_mipmap_nearest|\n"
    "        nearest_mipmap_linear|linear_mipmap_linear|cubic|cubic_mipmap_nearest|\n"
    "        cubic_mipmap_linear                (default nearest_mipmap_linear, as GL)\n"
    "  --border R,G,B,A                         border colour (linear)\n"
    "  --cubic catmull-rom|bspline|mitchell     cubic variant\n"
    "  --cubic-clamp                            clamp cubic overshoot to the 2x2 range\n"
    "  --lod-bias B, --min-lod L, --max-lod L, --base-level N, --max-level N\n"
    "  --filter none|aniso|blinn-newell|ewa|feline  footprint filter for minification\n"
    "  --filter NAME                            a filter of the tools' registry (below): its\n"
    "                                           min, mag, footprint, cubic, max anisotropy and\n"
    "                                           options; options after it override them\n"
    "  --aniso N                                max anisotropy (default 1; 16 with --filter aniso)\n"
    "  --nearest-level-floor                    NEAREST_MIPMAP_*: floor(base+lambda+1/2)\n"
    "  --legacy-switchover                      pre-GL-4.5 c = 0.5 rule\n"
    "  --aniso-pow2                             round the anisotropic probe count up to 2^k\n"
    "  --bn-area-weight                         Blinn-Newell corners: screen-space (area) weights\n"
    "  --ewa-kernel gaussian|lanczos2|lanczos3|mitchell  EWA's radial weight (default gaussian)\n"
    "  --ewa-clamp                              clamp EWA kernels' ringing to the texels' range\n"
    "Registry filters for --filter NAME (doc/comparison.md; blinn-newell and ewa\n"
    "set the footprint only, which samples the same: it replaces min whenever\n"
    "lambda > 0; Blinn-Newell's corner mode is --filter blinn-newell --corners FILE):\n";

/* The registry entries --filter takes: libsample's, without the corner
 * entries (the corners come with the queries, where a tool has them). */
static const char *const no_defaults[] = {NULL};

void cli_sampler_help_print(void)
{
    fputs(sampler_help, stdout);
    tool_picks_help(stdout, "  ", no_defaults, 0);
}

/* --filter: a footprint filter name keeps meaning the footprint alone, so
 * that lookups written against it sample as before; otherwise a registry
 * entry. Returns 0, or −1 after reporting. */
static int filter_flag(const char *sub, const char *v, sample_sampler *s)
{
    int e = sample_footprint_parse(v);
    tool_pick p;
    if (e >= 0) {
        s->footprint = (sample_footprint)e;
        if (e == SAMPLE_FOOTPRINT_ANISOTROPIC && s->max_anisotropy == 1.0f) s->max_anisotropy = 16.0f;
        return 0;
    }
    if (tool_pick_read(sub, v, &p) != 0) {
        cli_usage_error(sub, "--filter: unknown filter '%s'", v);
        return -1;
    }
    if (!tool_pick_allowed(&p, 0)) {
        cli_usage_error(sub, "--filter: '%s' is not a libsample filter by itself%s", v,
                        p.oiio ? "" : " (corner mode: --filter blinn-newell --corners FILE)");
        return -1;
    }
    tool_filter_apply(p.f, s);
    return 0;
}

#define ENUM_FLAG(opt, parse, field, what)                                          \
    if (cli_opt(argc, argv, i, opt, &v)) {                                          \
        int e = parse(v);                                                           \
        if (e < 0) {                                                                \
            cli_usage_error(sub, "%s: unknown %s '%s'", opt, what, v);              \
            return -1;                                                              \
        }                                                                           \
        field;                                                                      \
        return 1;                                                                   \
    }

#define FLOAT_FLAG(opt, field)                                                      \
    if (cli_opt(argc, argv, i, opt, &v)) {                                          \
        float f;                                                                    \
        if (!cli_parse_float(v, &f)) {                                              \
            cli_usage_error(sub, "%s needs a finite number, not '%s'", opt, v);     \
            return -1;                                                              \
        }                                                                           \
        field = f;                                                                  \
        return 1;                                                                   \
    }

#define INT_FLAG(opt, field)                                                        \
    if (cli_opt(argc, argv, i, opt, &v)) {                                          \
        int n;                                                                      \
        if (!cli_parse_int(v, &n) || n < 0) {                                       \
            cli_usage_error(sub, "%s needs a non-negative integer, not '%s'", opt, v); \
            return -1;                                                              \
        }                                                                           \
        field = n;                                                                  \
        return 1;                                                                   \
    }

int cli_sampler_flag(const char *sub, int argc, char **argv, int *i, sample_sampler *s)
{
    const char *v = NULL;
    ENUM_FLAG("--wrap-s", sample_wrap_parse, s->wrap_s = (sample_wrap)e, "wrap mode")
    ENUM_FLAG("--wrap-t", sample_wrap_parse, s->wrap_t = (sample_wrap)e, "wrap mode")
    ENUM_FLAG("--wrap", sample_wrap_parse, s->wrap_s = s->wrap_t = (sample_wrap)e, "wrap mode")
    ENUM_FLAG("--min", sample_filter_parse, s->min_filter = (sample_filter)e, "filter")
    ENUM_FLAG("--cubic", sample_cubic_parse, s->cubic = (sample_cubic)e, "cubic variant")
    ENUM_FLAG("--ewa-kernel", sample_ewa_kernel_parse, s->ewa_kernel = (sample_ewa_kernel)e, "EWA kernel")
    if (cli_opt(argc, argv, i, "--filter", &v)) return filter_flag(sub, v, s) == 0 ? 1 : -1;
    if (cli_opt(argc, argv, i, "--mag", &v)) {
        int e = sample_filter_parse(v);
        if (e != SAMPLE_NEAREST && e != SAMPLE_LINEAR && e != SAMPLE_CUBIC) {
            cli_usage_error(sub, "--mag must be nearest, linear or cubic, not '%s'", v);
            return -1;
        }
        s->mag_filter = (sample_filter)e;
        return 1;
    }
    if (cli_opt(argc, argv, i, "--border", &v)) {
        if (!cli_parse_float4(v, s->border_color)) {
            cli_usage_error(sub, "--border needs R,G,B,A, not '%s'", v);
            return -1;
        }
        return 1;
    }
    FLOAT_FLAG("--lod-bias", s->lod_bias)
    FLOAT_FLAG("--min-lod", s->min_lod)
    FLOAT_FLAG("--max-lod", s->max_lod)
    FLOAT_FLAG("--aniso", s->max_anisotropy)
    INT_FLAG("--base-level", s->base_level)
    INT_FLAG("--max-level", s->max_level)
    if (cli_opt(argc, argv, i, "--cubic-clamp", NULL)) { s->options |= SAMPLE_OPT_CUBIC_CLAMP; return 1; }
    if (cli_opt(argc, argv, i, "--nearest-level-floor", NULL)) { s->options |= SAMPLE_OPT_NEAREST_LEVEL_FLOOR; return 1; }
    if (cli_opt(argc, argv, i, "--legacy-switchover", NULL)) { s->options |= SAMPLE_OPT_LEGACY_SWITCHOVER; return 1; }
    if (cli_opt(argc, argv, i, "--aniso-pow2", NULL)) { s->options |= SAMPLE_OPT_ANISO_POW2; return 1; }
    if (cli_opt(argc, argv, i, "--bn-area-weight", NULL)) { s->options |= SAMPLE_OPT_BN_AREA_WEIGHT; return 1; }
    if (cli_opt(argc, argv, i, "--ewa-clamp", NULL)) { s->options |= SAMPLE_OPT_EWA_CLAMP; return 1; }
    return 0;
}

int cli_read_file(const char *path, void **data, size_t *size, const char **why)
{
    /* O_NONBLOCK: open(2) of a FIFO would wait for a writer (POSIX); it
     * does nothing to a regular file's reads. Then fstat(2) on that
     * descriptor refuses all but a regular file (/dev/zero never ends).
     * The front program links libsample alone, so this is its check, not
     * libsample_io's sample_io_check_regular_file. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    size_t n;
    void *buf;
    FILE *f;
    *data = NULL;
    *size = 0;
    *why = NULL;
    if (fd < 0) return *why = strerror(errno), 0;
    if (fstat(fd, &st) != 0) *why = strerror(errno);
    else if (S_ISDIR(st.st_mode)) *why = strerror(EISDIR);
    else if (!S_ISREG(st.st_mode)) *why = "not a regular file (a FIFO or a device); only regular files are read";
    else if ((uintmax_t)st.st_size > (uintmax_t)(SIZE_MAX - 1)) *why = strerror(EFBIG);
    if (*why || !(f = fdopen(fd, "rb"))) {
        if (!*why) *why = strerror(errno);
        close(fd);
        return 0;
    }
    n = (size_t)st.st_size;
    if (!(buf = malloc(n > 0 ? n : 1))) {
        fclose(f);
        return *why = strerror(ENOMEM), 0;
    }
    if (fread(buf, 1, n, f) != n) {
        /* A short read without an error: the file shrank while read. */
        *why = ferror(f) ? strerror(errno) : "the file changed while it was read";
        free(buf);
        fclose(f);
        return 0;
    }
    fclose(f);
    *data = buf;
    *size = n;
    return 1;
}

int cli_write_file(const char *path, const void *data, size_t size)
{
    size_t len = strlen(path);
    char *tmp = (char *)malloc(len + 16);
    FILE *f;
    int ok, e;
    if (!tmp) return 0;
    snprintf(tmp, len + 16, "%s.tmp%ld", path, (long)getpid());
    f = fopen(tmp, "wb");
    if (!f) {
        free(tmp);
        return 0;
    }
    ok = fwrite(data, 1, size, f) == size;
    e = errno;
    if (fclose(f) != 0 && ok) ok = 0, e = errno;
    if (ok && rename(tmp, path) != 0) ok = 0, e = errno;
    if (!ok) remove(tmp);
    free(tmp);
    if (!ok) errno = e;
    return ok;
}

void cli_progress(const char *what, size_t done, size_t total)
{
    static const int width = 30;
    if (!isatty(2) && !getenv("TEXSAMPLE_PROGRESS")) return;
    if (total == 0) return;
    {
        int pct = (int)(100.0 * (double)done / (double)total), k, fill = pct * width / 100;
        fprintf(stderr, "\r%-10s [", what);
        for (k = 0; k < width; ++k) fputc(k < fill ? '#' : ' ', stderr);
        fprintf(stderr, "] %3d%%", pct);
        if (done >= total) fputc('\n', stderr);
        fflush(stderr);
    }
}
