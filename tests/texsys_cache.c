/*
 * The texture system (sample/texsys.h, doc/texture-system.md): textures
 * opened by name through a cache small enough that it evicts during the
 * test give an in-memory texture's results bit for bit — values,
 * derivatives, stats — for every filter, on tiled OpenEXR (half, float),
 * tiled TIFF (8-bit sRGB) and an untiled PNG (tiled and mip-mapped on
 * first use); the file's wrap modes; failures (a truncated file, a file
 * gone, unreadable, memory refused, more files than may be open) read as
 * the fill colour exactly and are recorded; two systems are independent;
 * UDIM sets continue across tile edges and read the fill where a tile is
 * missing; the direct OpenEXR tile reader serves PIZ, uncompressed and
 * float files (stats: tiles_direct) and leaves a ROUND_UP file to
 * OpenImageIO, with the same bits.
 */
#include "texsys_util.h"
#include "texsys_internal.h" /* io_texsys_fail_allocs */

#include <OpenEXR/openexr.h>
#include <fcntl.h>
#include <sys/wait.h>

static const char *texsample; /* the image program, or NULL (that part skipped) */

enum { NQ = 96 };

static sample_query qs[NQ];
static float rgba[2][NQ * 4], dds[2][NQ * 4], ddt[2][NQ * 4];
static sample_stats stats[2][NQ];
static const float fill[4] = {0.25f, 0.5f, 0.75f, 1.0f};

/* Results slot k of `tex` (through the system when sys is given), values
 * only, or with derivatives and stats (`all`): the fast path reads an
 * anisotropic query's probes from addresses planned ahead only when no
 * derivative is asked for (fast_gl.c, aniso_read). */
static void run_some(sample_texsys *sys, const sample_texture *tex, const sample_sampler *s, const sample_query *q,
                     size_t n, int k, int all)
{
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    memset(rgba[k], 0xA5, sizeof rgba[k]);
    memset(dds[k], 0xA5, sizeof dds[k]);
    memset(ddt[k], 0xA5, sizeof ddt[k]);
    memset(stats[k], 0xA5, sizeof stats[k]);
    a.count = n;
    a.queries = q;
    a.rgba = rgba[k];
    a.drgba_ds = all ? dds[k] : NULL;
    a.drgba_dt = all ? ddt[k] : NULL;
    a.stats = all ? stats[k] : NULL;
    CHECK((sys ? sample_texsys_batch(sys, tex, s, &a) : sample_batch(tex, s, &a)) == SAMPLE_OK, "batch");
}

static int same(void)
{
    return !memcmp(rgba[0], rgba[1], sizeof rgba[0]) && !memcmp(dds[0], dds[1], sizeof dds[0]) &&
           !memcmp(ddt[0], ddt[1], sizeof ddt[0]) && !memcmp(stats[0], stats[1], sizeof stats[0]);
}

static sample_texsys *new_system(double mb, int files)
{
    sample_texsys_options o;
    sample_texsys *sys = NULL;
    sample_error e;
    sample_texsys_options_init(&o);
    o.max_memory_mb = mb;
    o.max_open_files = files;
    memcpy(o.fill, fill, sizeof o.fill);
    CHECK(sample_texsys_create(&o, &sys, &e) == SAMPLE_OK, "create: %s", e.message);
    return sys;
}

static const sample_texture *open_ok(sample_texsys *sys, const char *path)
{
    const sample_texture *t = NULL;
    sample_error e;
    CHECK(sample_texsys_open(sys, path, &t, &e) == SAMPLE_OK, "open %s: %s", path, e.message);
    return t;
}

/* Every kind of filter on random queries, the cached texture against the
 * resident one, with derivatives and stats and values alone; returns how
 * many configurations differ. */
static int compare_all(sample_texsys *sys, const sample_texture *cached, const sample_texture *resident)
{
    int k, fails = 0;
    for (k = 0; k < 2 * TS_KINDS; ++k) {
        sample_sampler s;
        ts_sampler(&s, k % TS_KINDS);
        ts_queries(qs, NQ);
        run_some(NULL, resident, &s, qs, NQ, 0, k < TS_KINDS);
        run_some(sys, cached, &s, qs, NQ, 1, k < TS_KINDS);
        if (!same() && fails++ < 5)
            fprintf(stderr, "differs: filter %s footprint %s%s\n", sample_filter_name(s.min_filter),
                    sample_footprint_name(s.footprint), k < TS_KINDS ? "" : " (values only)");
    }
    return fails;
}

