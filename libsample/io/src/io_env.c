/* Environment maps in files (doc/environment-maps.md, "Files"): which
 * layout a file holds, OpenEXR's cube layout both ways. Resampling between
 * layouts is io_env_convert.c's.
 *
 * OpenEXR's cube layout (ImfEnvmap.h, CubeMap::pixelPosition): the six
 * faces +X, −X, +Y, −Y, +Z, −Z stacked from the top of an N × 6N image,
 * each seen from outside the cube, so each is OpenGL's face (GL 4.6
 * table 8.19, seen from inside) mirrored: the ±X and ±Z faces left to
 * right, the ±Y faces top to bottom. Both are in OpenEXR's direction space
 * (y up), the space of its lat-long layout and of sample_batch_latlong, so a
 * cube and a lat-long map of one environment agree direction by direction.
 * OpenEXR's helpers put the edge texels' centres on the cube's edges
 * (positionInFace / (N − 1)); OpenImageIO, OpenGL and libsample put texel
 * edges there ((i + ½) / N), which this file keeps: only the flips are
 * taken from OpenEXR. */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>

/* Texel (i, j) of GL face f ↔ pixel (x, y) of OpenEXR's stacked image: a
 * mirror either way, so the same function maps both directions. */
static void exr_face_pixel(int f, int n, int i, int j, int *x, int *y)
{
    int vertical = f == 2 || f == 3; /* ±Y */
    *x = vertical ? i : n - 1 - i;
    *y = f * n + (vertical ? n - 1 - j : j);
}

const sample_mip_params *io_env_latlong_mip(const sample_mip_params *mip, sample_mip_params *copy)
{
    if (!mip) return NULL;
    *copy = *mip;
    copy->wrap_s = SAMPLE_WRAP_REPEAT;
    copy->wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    return copy;
}

/* ---- Reading ------------------------------------------------------------- */

static sample_status read_cube(const char *path, const sample_io_options *o, const sample_mip_params *mip, int n,
                               sample_texture **out, sample_error *err)
{
    sample_io_options ro;
    sample_texture *flat = NULL;
    sample_texture_info inf;
    sample_image faces[6];
    float *px = NULL;
    size_t face_floats;
    sample_status st;
    int f, i, j, c;
    if (o) ro = *o;
    else sample_io_options_init(&ro);
    ro.use_file_levels = 0;
    ro.float_storage = 1;
    ro.file_info = NULL;
    if ((st = sample_io_read_texture(path, &ro, NULL, &flat, err)) != SAMPLE_OK) return st;
    sample_texture_info_get(flat, &inf);
    face_floats = (size_t)n * (size_t)n * (size_t)inf.channels;
    if (!(px = (float *)malloc(6 * face_floats * sizeof(float)))) {
        sample_texture_destroy(flat);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate six %d x %d faces", n, n);
    }
    for (f = 0; f < 6; ++f) {
        float *face = px + (size_t)f * face_floats;
        for (j = 0; j < n; ++j)
            for (i = 0; i < n; ++i) {
                float v[4];
                int x, y;
                exr_face_pixel(f, n, i, j, &x, &y);
                sample_texture_texel(flat, 0, x, y, v);
                for (c = 0; c < inf.channels; ++c) face[((size_t)j * (size_t)n + (size_t)i) * (size_t)inf.channels + (size_t)c] = v[c];
            }
        faces[f].width = faces[f].height = n;
        faces[f].channels = inf.channels;
        faces[f].format = SAMPLE_FORMAT_F32;
        faces[f].data = face;
        faces[f].row_stride = 0;
    }
    sample_texture_destroy(flat);
    st = sample_texture_create_cube(faces, mip, out, err);
    free(px);
    return st;
}

sample_status sample_io_read_env(const char *path, const sample_io_options *o, const sample_mip_params *mip,
                                 sample_texture **out, sample_error *err)
{
    sample_io_file_info info;
    sample_mip_params ll;
    sample_status st;
    int cube, named_cube;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_read_env: out is NULL");
    *out = NULL;
    if ((st = sample_io_describe(path, o, &info, err)) != SAMPLE_OK) return st;
    /* The shape decides where it can (1:6 can only be a cube, 2:1 only
     * lat-long): a file's attributes may contradict it, as exrenvmap copies
     * its input's textureformat beside the envmap attribute it writes. */
    named_cube = strcmp(info.textureformat, "CubeFace Environment") == 0;
    if (info.height == 6 * info.width) cube = 1;
    else if (info.width == 2 * info.height) cube = 0;
    else if (named_cube)
        return sample_error_set(err, SAMPLE_E_UNSUPPORTED,
                                "'%s' says it is a cube map but is %d x %d: OpenEXR's cube layout is N x 6N", path,
                                info.width, info.height);
    else if (strcmp(info.textureformat, "LatLong Environment") == 0) cube = 0;
    else
        return sample_error_set(err, SAMPLE_E_UNSUPPORTED,
                                "'%s' (%d x %d) names no environment layout and has neither shape: a lat-long map "
                                "is 2:1, a cube map 1:6 (OpenEXR's stacked faces)",
                                path, info.width, info.height);
    if (cube) return read_cube(path, o, mip, info.width, out, err);
    return sample_io_read_texture(path, o, io_env_latlong_mip(mip, &ll), out, err);
}

