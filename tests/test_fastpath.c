/*
 * The fast path of sample_batch (fast_gl.c) against the reference path
 * (sample_batch_reference, sample/testing.h): for every format × channel count, wrap mode,
 * OpenGL min/mag filter (cubic included) and option, random queries in
 * range, out of range, huge, negative and non-finite (and the same sets
 * with every float finite, which the fast path plans in passes), with and without
 * derivatives, per-query bias, corners and stats, the results must be
 * memcmp-identical — and stay so for any batch size and thread count.
 *
 * All of it runs once per instruction set the fast path was built for and
 * this CPU runs (isa.c: scalar, SSE2, AVX2, AVX-512), on the same query
 * sets, against one reference: the reference path, one query at a time
 * with the reference readers. So every build is checked against the same bits, not only
 * against itself.
 */
#include "check.h"
#include "internal.h"
#include "isa_util.h"
#include "query_gen.h"

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>

/* The instruction set under test. */
static const char *test_isa = "scalar";

static void random_sampler(sample_sampler *s, int wrap, int min)
{
    static const sample_filter mags[3] = {SAMPLE_NEAREST, SAMPLE_LINEAR, SAMPLE_CUBIC};
    sample_sampler_init(s);
    s->wrap_s = (sample_wrap)wrap;
    s->wrap_t = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
    if (rnd() & 1) { /* swap, so that every mode is tested on both axes */
        sample_wrap x = s->wrap_s;
        s->wrap_s = s->wrap_t;
        s->wrap_t = x;
    }
    s->min_filter = (sample_filter)min;
    s->mag_filter = mags[rnd() % 3];
    s->cubic = (sample_cubic)(rnd() % SAMPLE_CUBIC_COUNT);
    s->options = rnd() & (SAMPLE_OPT_LEGACY_SWITCHOVER | SAMPLE_OPT_NEAREST_LEVEL_FLOOR | SAMPLE_OPT_CUBIC_CLAMP);
    s->border_color[0] = 0.25f;
    s->border_color[1] = -2.0f;
    s->border_color[2] = 7.0f;
    s->border_color[3] = 0.5f;
    if (rnd() % 4 == 0) s->lod_bias = frand(-3.0f, 3.0f);
    if (rnd() % 4 == 0) s->base_level = (int)(rnd() % 3);
    if (rnd() % 4 == 0) s->max_level = s->base_level + (int)(rnd() % 3);
    if (rnd() % 8 == 0) s->min_lod = frand(-1.0f, 2.0f), s->max_lod = s->min_lod + frand(0.0f, 3.0f);
}

enum { NQ = 240 };

typedef struct outputs {
    float rgba[NQ * 4], ds[NQ * 4], dt[NQ * 4];
    sample_stats st[NQ];
} outputs;

static void fill_queries(sample_query *q, float *bias, sample_quad *quad)
{
    int i, k;
    for (i = 0; i < NQ; ++i) {
        q[i].s = coord();
        q[i].t = rnd() % 3 ? coord() : q[i].s;
        q[i].dsdx = deriv();
        q[i].dtdx = deriv();
        q[i].dsdy = deriv();
        q[i].dtdy = deriv();
        bias[i] = rnd() % 50 == 0 ? NAN : frand(-2.0f, 2.0f);
        for (k = 0; k < 4; ++k) {
            quad->st[k][0] = q[i].s;
            quad->st[k][1] = rnd() % 200 == 0 ? INFINITY : q[i].t;
        }
        ++quad;
    }
}

/* Every non-finite float of the query set replaced by a finite one of the
 * same class's size (coordinates 0.3, derivatives 1e20, biases 0.5,
 * corners the query's t), so that every block of the batch is planned as
 * passes (fast_gl.c, gl_blocks: only an all-finite block is); fill_queries
 * alone makes a non-finite float in nearly every block of 32. */
static void make_finite(sample_query *q, float *bias, sample_quad *quad)
{
    int i, k;
    for (i = 0; i < NQ; ++i) {
        float *d[4] = {&q[i].dsdx, &q[i].dtdx, &q[i].dsdy, &q[i].dtdy};
        if (!isfinite(q[i].s)) q[i].s = 0.3f;
        if (!isfinite(q[i].t)) q[i].t = 0.3f;
        for (k = 0; k < 4; ++k)
            if (!isfinite(*d[k])) *d[k] = 1e20f;
        if (!isfinite(bias[i])) bias[i] = 0.5f;
        for (k = 0; k < 4; ++k) {
            quad[i].st[k][0] = q[i].s;
            quad[i].st[k][1] = q[i].t;
        }
    }
}

