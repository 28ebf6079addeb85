/*
 * Cube maps (GL 4.6 §8.13, doc/environment-maps.md): the query on a face,
 * creation from six faces or from levels, and the pyramid built across
 * face edges.
 */
#include "cube.h"

#include "env_addr.h"
#include "mip.h"

#include <stdio.h>
#include <stdlib.h>

/* A float derivative, held inside float's range. */
static float finite_float(double v)
{
    if (v > FLT_MAX) return FLT_MAX;
    if (v < -FLT_MAX) return -FLT_MAX;
    return (float)v;
}

int ls_cube_query_on(const sample_query3 *q, int f, sample_query *out)
{
    double r[3] = {q->p[0], q->p[1], q->p[2]}, dx[3] = {q->dpdx[0], q->dpdx[1], q->dpdx[2]},
           dy[3] = {q->dpdy[0], q->dpdy[1], q->dpdy[2]}, s, t, a, b;
    cube_face_st(f, r, &s, &t);
    if (!(fabs(s) <= FLT_MAX && fabs(t) <= FLT_MAX)) return 0;
    out->s = (float)s;
    out->t = (float)t;
    cube_face_dst(f, r, dx, &a, &b);
    out->dsdx = finite_float(a);
    out->dtdx = finite_float(b);
    cube_face_dst(f, r, dy, &a, &b);
    out->dsdy = finite_float(a);
    out->dtdy = finite_float(b);
    return 1;
}

int ls_cube_query(const sample_query3 *q, sample_query *out)
{
    double r[3] = {q->p[0], q->p[1], q->p[2]};
    int f;
    if (r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0) return -1;
    f = cube_face_of(r);
    ls_cube_query_on(q, f, out);
    return f;
}

/* ---- Creation ------------------------------------------------------------ */

static int level_dim(int n, int k) { return (n >> k) > 0 ? (n >> k) : 1; }

static const char *const face_names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

/* Checks level k's six faces (faces[0 … 5]) against face 0 of level 0. */
static sample_status check_faces(const sample_image *faces, const sample_image *base, int k, sample_error *err)
{
    int f, n = level_dim(base->width, k);
    sample_status st;
    for (f = 0; f < 6; ++f) {
        const sample_image *im = &faces[f];
        char what[48];
        snprintf(what, sizeof what, "cube level %d face %s", k, face_names[f]);
        if ((st = ls_tex_check_image(im, what, err)) != SAMPLE_OK) return st;
        RETURN_ERROR_IF(im->width != n || im->height != n, err, SAMPLE_E_BAD_SIZE,
                        "%s is %d x %d, expected %d x %d (cube faces are square and equal)", what, im->width,
                        im->height, n, n);
        RETURN_ERROR_IF(im->channels != base->channels || im->format != base->format, err,
                        SAMPLE_E_INVALID_ARGUMENT, "%s has a different channel count or format from face +X", what);
    }
    return SAMPLE_OK;
}

static int full_levels(int n)
{
    int full = 1;
    while (n > 1) {
        n >>= 1;
        ++full;
    }
    return full;
}

