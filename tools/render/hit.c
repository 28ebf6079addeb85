/*
 * The visible surface at a screen point.
 *
 * Visibility is a depth test per sample: every object offers its nearest
 * exact intersection with the pixel ray (closed form for quadrics, the plane
 * and polygons; tessellation seed + Newton for patches) and the smallest
 * depth wins — a depth buffer evaluated at the exact surface points rather
 * than at interpolated polygon depths.
 */
#include "rn_internal.h"

#include <stdlib.h>

/* Domain tolerance after Newton: a solution this far outside a patch is
 * still that patch's (its neighbour would give the same point). */
#define RN_DOMAIN_EPS 1e-7
#define RN_NEAR 1e-6
#define RN_MAX_SEEDS 8

int hit_finish(const render_scene *sc, int object, int prim, double u, double v, int converged,
               render_hit *h)
{
    const rn_object *o = &sc->obj[object];
    rn_surf S;
    obj_eval(o, prim, u, v, &S);
    h->object = object;
    h->prim = prim;
    h->material = o->material;
    h->u = u;
    h->v = v;
    h->s = o->st_offset[0] + o->st_scale[0] * u;
    h->t = o->st_offset[1] + o->st_scale[1] * v;
    h->converged = jacobian_complete(&sc->cam, o, &S, h) && converged;
    return h->converged;
}

static void hit_clear(render_hit *h)
{
    memset(h, 0, sizeof *h);
    h->object = -1;
    h->material = -1;
    h->depth = HUGE_VAL;
}

/* Newton from (u, v) on patch prim to screen point (x, y): 1 with the root
 * and its depth in *s if it converges inside the patch. *spill gets how far
 * outside the domain a converged root lies (0 inside, HUGE_VAL if none). */
static int patch_root(const render_scene *sc, const rn_object *o, int prim, double x, double y,
                      double u, double v, rn_seed *s, double *spill)
{
    rn_surf S;
    double xy[2], z;
    *spill = HUGE_VAL;
    if (!newton_screen(&sc->cam, o, prim, x, y, &u, &v)) return 0;
    *spill = fmax(fmax(-u, u - 1.0), fmax(-v, v - 1.0));
    if (*spill < 0.0) *spill = 0.0;
    patch_eval(&o->patches[prim], u, v, &S);
    z = cam_project(&sc->cam, S.P, xy, NULL);
    s->prim = prim;
    s->u = u;
    s->v = v;
    s->depth = z;
    return z > RN_NEAR && obj_in_domain(o, prim, u, v, RN_DOMAIN_EPS);
}

/* A root just outside its patch belongs to a neighbour: the flat
 * tessellation crosses a seam at a different place than the curved
 * surface does, so near a seam the ray can hit only the wrong side's
 * triangles (the seed), and Newton then leaves that patch by a fraction of
 * a cell. Hand the point over: Newton again on every other patch whose
 * tessellation passes within a cell of the extended point, from its
 * nearest grid point; the nearest in-domain root wins. */
static int patch_handoff(const render_scene *sc, const rn_object *o, const rn_seed *out,
                         double x, double y, rn_seed *best)
{
    rn_surf S;
    double reach2, du = 1.0 / RN_TESS;
    int pi, found = 0;
    patch_eval(&o->patches[out->prim], out->u, out->v, &S);
    /* A cell's extent around the point, squared. */
    reach2 = (v3_dot(S.Pu, S.Pu) + v3_dot(S.Pv, S.Pv)) * du * du;
    for (pi = 0; pi < o->count; ++pi) {
        double u, v, d2, spill;
        rn_seed s;
        if (pi == out->prim) continue;
        patch_nearest_grid(&o->patches[pi], S.P, &u, &v, &d2);
        if (d2 > reach2) continue;
        /* Start half a cell inside: a boundary row may be a collapsed pole
         * (the lid's top), where Newton's matrix is singular. */
        u = fmin(fmax(u, 0.5 * du), 1.0 - 0.5 * du);
        v = fmin(fmax(v, 0.5 * du), 1.0 - 0.5 * du);
        if (!patch_root(sc, o, pi, x, y, u, v, &s, &spill)) continue;
        if (!found || s.depth < best->depth) *best = s;
        found = 1;
    }
    return found;
}

