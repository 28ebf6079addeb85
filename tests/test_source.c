/*
 * Texel sources (libsample/src/texel.h, struct ls_texel_source): a texture
 * whose levels are held as tiles in memory of their own (tiled.c, the shape
 * a tile cache holds) is sampled through the same filters as the resident
 * texture it was copied from, and must give its results bit for bit —
 * values, derivatives and stats — for every format × channel count, wrap
 * mode, OpenGL filter and footprint filter, on tiles of 1, 4 and 8 texels
 * a side over levels that end in partial tiles. A tile the source cannot
 * supply reads as its fill colour: exact values by hand, and the fast
 * path's reads of a source with missing tiles the reference path's bits.
 * The fast path addresses a block inside one tile with one texel() call
 * (texel.h, tile_side), and consecutive blocks in one tile with one call
 * a batch (ls_tile_memo): counted. Blinn–Newell and EWA read a row's
 * pieces inside tiles with one texel() call each (ls_fp_span_tiles):
 * long footprints across tile and level edges under every wrap, and
 * missing tiles, against the resident bits; the calls counted.
 */
#include "check.h"
#include "query_gen.h"
#include "sample/testing.h"
#include "texel.h" /* struct ls_texel_source: texel() calls counted */

enum { NQ = 160 };

static sample_query qs[NQ];
static float rgba[2][NQ * 4], dds[2][NQ * 4], ddt[2][NQ * 4];
static sample_stats stats[2][NQ];

/* Results slot k: values, derivatives and stats (`all`), or values alone
 * (the fast path then reads anisotropic probes from addresses planned
 * ahead, fast_gl.c aniso_read); through the reference path if `ref`. */
static void sample_some(const sample_texture *tex, const sample_sampler *s, int k, int all, int ref)
{
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    memset(rgba[k], 0xA5, sizeof rgba[k]);
    memset(dds[k], 0xA5, sizeof dds[k]);
    memset(ddt[k], 0xA5, sizeof ddt[k]);
    memset(stats[k], 0xA5, sizeof stats[k]);
    a.count = NQ;
    a.queries = qs;
    a.rgba = rgba[k];
    a.drgba_ds = all ? dds[k] : NULL;
    a.drgba_dt = all ? ddt[k] : NULL;
    a.stats = all ? stats[k] : NULL;
    CHECK((ref ? sample_batch_reference(tex, s, &a) : sample_batch(tex, s, &a)) == SAMPLE_OK, "sample_batch");
}


static int same_results(void)
{
    return !memcmp(rgba[0], rgba[1], sizeof rgba[0]) && !memcmp(dds[0], dds[1], sizeof dds[0]) &&
           !memcmp(ddt[0], ddt[1], sizeof ddt[0]) && !memcmp(stats[0], stats[1], sizeof stats[0]);
}

static void fill_queries(int inside)
{
    int i;
    for (i = 0; i < NQ; ++i) {
        qs[i].s = inside ? frand(0.1f, 0.9f) : coord();
        qs[i].t = inside ? frand(0.1f, 0.9f) : coord();
        qs[i].dsdx = deriv();
        qs[i].dtdx = deriv();
        qs[i].dsdy = deriv();
        qs[i].dtdy = deriv();
    }
}