/* Run `count` queries in batches of `chunk`, through the reference path
 * when `scalar`, through the fast path of test_isa otherwise; extras (derivatives, stats, bias,
 * corners) by the bits of `what`. Leaves test_isa running. */
static void run(const sample_texture *tex, sample_sampler s, int scalar, const sample_query *q,
                const float *bias, const sample_quad *quad, unsigned what, size_t chunk, outputs *o)
{
    size_t i;
    memset(o, 0xA5, sizeof *o);
    for (i = 0; i < NQ; i += chunk) {
        sample_batch_args a;
        memset(&a, 0, sizeof a);
        a.count = NQ - i < chunk ? NQ - i : chunk;
        a.queries = q + i;
        a.rgba = o->rgba + 4 * i;
        if (what & 1) a.drgba_ds = o->ds + 4 * i;
        if (what & 2) a.drgba_dt = o->dt + 4 * i;
        if (what & 4) a.stats = o->st + i;
        if (what & 8) a.lod_bias = bias + i;
        if (what & 16) a.corners = quad + i;
        CHECK((scalar ? sample_batch_reference(tex, &s, &a) : sample_batch(tex, &s, &a)) == SAMPLE_OK,
              "sample_batch");
    }
}

static int same(const outputs *x, const outputs *y, const sample_texture *tex, const sample_sampler *s,
                const sample_query *q)
{
    int i;
    if (!memcmp(x, y, sizeof *x)) return 1;
    for (i = 0; i < NQ; ++i) {
        if (memcmp(x->rgba + 4 * i, y->rgba + 4 * i, 16) || memcmp(x->ds + 4 * i, y->ds + 4 * i, 16) ||
            memcmp(x->dt + 4 * i, y->dt + 4 * i, 16) || memcmp(&x->st[i], &y->st[i], sizeof x->st[i])) {
            fprintf(stderr,
                    "%s: query %d (s %.9g t %.9g J %g %g %g %g) format %d ch %d wrap %d/%d min %d mag %d "
                    "footprint %d: %.9g %.9g vs %.9g %.9g\n",
                    test_isa, i, q[i].s, q[i].t, q[i].dsdx, q[i].dtdx, q[i].dsdy, q[i].dtdy,
                    (int)tex->format, tex->channels, s->wrap_s, s->wrap_t, s->min_filter, s->mag_filter,
                    (int)s->footprint, x->rgba[4 * i],
                    x->rgba[4 * i + 3], y->rgba[4 * i], y->rgba[4 * i + 3]);
            break;
        }
    }
    return 0;
}

static outputs ref, got;
static sample_query qs[NQ];
static float biases[NQ];
static sample_quad quads[NQ];

/* The reference and the fast path on the query set qs, in one batch:
 * nonzero (and a line on stderr) when they differ. */
static int differs(const sample_texture *tex, const sample_sampler *s, unsigned what)
{
    run(tex, *s, 1, qs, biases, quads, what, NQ, &ref);
    run(tex, *s, 0, qs, biases, quads, what, NQ, &got);
    return !same(&ref, &got, tex, s, qs);
}

/* Run `body` on a texture of every format and channel count at each of
 * the sizes; it returns how many configurations differed (it stops after
 * a few). One CHECK per texture, naming `what`. */
typedef int (*texture_body)(const sample_texture *tex, int w, int h);

static void for_each_texture(const int (*sizes)[2], int nsizes, texture_body body, const char *what)
{
    int f, nc, z;
    for (f = 0; f < SAMPLE_FORMAT_COUNT; ++f)
        for (nc = 1; nc <= 4; ++nc)
            for (z = 0; z < nsizes; ++z) {
                sample_texture *tex = make_texture((sample_format)f, nc, sizes[z][0], sizes[z][1]);
                int fails;
                if (!tex) continue;
                fails = body(tex, sizes[z][0], sizes[z][1]);
                CHECK(fails == 0, "%d %s differ (format %d, %d channels, %d x %d)", fails, what, f, nc,
                      sizes[z][0], sizes[z][1]);
                sample_texture_destroy(tex);
            }
}

