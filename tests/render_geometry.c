/* Renderer geometry: teapot data, cracks, exact Jacobians, the plane. */
#include "check.h"
#include "rn_internal.h"

#include <stdlib.h>

static void test_teapot_data(void)
{
    int used[TEAPOT_POINTS + 1] = {0}, p, k, unused = 0;
    CHECK(TEAPOT_PATCHES == 32 && TEAPOT_POINTS == 306, "counts");
    for (p = 0; p < TEAPOT_PATCHES; ++p)
        for (k = 0; k < 16; ++k) {
            int i = teapot_index[p][k];
            CHECK(i >= 1 && i <= TEAPOT_POINTS, "patch %d index %d", p, i);
            if (i >= 1 && i <= TEAPOT_POINTS) used[i] = 1;
        }
    for (k = 1; k <= TEAPOT_POINTS; ++k) unused += !used[k];
    /* The published set lists four points no patch uses. */
    CHECK(unused == 4 && !used[205] && !used[206] && !used[216] && !used[223], "unused %d", unused);
}

/* Boundary curve e (0: v = 0 row, 1: u = 1 column, 2: v = 1 row, 3: u = 0
 * column) of patch p as 4 points. */
static void edge(int p, int e, double out[4][3])
{
    int k;
    for (k = 0; k < 4; ++k) {
        int i = e == 0 ? 0 : e == 2 ? 3 : k, j = e == 1 ? 3 : e == 3 ? 0 : k;
        int idx = teapot_index[p][4 * i + j] - 1, c;
        for (c = 0; c < 3; ++c) out[k][c] = teapot_point[idx][c];
    }
}

static int same_pt(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* adjacent[p][q]: patches p and q share a boundary curve. */
static unsigned char adjacent[TEAPOT_PATCHES][TEAPOT_PATCHES];

static void test_teapot_boundaries(void)
{
    int p, e, q, f, unmatched = 0, degenerate = 0;
    for (p = 0; p < TEAPOT_PATCHES; ++p)
        for (e = 0; e < 4; ++e) {
            double a[4][3];
            int found = 0;
            edge(p, e, a);
            if (same_pt(a[0], a[1]) && same_pt(a[1], a[2]) && same_pt(a[2], a[3])) {
                ++degenerate; /* collapsed row: lid top and bottom poles */
                continue;
            }
            for (q = 0; q < TEAPOT_PATCHES && !found; ++q)
                for (f = 0; f < 4 && !found; ++f) {
                    double b[4][3];
                    int k, fw = 1, bw = 1;
                    if (q == p && f == e) continue;
                    edge(q, f, b);
                    for (k = 0; k < 4; ++k) {
                        fw = fw && same_pt(a[k], b[k]);
                        bw = bw && same_pt(a[k], b[3 - k]);
                    }
                    found = fw || bw;
                    if (found) adjacent[p][q] = adjacent[q][p] = 1;
                }
            unmatched += !found;
        }
    /* Open boundaries, counted by hand from the data: the rim's top edge
     * (4 patches), the lid's outer edge (4), the handle's two ends (2 + 2)
     * and the spout's two ends (2 + 2). Everything else is shared. */
    CHECK(unmatched == 16, "unmatched boundary curves %d", unmatched);
    CHECK(degenerate == 8, "degenerate boundary curves %d", degenerate);
}

static render_scene *scene(const char *name, int w)
{
    render_scene *sc = NULL;
    char err[256];
    int r = render_scene_builtin(name, w, w, &sc, err, sizeof err);
    CHECK(r == 0, "%s: %s", name, err);
    return sc;
}

/* Is (u, v) within a tessellation cell of its patch's boundary? */
static int near_edge(const float *uv)
{
    const float e = 1.0f / RN_TESS;
    return uv[0] < e || uv[0] > 1.0f - e || uv[1] < e || uv[1] > 1.0f - e;
}

/* Cracks, in rows and columns of pixel centres at 256² (where many centres
 * fall on seams):
 * - a background pixel between two hits on the same patch or on two
 *   patches that share a boundary curve;
 * - a pixel between hits on two neighbouring patches, both next to their
 *   boundary, that shows a surface farther than both: the seam let the ray
 *   through to the far side (pixel (62, 185) once showed the bottom through
 *   the body's seam, by 13 % of the depth).
 * Between unrelated parts — knob and rim, handle and body, spout and body —
 * one-pixel wedges of background or of a farther part are real geometry, as
 * is the spout's mouth between its upper and lower halves. */
static void test_teapot_no_cracks(void)
{
    const int n = 256;
    render_scene *sc = scene("teapot", n);
    unsigned char *m = malloc((size_t)n * n);
    double *z = malloc(sizeof *z * (size_t)n * n);
    float *uv = malloc(sizeof *uv * 2 * (size_t)n * n);
    int i, j, d, cracks = 0, hits = 0;
    render_hit h;
    if (!sc || !m || !z || !uv) return;
    /* m holds prim + 1, 0 for background. */
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            int r = render_scene_hit(sc, i + 0.5, j + 0.5, &h);
            hits += r;
            m[j * n + i] = (unsigned char)(r ? h.prim + 1 : 0);
            z[j * n + i] = h.depth;
            uv[2 * (j * n + i)] = (float)h.u;
            uv[2 * (j * n + i) + 1] = (float)h.v;
        }
#define LINKED(a, b) ((a) && (b) && ((a) == (b) || adjacent[(a) - 1][(b) - 1]))
    for (j = 1; j + 1 < n; ++j)
        for (i = 1; i + 1 < n; ++i)
            for (d = 0; d < 2; ++d) {
                int c = j * n + i, a = d ? c - n : c - 1, b = d ? c + n : c + 1;
                int seam = LINKED(m[a], m[b]) && m[a] != m[b] && near_edge(uv + 2 * a) &&
                           near_edge(uv + 2 * b);
                if (!LINKED(m[a], m[b]) || (m[c] && !(seam && z[c] > fmax(z[a], z[b]) * 1.01)))
                    continue;
                if (cracks < 8)
                    fprintf(stderr, "crack at pixel (%d, %d): prim %d between %d and %d\n", i, j,
                            m[c] - 1, m[a] - 1, m[b] - 1);
                ++cracks;
                break;
            }
    CHECK(cracks == 0, "%d crack pixels inside the silhouette", cracks);
    CHECK(hits > n * n / 5, "teapot covers %d pixels", hits);
    free(m);
    free(z);
    free(uv);
    render_scene_destroy(sc);
}

