/*
 * What texsample does with what files say: the colour space a file is
 * labelled with (the working space's own name, and OpenEXR chromaticities
 * where known, under an ACES-like OCIO config this test writes), an unknown
 * --colorspace listing the config's names, a file naming a colour space the
 * config does not know (a warning naming both), and the wrap modes a `mip`
 * file stores, which `lookup` follows unless --wrap* says otherwise. The
 * labels are read back from the OpenEXR headers.
 *
 *   cli_colour TEXSAMPLE SOURCE_DIR
 */
#define _XOPEN_SOURCE 700
#include "check.h"
#include "cli_util.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static char *exe;
static const char *image; /* testimages/rgb8.png, 19 x 13 */
static char dir[256];

/* ACES2065-1 as the reference (the aces_interchange role) and ACEScg as
 * scene_linear: the AP1 → AP0 matrix of Academy S-2014-004. */
static const char aces_config[] =
    "ocio_profile_version: 2\n"
    "search_path: \"\"\n"
    "strictparsing: true\n"
    "roles:\n"
    "  aces_interchange: ACES2065-1\n"
    "  reference: ACES2065-1\n"
    "  scene_linear: \"%s\"\n"
    "  default: \"%s\"\n"
    "  data: Raw\n"
    "file_rules:\n"
    "  - !<Rule> {name: Default, colorspace: default}\n"
    "displays:\n"
    "  sRGB:\n"
    "    - !<View> {name: Raw, colorspace: Raw}\n"
    "active_displays: []\n"
    "active_views: []\n"
    "colorspaces:\n"
    "  - !<ColorSpace>\n"
    "    name: ACES2065-1\n"
    "  - !<ColorSpace>\n"
    "    name: \"%s\"\n"
    "    to_scene_reference: !<MatrixTransform> {matrix: [0.6954522414, 0.1406786965, 0.1638690622, 0, "
    "0.0447945634, 0.8596711185, 0.0955343182, 0, -0.0055258826, 0.0040252103, 1.0015006723, 0, 0, 0, 0, 1]}\n"
    "  - !<ColorSpace>\n"
    "    name: sRGB - Texture\n"
    "    to_scene_reference: !<GroupTransform>\n"
    "      children:\n"
    "        - !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055}\n"
    "        - !<MatrixTransform> {matrix: [0.4397010, 0.3829780, 0.1773350, 0, 0.0897923, 0.8134230, "
    "0.0967616, 0, 0.0175440, 0.1115440, 0.8707040, 0, 0, 0, 0, 1]}\n"
    "  - !<ColorSpace>\n"
    "    name: Raw\n"
    "    isdata: true\n";

/* Write the config with its working space named `working`. */
static void write_config(const char *name, const char *working)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    CHECK(f != NULL, "write %s", path);
    if (!f) return;
    fprintf(f, aces_config, working, working, working);
    fclose(f);
}

/* Run several "ENV texsample ARGS" at once in the scratch dir (each loads
 * OpenImageIO: about 0.3 s); job k's stdout in out.K, stderr in err.K,
 * exit code in rc[k]. */
static void run_all(int n, const char *const *env, const char *const *args, int *rc)
{
    char cmd[8192], name[32];
    size_t len = (size_t)snprintf(cmd, sizeof cmd, "cd %s || exit 1; ", dir);
    int k;
    for (k = 0; k < n; ++k)
        len += (size_t)snprintf(cmd + len, sizeof cmd - len, "(%s %s %s >out.%d 2>err.%d; echo $? >rc.%d) & ", env[k],
                                exe, args[k], k, k, k);
    snprintf(cmd + len, sizeof cmd - len, "wait");
    CHECK(len < sizeof cmd - 8 && check_shell(cmd) == 0, "the commands ran");
    for (k = 0; k < n; ++k) {
        char *s;
        snprintf(name, sizeof name, "rc.%d", k);
        s = check_slurp_in(dir, name);
        rc[k] = s ? atoi(s) : -1;
        free(s);
    }
}

/* An OpenEXR header attribute (OpenEXR file layout: after the magic number
 * and version, "name\0type\0" size value, up to an empty name): its value
 * copied to val (at most n bytes); its size, or −1 if absent. */
