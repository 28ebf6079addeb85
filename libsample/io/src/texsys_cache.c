/*
 * The texture system's tile cache (doc/texture-system.md, "The cache"): a
 * texel source per file whose texel() finds the tile in an atomic slot and
 * loads it on a miss; clock eviction under the memory limit; epochs that
 * free an evicted tile only once no batch that could hold it is running.
 */
#include "texsys_internal.h"
#include "exr_tile.h"

#include <stdlib.h>

/* The slot of a tile that failed to load: never in the ring, never freed;
 * its texels read as the fill colour (texel.h: NULL). */
static ts_tile ts_failed;

void io_ts_lock_init(ts_lock *l)
{
    pthread_mutex_init(&l->m, NULL);
    pthread_cond_init(&l->c, NULL);
    l->next = l->serving = 0;
}

static void ts_lock_destroy(ts_lock *l)
{
    pthread_mutex_destroy(&l->m);
    pthread_cond_destroy(&l->c);
}

static void ts_lock_take(ts_lock *l)
{
    unsigned long mine;
    pthread_mutex_lock(&l->m);
    mine = l->next++;
    while (l->serving != mine) pthread_cond_wait(&l->c, &l->m);
    pthread_mutex_unlock(&l->m);
}

static int ts_trylock(ts_lock *l)
{
    int taken;
    pthread_mutex_lock(&l->m);
    taken = l->next == l->serving;
    if (taken) l->next++;
    pthread_mutex_unlock(&l->m);
    return taken;
}

static void ts_unlock(ts_lock *l)
{
    pthread_mutex_lock(&l->m);
    l->serving++;
    pthread_cond_broadcast(&l->c);
    pthread_mutex_unlock(&l->m);
}

/* The memory held now, and the most ever held (sys->lock held). */
static void note_memory(sample_texsys *sys)
{
    size_t m = sys->resident + sys->retired_bytes;
    sys->st.memory = m;
    if (m > sys->st.peak_memory) sys->st.peak_memory = m;
}

/* ---- Epochs ----------------------------------------------------------------
 * A batch takes the current epoch as its ticket. A tile evicted during epoch
 * g can be read only by batches holding tickets ≤ g (a batch with a later
 * ticket read the epoch after the eviction emptied its slot, and the epoch
 * moves under sys->lock after that). The epoch moves from g to g + 1 once
 * no batch holds ticket g − 1; the tiles evicted during g − 1 are then
 * freed. So two parities suffice, as in the two-counter form of
 * read-copy-update (McKenney, "Sleepable RCU", 2006).
 *
 * A batch counts itself without the lock (io_ts_reads_begin): it adds
 * itself to the count of its ticket's parity and checks that the epoch is
 * still its ticket, else takes itself back out and tries again; all of
 * these sequentially consistent, so an advance that could free what the
 * batch reads sees its count. Where the working set fits the cache nothing
 * is ever retired, and batches on many threads share no lock
 * (retired_any: a batch's end takes the lock only to advance the epochs
 * past retired tiles). The functions below run with sys->lock held. */
static void free_retired(sample_texsys *sys, int parity)
{
    ts_tile *t, *next;
    for (t = sys->retired[parity]; t; t = next) {
        next = t->retired;
        sys->retired_bytes -= t->bytes;
        free(t);
    }
    sys->retired[parity] = NULL;
}

/* The batches counted in every stripe with ticket parity p. The sum is no
 * snapshot, and need not be: a batch that holds a ticket counted itself
 * before it confirmed the epoch, so its count stays in its stripe, seen by
 * every read of the stripes from then until its end. */
static unsigned long ts_active(sample_texsys *sys, int p)
{
    unsigned long n = 0;
    int k;
    for (k = 0; k < TS_STRIPES; ++k) n += atomic_load(&sys->active[k].n[p]);
    return n;
}

static void ts_advance(sample_texsys *sys)
{
    const uint64_t epoch = atomic_load(&sys->epoch);
    const int old = (int)((epoch + 1) & 1); /* parity of epoch − 1 */
    if (ts_active(sys, old) != 0) return;
    free_retired(sys, old);
    atomic_store(&sys->epoch, epoch + 1);
    /* No batch at all: nothing evicted can be held (a batch that counts
     * itself from now on finds the new epoch and holds no retired tile). */
    if (ts_active(sys, 0) + ts_active(sys, 1) == 0) {
        free_retired(sys, 0);
        free_retired(sys, 1);
    }
    atomic_store(&sys->retired_any, sys->retired[0] != NULL || sys->retired[1] != NULL);
    note_memory(sys);
}