/* J against central differences of the renderer's own exact (s, t) at
 * ±h and ±2h pixel, Richardson-extrapolated (error O(h⁴)): with Newton
 * converged to 1e-9 px the quotient's noise is ~1e-9/h = 1e-6 relative, and
 * the truncation term stays small even at the horizon, where s, t grow like
 * 1/(y − y_horizon). Bound: 5e-4 of the Jacobian's largest entry (the
 * worst teapot pixel, next to a silhouette, measured 1.2e-4). */
static void jacobian_fd(const char *name, int stride)
{
    const int n = 64;
    const double h = 1e-3, rel = 5e-4;
    render_scene *sc = scene(name, n);
    int i, j, tested = 0, bad = 0;
    double worst = 0.0;
    if (!sc) return;
    for (j = 0; j < n; j += stride)
        for (i = 0; i < n; i += stride) {
            render_hit c, xp, xm, yp, ym, xp2, xm2, yp2, ym2;
            double x = i + 0.5, y = j + 0.5, fd[4], mx = 0.0;
            int k;
            if (!render_scene_hit(sc, x, y, &c) || !c.converged) continue;
            if (!render_scene_hit_from(sc, &c, x + h, y, &xp) || !render_scene_hit_from(sc, &c, x - h, y, &xm) ||
                !render_scene_hit_from(sc, &c, x, y + h, &yp) || !render_scene_hit_from(sc, &c, x, y - h, &ym))
                continue; /* the stencil leaves the primitive */
            if (!render_scene_hit_from(sc, &c, x + 2 * h, y, &xp2) ||
                !render_scene_hit_from(sc, &c, x - 2 * h, y, &xm2) ||
                !render_scene_hit_from(sc, &c, x, y + 2 * h, &yp2) ||
                !render_scene_hit_from(sc, &c, x, y - 2 * h, &ym2))
                continue;
            /* Richardson: (4 D(h) − D(2h))/3 cancels the h² term. */
            fd[0] = (4.0 * (xp.s - xm.s) / (2 * h) - (xp2.s - xm2.s) / (4 * h)) / 3.0;
            fd[1] = (4.0 * (xp.t - xm.t) / (2 * h) - (xp2.t - xm2.t) / (4 * h)) / 3.0;
            fd[2] = (4.0 * (yp.s - ym.s) / (2 * h) - (yp2.s - ym2.s) / (4 * h)) / 3.0;
            fd[3] = (4.0 * (yp.t - ym.t) / (2 * h) - (yp2.t - ym2.t) / (4 * h)) / 3.0;
            for (k = 0; k < 4; ++k) mx = fmax(mx, fabs(c.J[k]));
            for (k = 0; k < 4; ++k) {
                double e = fabs(fd[k] - c.J[k]) / mx;
                if (e > worst) worst = e;
                if (e > rel) ++bad;
            }
            ++tested;
        }
    CHECK(bad == 0, "%s: %d Jacobian entries off by more than %g relative (worst %g)", name, bad, rel, worst);
    CHECK(tested > 100, "%s: only %d pixels tested", name, tested);
    render_scene_destroy(sc);
}

