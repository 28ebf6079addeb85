/*
 * UDIM sets (sample/texsys.h section 3, doc/texture-system.md "UDIM"): one
 * virtual texture of C × R tiles, C and R the powers of two that cover the
 * set's columns and rows. Tile (u, v) holds the virtual texels
 * [u·W, (u+1)·W) × [v·H, (v+1)·H) of level 0, and the same block of every
 * level k (W and H halved k times), so a filter's footprint that crosses a
 * tile's edge reads on into the neighbour, and a missing tile reads the
 * fill colour. Queries map from (s, t) to (s / C, t / R): a power of two,
 * so the texel coordinates s / C · C·W are s · W exactly, and λ is the one
 * of the tile alone.
 */
#include "texsys_internal.h"

#include <stdio.h>
#include <stdlib.h>

#define UDIM_MAX 16 /* columns and rows of the virtual texture at most */

struct ts_udim {
    ts_head h; /* first */
    sample_texture *tex;
    char *name;
    const char *colorspace; /* its tiles' (ts_file.colorspace) */
    int cols, rows;      /* the virtual texture's, powers of two */
    int used_cols, used_rows;
    int tw[SAMPLE_MAX_LEVELS], th[SAMPLE_MAX_LEVELS]; /* a tile's extent at each level */
    ts_file *tile[UDIM_MAX * UDIM_MAX]; /* [v · cols + u]; NULL: missing */
    ts_udim *next;
};

static const char *const tokens[] = {"<UDIM>", "<u>", "<v>", "<U>", "<V>", "<uvtile>", "<UVTILE>"};
enum { NTOK = sizeof tokens / sizeof tokens[0] };

int io_ts_udim_pattern(const char *name)
{
    int k;
    for (k = 0; k < NTOK; ++k)
        if (strstr(name, tokens[k])) return 1;
    return 0;
}

/* The name of tile (u, v) (0-based): <UDIM> is 1001 + u + 10 v; <u>, <v>
 * are "u"/"v" and the 0-based index, <U>, <V> the 1-based one, <uvtile>
 * is "<U>_<V>" (OpenImageIO's conventions). 0 if it does not fit. */
static int expand(const char *name, int u, int v, char *out, size_t size)
{
    size_t n = 0;
    while (*name) {
        char sub[32] = "";
        int k, len = 0;
        for (k = 0; k < NTOK; ++k) {
            len = (int)strlen(tokens[k]);
            if (!strncmp(name, tokens[k], (size_t)len)) break;
        }
        switch (k) {
        case 0: snprintf(sub, sizeof sub, "%04d", 1001 + u + 10 * v); break;
        case 1: snprintf(sub, sizeof sub, "u%d", u); break;
        case 2: snprintf(sub, sizeof sub, "v%d", v); break;
        case 3: snprintf(sub, sizeof sub, "u%d", u + 1); break;
        case 4: snprintf(sub, sizeof sub, "v%d", v + 1); break;
        case 5:
        case 6: snprintf(sub, sizeof sub, "u%d_v%d", u + 1, v + 1); break;
        default: sub[0] = *name, sub[1] = 0, len = 1; break;
        }
        if (n + strlen(sub) + 1 > size) return 0;
        memcpy(out + n, sub, strlen(sub));
        n += strlen(sub);
        name += len;
    }
    out[n] = 0;
    return 1;
}

/* The texel of the tile's file; NULL (the fill colour) where the set lacks
 * the tile. Where the set declares tiles (declare_tiles), the file's
 * pointer addresses the file's whole cache tile, which is the virtual
 * texture's tile. */
static const unsigned char *udim_texel(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    const ts_udim *u = (const ts_udim *)src;
    const int tw = u->tw[lv], th = u->th[lv], x = i / tw, y = j / th;
    const ts_file *f = u->tile[y * u->cols + x];
    (void)layer;
    if (!f) return NULL;
    return f->h.base.texel(&f->h.base, lv, i - x * tw, j - y * th, 0);
}

/* The fast path's planners read a 2 × 2 or 4 × 4 block inside one tile
 * of T texels with one texel() call (texel.h, tile_side). The virtual
 * tile (tx, ty) of level k is one cache tile of one file when the files'
 * tiles have one side T and, on each axis, the UDIM tile's extent at k is
 * a multiple of T — the edges between UDIM tiles are then tile edges — or
 * the set is one tile across on that axis (the virtual level is then the
 * file's there, a tile past its edge keeping its shape as the file's
 * does). Halving keeps neither once it is lost, so it holds for the levels
 * [0, n): those are declared in tiles (tile_levels), and on the smaller
 * ones, where a tile of T texels would hold texels of several files, the
 * planners read texel by texel, as the reference path does at every
 * level. A missing tile needs no tile of fill texels: texel() answers NULL
 * there and the planners read the fill colour texel by texel, the
 * reference path's bits (the fill is not a texel of every format). */