static void test_tiled_same_bits(void)
{
    static const int tiles[3] = {0, 2, 3};
    int f, nc, tl, filt, configs = 0, fails = 0;
    for (f = 0; f < SAMPLE_FORMAT_COUNT; ++f)
        for (nc = 1; nc <= 4; ++nc) {
            /* 37 × 23: every level ends in a partial tile. */
            sample_texture *tex = make_texture((sample_format)f, nc, 37, 23);
            for (tl = 0; tl < 3; ++tl) {
                sample_texture *tiled = NULL;
                sample_error err;
                CHECK(sample_texture_tiled_copy(tex, tiles[tl], &tiled, &err) == SAMPLE_OK, "tiled copy: %s",
                      err.message);
                /* The nine OpenGL filters, then anisotropic, Blinn–Newell and EWA. */
                for (filt = 0; filt < KIND_SAMPLERS; ++filt) {
                    sample_sampler s;
                    kind_sampler(&s, filt);
                    fill_queries(configs & 1);
                    sample_some(tex, &s, 0, !(configs & 2), 0);
                    sample_some(tiled, &s, 1, !(configs & 2), 0);
                    ++configs;
                    if (!same_results()) {
                        if (++fails <= 10)
                            fprintf(stderr, "differs: %s x%d, tiles of %d, filter %s footprint %s, wraps %s %s\n",
                                    sample_format_name((sample_format)f), nc, 1 << tiles[tl],
                                    sample_filter_name(s.min_filter), sample_footprint_name(s.footprint),
                                    sample_wrap_name(s.wrap_s), sample_wrap_name(s.wrap_t));
                    }
                }
                sample_texture_destroy(tiled);
            }
            sample_texture_destroy(tex);
        }
    CHECK(fails == 0, "%d of %d configurations differ between resident and tiled texels", fails, configs);
}

/* An 8 × 8 texture of 1.0 in tiles of 4 × 4, tile (1, 0) dropped with fill
 * (3, 3, 3, 3): its texels read as 3, the others as 1, and a bilinear read
 * across the tile edge blends them (GL 4.6 eq. 8.13). */
static void test_missing_tile_reads_fill(void)
{
    float data[8 * 8 * 4], out[4];
    const float fill[4] = {3.0f, 3.0f, 3.0f, 3.0f};
    sample_image im = {8, 8, 4, SAMPLE_FORMAT_F32, data, 0};
    sample_texture *tex = NULL, *tiled = NULL;
    sample_texture_info info;
    sample_sampler s;
    sample_query q = {0};
    int k;
    for (k = 0; k < 8 * 8 * 4; ++k) data[k] = 1.0f;
    CHECK(sample_texture_create(&im, NULL, &tex, NULL) == SAMPLE_OK, "create");
    CHECK(sample_texture_tiled_copy(tex, 2, &tiled, NULL) == SAMPLE_OK, "tiled copy");
    sample_texture_info_get(tiled, &info);
    CHECK(info.kind == SAMPLE_TEXTURE_2D && info.width == 8 && info.levels == 1, "info of the tiled copy");
    CHECK(sample_texture_tile_drop(tiled, 0, 1, 0, fill) == SAMPLE_OK, "drop");
    CHECK(sample_texture_tile_drop(tiled, 0, 2, 0, fill) == SAMPLE_E_INVALID_ARGUMENT, "no tile (2, 0)");
    CHECK(sample_texture_tile_drop(tex, 0, 0, 0, fill) == SAMPLE_E_INVALID_ARGUMENT, "resident: nothing to drop");
    sample_sampler_init(&s);
    s.min_filter = s.mag_filter = SAMPLE_NEAREST;
    q.s = 5.5f / 8.0f; /* texel (5, 1): tile (1, 0) */
    q.t = 1.5f / 8.0f;
    CHECK(sample_one(tiled, &s, &q, out) == SAMPLE_OK && out[0] == 3.0f && out[3] == 3.0f, "fill: %g", out[0]);
    q.s = 1.5f / 8.0f;
    CHECK(sample_one(tiled, &s, &q, out) == SAMPLE_OK && out[0] == 1.0f, "texel (1, 1): %g", out[0]);
    q.t = 5.5f / 8.0f;
    q.s = 5.5f / 8.0f; /* tile (1, 1) is there */
    CHECK(sample_one(tiled, &s, &q, out) == SAMPLE_OK && out[0] == 1.0f, "texel (5, 5): %g", out[0]);
    s.mag_filter = SAMPLE_LINEAR;
    q.s = 4.0f / 8.0f; /* halfway between texels 3 and 4 of row 1 */
    q.t = 1.5f / 8.0f;
    CHECK(sample_one(tiled, &s, &q, out) == SAMPLE_OK && out[0] == 2.0f, "blend across the edge: %g", out[0]);
    sample_texture_destroy(tiled);
    sample_texture_destroy(tex);
}

/* Tiles missing on levels 0 and 1 (their texels the fill colour): the fast
 * path, which reads blocks in a missing tile and blocks across tile edges
 * through the source, gives the reference path's bits for every format,
 * filter and wrap, with and without derivatives. */