/* This thread's stripe: threads are numbered as they first sample, in
 * the process (a number, no shared state: every system indexes its own
 * stripes with it). */
static atomic_uint ts_threads;
static _Thread_local unsigned ts_thread_id; /* 0: not numbered yet */

static unsigned ts_stripe_of_thread(void)
{
    if (ts_thread_id == 0) ts_thread_id = atomic_fetch_add(&ts_threads, 1) + 1;
    return (ts_thread_id - 1) % TS_STRIPES;
}

/* The ticket handed to reads_end: the stripe counted in and the parity. */
uintptr_t io_ts_reads_begin(const struct ls_texel_source *src)
{
    sample_texsys *sys = ((const ts_head *)src)->sys;
    ts_stripe *stripe = &sys->active[ts_stripe_of_thread()];
    for (;;) {
        const uint64_t epoch = atomic_load(&sys->epoch);
        const int p = (int)(epoch & 1);
        atomic_fetch_add(&stripe->n[p], 1);
        if (atomic_load(&sys->epoch) == epoch) return (uintptr_t)(stripe - sys->active) * 2u + (uintptr_t)p;
        atomic_fetch_sub(&stripe->n[p], 1);
    }
}

void io_ts_reads_end(const struct ls_texel_source *src, uintptr_t ticket)
{
    sample_texsys *sys = ((const ts_head *)src)->sys;
    atomic_fetch_sub(&sys->active[ticket / 2].n[ticket & 1], 1);
    /* Every eviction happens inside a batch, whose own end then sees the
     * flag. */
    if (!atomic_load(&sys->retired_any)) return;
    pthread_mutex_lock(&sys->lock);
    ts_advance(sys);
    pthread_mutex_unlock(&sys->lock);
}

void io_ts_cache_drain(sample_texsys *sys)
{
    free_retired(sys, 0);
    free_retired(sys, 1);
}

/* ---- The clock (sys->lock held) ------------------------------------------ */

static void ring_insert(sample_texsys *sys, ts_tile *t)
{
    if (!sys->hand) {
        t->prev = t->next = t;
        sys->hand = t;
        return;
    }
    /* Just behind the hand: the last the sweep reaches. */
    t->next = sys->hand;
    t->prev = sys->hand->prev;
    t->prev->next = t;
    sys->hand->prev = t;
}

static void ring_remove(sample_texsys *sys, ts_tile *t)
{
    if (t->next == t) {
        sys->hand = NULL;
    } else {
        t->prev->next = t->next;
        t->next->prev = t->prev;
        if (sys->hand == t) sys->hand = t->next;
    }
}

/* Evict one tile: the first from the hand on whose reference bit is clear,
 * clearing the bits it passes (the clock approximation of least recently
 * used, as OpenImageIO's ImageCache evicts). Its slot empties now; its
 * memory waits for the epochs. */
static void ts_evict_one(sample_texsys *sys)
{
    ts_tile *t = sys->hand;
    while (atomic_exchange_explicit(&t->file->refs[t->lv][t->slot], 0, memory_order_relaxed)) t = t->next;
    sys->hand = t;
    ring_remove(sys, t);
    atomic_store_explicit(&t->file->slots[t->lv][t->slot], NULL, memory_order_release);
    sys->resident -= t->bytes;
    sys->retired_bytes += t->bytes;
    t->retired = sys->retired[atomic_load(&sys->epoch) & 1];
    sys->retired[atomic_load(&sys->epoch) & 1] = t;
    atomic_store(&sys->retired_any, 1);
    sys->st.evictions++;
}

/* Room for `bytes` more under the limit, evicting as needed, then the
 * tile's memory; NULL when it cannot be had. Its texels are zeroed only
 * where `partial` (a tile at a level's right or bottom edge, whose texels
 * outside the level no load writes): a full tile is written whole. */