static void declare_tiles(ts_udim *u)
{
    int k, n, log2 = -1, side;
    for (k = 0; k < u->cols * u->rows; ++k) {
        if (!u->tile[k]) continue;
        if (log2 >= 0 && u->tile[k]->log2 != log2) return;
        log2 = u->tile[k]->log2;
    }
    side = 1 << log2;
    for (n = 0; n < u->tex->nlevels; ++n)
        if ((u->cols > 1 && u->tw[n] % side) || (u->rows > 1 && u->th[n] % side)) break;
    if (n == 0) return;
    u->h.base.tile_side = side;
    u->h.base.tile_levels = n;
}

static void udim_source_destroy(struct ls_texel_source *src) { (void)src; }

static int pow2_at_least(int n)
{
    int p = 1;
    while (p < n) p <<= 1;
    return p;
}

/* The virtual texture over the tiles found (open_lock held). */
static sample_status build(sample_texsys *sys, ts_udim *u, sample_error *err)
{
    const sample_texture *t0 = NULL;
    sample_texture *tex;
    int k, n, levels = SAMPLE_MAX_LEVELS;
    for (k = 0; k < UDIM_MAX * UDIM_MAX; ++k) {
        const sample_texture *t;
        if (!u->tile[k]) continue;
        t = u->tile[k]->tex;
        if (!t0) t0 = t;
        if (t->width != t0->width || t->height != t0->height || t->channels != t0->channels ||
            t->format != t0->format)
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT,
                                    "UDIM set '%s': its tiles differ in size, channels or format", u->name);
        if (t->nlevels < levels) levels = t->nlevels;
    }
    if (!t0) return sample_error_set(err, SAMPLE_E_IO, "UDIM set '%s': no tile exists", u->name);
    /* Virtual level k is tile level k side by side while halving the
     * virtual size halves the tile's exactly. */
    for (n = 1; n < levels; ++n)
        if (t0->width % (1 << n) || t0->height % (1 << n)) break;
    levels = n;
    if ((long)t0->width * u->cols > SAMPLE_MAX_SIZE || (long)t0->height * u->rows > SAMPLE_MAX_SIZE)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "UDIM set '%s': %d x %d tiles of %d x %d exceed %d a side",
                                u->name, u->cols, u->rows, t0->width, t0->height, SAMPLE_MAX_SIZE);
    tex = (sample_texture *)calloc(1, sizeof *tex);
    if (!tex) return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture");
    *tex = *t0;
    tex->width = t0->width * u->cols;
    tex->height = t0->height * u->rows;
    tex->nlevels = levels;
    tex->bytes = 0;
    for (k = 0; k < levels; ++k) {
        u->tw[k] = t0->level[k].w;
        u->th[k] = t0->level[k].h;
        tex->level[k].w = t0->level[k].w * u->cols;
        tex->level[k].h = t0->level[k].h * u->rows;
        tex->bytes += (size_t)tex->level[k].w * (size_t)tex->level[k].h * tex->texel_bytes;
    }
    for (; k < SAMPLE_MAX_LEVELS; ++k) memset(&tex->level[k], 0, sizeof tex->level[k]);
    u->h.base.texel = udim_texel;
    u->h.base.destroy = udim_source_destroy;
    u->h.base.reads_begin = io_ts_reads_begin;
    u->h.base.reads_end = io_ts_reads_end;
    memcpy(u->h.base.fill, sys->o.fill, sizeof u->h.base.fill);
    tex->source = &u->h.base;
    u->tex = tex;
    declare_tiles(u);
    return SAMPLE_OK;
}

sample_status io_ts_udim_open(sample_texsys *sys, const char *name, const char *cs, const sample_texture **out,
                              sample_error *err)
{
    ts_udim *u;
    sample_status st = SAMPLE_OK;
    char path[4096];
    int x, y, maxu = -1, maxv = -1;
    if (!cs) cs = sys->colorspace;
    for (u = sys->udims; u; u = u->next)
        if (!strcmp(u->name, name) && io_ts_same_colorspace(u->colorspace, cs)) {
            *out = u->tex;
            return SAMPLE_OK;
        }
    u = (ts_udim *)calloc(1, sizeof *u);
    if (!u || !(u->name = io_strdup(name))) {
        free(u);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a UDIM set");
    }
    u->h.sys = sys;
    u->h.udim = 1;
    /* UDIM numbers 1001 to 1100: u < 10, v < 10. */
    for (y = 0; y < 10 && st == SAMPLE_OK; ++y)
        for (x = 0; x < 10 && st == SAMPLE_OK; ++x) {
            FILE *probe;
            if (!expand(name, x, y, path, sizeof path)) {
                st = sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "UDIM name '%s' is too long", name);
                break;
            }
            if (!(probe = fopen(path, "rb"))) continue; /* a tile the set lacks */
            fclose(probe);
            st = io_ts_open_file(sys, path, cs, &u->tile[y * UDIM_MAX + x], err);
            if (st == SAMPLE_OK) u->colorspace = u->tile[y * UDIM_MAX + x]->colorspace;
            if (x > maxu) maxu = x;
            if (y > maxv) maxv = y;
        }
    if (st == SAMPLE_OK) {
        /* Re-index [v · UDIM_MAX + u] → [v · cols + u]. */
        u->used_cols = maxu + 1;
        u->used_rows = maxv + 1;
        u->cols = pow2_at_least(maxu + 1);
        u->rows = pow2_at_least(maxv + 1);
        for (y = 0; y < u->rows; ++y)
            for (x = 0; x < u->cols; ++x) {
                ts_file *f = u->tile[y * UDIM_MAX + x];
                u->tile[y * UDIM_MAX + x] = NULL;
                u->tile[y * u->cols + x] = f;
            }
        st = build(sys, u, err);
    }
    if (st != SAMPLE_OK) {
        free(u->name);
        free(u);
        return st;
    }
    pthread_mutex_lock(&sys->lock);
    u->next = sys->udims;
    sys->udims = u;
    pthread_mutex_unlock(&sys->lock);
    *out = u->tex;
    return SAMPLE_OK;
}