static void test_missing_tiles_fast_path(void)
{
    static const float fill[4] = {0.125f, 2.0f, -1.0f, 0.5f};
    int f, nc, k, configs = 0, fails = 0;
    for (f = 0; f < SAMPLE_FORMAT_COUNT; ++f)
        for (nc = 1; nc <= 4; ++nc) {
            sample_texture *tex = make_texture((sample_format)f, nc, 37, 23), *tiled = NULL;
            CHECK(sample_texture_tiled_copy(tex, 2 + (nc & 1), &tiled, NULL) == SAMPLE_OK, "tiled copy");
            CHECK(sample_texture_tile_drop(tiled, 0, 1, 1, fill) == SAMPLE_OK &&
                      sample_texture_tile_drop(tiled, 0, 3, 0, fill) == SAMPLE_OK &&
                      sample_texture_tile_drop(tiled, 1, 0, 0, fill) == SAMPLE_OK,
                  "drop");
            for (k = 0; k < 2 * KIND_SAMPLERS; ++k) {
                sample_sampler s;
                kind_sampler(&s, k % KIND_SAMPLERS);
                fill_queries(k & 1);
                sample_some(tiled, &s, 0, k & 2, 1);
                sample_some(tiled, &s, 1, k & 2, 0);
                ++configs;
                if (!same_results() && ++fails <= 10)
                    fprintf(stderr, "missing tiles differ: %s x%d, filter %s footprint %s, wraps %s %s\n",
                            sample_format_name((sample_format)f), nc, sample_filter_name(s.min_filter),
                            sample_footprint_name(s.footprint), sample_wrap_name(s.wrap_s),
                            sample_wrap_name(s.wrap_t));
            }
            sample_texture_destroy(tiled);
            sample_texture_destroy(tex);
        }
    CHECK(fails == 0, "%d of %d configurations differ between the fast and the reference path", fails, configs);
}

/* The texel() calls of the texture under test, through a wrapper of its
 * source's hook. */
static const unsigned char *(*inner_texel)(const struct ls_texel_source *, int, int, int, int);
static unsigned long texel_calls;
static const unsigned char *counted_texel(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    ++texel_calls;
    return inner_texel(src, lv, i, j, layer);
}

/* A 64 × 64 texture in tiles of 8 (tile_side 8): bilinear reads whose
 * 2 × 2 block lies in one tile cost one texel() call on the fast path (the
 * block is addressed in the tile), four on the reference path; a block
 * across a tile's edge four on both; the same bits. */
static void test_one_call_per_block(void)
{
    sample_texture *tex = make_texture(SAMPLE_FORMAT_F16, 4, 64, 64), *tiled = NULL;
    sample_sampler s;
    int i;
    CHECK(sample_texture_tiled_copy(tex, 3, &tiled, NULL) == SAMPLE_OK, "tiled copy");
    CHECK(tiled->source->tile_side == 8, "tile side %d", tiled->source->tile_side);
    inner_texel = tiled->source->texel;
    tiled->source->texel = counted_texel;
    sample_sampler_init(&s);
    s.min_filter = s.mag_filter = SAMPLE_LINEAR;
    /* Query i at texel coordinates (x + 0.75, y + 0.25) (after the −½:
     * block (x, y) … (x + 1, y + 1)): x, y ≤ 6 inside a tile, 7 across. */
    for (i = 0; i < NQ; ++i) {
        int x = 8 * (i % 8) + (i % 7), y = 8 * ((i / 8) % 8) + (i % 5);
        memset(&qs[i], 0, sizeof qs[i]);
        qs[i].s = ((float)x + 0.75f) / 64.0f;
        qs[i].t = ((float)y + 0.75f) / 64.0f;
    }
    texel_calls = 0;
    sample_some(tiled, &s, 0, 1, 1);
    CHECK(texel_calls == 4 * NQ, "reference path: %lu texel() calls for %d blocks", texel_calls, NQ);
    texel_calls = 0;
    sample_some(tiled, &s, 1, 1, 0);
    CHECK(texel_calls == NQ, "fast path: %lu texel() calls for %d blocks inside a tile", texel_calls, NQ);
    CHECK(same_results(), "fast and reference paths differ");
    for (i = 0; i < NQ; ++i) qs[i].s = (8.0f * (float)(i % 8) + 7.75f) / 64.0f; /* columns 7 and 8: across */
    texel_calls = 0;
    sample_some(tiled, &s, 1, 1, 0);
    CHECK(texel_calls == 4 * NQ, "fast path: %lu texel() calls for %d blocks across a tile's edge", texel_calls,
          NQ);
    sample_some(tiled, &s, 0, 1, 1);
    CHECK(same_results(), "fast and reference paths differ across tile edges");
    tiled->source->texel = inner_texel;
    sample_texture_destroy(tiled);
    sample_texture_destroy(tex);
}