static void test_jacobian_teapot(void) { jacobian_fd("teapot", 1); }
static void test_jacobian_plane(void) { jacobian_fd("plane", 1); }
static void test_jacobian_sphere(void) { jacobian_fd("sphere", 1); }
static void test_jacobian_cylinder(void) { jacobian_fd("cylinder", 1); }

/* The plane scene: eye (0, 0, 1) looking at (0, 10, 0), fov 60°, so
 * f = (0, 10, −1)/√101, r = (1, 0, 0), u = (0, 1, 10)/√101, tan = 1/√3.
 * The bottom corners' rays f ∓ r/√3 − u/√3 meet z = 0 at
 * s = ∓(√101/√3)/(1 + 10/√3) … worked out below in closed form. */
static void test_plane_corners_and_horizon(void)
{
    const int n = 64;
    const double k = 1.0 / sqrt(3.0), q = sqrt(101.0);
    render_scene *sc = scene("plane", n);
    render_hit h;
    double dz, tau, s_exp, t_exp, yh;
    if (!sc) return;
    /* dir = f − k r − k u (bottom-left); its z is (−1 − 10k)/√101. */
    dz = (-1.0 - 10.0 * k) / q;
    tau = 1.0 / -dz;
    s_exp = -k * tau;
    t_exp = tau * (10.0 - k) / q;
    CHECK(render_scene_hit(sc, 0.0, n, &h), "bottom-left corner hits the plane");
    CHECK_NEAR(h.s, s_exp, 1e-12);
    CHECK_NEAR(h.t, t_exp, 1e-12);
    CHECK(render_scene_hit(sc, n, n, &h), "bottom-right corner hits the plane");
    CHECK_NEAR(h.s, -s_exp, 1e-12);
    CHECK_NEAR(h.t, t_exp, 1e-12);
    CHECK(!render_scene_hit(sc, 0.0, 0.0, &h), "top-left corner is sky");
    CHECK(!render_scene_hit(sc, n, 0.0, &h), "top-right corner is sky");
    /* Horizon: the horizontal direction (0, 1, 0) has b = (d·u)/(d·f) = 0.1,
     * so y = n/2 (1 − 0.1/tan 30°). */
    yh = 0.5 * n * (1.0 - 0.1 * sqrt(3.0));
    CHECK(render_scene_hit(sc, 10.5, yh + 1e-6, &h), "just below the horizon hits");
    CHECK(h.depth > 1e4, "depth near the horizon %g", h.depth);
    CHECK(!render_scene_hit(sc, 10.5, yh - 1e-6, &h), "just above the horizon misses");
    render_scene_destroy(sc);
}

int main(void)
{
    RUN(test_teapot_data);
    RUN(test_teapot_boundaries);
    RUN(test_teapot_no_cracks);
    RUN(test_jacobian_teapot);
    RUN(test_jacobian_plane);
    RUN(test_jacobian_sphere);
    RUN(test_jacobian_cylinder);
    RUN(test_plane_corners_and_horizon);
    return check_finish();
}