/* Nearest exact intersection of one patch object; 1 if found. */
static int patches_nearest(const render_scene *sc, const rn_object *o, double x, double y,
                           const double dir[3], rn_seed *best, int *converged)
{
    rn_seed seeds[RN_MAX_SEEDS], spilled = {0, 0.0, 0.0, HUGE_VAL};
    int n = patch_seeds(o, sc->cam.eye, dir, seeds, RN_MAX_SEEDS), k, found = 0, failed = -1;
    int have_spill = 0;
    for (k = 0; k < n; ++k) {
        rn_seed s;
        double spill;
        if (patch_root(sc, o, seeds[k].prim, x, y, seeds[k].u, seeds[k].v, &s, &spill)) {
            if (!found || s.depth < best->depth) *best = s;
            found = 1;
        } else if (spill == HUGE_VAL) {
            if (failed < 0) failed = k;
        } else if (spill > RN_DOMAIN_EPS && spill < 1.0 / RN_TESS && s.depth > RN_NEAR &&
                   (!have_spill || s.depth < spilled.depth)) {
            spilled = s;
            have_spill = 1;
        }
    }
    if (have_spill && (!found || spilled.depth < best->depth)) {
        rn_seed h;
        if (patch_handoff(sc, o, &spilled, x, y, &h) && (!found || h.depth < best->depth)) {
            *best = h;
            found = 1;
        }
    }
    *converged = found;
    if (!found && failed >= 0) {
        /* Newton found no root near any seed: a degenerate point (the lid's
         * and the bottom's collapsed rows). The tessellation point is the
         * best estimate, and dropping it would leave a hole. */
        *best = seeds[failed];
        return 1;
    }
    return found;
}

int render_scene_hit(const render_scene *sc, double x, double y, render_hit *hit)
{
    double dir[3];
    int k, best_obj = -1, best_conv = 1;
    rn_seed best = {0, 0.0, 0.0, HUGE_VAL};
    hit_clear(hit);
    if (!(x == x) || !(y == y)) return 0;
    cam_ray(&sc->cam, x, y, dir);
    for (k = 0; k < sc->nobj; ++k) {
        const rn_object *o = &sc->obj[k];
        rn_seed s;
        int conv = 1, ok;
        if (o->kind == RN_PATCHES)
            ok = patches_nearest(sc, o, x, y, dir, &s, &conv);
        else
            ok = shape_intersect(o, sc->cam.eye, dir, RN_NEAR, &s);
        if (ok && s.depth < best.depth) {
            best = s;
            best_obj = k;
            best_conv = conv;
        }
    }
    if (best_obj < 0) return 0;
    hit_finish(sc, best_obj, best.prim, best.u, best.v, best_conv, hit);
    return 1;
}

/* Bring a periodic u (sphere, cylinder azimuth) to the period nearest ref,
 * so that (s, t) near a seam stay continuous around the seed. */
static double unwrap_near(double u, double ref)
{
    return u + floor(ref - u + 0.5);
}

int render_scene_hit_from(const render_scene *sc, const render_hit *seed, double x, double y,
                          render_hit *hit)
{
    const rn_object *o;
    double u, v;
    hit_clear(hit);
    if (!seed || seed->object < 0 || seed->object >= sc->nobj) return 0;
    o = &sc->obj[seed->object];
    u = seed->u;
    v = seed->v;
    if (o->kind == RN_PATCHES) {
        if (!newton_screen(&sc->cam, o, seed->prim, x, y, &u, &v) ||
            !obj_in_domain(o, seed->prim, u, v, RN_DOMAIN_EPS))
            return 0;
    } else {
        double dir[3];
        rn_seed s;
        cam_ray(&sc->cam, x, y, dir);
        if (!shape_intersect(o, sc->cam.eye, dir, RN_NEAR, &s) || s.prim != seed->prim) return 0;
        u = s.u;
        v = s.v;
        if (o->kind == RN_SPHERE || o->kind == RN_CYLINDER) u = unwrap_near(u, seed->u);
    }
    hit_finish(sc, seed->object, seed->prim, u, v, 1, hit);
    return 1;
}

