/*
 * The API's contract around the sampling maths: creation validates and
 * reports, nothing half-built is returned, names round-trip, sampler state
 * is validated, batches equal single queries.
 */
#include "check.h"
#include "sample/sample.h"

#include <stdint.h>
#include <stdlib.h>

static void creation_errors(void)
{
    float px[16] = {0};
    sample_image im = {2, 2, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_texture *t = (sample_texture *)&im; /* must be overwritten with NULL */
    sample_error err;

    im.width = 0;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_BAD_SIZE && t == NULL, "zero width");
    CHECK(strstr(err.message, "0 x 2") != NULL, "message names the size: %s", err.message);
    im.width = -3;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_BAD_SIZE, "negative width");
    im.width = 100000;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_TOO_LARGE && t == NULL, "100000 wide");
    im.width = 65536;
    im.height = 65536; /* 64 GiB of float RGBA: over the byte limit, refused before malloc */
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_TOO_LARGE, "65536² float RGBA");
    im.width = im.height = 2;
    im.channels = 5;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "5 channels");
    im.channels = 0;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "0 channels");
    im.channels = 4;
    im.format = (sample_format)9;
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "bad format");
    im.format = SAMPLE_FORMAT_F32;
    im.row_stride = 4; /* less than a row */
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_E_BAD_SIZE, "short stride");
    im.row_stride = 0;
    im.data = NULL;
    CHECK(sample_texture_create(&im, NULL, &t, NULL) == SAMPLE_E_INVALID_ARGUMENT, "NULL data, NULL err");
    CHECK(sample_texture_create(NULL, NULL, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "NULL image");
    im.data = px;
    CHECK(sample_texture_create(&im, NULL, NULL, &err) == SAMPLE_E_INVALID_ARGUMENT, "NULL out");
    CHECK(sample_texture_create(&im, NULL, &t, &err) == SAMPLE_OK && t != NULL, "valid");
    sample_texture_destroy(t);
    sample_texture_destroy(NULL); /* accepted */
}

static void create_levels_checks(void)
{
    float a[8 * 4 * 4] = {0}, b[4 * 2 * 4] = {0}, c[2 * 1 * 4] = {0};
    sample_image lv[4] = {
        {8, 4, 4, SAMPLE_FORMAT_F32, a, 0},
        {4, 2, 4, SAMPLE_FORMAT_F32, b, 0},
        {2, 1, 4, SAMPLE_FORMAT_F32, c, 0},
        {1, 1, 4, SAMPLE_FORMAT_F32, c, 0},
    };
    sample_texture *t = NULL;
    sample_texture_info inf;
    sample_error err;
    int w, h;
    CHECK(sample_texture_create_levels(lv, 4, &t, &err) == SAMPLE_OK, "%s", err.message);
    sample_texture_info_get(t, &inf);
    CHECK(inf.levels == 4 && inf.width == 8 && inf.height == 4, "info");
    CHECK(inf.bytes == (size_t)(32 + 8 + 2 + 1) * 16, "bytes %zu", inf.bytes);
    CHECK(sample_texture_level_size(t, 2, &w, &h) && w == 2 && h == 1, "level 2 size");
    CHECK(!sample_texture_level_size(t, 4, &w, &h) && w == 0, "level 4 does not exist");
    sample_texture_destroy(t);
    lv[2].width = 3;
    CHECK(sample_texture_create_levels(lv, 4, &t, &err) == SAMPLE_E_BAD_SIZE && t == NULL, "wrong level size");
    CHECK(strstr(err.message, "level 2") != NULL, "names the level: %s", err.message);
    lv[2].width = 2;
    lv[1].format = SAMPLE_FORMAT_F16;
    CHECK(sample_texture_create_levels(lv, 2, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "format mismatch");
    lv[1].format = SAMPLE_FORMAT_F32;
    CHECK(sample_texture_create_levels(lv, 5, &t, &err) == SAMPLE_E_BAD_SIZE, "more levels than the chain");
    CHECK(sample_texture_create_levels(lv, 0, &t, &err) == SAMPLE_E_INVALID_ARGUMENT, "zero levels");
}

static void names_round_trip(void)
{
    int k;
    for (k = 0; k < SAMPLE_WRAP_COUNT; ++k) CHECK(sample_wrap_parse(sample_wrap_name((sample_wrap)k)) == k, "wrap %d", k);
    for (k = 0; k < SAMPLE_FILTER_COUNT; ++k) CHECK(sample_filter_parse(sample_filter_name((sample_filter)k)) == k, "filter %d", k);
    for (k = 0; k < SAMPLE_CUBIC_COUNT; ++k) CHECK(sample_cubic_parse(sample_cubic_name((sample_cubic)k)) == k, "cubic %d", k);
    for (k = 0; k < SAMPLE_FOOTPRINT_COUNT; ++k) CHECK(sample_footprint_parse(sample_footprint_name((sample_footprint)k)) == k, "fp %d", k);
    for (k = 0; k < SAMPLE_MIPGEN_COUNT; ++k) CHECK(sample_mipgen_parse(sample_mipgen_name((sample_mipgen)k)) == k, "mipgen %d", k);
    for (k = 0; k < SAMPLE_STATUS_COUNT; ++k) CHECK(strcmp(sample_strerror((sample_status)k), "unknown") != 0, "status %d", k);
    CHECK(sample_wrap_parse("bogus") == -1 && sample_wrap_parse(NULL) == -1, "unknown names");
    CHECK(strcmp(sample_strerror((sample_status)99), "unknown") == 0, "out of range status");
    CHECK(strcmp(sample_wrap_name(SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER), "mirror_clamp_to_border") == 0, "CLI spelling");
}

static void sampler_validation(void)
{
    sample_sampler s;
    sample_sampler_init(&s);
    /* GL 4.6 table 23.18 initial state */
    CHECK(s.wrap_s == SAMPLE_WRAP_REPEAT && s.min_filter == SAMPLE_NEAREST_MIPMAP_LINEAR &&
          s.mag_filter == SAMPLE_LINEAR && s.min_lod == -1000.0f && s.max_lod == 1000.0f &&
          s.max_level == 1000 && s.max_anisotropy == 1.0f, "GL defaults");
    CHECK(sample_sampler_validate(&s) == SAMPLE_OK, "defaults valid");
    s.mag_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "mag cannot be a mipmap filter");
    sample_sampler_init(&s);
    s.min_lod = 2.0f;
    s.max_lod = 1.0f;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "min_lod > max_lod");
    sample_sampler_init(&s);
    s.max_anisotropy = NAN;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "NaN anisotropy");
    sample_sampler_init(&s);
    s.lod_bias = INFINITY;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "inf bias");
    sample_sampler_init(&s);
    s.wrap_t = (sample_wrap)8;
    CHECK(sample_sampler_validate(&s) == SAMPLE_E_INVALID_ARGUMENT, "bad wrap");
    CHECK(sample_sampler_validate(NULL) == SAMPLE_E_INVALID_ARGUMENT, "NULL");
}

