/* Resampling an environment map into the other layout, or the same at
 * another size (sample_io_env_convert; doc/environment-maps.md, "Files"):
 * each new texel is the source filtered by EWA over that texel's
 * footprint, its centre direction and the derivatives of the direction
 * along the new map's texel axes, through the library's own lookups
 * (sample_batch_cube, sample_batch_latlong). */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* Largest side a conversion makes (a 16384² face is 4 GiB of float RGBA). */
#define ENV_MAX_SIDE 16384

/* Table 8.19 as a frame per face: R = axis + sc·U + tc·V on the unit cube. */
static const double face_frame[6][3][3] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
};

/* The query of cube texel (i, j) of face f on an n × n face: its centre's
 * direction and the derivatives of the direction along i and j, so that the
 * footprint a filter sees is that one texel. */
static void cube_texel_query(int f, int n, int i, int j, sample_query3 *q)
{
    double sc = 2.0 * (i + 0.5) / n - 1.0, tc = 2.0 * (j + 0.5) / n - 1.0, step = 2.0 / n;
    int a;
    for (a = 0; a < 3; ++a) {
        q->p[a] = (float)(face_frame[f][0][a] + sc * face_frame[f][1][a] + tc * face_frame[f][2][a]);
        q->dpdx[a] = (float)(step * face_frame[f][1][a]);
        q->dpdy[a] = (float)(step * face_frame[f][2][a]);
    }
}

/* The same for lat-long texel (i, j) of a w × h map: the inverse of
 * sample_batch_latlong's s = atan2(−x, z)/2π + ½, t = ½ − atan2(y, √(x² +
 * z²))/π, i.e. φ = 2π(s − ½), θ = π(½ − t), R = (−sin φ cos θ, sin θ,
 * cos φ cos θ), and its derivatives ∂R/∂φ · 2π/w, ∂R/∂θ · (−π/h). */
static void latlong_texel_query(int w, int h, int i, int j, sample_query3 *q)
{
    double phi = 2.0 * PI * ((i + 0.5) / w - 0.5), theta = PI * (0.5 - (j + 0.5) / h);
    double sp = sin(phi), cp = cos(phi), st = sin(theta), ct = cos(theta);
    double di = 2.0 * PI / w, dj = -PI / h;
    q->p[0] = (float)(-sp * ct), q->p[1] = (float)st, q->p[2] = (float)(cp * ct);
    q->dpdx[0] = (float)(-cp * ct * di), q->dpdx[1] = 0.0f, q->dpdx[2] = (float)(-sp * ct * di);
    q->dpdy[0] = (float)(sp * st * dj), q->dpdy[1] = (float)(ct * dj), q->dpdy[2] = (float)(-cp * st * dj);
}

/* Resample one row of the target (count texels, queries made by the
 * caller) from src into rgba. */
static sample_status lookup(const sample_texture *src, const sample_sampler *smp, const sample_query3 *q, size_t count,
                            float *rgba)
{
    sample_batch3_args a;
    memset(&a, 0, sizeof a);
    a.count = count;
    a.queries = q;
    a.rgba = rgba;
    return sample_batch_env(src, smp, &a);
}

/* rgba (count × 4) into count texels of `channels` channels. */
static void keep_channels(const float *rgba, size_t count, int channels, float *dst)
{
    size_t k;
    int c;
    for (k = 0; k < count; ++k)
        for (c = 0; c < channels; ++c) dst[k * (size_t)channels + (size_t)c] = rgba[k * 4 + (size_t)c];
}

sample_status sample_io_env_convert(const sample_texture *src, sample_texture_kind to, int size,
                                    const sample_mip_params *mip, sample_texture **out, sample_error *err)
{
    sample_texture_info inf;
    sample_sampler smp;
    sample_query3 *q = NULL;
    float *rgba = NULL, *px = NULL;
    sample_status st = SAMPLE_OK;
    int w, h, faces, f, i, j;
    size_t plane;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_env_convert: out is NULL");
    *out = NULL;
    if (!src) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_io_env_convert: no source texture");
    sample_texture_info_get(src, &inf);
    if (inf.kind != SAMPLE_TEXTURE_CUBE && inf.kind != SAMPLE_TEXTURE_2D)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "a %s texture is no environment map",
                                sample_texture_kind_name(inf.kind));
    if (to != SAMPLE_TEXTURE_CUBE && to != SAMPLE_TEXTURE_2D)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "environment maps are cube or lat-long (2d) textures");
    if (size < 0 || size > ENV_MAX_SIDE)
        return sample_error_set(err, size < 0 ? SAMPLE_E_INVALID_ARGUMENT : SAMPLE_E_TOO_LARGE,
                                "environment map size %d: 1 to %d (0: from the source)", size, ENV_MAX_SIDE);
    if (to == SAMPLE_TEXTURE_CUBE) {
        w = h = size ? size : inf.kind == SAMPLE_TEXTURE_CUBE ? inf.width : (inf.width / 4 > 0 ? inf.width / 4 : 1);
        faces = 6;
    } else {
        h = size ? size : inf.kind == SAMPLE_TEXTURE_CUBE ? 2 * inf.width : inf.height;
        if (h > ENV_MAX_SIDE / 2) h = ENV_MAX_SIDE / 2;
        w = 2 * h;
        faces = 1;
    }
    plane = (size_t)w * (size_t)h * (size_t)inf.channels;
    /* EWA over each new texel's footprint: the filter that follows a
     * footprint's true shape, which between these layouts is strongly
     * anisotropic (a lat-long row near a pole is a sliver of a cube face),
     * where trilinear would blur along the short axis by the long one. */
    sample_sampler_init(&smp);
    smp.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    smp.mag_filter = SAMPLE_LINEAR;
    smp.footprint = SAMPLE_FOOTPRINT_EWA;
    q = (sample_query3 *)malloc((size_t)w * sizeof *q);
    rgba = (float *)malloc((size_t)w * 4 * sizeof *rgba);
    px = (float *)malloc((size_t)faces * plane * sizeof *px);
    if (!q || !rgba || !px) st = sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a %d x %d map", w, h);
    for (f = 0; st == SAMPLE_OK && f < faces; ++f)
        for (j = 0; st == SAMPLE_OK && j < h; ++j) {
            for (i = 0; i < w; ++i) {
                if (to == SAMPLE_TEXTURE_CUBE) cube_texel_query(f, w, i, j, &q[i]);
                else latlong_texel_query(w, h, i, j, &q[i]);
            }
            if ((st = lookup(src, &smp, q, (size_t)w, rgba)) == SAMPLE_OK)
                keep_channels(rgba, (size_t)w, inf.channels,
                              px + (size_t)f * plane + (size_t)j * (size_t)w * (size_t)inf.channels);
            else
                sample_error_set(err, st, "resampling the environment map failed");
        }
    if (st == SAMPLE_OK) {
        sample_image img[6];
        sample_mip_params ll;
        for (f = 0; f < faces; ++f) {
            img[f].width = w, img[f].height = h, img[f].channels = inf.channels;
            img[f].format = SAMPLE_FORMAT_F32;
            img[f].data = px + (size_t)f * plane;
            img[f].row_stride = 0;
        }
        st = to == SAMPLE_TEXTURE_CUBE ? sample_texture_create_cube(img, mip, out, err)
                                       : sample_texture_create(img, io_env_latlong_mip(mip, &ll), out, err);
    }
    free(q);
    free(rgba);
    free(px);
    return st;
}