ts_udim *io_ts_udim_of(const sample_texsys *sys, const sample_texture *tex)
{
    const ts_head *h;
    if (!sys || !tex || !tex->source || tex->source->reads_begin != io_ts_reads_begin) return NULL;
    h = (const ts_head *)tex->source;
    return h->sys == sys && h->udim ? (ts_udim *)(uintptr_t)h : NULL;
}

void io_ts_udim_info(const ts_udim *u, sample_texsys_info *info)
{
    int k;
    info->udim = 1;
    info->udim_cols = u->used_cols;
    info->udim_rows = u->used_rows;
    for (k = 0; k < u->cols * u->rows; ++k)
        if (u->tile[k]) {
            info->tile_size = 1 << u->tile[k]->log2;
            info->file_tiled = u->tile[k]->file_tiled;
            snprintf(info->colorspace, sizeof info->colorspace, "%s",
                     u->tile[k]->plan.colorspace ? u->tile[k]->plan.colorspace : "");
            break;
        }
    info->has_wrap = 1;
    info->wrap_s = info->wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
}

unsigned long io_ts_udim_errors(const ts_udim *u, sample_error *first)
{
    unsigned long n = 0;
    int k;
    /* sys->lock held by the caller. */
    for (k = 0; k < u->cols * u->rows; ++k) {
        const ts_file *f = u->tile[k];
        if (!f || !f->nerrors) continue;
        if (!n && first) *first = f->first_error;
        n += f->nerrors;
    }
    return n;
}

/* Queries mapped to the virtual texture, chunk by chunk: s / C, t / R and
 * their derivatives, and ∂/∂s, ∂/∂t of the result scaled back (all by
 * powers of two: exact). Outside the set's C × R tiles is the border, the
 * fill colour. */
typedef struct udim_map {
    float sc, tc;
    sample_query q[TS_CHUNK];
    sample_quad c[TS_CHUNK];
} udim_map;

static void udim_map_chunk(void *ctx, sample_batch_args *b, size_t i0)
{
    udim_map *m = (udim_map *)ctx;
    size_t i, k;
    if (i0 == (size_t)-1) {
        for (i = 0; i < 4 * b->count; ++i) {
            if (b->drgba_ds) b->drgba_ds[i] *= m->sc;
            if (b->drgba_dt) b->drgba_dt[i] *= m->tc;
        }
        return;
    }
    for (i = 0; i < b->count; ++i) {
        const sample_query *p = &b->queries[i];
        m->q[i].s = p->s * m->sc, m->q[i].dsdx = p->dsdx * m->sc, m->q[i].dsdy = p->dsdy * m->sc;
        m->q[i].t = p->t * m->tc, m->q[i].dtdx = p->dtdx * m->tc, m->q[i].dtdy = p->dtdy * m->tc;
        if (b->corners)
            for (k = 0; k < 4; ++k) {
                m->c[i].st[k][0] = b->corners[i].st[k][0] * m->sc;
                m->c[i].st[k][1] = b->corners[i].st[k][1] * m->tc;
            }
    }
    b->queries = m->q;
    if (b->corners) b->corners = m->c;
}

sample_status io_ts_udim_batch(ts_udim *u, const sample_sampler *s, const sample_batch_args *a)
{
    udim_map m;
    sample_sampler vs;
    if (!s || !a) return SAMPLE_E_INVALID_ARGUMENT;
    if (a->count && (!a->queries || !a->rgba)) return SAMPLE_E_INVALID_ARGUMENT;
    vs = *s;
    vs.wrap_s = vs.wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
    memcpy(vs.border_color, u->h.base.fill, sizeof vs.border_color);
    m.sc = 1.0f / (float)u->cols;
    m.tc = 1.0f / (float)u->rows;
    return io_ts_batch_chunks(u->tex, &vs, a, udim_map_chunk, &m);
}

void io_ts_udim_free_all(sample_texsys *sys)
{
    while (sys->udims) {
        ts_udim *u = sys->udims;
        sys->udims = u->next;
        sample_texture_destroy(u->tex);
        free(u->name);
        free(u);
    }
}
