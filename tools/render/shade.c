/*
 * Shading as Blinn & Newell (1976) describe it:
 *
 *     i = T·s·(L·N) + g·(L'·N)^n + r·E(R)
 *
 * Lambert diffuse scaled by the texture T; a highlight from a virtual light
 * L' halfway between the light and the eye, of glossiness g and exponent n,
 * that the texture does not scale ("specularly reflected at the surface and
 * not affected by the pigment"); and mirror reflection of the environment
 * E in the reflected direction R. The normal N can be perturbed by a height
 * texture (Blinn 1978, "Simulation of Wrinkled Surfaces") or replaced by a
 * tangent-space normal map.
 */
#include "rn_internal.h"

static int tex_lookup(const sample_texture *tex, const sample_sampler *smp, const render_hit *h,
                      const sample_quad *quad, float rgba[4], float dds[4], float ddt[4],
                      sample_stats *stats)
{
    sample_query q;
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    q.s = (float)h->s;
    q.t = (float)h->t;
    q.dsdx = (float)h->J[0];
    q.dtdx = (float)h->J[1];
    q.dsdy = (float)h->J[2];
    q.dtdy = (float)h->J[3];
    a.count = 1;
    a.queries = &q;
    a.corners = quad;
    a.rgba = rgba;
    a.drgba_ds = dds;
    a.drgba_dt = ddt;
    a.stats = stats;
    return sample_batch(tex, smp, &a) == SAMPLE_OK;
}

/* Blinn 1978: with n = Pu × Pv unnormalized and F the height,
 * N' = n + (Fu (n × Pv) − Fv (n × Pu)) / |n|. */
static void bump_normal(const rn_object *o, const render_hit *h, double Fs, double Ft,
                        double N[3])
{
    rn_surf S;
    double n[3], a[3], b[3], nl, Fu = Fs * o->st_scale[0], Fv = Ft * o->st_scale[1];
    int k;
    obj_eval(o, h->prim, h->u, h->v, &S);
    v3_cross(n, S.Pu, S.Pv);
    nl = v3_len(n);
    if (!(nl > 0.0)) return;
    if (v3_dot(n, h->N) < 0.0) {
        /* The eye sees the back: Pu × Pv was flipped for shading. */
        v3_scale(n, n, -1.0);
        Fu = -Fu;
        Fv = -Fv;
    }
    v3_cross(a, n, S.Pv);
    v3_cross(b, n, S.Pu);
    for (k = 0; k < 3; ++k) N[k] = n[k] + (Fu * a[k] - Fv * b[k]) / nl;
    v3_normalize(N);
}

/* Tangent frame (Pu, N × Pu, N); the map stores (n + 1)/2. */
static void mapped_normal(const rn_object *o, const render_hit *h, const float c[4], double N[3])
{
    rn_surf S;
    double T[3], B[3], m[3];
    int k;
    obj_eval(o, h->prim, h->u, h->v, &S);
    v3_copy(T, S.Pu);
    v3_madd(T, T, h->N, -v3_dot(T, h->N));
    if (!(v3_normalize(T) > 0.0)) return;
    v3_cross(B, h->N, T);
    for (k = 0; k < 3; ++k) m[k] = 2.0 * c[k] - 1.0;
    for (k = 0; k < 3; ++k) N[k] = m[0] * T[k] + m[1] * B[k] + m[2] * h->N[k];
    if (!(v3_normalize(N) > 0.0)) v3_copy(N, h->N);
}

void rn_view_vector(const render_scene *sc, const render_hit *h, double V[3], double dV[2][3])
{
    double dist;
    int l, k;
    v3_sub(V, sc->cam.eye, h->P);
    dist = v3_normalize(V);
    /* dV = −(dP − V (V·dP)) / |E − P| */
    for (l = 0; l < 2; ++l) {
        const double *dP = l ? h->dPdy : h->dPdx;
        double k2 = v3_dot(V, dP);
        for (k = 0; k < 3; ++k) dV[l][k] = -(dP[k] - V[k] * k2) / dist;
    }
}

void shade_hit(const render_scene *sc, const render_options *o, const render_hit *h,
               const sample_quad *quad, float out[4], sample_stats *stats)
{
    const rn_material *m = &sc->mat[h->material];
    const rn_object *obj = &sc->obj[h->object];
    const sample_sampler *smp = &o->sampler;
    float T[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    double N[3], V[3], dV[2][3], c[3] = {0, 0, 0};
    int k, l;
    if (m->texture >= 0) {
        const rn_texture *tx = &sc->tex[m->texture];
        sample_query3 q3;
        if (solid_query(tx, h, &q3)) {
            /* A baked solid: filtered over the footprint in the volume. */
            if (!solid_sample(tx, smp, &q3, 1, T, stats)) T[0] = T[1] = T[2] = 0.0f;
        } else if (tx->kind == RN_TEX_SOLID && o->shade == RENDER_SHADE_FULL)
            proc_eval(tx, h->s, h->t, h->P, T); /* solid: exact at P, unfiltered */
        else if (!tex_lookup(tx->tex, smp, h, quad, T, NULL, NULL, stats))
            T[0] = T[1] = T[2] = 0.0f;
    }
    if (o->shade == RENDER_SHADE_TEXTURE) {
        for (k = 0; k < 4; ++k) out[k] = T[k];
        return;
    }
    v3_copy(N, h->N);
    if (m->bump >= 0) {
        float v[4], ds[4], dt[4];
        if (tex_lookup(sc->tex[m->bump].tex, smp, h, NULL, v, ds, dt, NULL))
            bump_normal(obj, h, m->bump_scale * ds[0], m->bump_scale * dt[0], N);
    } else if (m->normal_map >= 0) {
        float v[4];
        if (tex_lookup(sc->tex[m->normal_map].tex, smp, h, NULL, v, NULL, NULL, NULL))
            mapped_normal(obj, h, v, N);
    }
    rn_view_vector(sc, h, V, dV);
    for (k = 0; k < 3; ++k) c[k] = m->ambient * m->diffuse[k] * T[k];
    for (l = 0; l < sc->nlight; ++l) {
        const rn_light *L = &sc->light[l];
        double H[3], d = v3_dot(N, L->dir), sp;
        v3_add(H, L->dir, V);
        v3_normalize(H);
        sp = v3_dot(N, H);
        sp = sp > 0.0 ? m->gloss * pow(sp, m->exponent) : 0.0;
        if (d < 0.0) d = 0.0;
        for (k = 0; k < 3; ++k) c[k] += L->color[k] * (m->diffuse[k] * T[k] * d + sp);
    }
    if (m->reflect > 0.0f && sc->env.kind != RN_ENV_NONE) {
        float e[4];
        render_hit hb = *h;
        v3_copy(hb.N, N);
        env_lookup(&sc->env, smp, &hb, V, dV[0], dV[1], e);
        for (k = 0; k < 3; ++k) c[k] += m->reflect * e[k];
    }
    for (k = 0; k < 3; ++k) out[k] = (float)c[k];
    out[3] = 1.0f;
}