static void test_same_bits(void)
{
    /* Each in a cache of about a third of its texels (kib), so that tiles
     * are evicted. */
    static const struct {
        const char *name;
        sample_format fmt;
        int nc, w, h, tile, use_float, tiled, kib;
    } files[] = {
        {"half.exr", SAMPLE_FORMAT_F16, 4, 77, 45, 16, 0, 1, 12},
        {"float3.exr", SAMPLE_FORMAT_F32, 3, 40, 64, 8, 1, 1, 12},
        {"rgb8.png", SAMPLE_FORMAT_F32, 3, 70, 33, 0, 0, 0, 80},
    };
    size_t f;
    for (f = 0; f < sizeof files / sizeof files[0]; ++f) {
        sample_texsys *sys = new_system(files[f].kib / 1024.0, 4);
        sample_texsys_stats st;
        char path[1024];
        sample_texture *src = io_test_texture(files[f].w, files[f].h, files[f].nc, files[f].fmt, 7u + (unsigned)f,
                                              SAMPLE_MIPGEN_BOX, 0);
        sample_texture *resident;
        const sample_texture *cached;
        sample_texsys_info info;
        io_path(path, sizeof path, io_scratch, files[f].name);
        if (files[f].tiled) {
            ts_write(path, src, files[f].tile, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT, files[f].use_float);
        } else {
            float *px = (float *)malloc((size_t)files[f].w * files[f].h * 4 * sizeof(float));
            int i, j;
            for (j = 0; j < files[f].h; ++j)
                for (i = 0; i < files[f].w; ++i)
                    sample_texture_texel(src, 0, i, j, px + 4 * ((size_t)j * files[f].w + i));
            CHECK(sample_io_write_image(path, px, files[f].w, files[f].h, 3, NULL, NULL) == SAMPLE_OK, "png");
            free(px);
        }
        resident = ts_resident(path);
        cached = open_ok(sys, path);
        if (!resident || !cached) {
            sample_texsys_destroy(sys);
            continue;
        }
        CHECK(sample_texsys_texture_info(sys, cached, &info, NULL) == SAMPLE_OK, "info");
        CHECK(info.texture.width == resident->width && info.texture.height == resident->height &&
                  info.texture.levels == resident->nlevels && info.texture.channels == resident->channels &&
                  info.texture.format == resident->format && info.texture.kind == SAMPLE_TEXTURE_2D,
              "%s: info %d x %d, %d levels, %d channels, %s", files[f].name, info.texture.width, info.texture.height,
              info.texture.levels, info.texture.channels, sample_format_name(info.texture.format));
        CHECK(info.file_tiled == files[f].tiled && info.tile_size == (files[f].tiled ? files[f].tile : 64),
              "%s: tiles of %d, from the file %d", files[f].name, info.tile_size, info.file_tiled);
        {
            /* The colour space sample_io_read_texture decodes from. */
            sample_io_file_info fi;
            CHECK(sample_io_describe(path, NULL, &fi, NULL) == SAMPLE_OK && !strcmp(fi.colorspace_used, info.colorspace),
                  "%s: colour space '%s', the reader's '%s'", files[f].name, info.colorspace, fi.colorspace_used);
        }
        if (files[f].tiled)
            CHECK(info.has_wrap && info.wrap_s == SAMPLE_WRAP_REPEAT && info.wrap_t == SAMPLE_WRAP_MIRRORED_REPEAT,
                  "%s: wrap modes from the file", files[f].name);
        CHECK(compare_all(sys, cached, resident) == 0, "%s: cached texels differ from resident ones", files[f].name);
        CHECK(open_ok(sys, path) == cached, "a name opens once");
        sample_texsys_stats_get(sys, &st);
        CHECK(st.tiles_direct == (files[f].tiled ? st.tiles_read : 0), "%s: %llu of %llu tiles read directly",
              files[f].name, (unsigned long long)st.tiles_direct, (unsigned long long)st.tiles_read);
        CHECK(st.evictions > 0 && st.tiles_read > st.evictions && st.misses > 0 && st.errors == 0,
              "%s: %llu evictions, %llu tiles read, %llu misses, %llu errors", files[f].name,
              (unsigned long long)st.evictions, (unsigned long long)st.tiles_read, (unsigned long long)st.misses,
              (unsigned long long)st.errors);
        /* With no batch running nothing evicted is kept: the limit holds. */
        CHECK(st.memory <= (size_t)files[f].kib * 1024 && st.peak_memory > st.memory / 2,
              "%s: memory %zu, peak %zu", files[f].name, st.memory, st.peak_memory);
        printf("%s: %llu tiles read, %llu evicted, peak %zu bytes under a limit of %d\n", files[f].name,
               (unsigned long long)st.tiles_read, (unsigned long long)st.evictions, st.peak_memory,
               files[f].kib * 1024);
        sample_texture_destroy(resident);
        sample_texture_destroy(src);
        sample_texsys_destroy(sys);
    }
}

/* Every level of `src` as a single-part tiled OpenEXR written with the
 * OpenEXR core library: MIPMAP_LEVELS with rounding `round`, channels R,
 * G, B, A (as many as src has) of `type`, compression `comp` — the
 * layouts sample_io_write_mip (ZIP only) does not write. */
