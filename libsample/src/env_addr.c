/*
 * Texel addressing of environment maps (env_addr.h, doc/environment-maps.md).
 */
#include "env_addr.h"

#include "cube.h"
#include "wrap.h"

const signed char ls_cube_frame[6][3][3] = {
    /* axis         U (sc = R·U)   V (tc = R·V)      GL 4.6 table 8.19 */
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},  /* +X: sc = −rz, tc = −ry */
    {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},  /* −X: sc = +rz, tc = −ry */
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},    /* +Y: sc = +rx, tc = +rz */
    {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},  /* −Y: sc = +rx, tc = −rz */
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},   /* +Z: sc = +rx, tc = −ry */
    {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}, /* −Z: sc = −rx, tc = −ry */
};

/* How far texel index i lies outside [0, n): 0 inside, else the number of
 * texels past the edge (1 for the first texel beyond it). */
static double past(double i, int n)
{
    return i < 0.0 ? -i : (i >= (double)n ? i - (double)n + 1.0 : 0.0);
}

/* One step from i towards [0, n). */
static double inward(double i, int n) { return i < 0.0 ? i + 1.0 : (i >= (double)n ? i - 1.0 : i); }

/* A face index from a face coordinate in [0, 1]: the texel holding it,
 * kept inside the face against rounding. */
static int face_index(double s, int n)
{
    double u = s * (double)n;
    if (!(u > 0.0)) return 0;
    if (u >= (double)(n - 1)) return u >= (double)n ? n - 1 : (int)u;
    return (int)u;
}

/* Texel (i, j) of face f of an n × n level, past its edges (not a corner:
 * seamless_corner). Past one edge the texel is on the adjacent face: the
 * face's plane is unfolded about the edge, so that the k-th texel past the
 * edge is the neighbour's k-th texel in from it — for k = 1 the texel that
 * §8.13.1 asks for, and beyond (bicubic's taps, the pyramid's kernels) the
 * texel at the same distance over the edge. The unfolded point of
 * (sc, tc), |sc| > 1 ≥ |tc|, is the direction (2 − |sc|)·axis +
 * sign(sc)·U + tc·V. Past both edges by different amounts (only bicubic
 * and the pyramid's wider kernels reach there), the point's own direction is projected
 * onto the face it selects: the nearest texel in direction. */
static void seamless_face(const sample_texture *tex, int lv, int f, double i, double j, float out[4])
{
    const int n = tex->level[lv].w;
    double sc = (2.0 * i + 1.0) / n - 1.0, tc = (2.0 * j + 1.0) / n - 1.0, r[3], s, t;
    int g, k;
    if (fabs(sc) > 1.0 && fabs(tc) <= 1.0) {
        for (k = 0; k < 3; ++k)
            r[k] = (2.0 - fabs(sc)) * ls_cube_frame[f][0][k] + (sc < 0.0 ? -1.0 : 1.0) * ls_cube_frame[f][1][k] +
                   tc * ls_cube_frame[f][2][k];
    } else if (fabs(tc) > 1.0 && fabs(sc) <= 1.0) {
        for (k = 0; k < 3; ++k)
            r[k] = (2.0 - fabs(tc)) * ls_cube_frame[f][0][k] + sc * ls_cube_frame[f][1][k] +
                   (tc < 0.0 ? -1.0 : 1.0) * ls_cube_frame[f][2][k];
    } else {
        cube_direction(f, sc, tc, r);
    }
    g = cube_face_of(r);
    cube_face_st(g, r, &s, &t);
    tex_read_layer(tex, lv, face_index(s, n), face_index(t, n), g, out);
}

/* Texel (i, j) of a cube face, inside or past its edges. A corner texel —
 * past two edges by the same count k, where no face has a texel — is the
 * mean of the three texels of its 2 × 2 block that lie towards the face
 * (GL 4.6 §8.13.1: for k = 1 the three real texels of a LINEAR block; the
 * rule ARB_seamless_cube_map recommends). For k > 1, which only bicubic
 * and the pyramid's wider kernels reach, the block's inner texel is a corner
 * again; its two edge neighbours alone are averaged, which keeps the read
 * bounded. */
static void cube_texel(const sample_texture *tex, int lv, int f, double i, double j, float out[4])
{
    const int n = tex->level[lv].w;
    double pi = past(i, n), pj = past(j, n);
    float a[4], b[4], c[4];
    int k;
    if (pi == 0.0 && pj == 0.0) {
        tex_read_layer(tex, lv, (int)i, (int)j, f, out);
        return;
    }
    if (pi != pj) {
        seamless_face(tex, lv, f, i, j, out);
        return;
    }
    seamless_face(tex, lv, f, inward(i, n), j, a);
    seamless_face(tex, lv, f, i, inward(j, n), b);
    if (pi == 1.0) {
        tex_read_layer(tex, lv, (int)inward(i, n), (int)inward(j, n), f, c);
        for (k = 0; k < 4; ++k) out[k] = (a[k] + b[k] + c[k]) / 3.0f;
    } else {
        for (k = 0; k < 4; ++k) out[k] = 0.5f * (a[k] + b[k]);
    }
}

/* Texel (i, j) of a lat-long level, w × h: REPEAT in s; a row past t = 0
 * or t = 1 is the row mirrored about that pole, on the other half of the
 * map (s + ½: i + w/2, rounded down for odd w), because the great circle
 * through the pole continues there. Rows further out fold again
 * (MIRRORED_REPEAT's period 2h); every fold moves half a turn. */
static void latlong_texel(const sample_texture *tex, int lv, double i, double j, float out[4])
{
    const struct sample_level *L = &tex->level[lv];
    double fold = floor(j / (double)L->h);
    int y = ls_wrap_index(SAMPLE_WRAP_MIRRORED_REPEAT, j, L->h, 1), x;
    if (fmod(fabs(fold), 2.0) == 1.0) i += (double)(L->w / 2);
    x = ls_wrap_index(SAMPLE_WRAP_REPEAT, i, L->w, 1);
    tex_read(tex, lv, x, y, out);
}

void ls_env_texel(const sample_texture *tex, int lv, int face, ls_env_mode mode, double i, double j, int linear,
                  float out[4])
{
    const struct sample_level *L = &tex->level[lv];
    if (mode == LS_ENV_LATLONG) {
        latlong_texel(tex, lv, i, j, out);
        return;
    }
    if (!linear) {
        /* §8.13.1: NEAREST reads as CLAMP_TO_EDGE on the selected face. */
        tex_read_layer(tex, lv, ls_wrap_index(SAMPLE_WRAP_CLAMP_TO_EDGE, i, L->w, 0),
                       ls_wrap_index(SAMPLE_WRAP_CLAMP_TO_EDGE, j, L->h, 0), face, out);
        return;
    }
    cube_texel(tex, lv, face, i, j, out);
}
