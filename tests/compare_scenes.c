/*
 * compare's own scenes (tools/compare/scenes.c, doc/comparison.md "The
 * scenes"), through the queries every filter answers (cmp_view):
 *   - the teapots are whole in the picture: no pixel of the outer rows and
 *     columns (a margin of 4 % of the side) sees the object, and the teapot
 *     still spans most of the width;
 *   - the oblique zone plate asks for anisotropic footprints that vary
 *     over the picture (ratio of the Jacobian's singular values from under
 *     2 to over 8, λ over more than 4 levels).
 */
#include "check.h"
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>

enum { SIZE = 96, MARGIN = SIZE / 25 };

static int open_view(const char *name, render_scene **sc, cmp_view *v)
{
    char label[64], err[512];
    if (cmp_scene_open(name, SIZE, RENDER_CACHE_MB, sc, label, sizeof label, err, sizeof err) != 0) {
        CHECK(0, "%s: %s", name, err);
        return 1;
    }
    if (cmp_view_build(*sc, 2, v, err, sizeof err) != 0) {
        CHECK(0, "%s: %s", name, err);
        render_scene_destroy(*sc);
        return 1;
    }
    return 0;
}

static void whole_teapot(const char *name)
{
    render_scene *sc;
    cmp_view v = {0};
    int i, j, x0 = SIZE, x1 = -1, y0 = SIZE, y1 = -1;
    if (open_view(name, &sc, &v)) return;
    for (j = 0; j < v.h; ++j)
        for (i = 0; i < v.w; ++i)
            if (v.object[(size_t)j * (size_t)v.w + (size_t)i] >= 0) {
                if (i < x0) x0 = i;
                if (i > x1) x1 = i;
                if (j < y0) y0 = j;
                if (j > y1) y1 = j;
            }
    printf("%s: object in x %d..%d, y %d..%d of %d x %d\n", name, x0, x1, y0, y1, v.w, v.h);
    CHECK(x0 >= MARGIN && y0 >= MARGIN && x1 < v.w - MARGIN && y1 < v.h - MARGIN,
          "%s: the object comes within %d pixels of the border (x %d..%d, y %d..%d)", name, MARGIN,
          x0, x1, y0, y1);
    /* Framed, not lost in the middle. */
    CHECK(x1 - x0 + 1 >= v.w * 3 / 4, "%s: object only %d pixels wide", name, x1 - x0 + 1);
    cmp_view_free(&v);
    render_scene_destroy(sc);
}

static void teapot(void) { whole_teapot("teapot"); }

static void teapot_image(void)
{
#ifdef TEXSAMPLE_HAVE_IO
    whole_teapot("teapot-image");
#else
    check_skip("teapot-image needs libsample_io");
#endif
}

/* Over the pixels that see the plane: the smallest and largest anisotropy
 * (ratio of the Jacobian's singular values) and λ = log2 of the major axis
 * in texels of the base level. */
static void footprints(const char *name, double *rmin, double *rmax, double *lmin, double *lmax)
{
    render_scene *sc;
    cmp_view v = {0};
    size_t px, n;
    *rmin = *lmin = HUGE_VAL;
    *rmax = *lmax = -HUGE_VAL;
    int tw, th;
    if (open_view(name, &sc, &v)) return;
    sample_texture_level_size(render_scene_texture(sc, 0), 0, &tw, &th);
    n = (size_t)v.w * (size_t)v.h;
    for (px = 0; px < n; ++px) {
        const sample_query *q = &v.q[px];
        double a = q->dsdx * tw, b = q->dsdy * tw, c = q->dtdx * th, d = q->dtdy * th;
        double s1 = a * a + b * b + c * c + d * d, det = fabs(a * d - b * c);
        double disc = sqrt(fmax(0.0, s1 * s1 - 4.0 * det * det));
        double major = sqrt(0.5 * (s1 + disc)), minor = sqrt(fmax(0.0, 0.5 * (s1 - disc)));
        if (v.tex[px] < 0 || minor <= 0.0) continue;
        if (major / minor < *rmin) *rmin = major / minor;
        if (major / minor > *rmax) *rmax = major / minor;
        if (log2(major) < *lmin) *lmin = log2(major);
        if (log2(major) > *lmax) *lmax = log2(major);
    }
    printf("%s: anisotropy %.2f .. %.2f, lambda %.2f .. %.2f\n", name, *rmin, *rmax, *lmin, *lmax);
    cmp_view_free(&v);
    render_scene_destroy(sc);
}

/* (The face-on plate's single footprint shows in its scores: the four
 * isotropic mip filters tie, tests/compare_cli.c.) */
static void zoneplate_oblique(void)
{
    double rmin, rmax, lmin, lmax;
    footprints("zoneplate-oblique", &rmin, &rmax, &lmin, &lmax);
    CHECK(rmin < 2.0 && rmax > 8.0, "oblique: anisotropy %g .. %g", rmin, rmax);
    CHECK(lmax - lmin > 4.0, "oblique: lambda %g .. %g", lmin, lmax);
}

int main(void)
{
    RUN(teapot);
    RUN(teapot_image);
    RUN(zoneplate_oblique);
    return check_finish();
}