/* Every wrap mode with every min filter (no footprint filter), or with
 * every footprint filter (min LINEAR_MIPMAP_LINEAR, max_anisotropy 16: the
 * fast path takes their λ ≤ 0 queries, the mag filter, and hands the
 * others to the filter); random mag filter and extras. */
static int wrap_cases(const sample_texture *tex, int footprints)
{
    int wrap, k, fails = 0, n = footprints ? SAMPLE_FOOTPRINT_COUNT - 1 : SAMPLE_FILTER_COUNT;
    for (wrap = 0; wrap < SAMPLE_WRAP_COUNT; ++wrap)
        for (k = 0; k < n; ++k) {
            sample_sampler s;
            unsigned what = rnd() & 31;
            random_sampler(&s, wrap, footprints ? SAMPLE_LINEAR_MIPMAP_LINEAR : k);
            if (footprints) {
                s.footprint = (sample_footprint)(k + 1);
                s.max_anisotropy = 16.0f;
            }
            fill_queries(qs, biases, quads);
            if (k & 1) make_finite(qs, biases, quads);
            if (differs(tex, &s, what) && ++fails > 5) return fails;
        }
    return fails;
}

static int all_combinations(const sample_texture *tex, int w, int h)
{
    (void)w;
    (void)h;
    return wrap_cases(tex, 0);
}

static void test_identical_all_combinations(void)
{
    /* Sizes: an odd non-power-of-two pyramid, a power-of-two one, and a
     * one-texel-wide strip (every bilinear footprint wraps). */
    static const int sizes[3][2] = {{13, 7}, {16, 8}, {1, 5}};
    for_each_texture(sizes, 3, all_combinations, "configurations");
}

static void test_batch_sizes(void)
{
    static const size_t chunks[4] = {1, 7, 16, 1000};
    sample_texture *tex = make_texture(SAMPLE_FORMAT_F16, 4, 37, 21);
    int rep, c;
    for (rep = 0; rep < 40; ++rep) {
        sample_sampler s;
        unsigned what = 31;
        random_sampler(&s, (int)(rnd() % SAMPLE_WRAP_COUNT), (int)(rnd() % SAMPLE_FILTER_COUNT));
        fill_queries(qs, biases, quads);
        if (rep & 1) make_finite(qs, biases, quads);
        run(tex, s, 1, qs, biases, quads, what, NQ, &ref);
        for (c = 0; c < 4; ++c) {
            run(tex, s, 0, qs, biases, quads, what, chunks[c], &got);
            CHECK(same(&ref, &got, tex, &s, qs), "batch size %zu differs", chunks[c]);
        }
    }
    sample_texture_destroy(tex);
}

typedef struct job {
    const sample_texture *tex;
    const sample_sampler *s;
    size_t first, count;
    float *rgba;
} job;

static void *worker(void *p)
{
    job *j = (job *)p;
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    a.count = j->count;
    a.queries = qs + j->first;
    a.rgba = j->rgba + 4 * j->first;
    sample_batch(j->tex, j->s, &a);
    return NULL;
}

static void test_threads(void)
{
    sample_texture *tex = make_texture(SAMPLE_FORMAT_SRGB8, 3, 64, 64);
    sample_sampler s;
    static float par[NQ * 4];
    int nt, t;
    random_sampler(&s, SAMPLE_WRAP_REPEAT, SAMPLE_LINEAR_MIPMAP_LINEAR);
    fill_queries(qs, biases, quads);
    run(tex, s, 1, qs, biases, quads, 0, NQ, &ref);
    for (nt = 2; nt <= 4; ++nt) {
        pthread_t th[4];
        job jobs[4];
        for (t = 0; t < nt; ++t) {
            jobs[t].tex = tex;
            jobs[t].s = &s;
            jobs[t].first = (size_t)NQ * t / nt;
            jobs[t].count = (size_t)NQ * (t + 1) / nt - jobs[t].first;
            jobs[t].rgba = par;
            CHECK(pthread_create(&th[t], NULL, worker, &jobs[t]) == 0, "pthread_create");
        }
        for (t = 0; t < nt; ++t) pthread_join(th[t], NULL);
        CHECK(!memcmp(par, ref.rgba, sizeof par), "%d threads differ", nt);
    }
    sample_texture_destroy(tex);
}

static int footprint_samplers(const sample_texture *tex, int w, int h)
{
    (void)w;
    (void)h;
    return wrap_cases(tex, 1);
}

static void test_footprint_samplers(void)
{
    static const int sizes[2][2] = {{13, 7}, {16, 8}};
    for_each_texture(sizes, 2, footprint_samplers, "footprint configurations");
}

