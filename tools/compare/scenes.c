/*
 * The comparison set: the renderer's built-in checkerboard plane
 * to the horizon, grid teapot, teapot with the photograph and photograph on
 * a tilted plane ("teapot-image", "photo-plane": testimages/photo.jpg of the
 * source tree, read through libsample_io), and one scene of compare's own,
 * a minified zone plate. The photo scenes are the renderer's, not copies,
 * so that `texsample render` and `texsample compare` show the same view.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

const char *const cmp_scene_names[] = {"plane", "teapot", "teapot-image", "zoneplate",
                                       "photo-plane", NULL};
const char *const cmp_default_scenes[] = {"plane", "teapot", NULL};

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
    if (strcmp(name, "zoneplate") == 0)
        return render_scene_parse(zoneplate_json, strlen(zoneplate_json), size, size, out, err,
                                  errlen);
    for (k = 0; render_builtin_names[k]; ++k)
        if (strcmp(name, render_builtin_names[k]) == 0)
            return render_scene_builtin(name, size, size, out, err, errlen);
    file_label(name, label, labellen);
    return render_scene_load(name, size, size, out, err, errlen);
}
