/*
 * Perspective footprints for the Blinn–Newell corner-mode tests
 * (test_footprint_bn.c, test_footprint_area.c): a random homography — the
 * exact screen → texture map of a plane under a pinhole camera — its four
 * corners as a sample_quad, and the dense screen-space integrals the filter
 * approximates, evaluated through THAT homography (not through anything
 * the library computes from the corners). Include after footprint_util.h.
 */
#ifndef SAMPLE_TEST_FOOTPRINT_PROJ_H
#define SAMPLE_TEST_FOOTPRINT_PROJ_H

#include "footprint_util.h"

/* (u, v) = (c + A·(x, y)) / w, w = 1 + k·(x, y), in texels of a w × h
 * texture; screen offsets (x, y) ∈ [−1, 1]² are the 2 × 2-pixel region. */
typedef struct proj_map {
    double A[2][2], c[2], k[2];
} proj_map;

static void proj_eval(const proj_map *m, double x, double y, double p[2])
{
    double w = 1.0 + m->k[0] * x + m->k[1] * y;
    p[0] = (m->c[0] + m->A[0][0] * x + m->A[0][1] * y) / w;
    p[1] = (m->c[1] + m->A[1][0] * x + m->A[1][1] * y) / w;
}

/* |det ∂(u, v)/∂(x, y)| = |det H| / w³ for H = [A c; k 1]. */
static double proj_det(const proj_map *m, double x, double y)
{
    double w = 1.0 + m->k[0] * x + m->k[1] * y;
    double dh = m->A[0][0] * (m->A[1][1] - m->c[1] * m->k[1]) - m->A[0][1] * (m->A[1][0] - m->c[1] * m->k[0]) +
                m->c[0] * (m->A[1][0] * m->k[1] - m->A[1][1] * m->k[0]);
    return fabs(dh) / (w * w * w);
}

/* Random map: semi-axes a, b texels at the centre, rotation and skew as
 * footprint(), centre (cs, ct) texels, and |k0| + |k1| = kk (so w on the
 * square lies in [1 − kk, 1 + kk]: far corners up to (1 + kk)/(1 − kk)
 * times as far from the camera as near ones). */
static proj_map proj_random(double a, double b, double kk, double cs, double ct)
{
    proj_map m;
    double th = urand(0, 6.3), skew = urand(-1.0, 1.0), phi = urand(0, 6.3);
    double c = cos(th), sn = sin(th), cw = cos(skew), sw = sin(skew);
    m.A[0][0] = c * a * cw - sn * b * sw;
    m.A[0][1] = -c * a * sw - sn * b * cw;
    m.A[1][0] = sn * a * cw + c * b * sw;
    m.A[1][1] = -sn * a * sw + c * b * cw;
    m.k[0] = kk * cos(phi) / (fabs(cos(phi)) + fabs(sin(phi)));
    m.k[1] = kk * sin(phi) / (fabs(cos(phi)) + fabs(sin(phi)));
    m.c[0] = cs;
    m.c[1] = ct;
    /* With w = 1 + k·(x, y) the centre Jacobian is A − c·kᵀ; fold c·kᵀ
     * into A so that a, b, th, skew describe the footprint at the centre. */
    m.A[0][0] += cs * m.k[0];
    m.A[0][1] += cs * m.k[1];
    m.A[1][0] += ct * m.k[0];
    m.A[1][1] += ct * m.k[1];
    return m;
}

/* Corner k of the 2 × 2 region: (−1,−1), (+1,−1), (+1,+1), (−1,+1). */
static const double proj_corner_xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

static sample_quad proj_quad(const proj_map *m, int w, int h)
{
    sample_quad q;
    int k;
    for (k = 0; k < 4; ++k) {
        double p[2];
        proj_eval(m, proj_corner_xy[k][0], proj_corner_xy[k][1], p);
        q.st[k][0] = (float)(p[0] / w);
        q.st[k][1] = (float)(p[1] / h);
    }
    return q;
}

/* ∫ pyr · T_bil(H) · |det DH|^area / ∫ pyr · |det DH|^area over a G × G
 * midpoint grid (level 0 of c): area = 0 is the screen-space integral
 * (DESIGN §8, SAMPLE_OPT_BN_AREA_WEIGHT's target), area = 1 the texture-
 * space one ∫ pyr(H⁻¹(u))·T(u) du (the default's). */
static double proj_reference(const sample_ctx *c, const proj_map *m, int area)
{
    enum { G = 160 };
    const struct sample_level *L = &c->tex->level[0];
    double num = 0.0, den = 0.0;
    int a, b;
    for (b = 0; b < G; ++b)
        for (a = 0; a < G; ++a) {
            double x = -1.0 + (a + 0.5) * 2.0 / G, y = -1.0 + (b + 0.5) * 2.0 / G, p[2], wt;
            float T[4];
            proj_eval(m, x, y, p);
            wt = (1.0 - fabs(x)) * (1.0 - fabs(y)) * (area ? proj_det(m, x, y) : 1.0);
            ls_recon_level(c, 0, SAMPLE_LINEAR, (float)(p[0] / L->w), (float)(p[1] / L->h), T, NULL, NULL);
            num += wt * T[0];
            den += wt;
        }
    return num / den;
}

#endif
