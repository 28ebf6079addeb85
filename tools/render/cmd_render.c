/* texsample render: the reference renderer's command line. */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"
#include "commands.h"
#include "render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char render_help[] =
    "usage: texsample render [options] --out FILE\n"
    "\n"
    "Render a scene with exact (s, t) and Jacobians (Blinn & Newell 1976).\n"
    "\n"
    "  --scene NAME|FILE  built-in scene (teapot, plane, zoneplate, cylinder,\n"
    "                     sphere) or a JSON scene file; default teapot\n"
    "  --width N, --height N  image size (default: the scene's, 512 x 512)\n"
    "  --threads N        worker threads (default: all online CPUs)\n"
    "  --out FILE         image: .ppm (sRGB 8-bit) or .pfm (linear float)\n"
    "  --buffers FILE     per-pixel buffers as raw float32, channels\n"
    "                     interleaved: s t dsdx dtdx dsdy dtdy lod texels depth\n"
    "                     nx ny nz object prim (14 floats per pixel, row 0 at\n"
    "                     the top; see doc/renderer.md)\n"
    "  --shade full|texture  Blinn-Newell shading, or the filtered texture only\n"
    "  --corners          pass the exact footprint corners (Blinn-Newell mode)\n"
    "  --progress         show progress even when stderr is not a terminal\n"
    "\n"
    "Sampler flags (override the scene's sampler when given):\n";

/* Writers return 1 on success (cli_write_file's convention). */
static int write_ppm(const char *path, const render_image *img)
{
    size_t n = (size_t)img->width * img->height, k;
    char head[64];
    int hl = snprintf(head, sizeof head, "P6\n%d %d\n255\n", img->width, img->height);
    unsigned char *buf = malloc((size_t)hl + 3 * n);
    int r;
    if (!buf) return 0;
    memcpy(buf, head, (size_t)hl);
    for (k = 0; k < 3 * n; ++k) {
        float v = img->rgba[4 * (k / 3) + k % 3];
        float e = sample_linear_to_srgb(v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f);
        buf[hl + k] = (unsigned char)(e * 255.0f + 0.5f);
    }
    r = cli_write_file(path, buf, (size_t)hl + 3 * n);
    free(buf);
    return r;
}

/* PFM stores rows bottom to top; little-endian when the scale is negative. */
static int write_pfm(const char *path, const render_image *img)
{
    size_t w = (size_t)img->width, h = (size_t)img->height, i, j;
    char head[64];
    int hl = snprintf(head, sizeof head, "PF\n%d %d\n-1.0\n", img->width, img->height), r;
    unsigned char *buf = malloc((size_t)hl + 12 * w * h), *p;
    if (!buf) return 0;
    memcpy(buf, head, (size_t)hl);
    p = buf + hl;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            const float *src = img->rgba + 4 * ((h - 1 - j) * w + i);
            int c;
            for (c = 0; c < 3; ++c) {
                uint32_t u;
                memcpy(&u, &src[c], 4);
                *p++ = (unsigned char)(u & 255u);
                *p++ = (unsigned char)((u >> 8) & 255u);
                *p++ = (unsigned char)((u >> 16) & 255u);
                *p++ = (unsigned char)(u >> 24);
            }
        }
    r = cli_write_file(path, buf, (size_t)hl + 12 * w * h);
    free(buf);
    return r;
}

