/*
 * Texel sources (libsample/src/texel.h, struct ls_texel_source): a texture
 * whose levels are held as tiles in memory of their own (tiled.c, the shape
 * a tile cache holds) is sampled through the same filters as the resident
 * texture it was copied from, and must give its results bit for bit —
 * values, derivatives and stats — for every format × channel count, wrap
 * mode, OpenGL filter and footprint filter, on tiles of 1, 4 and 8 texels
 * a side over levels that end in partial tiles. A tile the source cannot
 * supply reads as its fill colour: exact values by hand.
 */
#include "check.h"
#include "query_gen.h"
#include "sample/testing.h"

enum { NQ = 160 };

static sample_query qs[NQ];
static float rgba[2][NQ * 4], dds[2][NQ * 4], ddt[2][NQ * 4];
static sample_stats stats[2][NQ];

static void sample_all(const sample_texture *tex, const sample_sampler *s, int k)
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
    a.drgba_ds = dds[k];
    a.drgba_dt = ddt[k];
    a.stats = stats[k];
    CHECK(sample_batch(tex, s, &a) == SAMPLE_OK, "sample_batch");
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
                for (filt = 0; filt < SAMPLE_FILTER_COUNT + 3; ++filt) {
                    sample_sampler s;
                    sample_sampler_init(&s);
                    s.wrap_s = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
                    s.wrap_t = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
                    s.mag_filter = rnd() % 3 == 0 ? SAMPLE_NEAREST : (rnd() & 1 ? SAMPLE_LINEAR : SAMPLE_CUBIC);
                    s.border_color[0] = 0.25f;
                    s.border_color[3] = 0.5f;
                    if (filt < SAMPLE_FILTER_COUNT) {
                        s.min_filter = (sample_filter)filt;
                    } else {
                        s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
                        s.footprint = (sample_footprint)(filt - SAMPLE_FILTER_COUNT + 1);
                        s.max_anisotropy = 16.0f;
                    }
                    fill_queries(configs & 1);
                    sample_all(tex, &s, 0);
                    sample_all(tiled, &s, 1);
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
    RUN(test_bad_arguments);
    return check_finish();
}