static ts_tile *ts_tile_alloc(ts_file *f, int lv, size_t slot, size_t px_bytes, int partial)
{
    sample_texsys *sys = f->h.sys;
    const size_t bytes = sizeof(ts_tile) + px_bytes;
    ts_tile *t = NULL;
    pthread_mutex_lock(&sys->lock);
    ts_advance(sys);
    while (sys->hand && sys->resident + bytes > sys->limit) ts_evict_one(sys);
    if (sys->fail_allocs > 0) {
        sys->fail_allocs--;
    } else {
        t = (ts_tile *)malloc(bytes);
    }
    if (t) {
        memset(t, 0, sizeof *t);
        if (partial) memset(t + 1, 0, px_bytes);
        t->file = f;
        t->lv = lv;
        t->slot = slot;
        t->bytes = bytes;
        sys->resident += bytes;
        note_memory(sys);
    }
    pthread_mutex_unlock(&sys->lock);
    return t;
}

/* A tile allocated but not loaded: its memory back. */
static void ts_tile_discard(ts_file *f, ts_tile *t)
{
    sample_texsys *sys = f->h.sys;
    pthread_mutex_lock(&sys->lock);
    sys->resident -= t->bytes;
    note_memory(sys);
    pthread_mutex_unlock(&sys->lock);
    free(t);
}

/* A loaded tile into the ring and its slot; `direct`: decoded by the
 * direct OpenEXR tile reader. */
static void ts_publish(ts_file *f, ts_tile *t, size_t texel_bytes, int direct)
{
    sample_texsys *sys = f->h.sys;
    pthread_mutex_lock(&sys->lock);
    atomic_store_explicit(&f->refs[t->lv][t->slot], 1, memory_order_relaxed);
    ring_insert(sys, t);
    sys->st.tiles_read++;
    if (direct) sys->st.tiles_direct++;
    sys->st.bytes_read += (uint64_t)(t->bytes - sizeof(ts_tile)) / texel_bytes * texel_bytes;
    atomic_store_explicit(&f->slots[t->lv][t->slot], t, memory_order_release);
    pthread_mutex_unlock(&sys->lock);
}

static void ts_record_error(ts_file *f, const sample_error *e)
{
    sample_texsys *sys = f->h.sys;
    pthread_mutex_lock(&sys->lock);
    if (f->nerrors++ == 0) f->first_error = *e;
    sys->st.errors++;
    pthread_mutex_unlock(&sys->lock);
}

/* ---- Open files ----------------------------------------------------------- */

/* Close the least recently used reader other than f's whose lock is free
 * (sys->lock held); 0 if none could be closed. */
static int close_lru_reader(sample_texsys *sys, const ts_file *f)
{
    ts_file *g, *best = NULL;
    for (g = sys->files; g; g = g->next) {
        if (g == f || !g->open) continue;
        if (best && g->last_open >= best->last_open) continue;
        if (!ts_trylock(&g->io_lock)) continue;
        if (best) ts_unlock(&best->io_lock);
        best = g;
    }
    if (!best) return 0;
    io_reader_close(best->reader);
    best->reader = NULL;
    io_exr_tile_close(best->exr);
    best->exr = NULL;
    best->open = 0;
    sys->open_files--;
    ts_unlock(&best->io_lock);
    return 1;
}

/* f's reader open (io_lock held): the direct OpenEXR tile reader unless
 * it once refused the file, else OpenImageIO's. */
static sample_status ts_reader_acquire(ts_file *f, sample_error *err)
{
    sample_texsys *sys = f->h.sys;
    sample_status st;
    pthread_mutex_lock(&sys->lock);
    f->last_open = ++sys->clock;
    if (f->reader || f->exr) {
        pthread_mutex_unlock(&sys->lock);
        return SAMPLE_OK;
    }
    /* Over the limit only while every other open file is being read. */
    while (sys->open_files >= sys->o.max_open_files && close_lru_reader(sys, f)) {
    }
    sys->open_files++;
    f->open = 1;
    if (sys->open_files > sys->st.peak_open_files) sys->st.peak_open_files = sys->open_files;
    sys->st.files_opened++;
    pthread_mutex_unlock(&sys->lock);
    st = sample_io_check_regular_file(f->path, "texture", err);
    if (st == SAMPLE_OK && !f->exr_refused) {
        st = io_exr_tile_open(f->path, f->tex, f->log2, &f->plan, &f->exr, err);
        f->exr_refused = st == SAMPLE_OK && !f->exr;
    }
    if (st == SAMPLE_OK && !f->exr) st = io_reader_open(f->path, NULL, 0, NULL, &f->reader, err);
    if (st != SAMPLE_OK) {
        pthread_mutex_lock(&sys->lock);
        sys->open_files--;
        f->open = 0;
        pthread_mutex_unlock(&sys->lock);
    }
    return st;
}