static int write_buffers(const char *path, const render_image *img)
{
    size_t n = (size_t)img->width * img->height, k;
    float *b = malloc(n * 14 * sizeof *b);
    int r;
    if (!b) return 0;
    for (k = 0; k < n; ++k) {
        float *o = b + 14 * k;
        memcpy(o, img->st + 2 * k, 2 * sizeof *o);
        memcpy(o + 2, img->jacobian + 4 * k, 4 * sizeof *o);
        o[6] = img->lod[k];
        o[7] = img->texels[k];
        o[8] = img->depth[k];
        memcpy(o + 9, img->normal + 3 * k, 3 * sizeof *o);
        memcpy(o + 12, img->id + 2 * k, 2 * sizeof *o);
    }
    r = cli_write_file(path, b, n * 14 * sizeof *b);
    free(b);
    return r;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

int cmd_render(int argc, char **argv)
{
    const char *scene = "teapot", *out = NULL, *buffers = NULL, *val;
    int width = 0, height = 0, i, rc = EXIT_OK, sampler_given = 0;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    render_options o;
    render_scene *sc = NULL;
    render_image img;
    char err[256];
    render_options_init(&o);
    o.threads = ncpu > 0 && ncpu < 1024 ? (int)ncpu : 1;
    o.progress = cli_progress;
    for (i = 1; i < argc; ++i) {
        int r;
        if (cli_is_help(argv[i])) {
            printf("%s%s", render_help, cli_sampler_help);
            return EXIT_OK;
        }
        if ((r = cli_sampler_flag("render", argc, argv, &i, &o.sampler)) != 0) {
            if (r < 0) return EXIT_USAGE;
            sampler_given = 1;
        } else if (cli_opt(argc, argv, &i, "--scene", &val)) {
            if (!val) return EXIT_USAGE;
            scene = val;
        } else if (cli_opt(argc, argv, &i, "--out", &val)) {
            if (!val) return EXIT_USAGE;
            out = val;
        } else if (cli_opt(argc, argv, &i, "--buffers", &val)) {
            if (!val) return EXIT_USAGE;
            buffers = val;
        } else if (cli_opt(argc, argv, &i, "--width", &val)) {
            if (!val || !cli_parse_int(val, &width) || width < 1 || width > 16384)
                return cli_usage_error("render", "--width needs an integer in 1..16384");
        } else if (cli_opt(argc, argv, &i, "--height", &val)) {
            if (!val || !cli_parse_int(val, &height) || height < 1 || height > 16384)
                return cli_usage_error("render", "--height needs an integer in 1..16384");
        } else if (cli_opt(argc, argv, &i, "--threads", &val)) {
            if (!val || !cli_parse_int(val, &o.threads) || o.threads < 1 || o.threads > 1024)
                return cli_usage_error("render", "--threads needs an integer in 1..1024");
        } else if (cli_opt(argc, argv, &i, "--shade", &val)) {
            if (val && strcmp(val, "full") == 0) o.shade = RENDER_SHADE_FULL;
            else if (val && strcmp(val, "texture") == 0) o.shade = RENDER_SHADE_TEXTURE;
            else return cli_usage_error("render", "--shade is full or texture");
        } else if (strcmp(argv[i], "--corners") == 0) {
            o.corners = 1;
        } else if (strcmp(argv[i], "--progress") == 0) {
            setenv("TEXSAMPLE_PROGRESS", "1", 1);
        } else {
            return cli_usage_error("render", "unknown option '%s' (try --help)", argv[i]);
        }
    }
    if (!out && !buffers) return cli_usage_error("render", "--out FILE or --buffers FILE is required");
    if (out && !ends_with(out, ".ppm") && !ends_with(out, ".pfm"))
        return cli_usage_error("render", "--out: this build writes .ppm and .pfm");
    o.use_scene_sampler = !sampler_given;
    if (buffers) o.buffers = RENDER_BUF_ST | RENDER_BUF_JACOBIAN | RENDER_BUF_LOD |
                             RENDER_BUF_TEXELS | RENDER_BUF_DEPTH | RENDER_BUF_NORMAL | RENDER_BUF_ID;
    if ((ends_with(scene, ".json") ? render_scene_load(scene, width, height, &sc, err, sizeof err)
                                   : render_scene_builtin(scene, width, height, &sc, err, sizeof err)) != 0)
        return cli_runtime_error("render", "%s", err);
    if (render_image_run(sc, &o, &img, err, sizeof err) != 0) {
        render_scene_destroy(sc);
        return cli_runtime_error("render", "%s", err);
    }
    if (out && !(ends_with(out, ".ppm") ? write_ppm(out, &img) : write_pfm(out, &img)))
        rc = cli_runtime_error("render", "cannot write '%s'", out);
    if (rc == EXIT_OK && buffers && !write_buffers(buffers, &img))
        rc = cli_runtime_error("render", "cannot write '%s'", buffers);
    render_image_free(&img);
    render_scene_destroy(sc);
    return rc;
}