/* Bilinear reads of a 64 × 64 texture in tiles of 8 (REPEAT), in runs of
 * four queries whose blocks lie in one tile, every other run one period
 * to the right (s in [1, 2): its block repeated into the level, not
 * straddling its edge). The fast path reads a repeated block as one block
 * (fast_gl.c, axis_index) and asks the source once per run of blocks in
 * one tile (the batch's tile memo, ls_tile_memo): one texel() call per run
 * in one batch, one per run and batch in batches of two (the memo lives
 * for one batch); the reference path four per block; the same bits as the
 * resident texture's. */
static void test_one_call_per_tile_run(void)
{
    sample_texture *tex = make_texture(SAMPLE_FORMAT_F16, 4, 64, 64), *tiled = NULL;
    sample_sampler s;
    sample_batch_args a;
    int i;
    CHECK(sample_texture_tiled_copy(tex, 3, &tiled, NULL) == SAMPLE_OK, "tiled copy");
    inner_texel = tiled->source->texel;
    tiled->source->texel = counted_texel;
    sample_sampler_init(&s);
    s.min_filter = s.mag_filter = SAMPLE_LINEAR;
    for (i = 0; i < NQ; ++i) {
        const int r = i / 4, x = 8 * (r % 8) + i % 4, y = 8 * ((r / 8) % 8) + i % 3;
        memset(&qs[i], 0, sizeof qs[i]);
        qs[i].s = ((float)x + 0.75f) / 64.0f + (float)(r & 1);
        qs[i].t = ((float)y + 0.75f) / 64.0f;
    }
    sample_some(tex, &s, 0, 1, 0);
    texel_calls = 0;
    sample_some(tiled, &s, 1, 1, 0);
    CHECK(texel_calls == NQ / 4, "fast path: %lu texel() calls for %d runs of 4 blocks in a tile", texel_calls,
          NQ / 4);
    CHECK(same_results(), "tiled and resident textures differ");
    texel_calls = 0;
    sample_some(tiled, &s, 1, 1, 1);
    CHECK(texel_calls == 4 * NQ, "reference path: %lu texel() calls for %d blocks", texel_calls, NQ);
    CHECK(same_results(), "fast and reference paths differ");
    texel_calls = 0;
    memset(&a, 0, sizeof a);
    for (i = 0; i < NQ; i += 2) {
        a.count = 2;
        a.queries = qs + i;
        a.rgba = rgba[0] + 4 * i;
        CHECK(sample_batch(tiled, &s, &a) == SAMPLE_OK, "sample_batch");
    }
    CHECK(texel_calls == NQ / 2, "batches of 2: %lu texel() calls, %d wanted", texel_calls, NQ / 2);
    CHECK(!memcmp(rgba[0], rgba[1], sizeof rgba[0]), "batches of 2 differ");
    tiled->source->texel = inner_texel;
    sample_texture_destroy(tiled);
    sample_texture_destroy(tex);
}

/* Query i: an ellipse-like footprint (Jacobian columns a major and a
 * minor axis, eccentricity 1 to 16, the major axis 1/40 to 3/10 of the
 * texture, any direction) centred anywhere in [−0.3, 1.3]², so that rows
 * and columns cross many tile edges and the level's edges. */
