/*
 * The comparison set (doc/comparison.md, "The scenes"): the renderer's
 * built-in checkerboard plane to the horizon and photograph on a tilted
 * plane, and compare's own framings: the grid teapot and the teapot with
 * the photograph, whole in the picture, and two zone plates, one minified
 * face-on and one on an oblique plane; and mirrors in an environment map.
 * Compare shows the filtered texture (or the reflected environment) only,
 * so its own scenes carry no lights.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

const char *const cmp_scene_names[] = {"plane",         "teapot",      "teapot-image", "zoneplate",
                                       "zoneplate-oblique", "photo-plane", "mirrors", "solid", NULL};
const char *const cmp_default_scenes[] = {"plane", "teapot", NULL};

/* The renderer's teapot scenes (Fig. 10 of Blinn & Newell) look from the
 * same direction but frame the body, so the spout leaves the picture. Here
 * the view axis goes through the middle of the teapot's extent on the
 * screen (handle to spout tip, foot to knob) and the field of view takes
 * all of it with a margin: 8 % of the side left and right
 * (tests/compare_scenes.c checks that none of the outer 4 % sees it). */
#define TEAPOT_VIEW                                                                       \
    "{\"camera\":{\"eye\":[6.5,-8.5,5.2],\"look\":[0.52,0.24,1.45],\"up\":[0,0,1],\"fov\":33}," \
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
#define TEAPOT_OBJECT                                                    \
    "\"materials\":[{\"name\":\"glaze\",\"texture\":\"t\"}],"            \
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"glaze\"}]}"
/* The pattern of the renderer's teapot: Fig. 2's grid of parametric lines. */
static const char teapot_json[] =
    TEAPOT_VIEW "\"textures\":[{\"name\":\"t\",\"type\":\"grid\",\"freq\":4,\"width\":0.12,"
    "\"a\":[0.85,0.8,0.65,1],\"b\":[0.08,0.15,0.55,1]}]," TEAPOT_OBJECT;
/* testimages/photo.jpg on every patch (REPEAT across patch seams). */
static const char teapot_image_json[] =
    TEAPOT_VIEW "\"textures\":[{\"name\":\"t\",\"type\":\"image\",\"file\":\"photo.jpg\"}],"
    TEAPOT_OBJECT;

/* The zone plate cos(π k r²) on the unit square: k·r cycles per unit at
 * distance r from the centre, baked at n texels (Nyquist n/2 cycles per
 * unit, above k/√2 in the corners), each the mean of m × m samples. */
#define ZONEPLATE_SQUARE(k, n, m)                                                             \
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"                    \
    "\"textures\":[{\"name\":\"zp\",\"type\":\"zoneplate\",\"amount\":" #k ",\"size\":" #n ",\"samples\":" #m "}]," \
    "\"materials\":[{\"name\":\"m\",\"texture\":\"zp\"}],"                                  \
    "\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]," \
    "\"st\":[[0,0],[1,0],[1,1],[0,1]]}]}]}"
/* Face-on, filling the picture, k = 700 (495 cycles per unit in the
 * corners), 1024 texels: about 4 texels per pixel at 256 × 256 in both
 * directions everywhere (the renderer's built-in zone plate maps texels
 * 1:1 onto pixels, so nothing would be filtered). Every isotropic mip
 * filter then reads one level at λ = 2 alone, and they score alike. */
static const char zoneplate_json[] =
    "{\"camera\":{\"eye\":[0.5,0.5,1.2071067811865475],\"look\":[0.5,0.5,0],\"up\":[0,1,0],"
    "\"fov\":45}," ZONEPLATE_SQUARE(700, 1024, 4);
/* The square seen from low over its near edge, k = 300 (212 cycles per
 * unit in the corners), 1024 texels like the face-on plate (at 512 the
 * bake's own blur would put a floor under every filter's error near the
 * eye). At most 0.21 cycles per texel, so 2 × 2 samples per texel give
 * its mean within 2 % (4 × 4: 0.4 %) at a quarter of the bake. At 96 × 96
 * the anisotropy goes from 1.5 at the bottom of the picture to 8.9 at the
 * far edge and λ from 1.8 to 6.5, so the footprint's size and shape and
 * the local frequency all vary over the picture (tests/compare_scenes.c). */
static const char zoneplate_oblique_json[] =
    "{\"camera\":{\"eye\":[0.5,-0.15,0.15],\"look\":[0.5,0.6,0],\"up\":[0,0,1],\"fov\":50},"
    ZONEPLATE_SQUARE(300, 1024, 2);

/* Mirrors in an environment: a teapot and a sphere that reflect the
 * renderer's procedural room (sky, sun, a band of windows, a checkered
 * floor) baked into a 512 × 256 lat-long map, infinitely far. Each pixel
 * asks for the reflected direction with its exact screen derivatives
 * (curvature through dN/dx: the sphere's reflection minifies the whole
 * room into its rim, the teapot's spout and handle strongly), the truth is
 * the map's bilinear base level over the exact reflected directions, and
 * OpenImageIO's environment() reads the same map (doc/comparison.md). */
