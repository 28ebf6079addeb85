/*
 * Thread safety (DESIGN §10), once per instruction set this CPU runs
 * (isa_util.h): each has its own fast-path kernels for the GL filters and
 * the footprint walks (fast_gl.c, footprint_rows.c; doc/performance.md,
 * "Run-time ISA dispatch"), so each is run under ThreadSanitizer in CI
 * (doc/testing.md). In every round
 *   - sampler threads sample one shared texture, each with its own
 *     sampler state and batch size: the GL filters, cubic, and every
 *     footprint filter (anisotropic, Blinn–Newell from derivatives and
 *     from exact corners, EWA), some with derivatives and stats;
 *   - churn threads meanwhile create, sample and destroy textures of
 *     their own, in every texel format, with the same filters;
 * and every result must equal, bit for bit, the reference path's
 * (sample_batch_reference, one query at a time, no instruction-set
 * kernels). A last round runs on the automatic choice while one more
 * thread switches the instruction set process-wide (sample_isa_force),
 * which a batch already running must not notice.
 */
#include "check.h"
#include "isa_util.h"
#include "sample/sample.h"

#include <pthread.h>
#include <stdlib.h>

enum { W = 64, H = 48, NQ = 1000, NSAMPLERS = 8, NSAMPLE_THREADS = 8, NCHURN = 2, CHURN_Q = 48 };

/* The shared texture's queries, corners and single-threaded reference
 * results (values, ∂/∂s, ∂/∂t, stats) per sampler. */
static sample_texture *shared_tex;
static sample_query queries[NQ];
static sample_quad corners[NQ];
static sample_sampler samplers[NSAMPLERS];
typedef struct {
    float rgba[NQ * 4], ds[NQ * 4], dt[NQ * 4];
    sample_stats st[NQ];
} outputs;
static outputs expected[NSAMPLERS];

static uint32_t next_rand(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u; /* Numerical Recipes' LCG */
    return *state >> 8;
}
static float urand(uint32_t *state, float lo, float hi)
{
    return lo + (hi - lo) * (float)next_rand(state) / 16777216.0f;
}

/* Sampler k of NSAMPLERS: every footprint filter, under different GL
 * filters, wraps and anisotropy limits. Samplers 3 and 7 (Blinn–Newell)
 * are given exact corners; odd ones also ask for derivatives and stats. */
static void make_sampler(sample_sampler *s, int k)
{
    sample_sampler_init(s);
    s->wrap_s = (sample_wrap)(k % SAMPLE_WRAP_COUNT);
    s->wrap_t = (sample_wrap)((k + 3) % SAMPLE_WRAP_COUNT);
    s->min_filter = (sample_filter)(SAMPLE_NEAREST_MIPMAP_NEAREST + k % 4);
    s->mag_filter = k == 5 ? SAMPLE_CUBIC : SAMPLE_LINEAR;
    s->footprint = (sample_footprint)((k + 3) % SAMPLE_FOOTPRINT_COUNT);
    s->max_anisotropy = k < 4 ? 8.0f : 16.0f;
    if (k == 6) s->min_filter = SAMPLE_CUBIC_MIPMAP_LINEAR;
}
static int wants_corners(const sample_sampler *s) { return s->footprint == SAMPLE_FOOTPRINT_BLINN_NEWELL; }

/* Queries [first, first+count) of `q` on `tex` into `out` at the same
 * offsets, through the reference path or sample_batch. */
static sample_status run_batch(const sample_texture *tex, const sample_sampler *s, int reference,
                               int extras, const sample_query *q, const sample_quad *quad,
                               size_t first, size_t count, outputs *out)
{
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    a.count = count;
    a.queries = q + first;
    a.corners = wants_corners(s) ? quad + first : NULL;
    a.rgba = out->rgba + 4 * first;
    if (extras) {
        a.drgba_ds = out->ds + 4 * first;
        a.drgba_dt = out->dt + 4 * first;
        a.stats = out->st + first;
    }
    return reference ? sample_batch_reference(tex, s, &a) : sample_batch(tex, s, &a);
}

