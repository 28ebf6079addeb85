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
    "                     sphere, teapot-image, photo-plane) or else a JSON\n"
    "                     scene file (a regular file of at most 64 MiB; image\n"
    "                     files relative to it); default teapot\n"
    "  --width N, --height N  image size (default: the scene's, 512 x 512)\n"
    "  --threads N        worker threads (default: all online CPUs)\n"
    "  --out FILE         image: .exr (linear float RGBA) or .png (sRGB 8-bit)\n"
    "  --buffers FILE.exr per-pixel buffers as a float OpenEXR with channels\n"
    "                     s t dsdx dtdx dsdy dtdy lod texels Z N.X N.Y N.Z\n"
    "                     object prim (see doc/renderer.md)\n"
    "  --shade full|texture  Blinn-Newell shading, or the filtered texture only\n"
    "  --corners          pass the exact footprint corners (Blinn-Newell mode)\n"
    "  --progress         show progress even when stderr is not a terminal\n"
    "  --cache-mb N       image textures open through one texture system whose\n"
    "                     tile cache holds N MiB (default 1024, OpenImageIO's);\n"
    "                     0 reads each image file whole (doc/renderer.md)\n"
    "\n"
    "Sampler flags (override the scene's sampler when given):\n";

static int is_builtin(const char *name)
{
    int k;
    for (k = 0; render_builtin_names[k]; ++k)
        if (strcmp(name, render_builtin_names[k]) == 0) return 1;
    return 0;
}

int cmd_render(int argc, char **argv)
{
    const char *scene = "teapot", *out = NULL, *buffers = NULL, *val;
    int width = 0, height = 0, i, rc = EXIT_OK, sampler_given = 0;
    long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
    render_options o;
    render_parse_options po;
    render_scene *sc = NULL;
    render_image img;
    char err[1024];
    render_options_init(&o);
    render_parse_options_init(&po);
    o.threads = ncpu > 0 && ncpu < 1024 ? (int)ncpu : 1;
    o.progress = cli_progress;
    for (i = 1; i < argc; ++i) {
        int r;
        if (cli_is_help(argv[i])) {
            fputs(render_help, stdout);
            cli_sampler_help_print();
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
        } else if (cli_opt(argc, argv, &i, "--cache-mb", &val)) {
            float mb;
            if (!val || !cli_parse_float(val, &mb) || !(mb >= 0.0f) || mb > 1048576.0f)
                return cli_usage_error("render", "--cache-mb needs a size in MiB in [0, 1048576]");
            po.cache_mb = mb;
        } else if (strcmp(argv[i], "--corners") == 0) {
            o.corners = 1;
        } else if (strcmp(argv[i], "--progress") == 0) {
            setenv("TEXSAMPLE_PROGRESS", "1", 1);
        } else {
            return cli_usage_error("render", "unknown option '%s' (try --help)", argv[i]);
        }
    }
    if (!out && !buffers) return cli_usage_error("render", "--out FILE or --buffers FILE is required");
    if (out && !render_output_kind(out))
        return cli_usage_error("render", "--out '%s': the image is .exr or .png", out);
    if (buffers && render_output_kind(buffers) != 1)
        return cli_usage_error("render", "--buffers '%s': the buffers are an .exr file", buffers);
    o.use_scene_sampler = !sampler_given;
    if (buffers) o.buffers = RENDER_BUF_ST | RENDER_BUF_JACOBIAN | RENDER_BUF_LOD |
                             RENDER_BUF_TEXELS | RENDER_BUF_DEPTH | RENDER_BUF_NORMAL | RENDER_BUF_ID;
    /* A built-in name, else a file (whatever its name: /dev/zero or a FIFO
     * is refused by the loader as not a regular file). */
    if ((is_builtin(scene) ? render_scene_builtin_ex(scene, width, height, &po, &sc, err, sizeof err)
                           : render_scene_load_ex(scene, width, height, &po, &sc, err, sizeof err)) != 0)
        return cli_runtime_error("render", "%s", err);
    if (render_image_run(sc, &o, &img, err, sizeof err) != 0) {
        render_scene_destroy(sc);
        return cli_runtime_error("render", "%s", err);
    }
    if (out && render_image_write(&img, out, err, sizeof err) != 0)
        rc = cli_runtime_error("render", "%s", err);
    if (rc == EXIT_OK && buffers && render_image_write_buffers(&img, buffers, err, sizeof err) != 0)
        rc = cli_runtime_error("render", "%s", err);
    render_image_free(&img);
    render_scene_destroy(sc);
    return rc;
}