static void write_core_exr(const char *path, const sample_texture *src, int tile, exr_compression_t comp,
                           exr_tile_round_mode_t round, exr_pixel_type_t type)
{
    static const char *const names[4] = {"R", "G", "B", "A"};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t c = NULL;
    const int nc = src->channels;
    const size_t eb = type == EXR_PIXEL_HALF ? 2 : 4;
    int part = 0, lv, k, ok;
    int32_t nlx = 0, nly = 0;
    ok = exr_start_write(&c, path, EXR_WRITE_FILE_DIRECTLY, &init) == EXR_ERR_SUCCESS &&
         exr_add_part(c, "texture", EXR_STORAGE_TILED, &part) == EXR_ERR_SUCCESS &&
         exr_initialize_required_attr_simple(c, part, src->width, src->height, comp) == EXR_ERR_SUCCESS &&
         exr_set_tile_descriptor(c, part, (uint32_t)tile, (uint32_t)tile, EXR_TILE_MIPMAP_LEVELS, round) ==
             EXR_ERR_SUCCESS;
    for (k = 0; ok && k < nc; ++k)
        ok = exr_add_channel(c, part, names[k], type, EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1) == EXR_ERR_SUCCESS;
    ok = ok && exr_write_header(c) == EXR_ERR_SUCCESS && exr_get_tile_levels(c, part, &nlx, &nly) == EXR_ERR_SUCCESS;
    CHECK(ok && nlx == src->nlevels, "%s: header (%d levels)", path, nlx);
    for (lv = 0; ok && lv < nlx; ++lv) {
        int32_t w = 0, h = 0, tx, ty, i, j;
        unsigned char *px;
        ok = exr_get_level_sizes(c, part, lv, lv, &w, &h) == EXR_ERR_SUCCESS;
        px = (unsigned char *)malloc((size_t)w * (size_t)h * (size_t)nc * eb);
        for (j = 0; ok && j < h; ++j)
            for (i = 0; i < w; ++i) {
                float v[4];
                unsigned char *p = px + ((size_t)j * (size_t)w + (size_t)i) * (size_t)nc * eb;
                sample_texture_texel(src, lv, i, j, v);
                for (k = 0; k < nc; ++k) {
                    uint16_t hv = sample_float_to_half(v[k]);
                    memcpy(p + (size_t)k * eb, eb == 2 ? (void *)&hv : (void *)&v[k], eb);
                }
            }
        for (ty = 0; ok && ty * tile < h; ++ty)
            for (tx = 0; ok && tx * tile < w; ++tx) {
                exr_encode_pipeline_t e = EXR_ENCODE_PIPELINE_INITIALIZER;
                exr_chunk_info_t ci;
                ok = exr_write_tile_chunk_info(c, part, tx, ty, lv, lv, &ci) == EXR_ERR_SUCCESS;
                /* OpenEXR 3.1's exr_write_tile_chunk_info cuts edge tiles
                 * at level 0's data window, not the level's: a level's
                 * edge tile is sized here (OpenEXR file layout, "Tiles":
                 * a tile past a level's edge holds only the pixels
                 * inside). */
                ci.width = w - tx * tile < tile ? w - tx * tile : tile;
                ci.height = h - ty * tile < tile ? h - ty * tile : tile;
                ci.unpacked_size = (uint64_t)ci.width * (uint64_t)ci.height * (uint64_t)nc * eb;
                ok = ok && exr_encoding_initialize(c, part, &ci, &e) == EXR_ERR_SUCCESS;
                for (k = 0; ok && k < e.channel_count; ++k) {
                    exr_coding_channel_info_t *ch = &e.channels[k];
                    int n = 0;
                    while (strcmp(ch->channel_name, names[n])) ++n;
                    ch->encode_from_ptr = px + (((size_t)ty * (size_t)tile * (size_t)w + (size_t)tx * (size_t)tile) *
                                                    (size_t)nc + (size_t)n) * eb;
                    ch->user_pixel_stride = (int32_t)((size_t)nc * eb);
                    ch->user_line_stride = (int32_t)((size_t)w * (size_t)nc * eb);
                    ch->user_bytes_per_element = (int16_t)eb;
                    ch->user_data_type = (uint16_t)type;
                }
                ok = ok && exr_encoding_choose_default_routines(c, part, &e) == EXR_ERR_SUCCESS &&
                     exr_encoding_run(c, part, &e) == EXR_ERR_SUCCESS;
                exr_encoding_destroy(c, &e);
            }
        free(px);
    }
    CHECK(ok, "%s: tiles written", path);
    exr_finish(&c);
}

/* Layouts the direct OpenEXR tile reader takes (PIZ and uncompressed,
 * half and float, 1 to 4 channels, decoded as stored or converted from
 * another colour space) give the resident texture's bits, every tile decoded by
 * it; a ROUND_UP file (power-of-two sides: the same level sizes) is left
 * to OpenImageIO, with the same bits. */
static void test_direct_reader(void)
{
    static const struct {
        const char *name;
        sample_format fmt;
        int nc, w, h, tile;
        exr_compression_t comp;
        exr_tile_round_mode_t round;
        exr_pixel_type_t type;
        int direct;
        const char *cs; /* decoded from this colour space; NULL: the file's */
    } files[] = {
        {"piz.exr", SAMPLE_FORMAT_F16, 4, 77, 45, 16, EXR_COMPRESSION_PIZ, EXR_TILE_ROUND_DOWN, EXR_PIXEL_HALF, 1, NULL},
        {"raw3.exr", SAMPLE_FORMAT_F32, 3, 40, 64, 8, EXR_COMPRESSION_NONE, EXR_TILE_ROUND_DOWN, EXR_PIXEL_FLOAT, 1,
         NULL},
        {"raw2.exr", SAMPLE_FORMAT_F16, 2, 93, 70, 8, EXR_COMPRESSION_NONE, EXR_TILE_ROUND_DOWN, EXR_PIXEL_HALF, 1,
         NULL},
        {"raw1.exr", SAMPLE_FORMAT_F16, 1, 90, 70, 8, EXR_COMPRESSION_NONE, EXR_TILE_ROUND_DOWN, EXR_PIXEL_HALF, 1,
         NULL},
        /* Converted: decoded as float, then the plan (io_plan_apply). */
        {"aces.exr", SAMPLE_FORMAT_F16, 4, 50, 60, 16, EXR_COMPRESSION_PIZ, EXR_TILE_ROUND_DOWN, EXR_PIXEL_HALF, 1,
         "acescg"},
        {"up.exr", SAMPLE_FORMAT_F16, 4, 64, 32, 16, EXR_COMPRESSION_ZIP, EXR_TILE_ROUND_UP, EXR_PIXEL_HALF, 0, NULL},
    };
    size_t f;
    for (f = 0; f < sizeof files / sizeof files[0]; ++f) {
        sample_texsys *sys = new_system(12 / 1024.0, 4);
        sample_texsys_stats st;
        char path[1024];
        sample_texture *src = io_test_texture(files[f].w, files[f].h, files[f].nc, files[f].fmt, 31u + (unsigned)f,
                                              SAMPLE_MIPGEN_BOX, 0);
        sample_texture *resident = NULL;
        const sample_texture *cached = NULL;
        sample_error e;
        write_core_exr(io_path(path, sizeof path, io_scratch, files[f].name), src, files[f].tile, files[f].comp,
                       files[f].round, files[f].type);
        if (files[f].cs) {
            sample_io_options o;
            sample_mip_params mip;
            sample_io_options_init(&o);
            o.mip_wrap_from_file = 1;
            o.colorspace = files[f].cs;
            sample_mip_params_init(&mip);
            CHECK(io_read_texture_col(path, ts_col, &o, &mip, &resident, &e) == SAMPLE_OK, "%s", e.message);
            CHECK(sample_texsys_open_colorspace(sys, path, files[f].cs, &cached, &e) == SAMPLE_OK, "%s", e.message);
        } else {
            resident = ts_resident(path);
            cached = open_ok(sys, path);
        }
        if (resident && cached) {
            CHECK(compare_all(sys, cached, resident) == 0, "%s: cached texels differ from resident ones",
                  files[f].name);
            sample_texsys_stats_get(sys, &st);
            CHECK(st.evictions > 0 && st.errors == 0 &&
                      st.tiles_direct == (files[f].direct ? st.tiles_read : 0),
                  "%s: %llu of %llu tiles read directly, %llu evictions, %llu errors", files[f].name,
                  (unsigned long long)st.tiles_direct, (unsigned long long)st.tiles_read,
                  (unsigned long long)st.evictions, (unsigned long long)st.errors);
        }
        sample_texture_destroy(resident);
        sample_texture_destroy(src);
        sample_texsys_destroy(sys);
    }
}