/* A cube texture holding `count` levels copied from faces (level-major). */
static sample_status cube_from(const sample_image *faces, int count, sample_texture **out, sample_error *err)
{
    sample_texture *tex = ls_tex_new(SAMPLE_TEXTURE_CUBE, faces[0].width, faces[0].height, faces[0].channels,
                                     faces[0].format);
    sample_status st;
    int k, f;
    RETURN_ERROR_IF(!tex, err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture object");
    tex->depth = 6;
    for (k = 0; k < count; ++k) {
        if ((st = ls_tex_alloc_level(tex, k, err)) != SAMPLE_OK) {
            sample_texture_destroy(tex);
            return st;
        }
        tex->nlevels = k + 1;
        for (f = 0; f < 6; ++f) ls_tex_copy_layer(tex, k, f, &faces[6 * k + f]);
    }
    *out = tex;
    return SAMPLE_OK;
}

/* ---- The pyramid ------------------------------------------------------------ */

/* Face f of level k from level k − 1 with the tap table ax (both axes:
 * faces are square). Separable as mip.c's resampler, with the same
 * roundings (each pass summed in double, rounded once to float), so that
 * a face whose taps stay inside it (the box on even sizes) is exactly the
 * 2D pyramid of that face; the source is read through the seamless
 * addressing (env_addr.h) from index lo to hi on both axes, so a kernel
 * that reaches past an edge (odd sizes' boxes do not; Lanczos and Kaiser
 * do) reads the adjacent face, and level k is continuous across edges as
 * level k − 1 is. src holds (hi − lo + 1)² decoded texels, rows
 * (hi − lo + 1) × n_dst horizontally filtered ones. */
static void cube_face_level(sample_texture *tex, int k, int f, const mip_axis *ax, int lo, int hi, float *src,
                            float *rows)
{
    const struct sample_level *D = &tex->level[k];
    const int m = hi - lo + 1, nd = ax->n_dst;
    int x, y, i, t, c;
    for (y = 0; y < m; ++y)
        for (x = 0; x < m; ++x)
            ls_env_texel(tex, k - 1, f, LS_ENV_CUBE, (double)(x + lo), (double)(y + lo), 1,
                         src + 4 * ((size_t)y * m + x));
    for (y = 0; y < m; ++y)
        for (i = 0; i < nd; ++i) {
            double acc[4] = {0, 0, 0, 0};
            for (t = 0; t < ax->taps; ++t)
                for (c = 0; c < 4; ++c)
                    acc[c] += (double)ax->w[(size_t)i * ax->taps + t] *
                              src[4 * ((size_t)y * m + (ax->idx[(size_t)i * ax->taps + t] - lo)) + c];
            for (c = 0; c < 4; ++c) rows[4 * ((size_t)y * nd + i) + c] = (float)acc[c];
        }
    for (y = 0; y < nd; ++y)
        for (i = 0; i < nd; ++i) {
            double acc[4] = {0, 0, 0, 0};
            float v[4];
            for (t = 0; t < ax->taps; ++t) {
                float w = ax->w[(size_t)y * ax->taps + t];
                if (w == 0.0f) continue;
                for (c = 0; c < 4; ++c)
                    acc[c] += (double)w * rows[4 * ((size_t)(ax->idx[(size_t)y * ax->taps + t] - lo) * nd + i) + c];
            }
            for (c = 0; c < 4; ++c) v[c] = (float)acc[c];
            ls_tex_encode(tex, v, D->data + (size_t)f * D->slice + (size_t)y * D->stride + (size_t)i * tex->texel_bytes);
        }
}

/* Level k (allocated) from level k − 1, all six faces. */
static sample_status cube_level(sample_texture *tex, int k, sample_mipgen filter, sample_error *err)
{
    const int n = tex->level[k - 1].w, nd = tex->level[k].w;
    mip_axis ax;
    int lo = 0, hi = n - 1, f;
    size_t e;
    float *src, *rows;
    if (!ls_mip_axis_unwrapped(&ax, n, nd, filter))
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate filter taps for level %d", k);
    for (e = 0; e < (size_t)ax.n_dst * ax.taps; ++e) {
        if (ax.w[e] == 0.0f) continue;
        if (ax.idx[e] < lo) lo = ax.idx[e];
        if (ax.idx[e] > hi) hi = ax.idx[e];
    }
    /* Unused taps (weight 0) read index 0, inside [lo, hi]. */
    src = (float *)malloc((size_t)(hi - lo + 1) * (size_t)(hi - lo + 1) * 4 * sizeof(float));
    rows = (float *)malloc((size_t)(hi - lo + 1) * (size_t)nd * 4 * sizeof(float));
    if (!src || !rows) {
        free(src);
        free(rows);
        ls_mip_axis_free(&ax);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate scratch for cube level %d", k);
    }
    for (f = 0; f < 6; ++f) cube_face_level(tex, k, f, &ax, lo, hi, src, rows);
    free(src);
    free(rows);
    ls_mip_axis_free(&ax);
    return SAMPLE_OK;
}

sample_status sample_texture_create_cube(const sample_image faces[6], const sample_mip_params *mip,
                                         sample_texture **out, sample_error *err)
{
    sample_texture *tex = NULL;
    sample_status st;
    int k, full;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    RETURN_ERROR_IF(!faces, err, SAMPLE_E_INVALID_ARGUMENT, "cube faces are NULL");
    if ((st = ls_tex_check_mip(mip, err)) != SAMPLE_OK) return st;
    if ((st = ls_tex_check_image(&faces[0], "cube face +X", err)) != SAMPLE_OK) return st;
    if ((st = check_faces(faces, &faces[0], 0, err)) != SAMPLE_OK) return st;
    if ((st = cube_from(faces, 1, &tex, err)) != SAMPLE_OK) return st;
    full = full_levels(tex->width);
    if (!mip || mip->filter == SAMPLE_MIPGEN_NONE) full = 1;
    else if (mip->max_levels > 0 && mip->max_levels < full) full = mip->max_levels;
    for (k = 1; k < full; ++k) {
        if ((st = ls_tex_alloc_level(tex, k, err)) != SAMPLE_OK ||
            (st = cube_level(tex, k, mip->filter, err)) != SAMPLE_OK) {
            sample_texture_destroy(tex);
            return st;
        }
        tex->nlevels = k + 1;
    }
    *out = tex;
    return SAMPLE_OK;
}

sample_status sample_texture_create_cube_levels(const sample_image *faces, int count, sample_texture **out,
                                                sample_error *err)
{
    sample_status st;
    int k;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    RETURN_ERROR_IF(!faces || count < 1, err, SAMPLE_E_INVALID_ARGUMENT, "need at least one level (got %d)", count);
    if ((st = ls_tex_check_image(&faces[0], "cube face +X", err)) != SAMPLE_OK) return st;
    RETURN_ERROR_IF(count > full_levels(faces[0].width), err, SAMPLE_E_BAD_SIZE,
                    "%d levels given but a cube map of %d x %d faces has only %d", count, faces[0].width,
                    faces[0].width, full_levels(faces[0].width));
    for (k = 0; k < count; ++k)
        if ((st = check_faces(faces + 6 * k, &faces[0], k, err)) != SAMPLE_OK) return st;
    return cube_from(faces, count, out, err);
}
