/*
 * Cube-map geometry (cube.c, env_addr.c): the face a direction selects and
 * its face coordinates (GL 4.6 §8.13, table 8.19), their derivatives (the
 * quotient rule of §8.13 that level of detail needs), and the way back from
 * a face position to a direction, which seamless addressing (§8.13.1) uses
 * to find the texel of a neighbouring face. Faces in GL order: +X, −X, +Y,
 * −Y, +Z, −Z (layers 0 … 5).
 */
#ifndef SAMPLE_CUBE_H
#define SAMPLE_CUBE_H

#include "base.h"

/* Face f's frame: a direction on it is axis + sc·U + tc·V, with
 * (sc, tc) ∈ [−1, 1]² its major-axis-normalized coordinates. Table 8.19
 * read as dot products: sc = R·U, tc = R·V, |ma| = R·axis. */
extern const signed char ls_cube_frame[6][3][3]; /* [face][axis, U, V][x, y, z] */

/* The face GL 4.6 table 8.19 selects for direction r: the axis of largest
 * magnitude; ties go to x over y over z, as Mesa's samplers break them (the
 * specification leaves ties to the implementation). */
static inline int cube_face_of(const double r[3])
{
    double ax = fabs(r[0]), ay = fabs(r[1]), az = fabs(r[2]);
    if (ax >= ay && ax >= az) return r[0] >= 0.0 ? 0 : 1;
    if (ay >= az) return r[1] >= 0.0 ? 2 : 3;
    return r[2] >= 0.0 ? 4 : 5;
}

/* v · (row k of face f's frame). */
static inline double cube_dot(int f, int k, const double v[3])
{
    const signed char *e = ls_cube_frame[f][k];
    return (double)e[0] * v[0] + (double)e[1] * v[1] + (double)e[2] * v[2];
}

/* Face f's (s, t) of direction r (r·axis > 0): s = ½(sc/|ma| + 1),
 * t = ½(tc/|ma| + 1) (GL 4.6 eq. 8.10). */
static inline void cube_face_st(int f, const double r[3], double *s, double *t)
{
    double ma = cube_dot(f, 0, r);
    *s = 0.5 * (cube_dot(f, 1, r) / ma + 1.0);
    *t = 0.5 * (cube_dot(f, 2, r) / ma + 1.0);
}

/* The derivatives of face f's (s, t) along dr at r, by the quotient rule
 * including the ma term (GL 4.6 §8.13): ∂s = ½(∂sc·|ma| − sc·∂|ma|)/ma²,
 * likewise t. On the selected face |ma| = r·axis, so ∂|ma| = dr·axis. */
static inline void cube_face_dst(int f, const double r[3], const double dr[3], double *ds, double *dt)
{
    double ma = cube_dot(f, 0, r), dma = cube_dot(f, 0, dr), m2 = ma * ma;
    *ds = 0.5 * (cube_dot(f, 1, dr) * ma - cube_dot(f, 1, r) * dma) / m2;
    *dt = 0.5 * (cube_dot(f, 2, dr) * ma - cube_dot(f, 2, r) * dma) / m2;
}

/* The direction of face f's point (sc, tc) (face coordinates in [−1, 1],
 * also beyond: a texel past an edge). */
static inline void cube_direction(int f, double sc, double tc, double r[3])
{
    int k;
    for (k = 0; k < 3; ++k)
        r[k] = (double)ls_cube_frame[f][0][k] + sc * (double)ls_cube_frame[f][1][k] + tc * (double)ls_cube_frame[f][2][k];
}

/* The 2D query on its face of a cube-map query (direction, derivatives):
 * (s, t) and the Jacobian of the face coordinates (cube_face_dst), in
 * double and rounded once; derivatives past float's range are held at
 * ±FLT_MAX (λ then clamps to the last level). Returns the face, or −1 for
 * the zero direction. The query must be finite. */
int ls_cube_query(const sample_query3 *q, sample_query *out);
/* The same on face f, which need not be the one q selects (q->p·axis of f
 * must be > 0: f's plane then holds the direction, past f's edges where
 * another face is selected). Returns 0 where (s, t) is past float's range
 * (a direction nearly parallel to f's plane), else 1. */
int ls_cube_query_on(const sample_query3 *q, int f, sample_query *out);

#endif /* SAMPLE_CUBE_H */