static int exr_attribute(const char *file, const char *want, void *val, int n)
{
    size_t len = 0, p = 8;
    unsigned char *b = (unsigned char *)check_slurp(file, &len);
    int found = -1;
    while (b && p < len && b[p]) {
        const char *name = (const char *)b + p, *type;
        int32_t size;
        p += strnlen(name, len - p) + 1;
        type = (const char *)b + p;
        p += strnlen(type, len - p) + 1;
        if (p + 4 > len) break;
        memcpy(&size, b + p, 4); /* little-endian, as OpenEXR stores it */
        p += 4;
        if (size < 0 || p + (size_t)size > len) break;
        if (strcmp(name, want) == 0) {
            memcpy(val, b + p, (size_t)(size < n ? size : n));
            found = size;
            break;
        }
        p += (size_t)size;
    }
    free(b);
    return found;
}

static void check_label(const char *name, const char *want_name, int want_chromaticities)
{
    static const float ap1[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
    char path[512], text[128] = {0};
    float xy[8] = {0};
    int n, k;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (want_name) {
        n = exr_attribute(path, "oiio:ColorSpace", text, (int)sizeof text - 1);
        CHECK(n == (int)strlen(want_name) && strcmp(text, want_name) == 0, "%s names %s (%d: '%s')", name,
              want_name, n, text);
    }
    n = exr_attribute(path, "chromaticities", xy, (int)sizeof xy);
    if (!want_chromaticities) {
        CHECK(n < 0, "%s: Rec.709 needs no chromaticities (OpenEXR's default)", name);
        return;
    }
    CHECK(n == 32, "%s carries chromaticities", name);
    for (k = 0; k < 8; ++k) CHECK_EQF(xy[k], ap1[k]);
}

/* lookup's first value ("s t -> r g b a") in out.K. */
static float first_red(int k)
{
    char name[32], *s, *arrow;
    float r;
    snprintf(name, sizeof name, "out.%d", k);
    s = check_slurp_in(dir, name);
    arrow = s ? strstr(s, "-> ") : NULL;
    r = arrow ? strtof(arrow + 3, NULL) : -1.0f;
    free(s);
    return r;
}

/* A flat OpenEXR file (no levels) that stores "mirror,mirror": lookup
 * builds its pyramid with Lanczos-3, which reads past the edges, so the
 * edge handling of the pyramid shows in a minified corner lookup. */
static void flat_file_pyramid(void)
{
    const float q[6] = {0.02f, 0.03f, 0.2f, 0, 0, 0.2f};
    const char *env[2] = {"", ""};
    const char *args[2] = {"lookup --image flat.exr --mipgen lanczos3 --queries corner.raw --text",
                           "lookup --image flat.exr --mipgen lanczos3 --queries corner.raw --text "
                           "--wrap mirrored_repeat"};
    char cmd[1024];
    int rc[2];
    FILE *f;
    snprintf(cmd, sizeof cmd, "command -v oiiotool >/dev/null && cd %s && oiiotool %s --attrib wrapmodes mirror,mirror "
                              "-d half -o flat.exr",
             dir, image);
    if (check_shell(cmd) != 0) {
        check_skip("no oiiotool to write a flat file with wrap modes");
        return;
    }
    snprintf(cmd, sizeof cmd, "%s/corner.raw", dir);
    if ((f = fopen(cmd, "wb")) != NULL) fwrite(q, sizeof q, 1, f), fclose(f);
    run_all(2, env, args, rc);
    CHECK(rc[0] == 0 && rc[1] == 0, "lookups: %d %d", rc[0], rc[1]);
    CHECK(first_red(0) == first_red(1) && first_red(0) > 0, "the built pyramid's edges follow the file: %g, %g",
          first_red(0), first_red(1));
}

static void colour_and_wrap(void)
{
    const float q[6] = {-0.3f, 0.5f, 0, 0, 0, 0}; /* left of the texture */
    char mip_args[1024], bad_args[1024], png_args[1024], path[512];
    const char *env1[3] = {"OCIO=aces.ocio", "", "OCIO=aces.ocio"};
    const char *args1[3] = {mip_args, mip_args + 512,
                            "render --scene plane --width 8 --height 8 --out render.exr"};
    /* Read under a config that does not know ACEScg. */
    const char *env2[6] = {"OCIO=odd.ocio",  "OCIO=odd.ocio",  "OCIO=odd.ocio",
                           "OCIO=aces.ocio", "OCIO=aces.ocio", "OCIO=odd.ocio"};
    const char *args2[6] = {"lookup --image aces.exr --queries left.raw --text --mag nearest",
                            "lookup --image aces.exr --queries left.raw --text --mag nearest --wrap=mirrored_repeat",
                            "lookup --image aces.exr --queries left.raw --text --mag nearest --wrap-s clamp_to_edge",
                            bad_args, png_args, "info aces.exr"};
    int rc[6];
    FILE *f;
    write_config("aces.ocio", "ACEScg");
    write_config("odd.ocio", "ACEScg (test)");
    snprintf(path, sizeof path, "%s/left.raw", dir);
    if ((f = fopen(path, "wb")) != NULL) fwrite(q, sizeof q, 1, f), fclose(f);
    snprintf(mip_args, 512, "mip %s aces.exr --wrap mirrored_repeat", image);
    snprintf(mip_args + 512, 512, "mip %s shipped.exr", image);
    snprintf(bad_args, sizeof bad_args, "lookup --image %s --colorspace nosuch --queries left.raw", image);
    snprintf(png_args, sizeof png_args, "lookup --image %s --queries left.raw", image);

    run_all(3, env1, args1, rc);
    CHECK(rc[0] == 0 && rc[1] == 0 && rc[2] == 0, "mip, mip, render: %d %d %d", rc[0], rc[1], rc[2]);
    /* The working space by its own name, not OpenImageIO's "Linear". */
    check_label("aces.exr", "ACEScg", 1);
    check_label("shipped.exr", "lin_rec709", 0);
    /* OIIO 2.4's OpenEXR writer drops the name; the chromaticities stay. */
    check_label("render.exr", NULL, 1);

    run_all(6, env2, args2, rc);
    CHECK(rc[0] == 0 && rc[1] == 0 && rc[2] == 0, "lookups: %d %d %d", rc[0], rc[1], rc[2]);
    CHECK(cli_holds(dir, "err.0",
                    "warning: 'aces.exr' names colour space 'ACEScg', which the OCIO config does not know; "
                    "decoded as 'scene_linear'"),
          "a file's unknown colour space is reported, with the space used");
    CHECK(first_red(0) == first_red(1), "the file's wrap modes are used: %g, %g", first_red(0), first_red(1));
    CHECK(first_red(2) != first_red(0), "--wrap-s overrides them: %g, %g", first_red(2), first_red(0));
    CHECK(rc[3] == 1 && cli_holds(dir, "err.3",
                                  "unknown colour space 'nosuch'; the OCIO config 'aces.ocio' has ACES2065-1, "
                                  "ACEScg, sRGB - Texture, Raw"),
          "an unknown --colorspace lists the config's names");
    {
        char *err = check_slurp_in(dir, "err.4");
        /* OpenImageIO calls the PNG "sRGB"; the config says "sRGB - Texture". */
        CHECK(rc[4] == 0 && err && !*err, "OpenImageIO's generic names are not reported: '%s'", err ? err : "");
        free(err);
    }
    /* info says it too, and which space it would decode from. */
    CHECK(rc[5] == 0 &&
              cli_holds(dir, "err.5",
                        "texsample info: warning: 'aces.exr' names colour space 'ACEScg', which the OCIO config "
                        "does not know; decoded as 'scene_linear'") &&
              cli_holds(dir, "out.5", "colorspace ACEScg\n") &&
              cli_holds(dir, "out.5", "wrapmodes mirror,mirror\n") &&
              cli_holds(dir, "out.5",
                        "colorspace scene_linear (the rule: 8/16-bit sRGB, half/float linear; the OCIO config does "
                        "not know the file's)"),
          "info reports the unknown colour space (exit %d)", rc[5]);
}

int main(int argc, char **argv)
{
    static char path[1024];
    char tmpl[] = "/tmp/texsample_colour_XXXXXX";
    if (argc < 3) return 2;
    exe = realpath(argv[1], NULL);
    snprintf(path, sizeof path, "%s/testimages/rgb8.png", argv[2]);
    image = path;
    if (!exe || !mkdtemp(tmpl)) return 1;
    snprintf(dir, sizeof dir, "%s", tmpl);
    unsetenv("OCIO");
    RUN(colour_and_wrap);
    RUN(flat_file_pyramid);
    cli_remove_dir(dir);
    free(exe);
    return check_finish();
}