/* A 32 × 32 half texture of 1.0 in tiles of 8: the file and its system. */
static const sample_texture *one_file(sample_texsys *sys, const char *name, char *path, size_t size)
{
    sample_texture *src = io_test_texture(32, 32, 4, SAMPLE_FORMAT_F16, 3, SAMPLE_MIPGEN_BOX, 0);
    io_path(path, size, io_scratch, name);
    ts_write(path, src, 8, SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_CLAMP_TO_EDGE, 0);
    sample_texture_destroy(src);
    return open_ok(sys, path);
}

/* NEAREST at each level-0 texel centre: how many read the fill exactly;
 * *other counts those that read neither the fill nor the resident value. */
static int count_fill(sample_texsys *sys, const sample_texture *t, const sample_texture *resident, int *other)
{
    static sample_query q[32 * 32];
    sample_sampler s;
    sample_batch_args a;
    static float out[32 * 32 * 4];
    int i, n = 0;
    sample_sampler_init(&s);
    s.min_filter = s.mag_filter = SAMPLE_NEAREST;
    memset(q, 0, sizeof q);
    for (i = 0; i < 32 * 32; ++i) {
        q[i].s = ((float)(i % 32) + 0.5f) / 32.0f;
        q[i].t = ((float)(i / 32) + 0.5f) / 32.0f;
    }
    memset(&a, 0, sizeof a);
    a.count = 32 * 32;
    a.queries = q;
    a.rgba = out;
    CHECK(sample_texsys_batch(sys, t, &s, &a) == SAMPLE_OK, "batch");
    *other = 0;
    for (i = 0; i < 32 * 32; ++i) {
        float r[4];
        if (!memcmp(out + 4 * i, fill, sizeof fill)) {
            ++n;
            continue;
        }
        if (resident) sample_texture_texel(resident, 0, i % 32, i / 32, r);
        if (!resident || memcmp(r, out + 4 * i, sizeof r)) ++*other;
    }
    return n;
}

/* A system of 64 MiB holding one_file(name), and the file read whole. */
typedef struct fixture {
    sample_texsys *sys;
    const sample_texture *t;
    sample_texture *resident;
    char path[1024];
} fixture;

static void fixture_open(fixture *x, const char *name)
{
    x->sys = new_system(64.0, 4);
    x->t = one_file(x->sys, name, x->path, sizeof x->path);
    x->resident = ts_resident(x->path);
}

static void fixture_close(fixture *x)
{
    sample_texture_destroy(x->resident);
    sample_texsys_destroy(x->sys);
}

static void test_truncated(void)
{
    fixture x;
    sample_error first;
    struct stat sb;
    unsigned long before;
    int other, n;
    fixture_open(&x, "trunc.exr");
    CHECK(stat(x.path, &sb) == 0 && truncate(x.path, sb.st_size / 3) == 0, "truncate");
    n = count_fill(x.sys, x.t, x.resident, &other);
    CHECK(n > 0 && n < 32 * 32 && other == 0, "%d texels read the fill, %d neither fill nor texel", n, other);
    before = sample_texsys_texture_error(x.sys, x.t, &first);
    CHECK(before > 0 && strstr(first.message, x.path) && strstr(first.message, "of level ") &&
              strstr(first.message, "tile ("),
          "error recorded, naming the file, the tile and the level: %s", first.message);
    /* Once failed, a tile reads the fill again without another error. */
    CHECK(count_fill(x.sys, x.t, x.resident, &other) == n, "the same texels again");
    CHECK(sample_texsys_texture_error(x.sys, x.t, NULL) == before, "no new error");
    fixture_close(&x);
}

/* Bytes in the middle of a file of compressible tiles (1.0 everywhere:
 * ZIP keeps them compressed, so zlib sees the damage) overwritten after
 * open: the damaged tiles read the fill, the others 1.0, exactly. */
static void test_corrupt(void)
{
    static float ones[32 * 32 * 4];
    sample_image im = {32, 32, 4, SAMPLE_FORMAT_F32, ones, 0};
    sample_mip_params mip;
    sample_texture *src = NULL;
    sample_texsys *sys = new_system(64.0, 4);
    const sample_texture *t;
    char path[1024], junk[48];
    struct stat sb;
    FILE *f;
    int k, other, n;
    for (k = 0; k < 32 * 32 * 4; ++k) ones[k] = 1.0f;
    sample_mip_params_init(&mip);
    CHECK(sample_texture_create(&im, &mip, &src, NULL) == SAMPLE_OK, "create");
    ts_write(io_path(path, sizeof path, io_scratch, "corrupt.exr"), src, 8, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT, 0);
    t = open_ok(sys, path);
    memset(junk, 0x5A, sizeof junk);
    CHECK(stat(path, &sb) == 0 && (f = fopen(path, "r+b")) != NULL, "open for damage");
    if (f) {
        CHECK(fseek(f, (long)(sb.st_size / 2), SEEK_SET) == 0 && fwrite(junk, sizeof junk, 1, f) == 1, "damage");
        fclose(f);
    }
    n = count_fill(sys, t, src, &other);
    CHECK(n > 0 && n < 32 * 32 && other == 0, "%d texels read the fill, %d neither fill nor 1.0", n, other);
    CHECK(sample_texsys_texture_error(sys, t, NULL) > 0, "damage recorded");
    sample_texture_destroy(src);
    sample_texsys_destroy(sys);
}