static void fill_long_footprints(void)
{
    int i;
    for (i = 0; i < NQ; ++i) {
        const float a = frand(0.0f, 6.2831853f), major = frand(0.025f, 0.3f), minor = major / frand(1.0f, 16.0f);
        const float ca = cosf(a), sa = sinf(a);
        qs[i].s = frand(-0.3f, 1.3f);
        qs[i].t = frand(-0.3f, 1.3f);
        qs[i].dsdx = major * ca;
        qs[i].dtdx = major * sa;
        qs[i].dsdy = -minor * sa;
        qs[i].dtdy = minor * ca;
    }
}

/* Four wrap pairs that give each of REPEAT, CLAMP_TO_EDGE,
 * MIRRORED_REPEAT and CLAMP_TO_BORDER to both axes: pair k. */
static void wrap_pair(sample_sampler *s, int k)
{
    static const sample_wrap m[4] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRRORED_REPEAT,
                                     SAMPLE_WRAP_CLAMP_TO_BORDER};
    s->wrap_s = m[k & 3];
    s->wrap_t = m[(k + 1) & 3];
}

/* Blinn–Newell or EWA (k & 1) with wrap pair k / 2. */
static void span_sampler(sample_sampler *s, int k)
{
    sample_sampler_init(s);
    s->min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    s->footprint = k & 1 ? SAMPLE_FOOTPRINT_EWA : SAMPLE_FOOTPRINT_BLINN_NEWELL;
    wrap_pair(s, k / 2);
    s->border_color[0] = 0.25f;
    s->border_color[3] = 0.5f;
}

/* Blinn–Newell and EWA read each row of their footprint on a texture in
 * tiles piece by piece, one texel() call per piece inside a tile
 * (footprint.h, ls_fp_span_tiles): on a 64 × 48 texture (float, half
 * and 8-bit; float RGBA read in place) in tiles of 4 and 8, long
 * footprints across many tile edges and past the level's edges under
 * every wrap pair above, with and without derivatives, give the resident
 * texture's bits, and the texel() calls are fewer than half the texels
 * read (a texel at a time, they would be at least as many). */
static void test_footprint_spans_in_tiles(void)
{
    static const int fmt[3][2] = {{SAMPLE_FORMAT_F16, 4}, {SAMPLE_FORMAT_F32, 4}, {SAMPLE_FORMAT_UNORM8, 3}};
    unsigned long calls = 0, texels = 0;
    int f, tl, k, i, configs = 0, fails = 0;
    for (f = 0; f < 3; ++f) {
        sample_texture *tex = make_texture((sample_format)fmt[f][0], fmt[f][1], 64, 48);
        for (tl = 2; tl <= 3; ++tl) {
            sample_texture *tiled = NULL;
            CHECK(sample_texture_tiled_copy(tex, tl, &tiled, NULL) == SAMPLE_OK, "tiled copy");
            inner_texel = tiled->source->texel;
            tiled->source->texel = counted_texel;
            for (k = 0; k < 8; ++k) {
                sample_sampler s;
                span_sampler(&s, k);
                fill_long_footprints();
                sample_some(tex, &s, 0, k & 2, 0);
                texel_calls = 0;
                sample_some(tiled, &s, 1, k & 2, 0);
                if (k & 2) { /* with stats: the texels read */
                    calls += texel_calls;
                    for (i = 0; i < NQ; ++i) texels += stats[1][i].texels;
                }
                ++configs;
                if (!same_results() && ++fails <= 10)
                    fprintf(stderr, "spans in tiles differ: %s x%d, tiles of %d, footprint %s, wraps %s %s\n",
                            sample_format_name((sample_format)fmt[f][0]), fmt[f][1], 1 << tl,
                            sample_footprint_name(s.footprint), sample_wrap_name(s.wrap_s),
                            sample_wrap_name(s.wrap_t));
            }
            tiled->source->texel = inner_texel;
            sample_texture_destroy(tiled);
        }
        sample_texture_destroy(tex);
    }
    CHECK(fails == 0, "%d of %d configurations differ between resident and tiled spans", fails, configs);
    CHECK(texels > 0 && 2 * calls < texels, "%lu texel() calls for %lu texels read", calls, texels);
}