static int same(const outputs *x, const outputs *y, size_t n, int extras)
{
    return !memcmp(x->rgba, y->rgba, sizeof(float) * 4 * n) &&
           (!extras || (!memcmp(x->ds, y->ds, sizeof(float) * 4 * n) &&
                        !memcmp(x->dt, y->dt, sizeof(float) * 4 * n) &&
                        !memcmp(x->st, y->st, sizeof(sample_stats) * n)));
}

static void random_queries(uint32_t *rs, sample_query *q, sample_quad *quad, size_t n, float scale)
{
    size_t k;
    int c;
    for (k = 0; k < n; ++k) {
        q[k].s = urand(rs, -0.5f, 1.5f);
        q[k].t = urand(rs, -0.5f, 1.5f);
        q[k].dsdx = urand(rs, 0.0f, 0.2f) * scale;
        q[k].dtdx = urand(rs, -0.05f, 0.05f) * scale;
        q[k].dsdy = urand(rs, -0.03f, 0.03f) * scale;
        q[k].dtdy = urand(rs, 0.0f, 0.1f) * scale;
        /* A parallelogram around (s, t) with a little perspective. */
        for (c = 0; c < 4; ++c) {
            float x = (c == 1 || c == 2) ? 1.0f : -1.0f, y = c >= 2 ? 1.0f : -1.0f;
            quad[k].st[c][0] = q[k].s + x * q[k].dsdx + y * q[k].dsdy + urand(rs, -0.002f, 0.002f);
            quad[k].st[c][1] = q[k].t + x * q[k].dtdx + y * q[k].dtdy + urand(rs, -0.002f, 0.002f);
        }
    }
}

typedef struct { int id; int mismatches; int failures; } job;

static void *sampler_thread(void *arg)
{
    job *j = (job *)arg;
    int sidx = j->id % NSAMPLERS, extras = sidx & 1, rep;
    size_t batch = (size_t)(1 + 37 * j->id), k;
    outputs *out = (outputs *)calloc(1, sizeof *out);
    if (!out) return NULL;
    for (rep = 0; rep < 2; ++rep) {
        for (k = 0; k < NQ; k += batch)
            if (run_batch(shared_tex, &samplers[sidx], 0, extras, queries, corners, k,
                          k + batch <= NQ ? batch : NQ - k, out) != SAMPLE_OK)
                j->failures++;
        if (!same(out, &expected[sidx], NQ, extras)) j->mismatches++;
    }
    free(out);
    return NULL;
}

/* Textures of every format and of sizes 1 … 50 texels a side, each created,
 * sampled (fast and reference path, compared) and destroyed while the
 * sampler threads work on the shared one. */
static void *churn_thread(void *arg)
{
    job *j = (job *)arg;
    uint32_t rs = 7u + (uint32_t)j->id;
    static const size_t texel_bytes[SAMPLE_FORMAT_COUNT] = {4, 2, 1, 1};
    outputs *got = (outputs *)calloc(1, sizeof *got), *ref = (outputs *)calloc(1, sizeof *ref);
    sample_query q[CHURN_Q];
    sample_quad quad[CHURN_Q];
    int k;
    for (k = 0; got && ref && k < 24; ++k) {
        int w = 1 + (k * 7 + j->id) % 50, h = 1 + (k * 3) % 20, nc = 1 + k % 4;
        sample_format f = (sample_format)(k % SAMPLE_FORMAT_COUNT);
        size_t n = (size_t)w * (size_t)h * (size_t)nc * texel_bytes[f], b;
        unsigned char *px = (unsigned char *)malloc(n);
        sample_image im = {w, h, nc, f, px, 0};
        sample_mip_params mp;
        sample_texture *t = NULL;
        sample_sampler s;
        if (!px) break;
        /* Finite texels only, so that every result is a number and
         * memcmp compares them: halves with the sign clear and an
         * exponent field of at most 29 (0x77ff), floats in [0, 1). */
        for (b = 0; b < n / texel_bytes[f]; ++b) {
            if (f == SAMPLE_FORMAT_F32) ((float *)px)[b] = urand(&rs, 0.0f, 1.0f);
            else if (f == SAMPLE_FORMAT_F16) ((uint16_t *)px)[b] = (uint16_t)(next_rand(&rs) & 0x77ffu);
            else px[b] = (unsigned char)next_rand(&rs);
        }
        sample_mip_params_init(&mp);
        if (sample_texture_create(&im, &mp, &t, NULL) != SAMPLE_OK) {
            j->failures++;
        } else {
            make_sampler(&s, k % NSAMPLERS);
            random_queries(&rs, q, quad, CHURN_Q, 8.0f);
            if (run_batch(t, &s, 0, 1, q, quad, 0, CHURN_Q, got) != SAMPLE_OK ||
                run_batch(t, &s, 1, 1, q, quad, 0, CHURN_Q, ref) != SAMPLE_OK)
                j->failures++;
            else if (!same(got, ref, CHURN_Q, 1))
                j->mismatches++;
        }
        sample_texture_destroy(t);
        free(px);
    }
    free(got);
    free(ref);
    return NULL;
}