static void test_gone_and_unreadable(void)
{
    sample_texsys *sys = new_system(64.0, 4);
    char path[1024], path2[1024];
    const sample_texture *t = one_file(sys, "gone.exr", path, sizeof path);
    const sample_texture *t2 = one_file(sys, "locked.exr", path2, sizeof path2);
    sample_error first;
    int other;
    CHECK(unlink(path) == 0, "unlink");
    CHECK(count_fill(sys, t, NULL, &other) == 32 * 32, "a file gone reads the fill");
    CHECK(sample_texsys_texture_error(sys, t, &first) == 16 && strstr(first.message, "gone.exr"),
          "16 tiles failed: %s", first.message);
    if (geteuid() != 0) {
        CHECK(chmod(path2, 0) == 0, "chmod");
        CHECK(count_fill(sys, t2, NULL, &other) == 32 * 32, "an unreadable file reads the fill");
        CHECK(sample_texsys_texture_error(sys, t2, &first) > 0, "recorded: %s", first.message);
        chmod(path2, 0644);
    } else {
        /* root reads files whatever their mode: nothing to see here. */
        fprintf(stderr, "note: running as root, the unreadable-file case is not checked\n");
    }
    {
        const sample_texture *none = NULL;
        sample_error e;
        io_path(path, sizeof path, io_scratch, "never.exr");
        CHECK(sample_texsys_open(sys, path, &none, &e) == SAMPLE_E_IO && none == NULL, "open of a missing file");
    }
    sample_texsys_destroy(sys);
}

static void test_memory_refused(void)
{
    fixture x;
    sample_error first;
    int other;
    fixture_open(&x, "alloc.exr");
    io_texsys_fail_allocs(x.sys, 1);
    /* The first tile (texels of tile (0, 0), 8 × 8) fails; the rest load. */
    CHECK(count_fill(x.sys, x.t, x.resident, &other) == 64 && other == 0, "one tile reads the fill");
    CHECK(sample_texsys_texture_error(x.sys, x.t, &first) == 1 && first.status == SAMPLE_E_OUT_OF_MEMORY,
          "out of memory recorded: %s", first.message);
    fixture_close(&x);
}

static void test_open_file_limit(void)
{
    sample_texsys *sys = new_system(1.0 / 256.0, 2); /* 4 KiB: two tiles */
    const sample_texture *t[4];
    sample_texture *resident[4];
    sample_texsys_stats st;
    char path[1024];
    int k, round, other;
    for (k = 0; k < 4; ++k) {
        char name[32];
        snprintf(name, sizeof name, "many%d.exr", k);
        t[k] = one_file(sys, name, path, sizeof path);
        resident[k] = ts_resident(path);
    }
    for (round = 0; round < 2; ++round)
        for (k = 0; k < 4; ++k) CHECK(count_fill(sys, t[k], resident[k], &other) == 0 && other == 0, "file %d", k);
    sample_texsys_stats_get(sys, &st);
    CHECK(st.peak_open_files <= 2 && st.open_files <= 2 && st.files_opened >= 4 + 8 && st.errors == 0,
          "open %d (peak %d), opened %llu times, %llu errors", st.open_files, st.peak_open_files,
          (unsigned long long)st.files_opened, (unsigned long long)st.errors);
    for (k = 0; k < 4; ++k) sample_texture_destroy(resident[k]);
    sample_texsys_destroy(sys);
}

static void test_independent_systems(void)
{
    sample_texsys *a = new_system(64.0, 4), *b = new_system(64.0, 4);
    char path[1024];
    const sample_texture *ta = one_file(a, "shared.exr", path, sizeof path), *tb = open_ok(b, path);
    sample_texsys_stats sa, sb;
    int other;
    io_texsys_fail_allocs(a, 1000);
    CHECK(count_fill(a, ta, NULL, &other) == 32 * 32, "system a refuses memory");
    CHECK(count_fill(b, tb, NULL, &other) == 0, "system b reads its texels");
    sample_texsys_stats_get(a, &sa);
    sample_texsys_stats_get(b, &sb);
    CHECK(sa.errors == 16 && sb.errors == 0 && sa.tiles_read == 0 && sb.tiles_read == 16, "stats apart");
    CHECK(sample_texsys_batch(b, ta, NULL, NULL) == SAMPLE_E_INVALID_ARGUMENT, "a's texture is not b's");
    sample_texsys_destroy(a);
    sample_texsys_destroy(b);
}

/* Level k of the 2 × 2 set `tiles` side by side (tile (u, v) at column u,
 * row v), as one image. */
static sample_texture *assemble(sample_texture *const tiles[4], int present_mask)
{
    sample_image lv[SAMPLE_MAX_LEVELS];
    sample_texture *out = NULL;
    int k, n = tiles[0]->nlevels, u, v, i, j;
    memset(lv, 0, sizeof lv);
    for (k = 0; k < n; ++k) {
        int w, h;
        float *px;
        sample_texture_level_size(tiles[0], k, &w, &h);
        px = (float *)malloc((size_t)4 * w * h * 4 * sizeof(float));
        for (v = 0; v < 2; ++v)
            for (u = 0; u < 2; ++u)
                for (j = 0; j < h; ++j)
                    for (i = 0; i < w; ++i) {
                        float *p = px + 4 * ((size_t)(v * h + j) * (2 * w) + (size_t)(u * w + i));
                        if (present_mask >> (v * 2 + u) & 1)
                            sample_texture_texel(tiles[v * 2 + u], k, i, j, p);
                        else
                            memcpy(p, fill, sizeof fill);
                    }
        lv[k].width = 2 * w;
        lv[k].height = 2 * h;
        lv[k].channels = 4;
        lv[k].format = SAMPLE_FORMAT_F32;
        lv[k].data = px;
        lv[k].row_stride = 0;
    }
    CHECK(sample_texture_create_levels(lv, n, &out, NULL) == SAMPLE_OK, "assemble");
    for (k = 0; k < n; ++k) free((void *)lv[k].data);
    return out;
}