/* Batches give the same bits as single queries, whatever their size. */
static void batch_equals_single(void)
{
    enum { W = 13, H = 9, N = 257 };
    float px[W * H * 4];
    sample_query q[N];
    float out[N * 4], one[4];
    sample_image im = {W, H, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mp;
    sample_texture *t;
    sample_sampler s;
    sample_batch_args a;
    int k;
    srand(3);
    for (k = 0; k < W * H * 4; ++k) px[k] = (float)rand() / (float)RAND_MAX;
    for (k = 0; k < N; ++k) {
        q[k].s = 3.0f * (float)rand() / (float)RAND_MAX - 1.0f;
        q[k].t = 3.0f * (float)rand() / (float)RAND_MAX - 1.0f;
        q[k].dsdx = 0.3f * (float)rand() / (float)RAND_MAX;
        q[k].dtdx = 0.01f;
        q[k].dsdy = 0.0f;
        q[k].dtdy = 0.2f * (float)rand() / (float)RAND_MAX;
    }
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &t, NULL) == SAMPLE_OK, "create");
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    memset(&a, 0, sizeof a);
    a.count = N;
    a.queries = q;
    a.rgba = out;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
    for (k = 0; k < N; ++k) {
        sample_one(t, &s, &q[k], one);
        CHECK(memcmp(one, &out[4 * k], sizeof one) == 0, "query %d differs", k);
    }
    a.rgba = NULL;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "NULL output");
    a.count = 0;
    CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "empty batch is fine");
    CHECK(sample_batch(NULL, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "NULL texture");
    sample_texture_destroy(t);
}

/* Non-finite per-call bias and corners count as bad input too. */
static void nonfinite_extras(void)
{
    float px[4] = {0.5f, 0.5f, 0.5f, 1.0f}, out[4];
    sample_image im = {1, 1, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_texture *t;
    sample_sampler s;
    sample_query q = {0.5f, 0.5f, 0, 0, 0, 0};
    sample_quad c = {{{0, 0}, {1, 0}, {1, 1}, {NAN, 1}}};
    float bias = NAN;
    sample_stats st;
    sample_batch_args a;
    CHECK(sample_texture_create(&im, NULL, &t, NULL) == SAMPLE_OK, "create");
    sample_sampler_init(&s);
    s.border_color[1] = 7.0f;
    memset(&a, 0, sizeof a);
    a.count = 1; a.queries = &q; a.rgba = out; a.lod_bias = &bias; a.stats = &st;
    sample_batch(t, &s, &a);
    CHECK(out[1] == 7.0f && st.texels == 0 && st.level0 == -1, "NaN bias → border, no texels");
    a.lod_bias = NULL;
    a.corners = &c;
    sample_batch(t, &s, &a);
    CHECK(out[1] == 7.0f, "NaN corner → border");
    a.corners = NULL;
    sample_batch(t, &s, &a);
    CHECK(out[1] == 0.5f && st.texels == 4, "valid query reads the 4 bilinear texels");
    sample_texture_destroy(t);
}

int main(void)
{
    RUN(creation_errors);
    RUN(create_levels_checks);
    RUN(names_round_trip);
    RUN(sampler_validation);
    RUN(batch_equals_single);
    RUN(nonfinite_extras);
    return check_finish();
}