static const char mirrors_json[] =
    "{\"camera\":{\"eye\":[5.5,-9.5,4.6],\"look\":[1.35,0.5,1.25],\"up\":[0,0,1],\"fov\":38},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"materials\":[{\"name\":\"mirror\",\"reflect\":1}],"
    "\"environment\":{\"type\":\"latlong\",\"size\":512},"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"mirror\"},"
    "{\"type\":\"sphere\",\"centre\":[3.1,1.6,1],\"radius\":1,\"material\":\"mirror\"}]}";
/* Solid textures baked into 3D textures (doc/volumes.md, "Renderer"): a
 * teapot carved from wood (rings around its z axis, 1 per half unit) and a
 * smaller one from marble (Perlin's sin(x + turbulence)), each a 64³
 * volume over its box (CLAMP_TO_EDGE), on a plane tilted through a 3D
 * checker of unit cells to the horizon (a 64³ volume of 4³ cells,
 * REPEAT). The wood's texels are means of 2³ samples; the checker's need
 * one (16 texels per cell, none straddles a face) and the marble is
 * smooth at this size, so one sample each keeps the bakes (most of the
 * scene's setup, compare --scene all included) short. The truth evaluates
 * the procedural functions at the exact surface points
 * (render_scene_texture_truth). */
static const char solid_json[] =
    "{\"camera\":{\"eye\":[7.5,-9.5,4.2],\"look\":[1.6,1.2,0.9],\"up\":[0,0,1],\"fov\":40},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":["
    "{\"name\":\"wood\",\"type\":\"wood\",\"freq\":2,\"amount\":3,\"a\":[0.62,0.38,0.17,1],"
    "\"b\":[0.3,0.15,0.06,1],\"solid\":{\"min\":[-3.1,-2.1,-0.1],\"max\":[3.5,2.1,3.2]}},"
    "{\"name\":\"marble\",\"type\":\"marble\",\"freq\":1,\"amount\":3,\"a\":[0.92,0.9,0.86,1],"
    "\"b\":[0.2,0.22,0.3,1],\"solid\":{\"min\":[1.0,2.2,-0.1],\"max\":[5.6,5.2,2.3],\"samples\":1}},"
    "{\"name\":\"checker\",\"type\":\"checker\",\"freq\":1,\"a\":[0.1,0.1,0.12,1],"
    "\"b\":[0.85,0.85,0.8,1],\"solid\":{\"min\":[0,0,0],\"max\":[4,4,4],\"wrap\":\"repeat\",\"samples\":1}}],"
    "\"materials\":[{\"name\":\"wood\",\"texture\":\"wood\"},{\"name\":\"marble\",\"texture\":\"marble\"},"
    "{\"name\":\"checker\",\"texture\":\"checker\"}],"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"wood\"},"
    "{\"type\":\"teapot\",\"material\":\"marble\",\"scale\":0.7,\"offset\":[3.3,3.7,0]},"
    "{\"type\":\"plane\",\"material\":\"checker\",\"centre\":[0,0,-0.35],\"axis\":[0.12,0.2,1]}]}";

static const struct {
    const char *name, *json;
} own_scenes[] = {
    {"mirrors", mirrors_json},
    {"solid", solid_json},
    {"teapot", teapot_json},
    {"teapot-image", teapot_image_json},
    {"zoneplate", zoneplate_json},
    {"zoneplate-oblique", zoneplate_oblique_json},
};

/* Image files of the scenes: testimages/ of the source tree, as for the
 * renderer's built-in scenes (tools/compare.cmake). */
#ifdef TEXSAMPLE_SOURCE_DIR
#define CMP_IMAGES TEXSAMPLE_SOURCE_DIR "/testimages"
#else
#define CMP_IMAGES "testimages"
#endif

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

int cmp_scene_open(const char *name, int size, double cache_mb, render_scene **out, char *label,
                   size_t labellen, char *err, size_t errlen)
{
    render_parse_options po;
    size_t k;
    snprintf(label, labellen, "%s", name);
    render_parse_options_init(&po);
    po.cache_mb = cache_mb;
    for (k = 0; k < sizeof own_scenes / sizeof own_scenes[0]; ++k)
        if (strcmp(name, own_scenes[k].name) == 0) {
            po.base_dir = CMP_IMAGES;
            return render_scene_parse_ex(own_scenes[k].json, strlen(own_scenes[k].json), size,
                                         size, &po, out, err, errlen);
        }
    for (k = 0; render_builtin_names[k]; ++k)
        if (strcmp(name, render_builtin_names[k]) == 0)
            return render_scene_builtin_ex(name, size, size, &po, out, err, errlen);
    file_label(name, label, labellen);
    return render_scene_load_ex(name, size, size, &po, out, err, errlen);
}