/* The queries qs of the 2 × 2 set `set` against the tiles side by side
 * (`big`) sampled at (s / 2, t / 2) with the fill as its border, ∂/∂s and
 * ∂/∂t scaled back: with derivatives and stats or values alone (`all`);
 * 1 if the bits are the same. */
static int udim_same_bits(sample_texsys *sys, const sample_texture *set, const sample_texture *big,
                          const sample_sampler *s, int all)
{
    sample_query half[NQ];
    sample_sampler sb = *s;
    size_t i;
    for (i = 0; i < NQ; ++i) {
        half[i].s = qs[i].s * 0.5f, half[i].t = qs[i].t * 0.5f;
        half[i].dsdx = qs[i].dsdx * 0.5f, half[i].dtdx = qs[i].dtdx * 0.5f;
        half[i].dsdy = qs[i].dsdy * 0.5f, half[i].dtdy = qs[i].dtdy * 0.5f;
    }
    sb.wrap_s = sb.wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
    memcpy(sb.border_color, fill, sizeof fill);
    run_some(NULL, big, &sb, half, NQ, 0, all);
    for (i = 0; all && i < 4 * NQ; ++i) dds[0][i] *= 0.5f, ddt[0][i] *= 0.5f;
    run_some(sys, set, s, qs, NQ, 1, all);
    return same();
}

static void test_udim(void)
{
    static const char *const patterns[2] = {"udim_<UDIM>.exr", "uv_<uvtile>.exr"};
    sample_texture *tiles[4];
    int k, p;
    for (k = 0; k < 4; ++k) tiles[k] = io_test_texture(16, 16, 4, SAMPLE_FORMAT_F32, 40u + (unsigned)k, SAMPLE_MIPGEN_BOX, 0);
    for (p = 0; p < 2; ++p) {
        /* Set p lacks tile (1, 1) when p is 1. */
        const int mask = p ? 7 : 15;
        sample_texsys *sys = new_system(1.0 / 64.0, 3);
        sample_texture *big = assemble(tiles, mask);
        const sample_texture *set;
        sample_texsys_info info;
        char path[1024], pattern[1024];
        int kind, fails = 0;
        for (k = 0; k < 4; ++k) {
            char name[64];
            if (!(mask >> k & 1)) continue;
            if (p == 0) snprintf(name, sizeof name, "udim_%04d.exr", 1001 + k % 2 + 10 * (k / 2));
            else snprintf(name, sizeof name, "uv_u%d_v%d.exr", k % 2 + 1, k / 2 + 1);
            ts_write(io_path(path, sizeof path, io_scratch, name), tiles[k], 8, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT,
                     1);
        }
        set = open_ok(sys, io_path(pattern, sizeof pattern, io_scratch, patterns[p]));
        if (!set) continue;
        CHECK(sample_texsys_texture_info(sys, set, &info, NULL) == SAMPLE_OK && info.udim && info.udim_cols == 2 &&
                  info.udim_rows == 2 && info.texture.width == 32 && info.texture.levels == 5,
              "UDIM info: %d x %d tiles, %d wide, %d levels", info.udim_cols, info.udim_rows, info.texture.width,
              info.texture.levels);
        /* The set against one texture of the tiles side by side, sampled
         * at (s / 2, t / 2) with the fill as its border. */
        for (kind = 0; kind < TS_KINDS; ++kind) {
            sample_sampler s;
            size_t i;
            ts_sampler(&s, kind);
            for (i = 0; i < NQ; ++i) {
                qs[i].s = frand(-0.2f, 2.2f);
                qs[i].t = frand(-0.2f, 2.2f);
                qs[i].dsdx = frand(-0.3f, 0.3f);
                qs[i].dtdx = frand(-0.3f, 0.3f);
                qs[i].dsdy = frand(-0.3f, 0.3f);
                qs[i].dtdy = frand(-0.3f, 0.3f);
            }
            if (!udim_same_bits(sys, set, big, &s, 1)) ++fails;
        }
        CHECK(fails == 0, "%s: %d filters differ from the tiles side by side", patterns[p], fails);
        {
            /* Tile (1, 0) alone at a texel centre; the missing tile (1, 1)
             * the fill; bilinear across the edge of tiles (0, 0) and (1, 0)
             * halfway between their texels. */
            sample_sampler s;
            sample_query q = {0};
            float out[4], a[4], b[4];
            sample_batch_args ba;
            sample_sampler_init(&s);
            s.min_filter = s.mag_filter = SAMPLE_NEAREST;
            memset(&ba, 0, sizeof ba);
            ba.count = 1;
            ba.queries = &q;
            ba.rgba = out;
            q.s = 1.0f + 3.5f / 16.0f;
            q.t = 5.5f / 16.0f;
            CHECK(sample_texsys_batch(sys, set, &s, &ba) == SAMPLE_OK, "batch");
            sample_texture_texel(tiles[1], 0, 3, 5, a);
            CHECK(!memcmp(out, a, sizeof a), "tile 1002 texel (3, 5)");
            q.t = 1.5f;
            CHECK(sample_texsys_batch(sys, set, &s, &ba) == SAMPLE_OK, "batch");
            if (p) CHECK(!memcmp(out, fill, sizeof fill), "missing tile: the fill %g", out[0]);
            s.mag_filter = SAMPLE_LINEAR;
            q.s = 1.0f;
            q.t = 5.5f / 16.0f;
            CHECK(sample_texsys_batch(sys, set, &s, &ba) == SAMPLE_OK, "batch");
            sample_texture_texel(tiles[0], 0, 15, 5, a);
            sample_texture_texel(tiles[1], 0, 0, 5, b);
            CHECK(out[0] == 0.5f * a[0] + 0.5f * b[0], "across the edge: %g, texels %g %g", out[0], a[0], b[0]);
        }
        sample_texture_destroy(big);
        sample_texsys_destroy(sys);
    }
    for (k = 0; k < 4; ++k) sample_texture_destroy(tiles[k]);
}