/* Tiles missing on levels 0 and 1 of a texture in tiles of 4: the
 * footprint filters read their texels as the fill colour, exactly as the
 * resident texture with those texels set to the fill colour reads them
 * (float and half RGBA: the fill is exact in both). */
static void test_footprint_spans_missing_tiles(void)
{
    static const float fill[4] = {0.125f, 2.0f, -1.0f, 0.5f};
    static const int drop[3][3] = {{0, 1, 1}, {0, 3, 0}, {1, 0, 0}}; /* level, tile x, tile y */
    int f, d, x, y, k, configs = 0, fails = 0;
    for (f = 0; f < 2; ++f) {
        const sample_format fm = f ? SAMPLE_FORMAT_F32 : SAMPLE_FORMAT_F16;
        sample_texture *tex = make_texture(fm, 4, 64, 48), *tiled = NULL;
        CHECK(sample_texture_tiled_copy(tex, 2, &tiled, NULL) == SAMPLE_OK, "tiled copy");
        for (d = 0; d < 3; ++d) {
            const struct sample_level *L = &tex->level[drop[d][0]];
            CHECK(sample_texture_tile_drop(tiled, drop[d][0], drop[d][1], drop[d][2], fill) == SAMPLE_OK, "drop");
            for (y = 4 * drop[d][2]; y < 4 * drop[d][2] + 4; ++y)
                for (x = 4 * drop[d][1]; x < 4 * drop[d][1] + 4; ++x)
                    ls_tex_encode(tex, fill, L->data + (size_t)y * L->stride + (size_t)x * tex->texel_bytes);
        }
        for (k = 0; k < 8; ++k) {
            sample_sampler s;
            span_sampler(&s, k);
            fill_long_footprints();
            for (x = 0; x < NQ; x += 2) { /* half of them near the missing tiles */
                qs[x].s = frand(0.0f, 0.3f);
                qs[x].t = frand(0.0f, 0.3f);
            }
            sample_some(tex, &s, 0, k & 2, 0);
            sample_some(tiled, &s, 1, k & 2, 0);
            ++configs;
            if (!same_results() && ++fails <= 10)
                fprintf(stderr, "missing tiles differ: %s, footprint %s, wraps %s %s\n", sample_format_name(fm),
                        sample_footprint_name(s.footprint), sample_wrap_name(s.wrap_s), sample_wrap_name(s.wrap_t));
        }
        sample_texture_destroy(tiled);
        sample_texture_destroy(tex);
    }
    CHECK(fails == 0, "%d of %d configurations differ with missing tiles", fails, configs);
}

static void test_bad_arguments(void)
{
    sample_texture *out = (sample_texture *)&out;
    sample_error err;
    float data[4] = {0, 0, 0, 1};
    sample_image im = {1, 1, 4, SAMPLE_FORMAT_F32, data, 0};
    sample_texture *tex = NULL;
    CHECK(sample_texture_create(&im, NULL, &tex, NULL) == SAMPLE_OK, "create");
    CHECK(sample_texture_tiled_copy(tex, 13, &out, &err) == SAMPLE_E_INVALID_ARGUMENT && out == NULL,
          "tiles of 2^13 refused");
    CHECK(strstr(err.message, "0 to 12") != NULL, "message: %s", err.message);
    CHECK(sample_texture_tiled_copy(NULL, 2, &out, NULL) == SAMPLE_E_INVALID_ARGUMENT, "NULL texture");
    CHECK(!strcmp(sample_texture_kind_name(SAMPLE_TEXTURE_2D), "2d"), "kind name");
    CHECK(!strcmp(sample_texture_kind_name(SAMPLE_TEXTURE_KIND_COUNT), "unknown"), "unknown kind name");
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(test_tiled_same_bits);
    RUN(test_missing_tile_reads_fill);
    RUN(test_missing_tiles_fast_path);
    RUN(test_one_call_per_block);
    RUN(test_one_call_per_tile_run);
    RUN(test_footprint_spans_in_tiles);
    RUN(test_footprint_spans_missing_tiles);
    RUN(test_bad_arguments);
    return check_finish();
}