/* ---- Writing --------------------------------------------------------------- */

static int is_pow2(int n) { return n > 0 && (n & (n - 1)) == 0; }

/* The cube's levels as OpenEXR's stacked image: level k of an N × 6N
 * image is the faces' level k stacked while faces remain (N a power of
 * two: ROUND_DOWN halves 6N as it halves N), then 1 × 3 and 1 × 1 from
 * the 1 × 6 level by a box (they are no cube; a reader ignores them). */
static sample_status stack_cube(const sample_texture *cube, sample_texture **out, sample_error *err)
{
    sample_texture_info inf;
    sample_image lv[SAMPLE_MAX_LEVELS];
    float *buf[SAMPLE_MAX_LEVELS] = {0};
    int n, levels, face_levels, k, f, i, j, c, full = 0;
    sample_status st = SAMPLE_OK;
    sample_texture_info_get(cube, &inf);
    n = inf.width;
    for (k = n; k > 1; k >>= 1) ++full;
    face_levels = is_pow2(n) && inf.levels == full + 1 ? inf.levels : 1;
    levels = face_levels > 1 ? face_levels + 2 : 1;
    for (k = 0; k < levels && st == SAMPLE_OK; ++k) {
        int lw = n >> k > 0 ? n >> k : 1, lh = 6 * n >> k > 0 ? 6 * n >> k : 1;
        size_t nc = (size_t)inf.channels;
        if (!(buf[k] = (float *)malloc((size_t)lw * (size_t)lh * nc * sizeof(float)))) {
            st = sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate level %d of the cube's image", k);
            break;
        }
        if (k < face_levels) {
            for (f = 0; f < 6; ++f)
                for (j = 0; j < lw; ++j)
                    for (i = 0; i < lw; ++i) {
                        float v[4];
                        int x, y;
                        sample_texture_texel_layer(cube, k, f, i, j, v);
                        exr_face_pixel(f, lw, i, j, &x, &y);
                        for (c = 0; c < inf.channels; ++c) buf[k][((size_t)y * (size_t)lw + (size_t)x) * nc + (size_t)c] = v[c];
                    }
        } else {
            int ph = 6 * n >> (k - 1), r = ph / lh; /* 6 → 3 by pairs, 3 → 1 by three */
            for (j = 0; j < lh; ++j)
                for (c = 0; c < inf.channels; ++c) {
                    double s = 0;
                    for (i = 0; i < r; ++i) s += buf[k - 1][(size_t)(j * r + i) * nc + (size_t)c];
                    buf[k][(size_t)j * nc + (size_t)c] = (float)(s / r);
                }
        }
        lv[k].width = lw, lv[k].height = lh, lv[k].channels = inf.channels;
        lv[k].format = SAMPLE_FORMAT_F32;
        lv[k].data = buf[k];
        lv[k].row_stride = 0;
    }
    if (st == SAMPLE_OK) st = sample_texture_create_levels(lv, levels, out, err);
    for (k = 0; k < levels; ++k) free(buf[k]);
    return st;
}

sample_status sample_io_write_env(const char *path, const sample_texture *tex, const sample_io_exr_options *o,
                                  sample_error *err)
{
    sample_texture_info inf;
    sample_texture *flat = NULL;
    sample_status st;
    char ext[16];
    if (!path || !tex)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "writing an environment map: no path or no texture");
    io_extension(path, ext, sizeof ext);
    if (strcmp(ext, "exr") != 0)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT,
                                "'%s': environment maps are written as OpenEXR (.exr), whose envmap attribute names "
                                "the layout",
                                path);
    sample_texture_info_get(tex, &inf);
    if (inf.kind == SAMPLE_TEXTURE_2D) return io_write_mip_env(path, tex, o, IO_ENV_LATLONG, err);
    if (inf.kind != SAMPLE_TEXTURE_CUBE)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "a %s texture is no environment map",
                                sample_texture_kind_name(inf.kind));
    if ((st = stack_cube(tex, &flat, err)) != SAMPLE_OK) return st;
    st = io_write_mip_env(path, flat, o, IO_ENV_CUBE, err);
    sample_texture_destroy(flat);
    return st;
}