/* ---- Loads ---------------------------------------------------------------- */

static int min_int(int a, int b) { return a < b ? a : b; }

/* The texels of level lv's tile (tx, ty) inside the level: w × h. */
static void tile_extent(const ts_file *f, int lv, int tx, int ty, int *w, int *h)
{
    const struct sample_level *L = &f->tex->level[lv];
    const int side = 1 << f->log2;
    *w = min_int(side, L->w - tx * side);
    *h = min_int(side, L->h - ty * side);
}

static int tile_partial(const ts_file *f, int lv, int tx, int ty)
{
    int w, h;
    tile_extent(f, lv, tx, ty, &w, &h);
    return w < 1 << f->log2 || h < 1 << f->log2;
}

/* Texels of level lv's tile (tx, ty) of `from` (resident) into t. */
static void copy_tile(const ts_file *f, const sample_texture *from, int lv, int tx, int ty, ts_tile *t)
{
    const struct sample_level *L = &from->level[lv];
    const int side = 1 << f->log2, i0 = tx * side, j0 = ty * side;
    const size_t tb = from->texel_bytes;
    int w, h;
    int j;
    tile_extent(f, lv, tx, ty, &w, &h);
    for (j = 0; j < h; ++j)
        memcpy(ts_px(t) + (size_t)j * (size_t)side * tb, L->data + (size_t)(j0 + j) * L->stride + (size_t)i0 * tb,
               (size_t)w * tb);
}

static size_t tile_px_bytes(const ts_file *f)
{
    return ((size_t)1 << (2 * f->log2)) * f->tex->texel_bytes;
}

/* A file read whole (texsys.h, section 2): the texture sample_io_read_texture
 * makes, the wanted tile from it, and as many others as fit without
 * evicting (they would otherwise be read whole again). */
static ts_tile *load_whole(ts_file *f, int lv, int tx, int ty, sample_error *err)
{
    sample_texsys *sys = f->h.sys;
    sample_io_options o;
    sample_mip_params mip;
    sample_texture *tex = NULL;
    ts_tile *want = NULL;
    int k, x, y;
    sample_io_options_init(&o);
    o.colorspace = f->colorspace;
    o.mip_wrap_from_file = 1;
    sample_mip_params_init(&mip);
    if (io_read_texture_col(f->path, sys->col, &o, &mip, &tex, err) != SAMPLE_OK) return NULL;
    pthread_mutex_lock(&sys->lock);
    sys->st.files_opened++;
    pthread_mutex_unlock(&sys->lock);
    if (tex->nlevels != f->tex->nlevels || tex->width != f->tex->width || tex->height != f->tex->height ||
        tex->format != f->tex->format || tex->channels != f->tex->channels) {
        sample_error_set(err, SAMPLE_E_CORRUPT, "'%s' changed since it was opened", f->path);
        sample_texture_destroy(tex);
        return NULL;
    }
    for (k = 0; k < tex->nlevels; ++k)
        for (y = 0; y < f->nty[k]; ++y)
            for (x = 0; x < f->ntx[k]; ++x) {
                const size_t slot = (size_t)y * (size_t)f->ntx[k] + (size_t)x;
                const int wanted = k == lv && x == tx && y == ty;
                ts_tile *t;
                if (!wanted) {
                    int room;
                    if (atomic_load_explicit(&f->slots[k][slot], memory_order_acquire)) continue;
                    pthread_mutex_lock(&sys->lock);
                    room = sys->resident + sizeof(ts_tile) + tile_px_bytes(f) <= sys->limit;
                    pthread_mutex_unlock(&sys->lock);
                    if (!room) continue;
                }
                t = ts_tile_alloc(f, k, slot, tile_px_bytes(f), tile_partial(f, k, x, y));
                if (!t) {
                    if (wanted)
                        sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a tile of '%s'", f->path);
                    continue;
                }
                copy_tile(f, tex, k, x, y, t);
                ts_publish(f, t, tex->texel_bytes, 0);
                if (wanted) want = t;
            }
    sample_texture_destroy(tex);
    return want;
}

/* The plan keeps the file's texels as they are (no colour conversion, no
 * premultiplication, no narrowing): a reader may decode straight into the
 * tile. */