/* Switches the instruction set process-wide, over and over, among those
 * this CPU runs, while the other threads sample. */
static int switching_done; /* under switch_lock */
static pthread_mutex_t switch_lock = PTHREAD_MUTEX_INITIALIZER;
static void *switch_thread(void *arg)
{
    int i = 0, stop = 0;
    (void)arg;
    while (!stop) {
        sample_isa_force(test_isa_names[i++ % SAMPLE_ISA_COUNT]); /* −3 where the CPU lacks it: unchanged */
        pthread_mutex_lock(&switch_lock);
        stop = switching_done;
        pthread_mutex_unlock(&switch_lock);
    }
    return NULL;
}

/* One round: the sampler and churn threads at once (and the switcher if
 * asked); every thread's results as the reference's. */
static void round_of_threads(const char *what, int with_switcher)
{
    enum { NT = NSAMPLE_THREADS + NCHURN };
    pthread_t th[NT], sw;
    job jobs[NT];
    int k;
    if (with_switcher) CHECK(pthread_create(&sw, NULL, switch_thread, NULL) == 0, "spawn switcher");
    for (k = 0; k < NT; ++k) {
        jobs[k].id = k;
        jobs[k].mismatches = jobs[k].failures = 0;
        CHECK(pthread_create(&th[k], NULL, k < NSAMPLE_THREADS ? sampler_thread : churn_thread, &jobs[k]) == 0,
              "spawn");
    }
    for (k = 0; k < NT; ++k) {
        pthread_join(th[k], NULL);
        CHECK(jobs[k].mismatches == 0 && jobs[k].failures == 0, "%s: %s thread %d: %d differing runs, %d errors",
              what, k < NSAMPLE_THREADS ? "sampler" : "churn", k, jobs[k].mismatches, jobs[k].failures);
    }
    if (with_switcher) {
        pthread_mutex_lock(&switch_lock);
        switching_done = 1; /* once: the switching round is the last */
        pthread_mutex_unlock(&switch_lock);
        pthread_join(sw, NULL);
    }
}

static void concurrent_sampling(void)
{
    float *px = (float *)malloc(sizeof(float) * W * H * 4);
    sample_image im = {W, H, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mp;
    uint32_t rs = 11u;
    int k, i;
    CHECK(px != NULL, "allocation");
    if (!px) return;
    for (k = 0; k < W * H * 4; ++k) px[k] = urand(&rs, 0.0f, 1.0f);
    random_queries(&rs, queries, corners, NQ, 1.0f);
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &shared_tex, NULL) == SAMPLE_OK, "create");
    for (k = 0; k < NSAMPLERS; ++k) {
        make_sampler(&samplers[k], k);
        CHECK(run_batch(shared_tex, &samplers[k], 1, 1, queries, corners, 0, NQ, &expected[k]) == SAMPLE_OK,
              "reference, sampler %d", k);
    }
    for (i = 0; i < SAMPLE_ISA_COUNT; ++i)
        if (test_isa_enter(test_isa_names[i])) round_of_threads(test_isa_names[i], 0);
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
    round_of_threads("switching", 1);
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
    sample_texture_destroy(shared_tex);
    free(px);
}

int main(void)
{
    RUN(concurrent_sampling);
    return check_finish();
}
