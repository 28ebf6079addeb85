/*
 * The texture system's direct OpenEXR tile reader (exr_tile.h). The
 * OpenEXR core C library (OpenEXR 3.1, "OpenEXRCore" in its documentation)
 * decodes one chunk per call on the caller's thread: no C++ thread pool
 * woken per tile, no intermediate frame buffer, one pread per chunk. Only the layout exr_read.cpp takes is taken here — one
 * tiled part, MIPMAP_LEVELS, ROUND_DOWN, channels exactly a prefix of R,
 * G, B, A of one type — and the texels come out as OpenImageIO's reader
 * gives them: channels in R, G, B, A order, half kept or widened to float
 * exactly.
 */
#include "exr_tile.h"
#include "texel.h" /* the levels of a sample_texture */

#include <OpenEXR/openexr.h>

#include <stdlib.h>

struct io_exr_tile {
    exr_context_t ctx;
    char *path;
    int nchan;
    exr_pixel_type_t type; /* the channels' type in the file */
    size_t bytes;          /* its size: 2 or 4 */
    int widen;             /* 1: half in the file, read as float */
    /* One decoding pipeline kept from tile to tile, so that its buffers
     * are reused (exr_decoding_update) rather than allocated per tile. */
    exr_decode_pipeline_t d;
    int has_d;
};

/* The core library reports a failure's detail through the context's error
 * handler before the call returns (openexr_context.h, error_handler_fn);
 * each thread keeps its own last message, so that loads of different
 * files on other threads do not mix theirs in. */
static _Thread_local char last_message[256];

static void keep_message(exr_const_context_t ctx, exr_result_t code, const char *msg)
{
    (void)ctx;
    snprintf(last_message, sizeof last_message, "%s", msg ? msg : exr_get_default_error_message(code));
}

/* The channel index in R, G, B, A order, −1 for any other name. */
static int rgba_index(const char *name)
{
    static const char *const names[4] = {"R", "G", "B", "A"};
    int c;
    for (c = 0; c < 4; ++c)
        if (!strcmp(name, names[c])) return c;
    return -1;
}

/* Channels exactly a prefix of R, G, B, A (the core lists them sorted by
 * name), full resolution, all half or all float; their count, else 0. */
static int plain_rgba(const exr_attr_chlist_t *cl, exr_pixel_type_t *type)
{
    int seen = 0, k;
    if (cl->num_channels < 1 || cl->num_channels > 4) return 0;
    for (k = 0; k < cl->num_channels; ++k) {
        const exr_attr_chlist_entry_t *e = &cl->entries[k];
        const int c = e->name.str ? rgba_index(e->name.str) : -1;
        if (c < 0 || c >= cl->num_channels || (seen & (1 << c))) return 0;
        if (e->x_sampling != 1 || e->y_sampling != 1) return 0;
        if (e->pixel_type != EXR_PIXEL_HALF && e->pixel_type != EXR_PIXEL_FLOAT) return 0;
        if (k > 0 && e->pixel_type != *type) return 0;
        *type = e->pixel_type;
        seen |= 1 << c;
    }
    return cl->num_channels;
}

/* Does part 0 of x->ctx hold tex's levels in tiles of `side`, channels
 * decodable as plan asks? */
static int eligible(io_exr_tile *x, const sample_texture *tex, int side, const io_plan *plan)
{
    const exr_attr_chlist_t *cl = NULL;
    exr_storage_t storage;
    exr_tile_level_mode_t mode;
    exr_tile_round_mode_t round;
    exr_pixel_type_t type = EXR_PIXEL_HALF;
    uint32_t tw, th;
    int32_t nlx, nly;
    int parts, lv;
    if (exr_get_count(x->ctx, &parts) != EXR_ERR_SUCCESS || parts != 1) return 0;
    if (exr_get_storage(x->ctx, 0, &storage) != EXR_ERR_SUCCESS || storage != EXR_STORAGE_TILED) return 0;
    if (exr_get_tile_descriptor(x->ctx, 0, &tw, &th, &mode, &round) != EXR_ERR_SUCCESS) return 0;
    if (mode != EXR_TILE_MIPMAP_LEVELS || round != EXR_TILE_ROUND_DOWN) return 0;
    if (tw != (uint32_t)side || th != (uint32_t)side) return 0;
    if (exr_get_tile_levels(x->ctx, 0, &nlx, &nly) != EXR_ERR_SUCCESS || nlx != nly || nlx < tex->nlevels) return 0;
    for (lv = 0; lv < tex->nlevels; ++lv) {
        int32_t w, h;
        if (exr_get_level_sizes(x->ctx, 0, lv, lv, &w, &h) != EXR_ERR_SUCCESS) return 0;
        if (w != tex->level[lv].w || h != tex->level[lv].h) return 0;
    }
    if (exr_get_channels(x->ctx, 0, &cl) != EXR_ERR_SUCCESS || !cl) return 0;
    x->nchan = plain_rgba(cl, &type);
    if (x->nchan == 0 || x->nchan != plan->nchan) return 0;
    /* Half kept, half widened to float, float kept: exact, as OpenImageIO
     * converts. Float narrowed to half is the plan's (io_plan_apply). */
    x->type = type;
    x->bytes = type == EXR_PIXEL_HALF ? 2 : 4;
    x->widen = type == EXR_PIXEL_HALF && plan->read_as == IO_FLOAT;
    return plan->read_as == IO_FLOAT || (plan->read_as == IO_HALF && type == EXR_PIXEL_HALF);
}