/* The footprint filters' common case: the whole footprint inside both
 * levels of a texture larger than it. For the anisotropic filter the fast
 * path addresses its probes when it plans the query (fast_gl.c,
 * aniso_address): footprints of 1 to 24 probes (above 16 the probes are
 * read one at a time); Feline's weighted probe sets take the same path
 * (up to FP_PROBES_MAX probes addressed). For Blinn–Newell and EWA every row's span lies in
 * the level, so whole rows and columns are read where they lie (float
 * RGBA) or decoded by the format's reader (fast_gl.c, decode_row;
 * footprint.h, fp_span_texels), spans of odd and even length. At random angles and λ', on wraps with and without a
 * coordinate transform; values only, values with stats, and with
 * derivatives (the anisotropic filter then reads one probe at a time). */
static sample_footprint inside_filter;

static int footprint_inside(const sample_texture *tex, int w, int h)
{
    int rep, i, fails = 0;
    (void)h;
    for (rep = 0; rep < 6; ++rep) {
        sample_sampler s;
        unsigned what = rep < 3 ? 0u : (rep == 3 ? 4u : (unsigned)(rnd() & 7));
        sample_sampler_init(&s);
        s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
        s.footprint = inside_filter;
        s.max_anisotropy = rep == 2 ? 32.0f : 16.0f;
        s.wrap_s = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
        s.wrap_t = rep == 1 ? SAMPLE_WRAP_CLAMP : SAMPLE_WRAP_REPEAT;
        for (i = 0; i < NQ; ++i) {
            /* Minor axis 0.6–3 texels, major up to 16 (24) times that. */
            float ang = frand(0.0f, 6.2831853f), minor = frand(0.6f, 3.0f) / (float)w;
            float major = minor * frand(1.0f, rep == 2 ? 24.0f : 16.0f);
            qs[i].s = frand(0.25f, 0.75f);
            qs[i].t = frand(0.25f, 0.75f);
            qs[i].dsdx = major * cosf(ang);
            qs[i].dtdx = major * sinf(ang);
            qs[i].dsdy = -minor * sinf(ang);
            qs[i].dtdy = minor * cosf(ang);
        }
        if (differs(tex, &s, what) && ++fails > 5) return fails;
    }
    return fails;
}

static void test_footprints_inside(void)
{
    static const int sizes[2][2] = {{64, 64}, {61, 37}};
    inside_filter = SAMPLE_FOOTPRINT_ANISOTROPIC;
    for_each_texture(sizes, 2, footprint_inside, "anisotropic configurations");
    inside_filter = SAMPLE_FOOTPRINT_BLINN_NEWELL;
    for_each_texture(sizes, 2, footprint_inside, "Blinn-Newell configurations inside");
    inside_filter = SAMPLE_FOOTPRINT_EWA;
    for_each_texture(sizes, 2, footprint_inside, "EWA configurations inside");
    /* Feline reads up to 77 probes a query: one (odd) size keeps it short. */
    inside_filter = SAMPLE_FOOTPRINT_FELINE;
    for_each_texture(sizes + 1, 1, footprint_inside, "Feline configurations inside");
}

/* λ four queries at a time (lod_lanes.h) against the general path's, on
 * Jacobians that take sample_log2's special cases — zero (λ_base = −inf),
 * ρ² an exact power of two (exactly its exponent), from the smallest
 * subnormal float to the largest exponents, ρx² = ρy² — and ordinary ones;
 * every float finite, so every block is planned in passes. The stats
 * carry λ (clamped at ±1e30 only), the values follow it. */