int render_scene_corners(const render_scene *sc, const render_hit *centre, double x, double y,
                         sample_quad *quad)
{
    static const double off[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    int k, same = centre->object >= 0;
    for (k = 0; k < 4; ++k) {
        render_hit c;
        const rn_object *o;
        if (!render_scene_hit(sc, x + off[k][0], y + off[k][1], &c) || c.object != centre->object ||
            c.prim != centre->prim) {
            same = 0;
            quad->st[k][0] = quad->st[k][1] = 0.0f;
            continue;
        }
        o = &sc->obj[c.object];
        if (o->kind == RN_SPHERE || o->kind == RN_CYLINDER) {
            double u = unwrap_near(c.u, centre->u);
            c.s = o->st_offset[0] + o->st_scale[0] * u;
        }
        quad->st[k][0] = (float)c.s;
        quad->st[k][1] = (float)c.t;
    }
    return same;
}

/* ---- Per-pixel cache ------------------------------------------------------ */

struct render_cache {
    const render_scene *sc;
    int w, h;
    render_hit *hits;
    unsigned char *uniform;
};

static void cache_row(void *ctx, int j)
{
    render_cache *c = ctx;
    int i;
    for (i = 0; i < c->w; ++i)
        render_scene_hit(c->sc, i + 0.5, j + 0.5, &c->hits[(size_t)j * c->w + i]);
}

render_cache *render_cache_build(const render_scene *sc, int threads)
{
    render_cache *c = calloc(1, sizeof *c);
    int i, j;
    if (!c) return NULL;
    c->sc = sc;
    c->w = sc->cam.width;
    c->h = sc->cam.height;
    c->hits = malloc(sizeof *c->hits * (size_t)c->w * (size_t)c->h);
    c->uniform = calloc((size_t)c->w * (size_t)c->h, 1);
    if (!c->hits || !c->uniform) {
        render_cache_destroy(c);
        return NULL;
    }
    render_parallel_rows(c->h, threads, cache_row, c, NULL, NULL);
    /* A pixel is uniform when its 3 × 3 neighbourhood (inside the image)
     * sees one primitive, all converged: then that primitive is taken as the
     * visible one everywhere in the pixel's 2 × 2 footprint. */
    for (j = 1; j + 1 < c->h; ++j)
        for (i = 1; i + 1 < c->w; ++i) {
            const render_hit *h0 = &c->hits[(size_t)j * c->w + i];
            int a, b, ok = h0->object >= 0;
            for (b = -1; b <= 1 && ok; ++b)
                for (a = -1; a <= 1 && ok; ++a) {
                    const render_hit *n = &c->hits[(size_t)(j + b) * c->w + (i + a)];
                    ok = n->object == h0->object && n->prim == h0->prim && n->converged;
                }
            c->uniform[(size_t)j * c->w + i] = (unsigned char)ok;
        }
    return c;
}

void render_cache_destroy(render_cache *c)
{
    if (!c) return;
    free(c->hits);
    free(c->uniform);
    free(c);
}

const render_hit *render_cache_pixel(const render_cache *c, int i, int j)
{
    if (i < 0 || j < 0 || i >= c->w || j >= c->h) return NULL;
    return &c->hits[(size_t)j * c->w + i];
}

int render_cache_hit(const render_cache *c, double x, double y, render_hit *hit)
{
    if (x >= 0.0 && y >= 0.0 && x < c->w && y < c->h) {
        size_t k = (size_t)floor(y) * c->w + (size_t)floor(x);
        if (c->uniform[k] && render_scene_hit_from(c->sc, &c->hits[k], x, y, hit)) return 1;
    }
    return render_scene_hit(c->sc, x, y, hit);
}