sample_status io_exr_tile_open(const char *path, const sample_texture *tex, int log2, const io_plan *plan,
                               io_exr_tile **out, sample_error *err)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    io_exr_tile *x;
    *out = NULL;
    x = (io_exr_tile *)calloc(1, sizeof *x);
    if (x) x->path = io_strdup(path);
    if (!x || !x->path) {
        free(x);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate an OpenEXR tile reader");
    }
    init.error_handler_fn = keep_message;
    /* A header the core cannot parse is OpenImageIO's to report, as
     * exr_read.cpp leaves it; a file whose chunk table is damaged fails
     * per tile rather than being searched for its chunks. */
    init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE | EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    if (exr_start_read(&x->ctx, path, &init) != EXR_ERR_SUCCESS || !eligible(x, tex, 1 << log2, plan)) {
        io_exr_tile_close(x);
        return SAMPLE_OK;
    }
    *out = x;
    return SAMPLE_OK;
}

/* Half to float in place, pixel by pixel: channel c's float (bytes 4c to
 * 4c + 3) is written after the halves it covers (2c and up) were read,
 * the last channel first. Exact, as every half is a float. */
static void widen(unsigned char *dst, int w, int h, int nchan, size_t pixel, size_t line)
{
    int i, j, c;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            unsigned char *p = dst + (size_t)j * line + (size_t)i * pixel;
            for (c = nchan - 1; c >= 0; --c) {
                uint16_t hv;
                float f;
                memcpy(&hv, p + 2 * c, 2);
                f = sample_half_to_float(hv);
                memcpy(p + 4 * c, &f, 4);
            }
        }
}

sample_status io_exr_tile_read(io_exr_tile *x, int lv, int tx, int ty, int w, int h, unsigned char *dst,
                               size_t pixel, size_t line, sample_error *err)
{
    exr_decode_pipeline_t *d = &x->d;
    exr_chunk_info_t ci;
    exr_result_t rv;
    int c;
    last_message[0] = '\0';
    rv = exr_read_tile_chunk_info(x->ctx, 0, tx, ty, lv, lv, &ci);
    /* The chunk's size comes from the header the level sizes were checked
     * against, its offset from the file: both checked before a byte is
     * written to dst. */
    if (rv == EXR_ERR_SUCCESS && (ci.width != w || ci.height != h)) {
        snprintf(last_message, sizeof last_message, "the chunk is %d x %d texels, the tile %d x %d", ci.width,
                 ci.height, w, h);
        rv = EXR_ERR_CORRUPT_CHUNK;
    }
    if (rv == EXR_ERR_SUCCESS && x->has_d) {
        rv = exr_decoding_update(x->ctx, 0, &ci, d);
    } else if (rv == EXR_ERR_SUCCESS) {
        rv = exr_decoding_initialize(x->ctx, 0, &ci, d);
        x->has_d = rv == EXR_ERR_SUCCESS;
    }
    for (c = 0; rv == EXR_ERR_SUCCESS && c < d->channel_count; ++c) {
        exr_coding_channel_info_t *ch = &d->channels[c];
        const int k = rgba_index(ch->channel_name);
        if (k < 0 || k >= x->nchan || ch->width != w || ch->height != h) {
            snprintf(last_message, sizeof last_message, "channel '%s' does not fit the tile", ch->channel_name);
            rv = EXR_ERR_CORRUPT_CHUNK;
            break;
        }
        /* The texels as stored, at the start of each pixel: OpenEXR
         * 3.1.5's half-to-float unpackers for channels in reverse order
         * (the file lists A, B, G, R) swap the channels, so half is
         * widened below instead. */
        ch->decode_to_ptr = dst + (size_t)k * x->bytes;
        ch->user_pixel_stride = (int32_t)pixel;
        ch->user_line_stride = (int32_t)line;
        ch->user_bytes_per_element = (int16_t)x->bytes;
        ch->user_data_type = (uint16_t)x->type;
    }
    /* The routines depend on where the texels go: chosen again per tile. */
    if (rv == EXR_ERR_SUCCESS) rv = exr_decoding_choose_default_routines(x->ctx, 0, d);
    if (rv == EXR_ERR_SUCCESS) rv = exr_decoding_run(x->ctx, 0, d);
    if (rv == EXR_ERR_SUCCESS && x->widen) widen(dst, w, h, x->nchan, pixel, line);
    if (rv == EXR_ERR_SUCCESS) return SAMPLE_OK;
    /* After a failure the pipeline starts afresh. */
    exr_decoding_destroy(x->ctx, d);
    x->has_d = 0;
    if (rv == EXR_ERR_OUT_OF_MEMORY)
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "'%s': out of memory decoding tile (%d, %d) of level %d",
                                x->path, tx, ty, lv);
    return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s': cannot read tile (%d, %d) of level %d: %s", x->path, tx, ty,
                            lv, last_message[0] ? last_message : exr_get_default_error_message(rv));
}

void io_exr_tile_close(io_exr_tile *x)
{
    if (!x) return;
    if (x->has_d) exr_decoding_destroy(x->ctx, &x->d);
    if (x->ctx) exr_finish(&x->ctx);
    free(x->path);
    free(x);
}