static void test_lambda_lanes(void)
{
    sample_texture *tex = make_texture(SAMPLE_FORMAT_F32, 1, 64, 64);
    sample_sampler s;
    int rep, i, fails = 0;
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    s.min_lod = -1e30f;
    s.max_lod = 1e30f;
    for (rep = 0; rep < 20; ++rep) {
        for (i = 0; i < NQ; ++i) {
            float d[4] = {0.0f, 0.0f, 0.0f, 0.0f}, a = frand(-1.0f, 1.0f), b = frand(-1.0f, 1.0f);
            int k, e = (int)(rnd() % 277) - 149; /* 2^e: every float exponent, subnormals too */
            switch (rnd() % 6) {
            case 0: break;
            case 1: d[rnd() % 4] = (rnd() & 1 ? -1.0f : 1.0f) * ldexpf(1.0f, e); break;
            case 2: /* ρ² = 25·2^2e·64²: not a power of two */
                d[0] = 3.0f * ldexpf(1.0f, e < 125 ? e : 125);
                d[1] = 4.0f * ldexpf(1.0f, e < 125 ? e : 125);
                break;
            case 3:
                for (k = 0; k < 4; ++k) d[k] = frand(-1.0f, 1.0f) * ldexpf(1.0f, (int)(rnd() % 250) - 125);
                break;
            case 4: d[0] = d[3] = a, d[1] = d[2] = b; break; /* ρx² = ρy² */
            default:
                for (k = 0; k < 4; ++k) d[k] = 0.3f * frand(-1.0f, 1.0f);
            }
            qs[i] = (sample_query){frand(0.0f, 1.0f), frand(0.0f, 1.0f), d[0], d[1], d[2], d[3]};
        }
        if (differs(tex, &s, 4) && ++fails > 5) break;
    }
    CHECK(fails == 0, "%d query sets differ", fails);
    sample_texture_destroy(tex);
}

/* floats_finite's bit test against isfinite on the boundaries of every
 * class (±0, subnormals, FLT_MAX, ±inf, quiet and signalling NaNs) and on
 * random bit patterns; batch_range_finite sees a non-finite float in any
 * field of any query of a block, its bias or its corners. */
static void test_range_finite(void)
{
    static const uint32_t edge[] = {0x00000000u, 0x80000000u, 0x00000001u, 0x807fffffu, 0x00800000u,
                                    0x7f7fffffu, 0xff7fffffu, 0x7f800000u, 0xff800000u, 0x7f800001u,
                                    0x7fc00000u, 0xffffffffu, 0x7fffffffu, 0x3f800000u};
    sample_query q[40];
    sample_quad quad[40];
    float bias[40];
    sample_batch_args a;
    size_t k, f;
    uint32_t w;
    float x;
    for (k = 0; k < sizeof edge / sizeof edge[0]; ++k) {
        memcpy(&x, &edge[k], 4);
        CHECK(floats_finite(&x, 1) == (isfinite(x) != 0), "bits %08x", (unsigned)edge[k]);
    }
    for (k = 0; k < 1000000; ++k) {
        w = rnd();
        memcpy(&x, &w, 4);
        CHECK(floats_finite(&x, 1) == (isfinite(x) != 0), "bits %08x", (unsigned)w);
    }
    memset(&a, 0, sizeof a);
    for (k = 0; k < 40; ++k) {
        q[k] = (sample_query){0.5f, 0.25f, 1e-3f, 0.0f, 0.0f, 1e-3f};
        for (f = 0; f < 8; ++f) quad[k].st[f / 2][f % 2] = 0.5f;
        bias[k] = 1.0f;
    }
    a.queries = q;
    a.lod_bias = bias;
    a.corners = quad;
    a.count = 40;
    CHECK(batch_range_finite(&a, 0, 40) && batch_query_finite(&a, 39), "all finite");
    for (k = 0; k < 40; k += 13)
        for (f = 0; f < 15; ++f) {
            float *field[6] = {&q[k].s, &q[k].t, &q[k].dsdx, &q[k].dtdx, &q[k].dsdy, &q[k].dtdy};
            float *p = f < 6 ? field[f] : (f < 14 ? &quad[k].st[(f - 6) / 2][(f - 6) % 2] : &bias[k]);
            float keep = *p;
            *p = f & 1 ? NAN : -INFINITY;
            CHECK(!batch_range_finite(&a, 0, 40) && !batch_query_finite(&a, k), "query %zu float %zu", k, f);
            CHECK(batch_range_finite(&a, k + 1, 40 - k - 1), "after query %zu", k);
            CHECK(k == 0 || batch_range_finite(&a, 0, k), "before query %zu", k);
            *p = keep;
        }
}

int main(void)
{
    int k;
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        if (!test_isa_enter(test_isa_names[k])) continue;
        test_isa = test_isa_names[k];
        rng_state = RNG_SEED; /* the same textures and queries for every build */
        RUN(test_identical_all_combinations);
        RUN(test_footprint_samplers);
        RUN(test_footprints_inside);
        RUN(test_lambda_lanes);
        RUN(test_batch_sizes);
        RUN(test_threads);
    }
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
    RUN(test_range_finite);
    return check_finish();
}
