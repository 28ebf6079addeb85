/*
 * The comparison set of issue 7: the renderer's built-in checkerboard plane
 * to the horizon, grid teapot and zone plate, and two scenes of compare's
 * own — the teapot with an image texture, and a tilted plane with a
 * photograph. Both take an image from testimages/ when the renderer can
 * read images and one is there; otherwise they fall back to a procedural
 * "natural" texture (Perlin marble, detail kept below the bake's Nyquist
 * frequency so that the baked texture holds the whole signal) and say so.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

const char *const cmp_scene_names[] = {"plane", "teapot", "teapot-image", "zoneplate",
                                       "photo-plane", NULL};
const char *const cmp_default_scenes[] = {"plane", "teapot", NULL};

/* Image candidates, relative to the working directory (the README runs
 * texsample from the top of the repository). */
static const char *const photo_files[] = {"testimages/photo.png", "testimages/photo.jpg",
                                          "testimages/photo.exr", NULL};

/* Marble with 7 octaves from 4 cycles: detail up to 256 cycles per unit,
 * under the 1024-texel bake's Nyquist frequency (512). */
static const char natural_texture[] =
    "{\"name\":\"tex\",\"type\":\"marble\",\"freq\":4,\"octaves\":7,\"amount\":3,"
    "\"size\":1024,\"samples\":2,\"a\":[0.32,0.2,0.1,1],\"b\":[0.85,0.78,0.62,1]}";

/* The zone plate, minified: the renderer's built-in shows its 256-texel
 * texture one texel per pixel at 256 × 256 (nothing to filter). Here
 * cos(π k r²) with k = 700 reaches 495 cycles per unit in the corners,
 * about 2 cycles per pixel at 256 × 256, baked at 1024 texels (Nyquist 512). */
static const char zoneplate_json[] =
    "{\"camera\":{\"eye\":[0.5,0.5,1.2071067811865475],\"look\":[0.5,0.5,0],\"up\":[0,1,0],"
    "\"fov\":45},\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"zp\",\"type\":\"zoneplate\",\"amount\":700,\"size\":1024}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"zp\"}],"
    "\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],[1,1,0],[0,1,0]],"
    "\"st\":[[0,0],[1,0],[1,1],[0,1]]}]}]}";

/* %s: the texture object. */
static const char teapot_image_json[] =
    "{\"camera\":{\"eye\":[6.5,-8.5,5.2],\"look\":[0.15,0,1.35],\"up\":[0,0,1],\"fov\":28},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[%s],\"materials\":[{\"name\":\"m\",\"texture\":\"tex\"}],"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"m\"}]}";
static const char photo_plane_json[] =
    "{\"camera\":{\"eye\":[0,-1.6,0.75],\"look\":[0,1.2,0],\"up\":[0,0,1],\"fov\":50},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\","
    "\"wrap_s\":\"clamp_to_edge\",\"wrap_t\":\"clamp_to_edge\"},"
    "\"textures\":[%s],\"materials\":[{\"name\":\"m\",\"texture\":\"tex\"}],"
    "\"objects\":[{\"type\":\"polygons\",\"material\":\"m\",\"polygons\":[{\"v\":[[-1,-0.5,0],"
    "[1,-0.5,0],[1,3.5,0],[-1,3.5,0]],\"st\":[[0,1],[1,1],[1,0],[0,0]]}]}]}";

static int file_exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f) fclose(f);
    return f != NULL;
}

/* One of compare's own scenes: with the photo if possible, else procedural. */
static int own_scene(const char *fmt, int size, render_scene **out, char *err, size_t errlen)
{
    char json[4096], tex[1024];
    int k;
    for (k = 0; photo_files[k]; ++k) {
        if (!file_exists(photo_files[k])) continue;
        snprintf(tex, sizeof tex, "{\"name\":\"tex\",\"type\":\"image\",\"file\":\"%s\"}",
                 photo_files[k]);
        snprintf(json, sizeof json, fmt, tex);
        if (render_scene_parse(json, strlen(json), size, size, out, err, errlen) == 0) return 0;
        fprintf(stderr, "texsample compare: %s: %s; using a procedural texture instead\n",
                photo_files[k], err);
        break;
    }
    snprintf(json, sizeof json, fmt, natural_texture);
    return render_scene_parse(json, strlen(json), size, size, out, err, errlen);
}

static void file_label(const char *path, char *label, size_t len)
{
    const char *b = strrchr(path, '/'), *dot;
    size_t n, k;
    b = b ? b + 1 : path;
    dot = strrchr(b, '.');
    n = dot && dot != b ? (size_t)(dot - b) : strlen(b);
    if (n >= len) n = len - 1;
    for (k = 0; k < n; ++k) {
        char c = b[k];
        int ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '-' || c == '_';
        label[k] = ok ? c : '_';
    }
    label[n] = '\0';
}

int cmp_scene_open(const char *name, int size, render_scene **out, char *label, size_t labellen,
                   char *err, size_t errlen)
{
    int k;
    snprintf(label, labellen, "%s", name);
    if (strcmp(name, "teapot-image") == 0) return own_scene(teapot_image_json, size, out, err, errlen);
    if (strcmp(name, "photo-plane") == 0) return own_scene(photo_plane_json, size, out, err, errlen);
    if (strcmp(name, "zoneplate") == 0)
        return render_scene_parse(zoneplate_json, strlen(zoneplate_json), size, size, out, err,
                                  errlen);
    for (k = 0; render_builtin_names[k]; ++k)
        if (strcmp(name, render_builtin_names[k]) == 0)
            return render_scene_builtin(name, size, size, out, err, errlen);
    file_label(name, label, labellen);
    return render_scene_load(name, size, size, out, err, errlen);
}