static int plan_is_identity(const ts_file *f)
{
    const io_plan *p = &f->plan;
    const size_t rb = p->read_as == IO_HALF ? 2 : p->read_as == IO_FLOAT ? 4 : 0;
    return !p->convert && !p->premultiply && rb * (size_t)p->nchan == f->tex->texel_bytes;
}

/* A tile of a tiled file, through the direct OpenEXR tile reader or
 * OpenImageIO's read_tiles. Where the plan is the identity the direct
 * reader decodes into the tile itself; otherwise the texels are read as
 * plan.read_as, then the plan (conversion, premultiplication, narrowing)
 * applies as whole levels get it (io_plan_apply), so the bits are
 * sample_io_read_texture's. */
static ts_tile *load_tile(ts_file *f, int lv, int tx, int ty, size_t slot, sample_error *err)
{
    const int side = 1 << f->log2, i0 = tx * side, j0 = ty * side;
    const size_t tb = f->tex->texel_bytes, line = (size_t)side * tb;
    const size_t rb = (size_t)f->plan.nchan * (f->plan.read_as == IO_HALF ? 2 : 4);
    unsigned char *buf;
    ts_tile *t;
    int w, h, j;
    sample_status st = ts_reader_acquire(f, err);
    if (st != SAMPLE_OK) return NULL;
    tile_extent(f, lv, tx, ty, &w, &h);
    t = ts_tile_alloc(f, lv, slot, tile_px_bytes(f), w < side || h < side);
    if (!t) {
        sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a tile of '%s' under the memory limit", f->path);
        return NULL;
    }
    if (f->exr && plan_is_identity(f)) {
        st = io_exr_tile_read(f->exr, lv, tx, ty, w, h, ts_px(t), tb, line, err);
    } else {
        const size_t n = (size_t)w * (size_t)h;
        buf = (unsigned char *)malloc(n * (size_t)f->plan.nchan * 4);
        if (!buf)
            st = sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate %zu bytes to read a tile",
                                  n * (size_t)f->plan.nchan * 4);
        else if (f->exr)
            st = io_exr_tile_read(f->exr, lv, tx, ty, w, h, buf, rb, rb * (size_t)w, err);
        else
            st = io_reader_read_tiles(f->reader, lv, i0, j0, i0 + w, j0 + h, f->plan.read_as, f->plan.nchan, buf,
                                      err);
        if (st == SAMPLE_OK) st = io_plan_apply(f->h.sys->col, &f->plan, buf, n, err);
        for (j = 0; st == SAMPLE_OK && j < h; ++j)
            memcpy(ts_px(t) + (size_t)j * line, buf + (size_t)j * (size_t)w * tb, (size_t)w * tb);
        free(buf);
    }
    if (st != SAMPLE_OK) {
        ts_tile_discard(f, t);
        return NULL;
    }
    ts_publish(f, t, tb, f->exr != NULL);
    return t;
}

/* The slot was empty: load the tile (one loader per file at a time), or
 * mark it failed. */
static SAMPLE_NOINLINE ts_tile *ts_miss(ts_file *f, int lv, int tx, int ty, size_t slot)
{
    sample_texsys *sys = f->h.sys;
    sample_error err;
    ts_tile *t;
    pthread_mutex_lock(&sys->lock);
    sys->st.misses++;
    pthread_mutex_unlock(&sys->lock);
    ts_lock_take(&f->io_lock);
    t = atomic_load_explicit(&f->slots[lv][slot], memory_order_acquire);
    if (!t) {
        memset(&err, 0, sizeof err);
        t = f->file_tiled ? load_tile(f, lv, tx, ty, slot, &err) : load_whole(f, lv, tx, ty, &err);
        if (!t) {
            ts_record_error(f, &err);
            t = &ts_failed;
            atomic_store_explicit(&f->slots[lv][slot], t, memory_order_release);
        }
    }
    ts_unlock(&f->io_lock);
    return t;
}

