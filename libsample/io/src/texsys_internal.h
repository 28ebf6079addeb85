/*
 * The texture system's pieces (doc/texture-system.md):
 *
 *   texsys.c       the system: options, open, info, stats, errors
 *   texsys_cache.c the tile cache: a texel source per file, tile loads,
 *                  clock eviction under the memory limit, the open-file
 *                  limit, and the epochs that keep evicted tiles alive
 *                  until no batch can still read them
 *   texsys_udim.c  UDIM sets: names, and one virtual texture of tiles
 *   exr_tile.c     the direct OpenEXR tile reader (exr_tile.h)
 *
 * A texture of the system is a sample_texture (libsample/src/texel.h)
 * whose texel source is a ts_file (or a ts_udim): libsample's filters
 * read it through struct ls_texel_source, as they read tiled.c's tiles.
 *
 * Locks: sys->lock guards the clock ring, the memory counts, the epochs,
 * the open-file count, the error records and the stats; a file's io_lock
 * guards its reader and serializes its tile loads. Order: io_lock, then
 * sys->lock; another file's io_lock is only ever try-locked (closing it
 * for the open-file limit). Slots are atomic pointers: readers load them
 * without a lock.
 */
#ifndef SAMPLE_TEXSYS_INTERNAL_H
#define SAMPLE_TEXSYS_INTERNAL_H

#include "io_internal.h"
#include "sample/texsys.h"
#include "texel.h" /* libsample's texel source interface */

#include <pthread.h>
#include <stdatomic.h>

/* Tiles of files read whole (section 2 of texsys.h): 64 texels a side,
 * OpenImageIO's default tile. */
#define TS_AUTOTILE_LOG2 6

typedef struct ts_file ts_file;

/* The longest colour space name an open may give, terminator included. */
#define TS_COLORSPACE_MAX 128

/* A first-come, first-served lock (a ticket lock over a mutex and a
 * condition): a thread that misses waits behind at most one load per
 * other thread. With an unfair mutex one thread can load tile after tile
 * while another, its batch's epoch still open, waits — and every tile the
 * first evicts meanwhile stays allocated (doc/texture-system.md,
 * "Memory"). */
typedef struct ts_lock {
    pthread_mutex_t m;
    pthread_cond_t c;
    unsigned long next, serving;
} ts_lock;
void io_ts_lock_init(ts_lock *l); /* the rest is texsys_cache.c's */

/* What every texture of a system has first: its texel source, the system
 * (the epoch hooks find it here) and whether it is a UDIM set. */
typedef struct ts_head {
    struct ls_texel_source base; /* first: the texture points at it */
    sample_texsys *sys;
    int udim;
} ts_head;

typedef struct ts_tile {
    struct ts_tile *prev, *next; /* the clock ring (sys->lock) */
    struct ts_tile *retired;     /* the retired list of its epoch */
    ts_file *file;
    int lv;
    size_t slot;  /* index in file->slots[lv] */
    size_t bytes; /* what it counts against the limit */
} ts_tile;

/* A tile's 2^log2 × 2^log2 texels, row after row, follow its header in
 * one allocation; a hit computes their address, so that it touches no
 * line of the tile but the texels it reads. */
static inline unsigned char *ts_px(ts_tile *t) { return (unsigned char *)(t + 1); }

struct ts_file {
    ts_head h; /* first */
    sample_texture *tex;
    char *path;
    int log2;       /* cache tiles are 2^log2 texels a side */
    int file_tiled; /* 1: tiles read from the file; 0: read whole */
    int ntx[SAMPLE_MAX_LEVELS], nty[SAMPLE_MAX_LEVELS];
    _Atomic(ts_tile *) *slots[SAMPLE_MAX_LEVELS]; /* NULL: absent */
    /* The clock's reference bits, one a slot, beside the slots rather
     * than in the tiles: a hit sets its bit without loading a line of the
     * tile's header (a cache miss on a cold tile, before the texels' own). */
    atomic_uchar *refs[SAMPLE_MAX_LEVELS];
    io_reader_info inf;
    io_plan plan;
    /* The colour space texels are decoded from: the open's, else the
     * system's option; NULL: the file's own (sample_io.h section 2). */
    const char *colorspace;
    char colorspace_own[TS_COLORSPACE_MAX];
    int has_wrap;
    sample_wrap wrap_s, wrap_t;
    ts_lock io_lock;
    /* The file's tiles come through one of two readers (doc/texture-system.md,
     * "Files"): the direct OpenEXR tile reader (exr_tile.h) where it takes
     * the file, else OpenImageIO's. Either counts as the file open. */
    io_reader *reader;  /* io_lock; NULL: closed */
    struct io_exr_tile *exr; /* io_lock; NULL: closed or not taken */
    int exr_refused;    /* io_lock: the direct reader did not take it */
    int open;           /* sys->lock: counted among the open files */
    uint64_t last_open; /* sys->lock: when its reader was last used */
    unsigned long nerrors;   /* sys->lock */
    sample_error first_error; /* sys->lock */
    ts_file *next;            /* the system's list */
};

/* The running batches' counts are split into stripes, one per thread
 * (up to TS_STRIPES threads; more share), each alone in its cache line:
 * a count every batch of every thread adds to and takes from would be the
 * one line all threads write, moved between cores at every batch
 * (doc/texture-system.md, "The cache"). A stripe fills 2 lines so that no
 * two stripes share one whatever the struct's alignment. */