/* texel() calls of the set's source, counted (test_udim_fast). */
static const unsigned char *(*udim_inner)(const struct ls_texel_source *, int, int, int, int);
static unsigned long udim_calls;
static const unsigned char *udim_counted(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    ++udim_calls;
    return udim_inner(src, lv, i, j, layer);
}

/* UDIM sets on the fast path (texsys_udim.c, declare_tiles): 32 × 32
 * tiles in file tiles of 8 declare tiles of 8 on the levels 32, 16, 8 and
 * read the levels 4, 2, 1 (where a tile of 8 spans files) texel by texel;
 * random queries crossing the edges between UDIM tiles, a complete set and
 * one lacking tile (1, 0), give the tiles side by side's bits for
 * bilinear, trilinear, bicubic and anisotropic ×16, with derivatives and
 * values alone (the planned-ahead anisotropic probes); bilinear blocks
 * inside a tile take at most one texel() call each. */
static void test_udim_fast(void)
{
    static const char *const names[2] = {"fast_<UDIM>.exr", "fastm_<UDIM>.exr"};
    static const int masks[2] = {15, 13};
    sample_texture *tiles[4];
    int k, p;
    for (k = 0; k < 4; ++k) tiles[k] = io_test_texture(32, 32, 4, SAMPLE_FORMAT_F32, 60u + (unsigned)k, SAMPLE_MIPGEN_BOX, 0);
    for (p = 0; p < 2; ++p) {
        sample_texsys *sys = new_system(1.0 / 32.0, 4);
        sample_texture *big = assemble(tiles, masks[p]);
        const sample_texture *set;
        char path[1024];
        int kind, fails = 0;
        for (k = 0; k < 4; ++k) {
            char name[64];
            if (!(masks[p] >> k & 1)) continue;
            snprintf(name, sizeof name, "fast%s_%04d.exr", p ? "m" : "", 1001 + k % 2 + 10 * (k / 2));
            ts_write(io_path(path, sizeof path, io_scratch, name), tiles[k], 8, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT,
                     1);
        }
        set = open_ok(sys, io_path(path, sizeof path, io_scratch, names[p]));
        if (!set) continue;
        CHECK(set->nlevels == 6 && set->source->tile_side == 8 && set->source->tile_levels == 3,
              "%s: %d levels, tiles of %d on %d levels", names[p], set->nlevels, set->source->tile_side,
              set->source->tile_levels);
        for (kind = 0; kind < 8; ++kind) {
            sample_sampler s;
            size_t i;
            sample_sampler_init(&s);
            s.mag_filter = kind % 4 == 2 ? SAMPLE_CUBIC : SAMPLE_LINEAR;
            s.min_filter = kind % 4 == 0   ? SAMPLE_LINEAR
                           : kind % 4 == 2 ? SAMPLE_CUBIC_MIPMAP_LINEAR
                                           : SAMPLE_LINEAR_MIPMAP_LINEAR;
            if (kind % 4 == 3) s.footprint = SAMPLE_FOOTPRINT_ANISOTROPIC, s.max_anisotropy = 16.0f;
            for (i = 0; i < NQ; ++i) {
                /* Near the edges s = 1, t = 1 of the tiles most of the time;
                 * footprints from a texel of level 0 to the whole set. */
                const float d = ldexpf(frand(0.5f, 1.0f), -(int)(rnd() % 7)) * (i % 3 == 0 ? 1.0f : 1.0f / 32.0f);
                const float a = frand(0.0f, 6.2831853f), e = i % 2 ? 1.0f : frand(1.0f, 16.0f);
                qs[i].s = rnd() % 3 ? 1.0f + frand(-0.15f, 0.15f) : frand(-0.1f, 2.1f);
                qs[i].t = rnd() % 3 ? 1.0f + frand(-0.15f, 0.15f) : frand(-0.1f, 2.1f);
                qs[i].dsdx = d * e * cosf(a), qs[i].dtdx = d * e * sinf(a);
                qs[i].dsdy = -d * sinf(a), qs[i].dtdy = d * cosf(a);
            }
            if (!udim_same_bits(sys, set, big, &s, kind < 4) && fails++ < 4)
                fprintf(stderr, "%s: filter %d%s differs from the tiles side by side\n", names[p], kind % 4,
                        kind < 4 ? "" : " (values only)");
        }
        CHECK(fails == 0, "%s: %d filters differ from the tiles side by side", names[p], fails);
        {
            /* Bilinear on level 0, each 2 × 2 block inside one file tile
             * of tile (0, 0) or (0, 1): at most one texel() call a query
             * (the reference path makes four). */
            sample_sampler s;
            size_t i;
            sample_sampler_init(&s);
            s.min_filter = s.mag_filter = SAMPLE_LINEAR;
            for (i = 0; i < NQ; ++i) {
                memset(&qs[i], 0, sizeof qs[i]);
                qs[i].s = (float)(8 * (int)(rnd() % 4) + 2) / 32.0f + 0.3f / 32.0f;
                qs[i].t = (float)(8 * (int)(rnd() % 8) + 2) / 32.0f + 0.3f / 32.0f;
            }
            udim_inner = set->source->texel;
            set->source->texel = udim_counted;
            udim_calls = 0;
            run_some(sys, set, &s, qs, NQ, 1, 0);
            set->source->texel = udim_inner;
            CHECK(udim_calls > 0 && udim_calls <= NQ, "%s: %lu texel() calls for %d bilinear queries", names[p],
                  udim_calls, (int)NQ);
        }
        sample_texture_destroy(big);
        sample_texsys_destroy(sys);
    }
    for (k = 0; k < 4; ++k) sample_texture_destroy(tiles[k]);
}