static const unsigned char *ts_texel(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    ts_file *f = (ts_file *)(uintptr_t)src; /* the cache changes behind a const source */
    const int b = f->log2, m = (1 << b) - 1;
    const size_t slot = (size_t)(j >> b) * (size_t)f->ntx[lv] + (size_t)(i >> b);
    ts_tile *t = atomic_load_explicit(&f->slots[lv][slot], memory_order_acquire);
    (void)layer; /* 2D files */
    if (SAMPLE_LIKELY(t != NULL)) {
        atomic_uchar *ref = &f->refs[lv][slot];
        if (!atomic_load_explicit(ref, memory_order_relaxed)) atomic_store_explicit(ref, 1, memory_order_relaxed);
    } else {
        t = ts_miss(f, lv, i >> b, j >> b, slot);
    }
    if (t == &ts_failed) return NULL;
    return ts_px(t) + (((size_t)(j & m) << b) + (size_t)(i & m)) * f->tex->texel_bytes;
}

/* The texture's destroy hook does nothing: the system owns the file. */
static void ts_source_destroy(struct ls_texel_source *src) { (void)src; }

sample_status io_ts_file_source_init(ts_file *f, sample_error *err)
{
    const int side = 1 << f->log2;
    uint64_t table = 0;
    int lv;
    f->h.base.texel = ts_texel;
    f->h.base.destroy = ts_source_destroy;
    f->h.base.reads_begin = io_ts_reads_begin;
    f->h.base.reads_end = io_ts_reads_end;
    /* ts_texel's layout: every tile is side × side texels, row after row,
     * at the level's edge too, so the fast path addresses within it
     * (texel.h, tile_side). */
    f->h.base.tile_side = side;
    memcpy(f->h.base.fill, f->h.sys->o.fill, sizeof f->h.base.fill);
    for (lv = 0; lv < f->tex->nlevels; ++lv) {
        const struct sample_level *L = &f->tex->level[lv];
        f->ntx[lv] = (L->w + side - 1) / side;
        f->nty[lv] = (L->h + side - 1) / side;
        table += (uint64_t)f->ntx[lv] * (uint64_t)f->nty[lv] * (sizeof *f->slots[lv] + sizeof *f->refs[lv]);
    }
    /* The table of tile pointers lies outside the limit: one larger than
     * the whole cache (65536² in tiles of 4 would need 2 GiB) is refused
     * rather than allocated. */
    RETURN_ERROR_IF(table > f->h.sys->limit, err, SAMPLE_E_TOO_LARGE,
                    "'%s': its table of %llu tiles of %d texels a side needs %llu bytes, more than the cache's %zu",
                    f->path, (unsigned long long)(table / (sizeof *f->slots[0] + sizeof *f->refs[0])), side, (unsigned long long)table,
                    f->h.sys->limit);
    for (lv = 0; lv < f->tex->nlevels; ++lv) {
        f->slots[lv] = (_Atomic(ts_tile *) *)calloc((size_t)f->ntx[lv] * (size_t)f->nty[lv], sizeof *f->slots[lv]);
        f->refs[lv] = (atomic_uchar *)calloc((size_t)f->ntx[lv] * (size_t)f->nty[lv], sizeof *f->refs[lv]);
        RETURN_ERROR_IF(!f->slots[lv] || !f->refs[lv], err, SAMPLE_E_OUT_OF_MEMORY,
                        "cannot allocate the tile table of '%s'", f->path);
    }
    return SAMPLE_OK;
}

/* Its tiles (resident ones leave the ring), tables, reader, texture. */
void io_ts_file_free(ts_file *f)
{
    sample_texsys *sys = f->h.sys;
    int lv;
    size_t k;
    for (lv = 0; lv < SAMPLE_MAX_LEVELS; ++lv) {
        free(f->refs[lv]);
        if (!f->slots[lv]) continue;
        for (k = 0; k < (size_t)f->ntx[lv] * (size_t)f->nty[lv]; ++k) {
            ts_tile *t = atomic_load_explicit(&f->slots[lv][k], memory_order_relaxed);
            if (!t || t == &ts_failed) continue;
            ring_remove(sys, t);
            sys->resident -= t->bytes;
            free(t);
        }
        free(f->slots[lv]);
    }
    if (f->open) sys->open_files--;
    io_reader_close(f->reader);
    io_exr_tile_close(f->exr);
    if (f->tex) sample_texture_destroy(f->tex);
    ts_lock_destroy(&f->io_lock);
    free(f->path);
    free(f);
}

void io_texsys_fail_allocs(sample_texsys *sys, int n)
{
    pthread_mutex_lock(&sys->lock);
    sys->fail_allocs = n;
    pthread_mutex_unlock(&sys->lock);
}