#define TS_LINE 64
#define TS_STRIPES 16
typedef struct ts_stripe {
    atomic_ulong n[2]; /* batches of this stripe, by ticket parity */
    char pad[2 * TS_LINE - 2 * sizeof(atomic_ulong)];
} ts_stripe;

struct sample_texsys {
    sample_texsys_options o;
    char *ocio_config, *colorspace; /* the options' strings, owned */
    size_t limit;                   /* bytes */
    io_colour *col;
    pthread_mutex_t lock;
    pthread_mutex_t open_lock; /* one open at a time: a name opens once */
    ts_tile *hand; /* the clock's hand; NULL: no tile resident */
    size_t resident, retired_bytes;
    ts_tile *retired[2];     /* tiles evicted in epochs of each parity */
    /* The epochs (texsys_cache.c): a batch takes its ticket and counts
     * itself without the lock; the epoch moves, and retired_any changes,
     * under it. epoch and retired_any are read by every batch and written
     * rarely; the counts are written by every batch, so each thread counts
     * in a stripe of its own, a cache line apart from the others and from
     * these two. */
    char pad_epoch[TS_LINE];
    _Atomic uint64_t epoch;    /* batches begun now get this ticket */
    atomic_int retired_any;    /* a retired list is not empty */
    char pad_active[TS_LINE];
    ts_stripe active[TS_STRIPES]; /* running batches, by ticket parity */
    uint64_t clock;          /* open-file recency */
    int open_files;
    sample_texsys_stats st;
    int fail_allocs; /* tests: the next n tile allocations fail */
    ts_file *files;
    struct ts_udim *udims;
    struct ts_whole *wholes;
};

/* texsys_cache.c */
/* Fill a file's source: its hooks, fill colour and tile tables for the
 * levels of f->tex. */
sample_status io_ts_file_source_init(ts_file *f, sample_error *err);
void io_ts_file_free(ts_file *f);
/* The epoch hooks every texture of a system shares. */
uintptr_t io_ts_reads_begin(const struct ls_texel_source *src);
void io_ts_reads_end(const struct ls_texel_source *src, uintptr_t ticket);
/* Free every retired tile (no batch may be running). */
void io_ts_cache_drain(sample_texsys *sys);

/* texsys.c: sample_batch over chunks of TS_CHUNK queries, each its own
 * epoch ticket, so that tiles evicted while a long batch runs are freed
 * as it goes rather than at its end (doc/texture-system.md, "Memory").
 * map, when given, rewrites chunk b (queries from i0 of a) before it is
 * sampled, and is called again with i0 = SIZE_MAX after. */
#define TS_CHUNK 16
sample_status io_ts_batch_chunks(const sample_texture *tex, const sample_sampler *s, const sample_batch_args *a,
                              void (*map)(void *ctx, sample_batch_args *b, size_t i0), void *ctx);
/* texsys.c: open a plain file (no UDIM pattern) decoded from colour space
 * cs (NULL: the system's option, else the file's), or return it if open. */
sample_status io_ts_open_file(sample_texsys *sys, const char *path, const char *cs, ts_file **out,
                              sample_error *err);
/* texsys.c: 1 if colour space names a and b (either NULL) are the same. */
int io_ts_same_colorspace(const char *a, const char *b);

/* texsys_udim.c */
typedef struct ts_udim ts_udim;
/* 1 if `name` holds a UDIM pattern. */
int io_ts_udim_pattern(const char *name);
sample_status io_ts_udim_open(sample_texsys *sys, const char *name, const char *cs, const sample_texture **out,
                              sample_error *err);
/* The set `tex` is, or NULL. */
ts_udim *io_ts_udim_of(const sample_texsys *sys, const sample_texture *tex);
void io_ts_udim_info(const ts_udim *u, sample_texsys_info *info);
sample_status io_ts_udim_batch(ts_udim *u, const sample_sampler *s, const sample_batch_args *a);
/* Failures of the set's files (sys->lock held), the first into *first. */
unsigned long io_ts_udim_errors(const ts_udim *u, sample_error *first);
void io_ts_udim_free_all(sample_texsys *sys);

/* texsys_kinds.c: cube maps and volumes, read whole (doc/texture-system.md,
 * "Cube maps and volumes"). io_ts_whole_open opens `path` as one if it is
 * one (*out set), leaves *out NULL if it is not (a 2D texture, or no image
 * at all: the 2D path says why), or fails reading it. open_lock held. */
typedef struct ts_whole ts_whole;
sample_status io_ts_whole_open(sample_texsys *sys, const char *path, const char *cs, const sample_texture **out,
                               sample_error *err);
/* The cube or volume `tex` is, or NULL. */
ts_whole *io_ts_whole_of(const sample_texsys *sys, const sample_texture *tex);
void io_ts_whole_info(const ts_whole *w, sample_texsys_info *info);
void io_ts_whole_free_all(sample_texsys *sys);
/* texsys_probe.cpp: 1 if OpenImageIO reads path as a volume
 * (sample_io_read_volume's rule: depth > 1, or subimages of one size). */
int io_ts_probe_volume(const char *path);

/* Tests (texsys_cache.c): the next n tile allocations of sys fail. */
void io_texsys_fail_allocs(sample_texsys *sys, int n);

#endif