static void test_bad_arguments(void)
{
    sample_texsys_options o;
    sample_texsys *sys = (sample_texsys *)&o;
    sample_error e;
    const sample_texture *t = (const sample_texture *)&o;
    sample_texsys_options_init(&o);
    o.max_memory_mb = 0;
    CHECK(sample_texsys_create(&o, &sys, &e) == SAMPLE_E_INVALID_ARGUMENT && !sys && strstr(e.message, "max_memory"),
          "memory 0: %s", e.message);
    sample_texsys_options_init(&o);
    o.max_open_files = 0;
    CHECK(sample_texsys_create(&o, &sys, &e) == SAMPLE_E_INVALID_ARGUMENT, "no files");
    CHECK(sample_texsys_create(NULL, &sys, &e) == SAMPLE_OK, "defaults");
    CHECK(sample_texsys_open(sys, "", &t, &e) == SAMPLE_E_INVALID_ARGUMENT && !t, "empty name");
    CHECK(sample_texsys_open(sys, io_scratch, &t, &e) == SAMPLE_E_IO, "a directory: %s", e.message);
    CHECK(sample_texsys_open(sys, "none_<UDIM>.exr", &t, &e) == SAMPLE_E_IO, "an empty UDIM set: %s", e.message);
    sample_texsys_destroy(sys);
    {
        /* 64 × 64 in tiles of 4: 343 tiles over 7 levels, a table of 2744
         * bytes, more than a cache of 2 KiB. */
        sample_texture *src = io_test_texture(64, 64, 1, SAMPLE_FORMAT_F16, 9, SAMPLE_MIPGEN_BOX, 0);
        char path[1024];
        ts_write(io_path(path, sizeof path, io_scratch, "tiny_tiles.exr"), src, 4, SAMPLE_WRAP_REPEAT,
                 SAMPLE_WRAP_REPEAT, 0);
        sample_texture_destroy(src);
        sys = new_system(2.0 / 1024.0, 4);
        CHECK(sample_texsys_open(sys, path, &t, &e) == SAMPLE_E_TOO_LARGE && strstr(e.message, "343 tiles"),
              "a tile table over the limit: %s", e.message);
        sample_texsys_destroy(sys);
    }
    sample_texsys_destroy(NULL);
}

/* Runs `prog args` in the scratch folder: the image program, or with
 * front = 1 the front program beside it (libsample alone: it reports usage
 * errors without loading OpenImageIO). */
static int run_texsample(int front, const char *args)
{
    char cmd[4096], prog[2048];
    const char *slash = strrchr(texsample, '/');
    int st;
    if (front && slash)
        snprintf(prog, sizeof prog, "%.*s/texsample", (int)(slash - texsample), texsample);
    else
        snprintf(prog, sizeof prog, "%s", texsample);
    snprintf(cmd, sizeof cmd, "cd '%s' && OCIO= timeout 20 '%s' %s >out.txt 2>err.txt", io_scratch, prog, args);
    st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* texsample lookup --cache-mb: the results of the texture loaded whole,
 * bit for bit (EWA, the file's wrap modes), through a cache of a fraction
 * of it; a usage error exits 2. */
static void test_lookup_cli(void)
{
    static float q[NQ * 6], a[NQ * 4];
    char path[1024];
    FILE *f;
    sample_texture *src, *resident;
    sample_sampler s;
    sample_batch_args args;
    if (!texsample) {
        check_skip("texsample is not built");
        return;
    }
    src = io_test_texture(100, 70, 4, SAMPLE_FORMAT_F16, 5, SAMPLE_MIPGEN_BOX, 0);
    ts_write(io_path(path, sizeof path, io_scratch, "cli.exr"), src, 16, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE,
             0);
    sample_texture_destroy(src);
    resident = ts_resident(path);
    ts_queries((sample_query *)(void *)q, NQ);
    f = fopen(io_path(path, sizeof path, io_scratch, "cli_q.raw"), "wb");
    CHECK(f && fwrite(q, sizeof q, 1, f) == 1, "queries");
    if (f) fclose(f);
    CHECK(run_texsample(0, "lookup --image cli.exr --queries cli_q.raw --out b.raw --min linear_mipmap_linear "
                           "--filter ewa --cache-mb 0.004 --stats") == 0,
          "cached lookup");
    f = fopen(io_path(path, sizeof path, io_scratch, "b.raw"), "rb");
    CHECK(f && fread(rgba[1], sizeof(float) * 4 * NQ, 1, f) == 1, "read results");
    if (f) fclose(f);
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    s.footprint = SAMPLE_FOOTPRINT_EWA;
    s.wrap_s = SAMPLE_WRAP_REPEAT;
    s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    memset(&args, 0, sizeof args);
    args.count = NQ;
    args.queries = (const sample_query *)(const void *)q;
    args.rgba = a;
    CHECK(resident && sample_batch(resident, &s, &args) == SAMPLE_OK, "resident");
    CHECK(!memcmp(a, rgba[1], sizeof a), "lookup --cache-mb differs from the texture loaded whole");
    CHECK(run_texsample(1, "lookup --raw x.raw --w 1 --h 1 --queries cli_q.raw --cache-mb 1") == 2, "--raw refused");
    sample_texture_destroy(resident);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: texsys_cache TESTIMAGES SCRATCH [TEXSAMPLE]\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    texsample = argc > 3 && argv[3][0] ? argv[3] : NULL;
    RUN(test_same_bits);
    RUN(test_direct_reader);
    RUN(test_truncated);
    RUN(test_corrupt);
    RUN(test_gone_and_unreadable);
    RUN(test_memory_refused);
    RUN(test_open_file_limit);
    RUN(test_independent_systems);
    RUN(test_udim);
    RUN(test_udim_fast);
    RUN(test_bad_arguments);
    RUN(test_lookup_cli);
    io_colour_close(ts_col);
    return check_finish();
}
