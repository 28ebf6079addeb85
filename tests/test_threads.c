/*
 * Thread safety (DESIGN §10): many threads sample one shared texture, each
 * with its own sampler state and batch size, while other threads create and
 * destroy textures of their own. Every result must equal the single-threaded
 * result bit for bit. CI also runs this under ThreadSanitizer.
 */
#include "check.h"
#include "sample/sample.h"

#include <pthread.h>
#include <stdlib.h>

enum { W = 64, H = 48, NQ = 2000, NSAMPLERS = 6, NTHREADS = 8 };

static sample_texture *shared_tex;
static sample_query queries[NQ];
static sample_sampler samplers[NSAMPLERS];
static float expected[NSAMPLERS][NQ * 4];

typedef struct { int id; int mismatches; } job;

static void *sampler_thread(void *arg)
{
    job *j = (job *)arg;
    int sidx = j->id % NSAMPLERS, batch = 1 + 37 * j->id, k, rep;
    float *out = (float *)malloc(sizeof(float) * 4 * NQ);
    if (!out) return NULL;
    for (rep = 0; rep < 3; ++rep) {
        for (k = 0; k < NQ; k += batch) {
            sample_batch_args a;
            memset(&a, 0, sizeof a);
            a.count = (size_t)(k + batch <= NQ ? batch : NQ - k);
            a.queries = &queries[k];
            a.rgba = &out[4 * k];
            sample_batch(shared_tex, &samplers[sidx], &a);
        }
        if (memcmp(out, expected[sidx], sizeof(float) * 4 * NQ) != 0) j->mismatches++;
    }
    free(out);
    return NULL;
}

static void *churn_thread(void *arg)
{
    job *j = (job *)arg;
    int k;
    for (k = 0; k < 40; ++k) {
        int w = 1 + (k * 7 + j->id) % 50, h = 1 + (k * 3) % 20;
        unsigned char *px = (unsigned char *)calloc((size_t)w * h * 4, 1);
        sample_image im = {w, h, 4, SAMPLE_FORMAT_SRGB8, px, 0};
        sample_mip_params mp;
        sample_texture *t = NULL;
        sample_sampler s;
        sample_query q = {0.3f, 0.6f, 0.1f, 0, 0, 0.1f};
        float out[4];
        sample_mip_params_init(&mp);
        if (px && sample_texture_create(&im, &mp, &t, NULL) == SAMPLE_OK) {
            sample_sampler_init(&s);
            sample_one(t, &s, &q, out);
            if (out[0] != 0.0f) j->mismatches++;
        }
        sample_texture_destroy(t);
        free(px);
    }
    return NULL;
}

static void concurrent_sampling(void)
{
    float *px = (float *)malloc(sizeof(float) * W * H * 4);
    sample_image im = {W, H, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mp;
    pthread_t th[NTHREADS + 2];
    job jobs[NTHREADS + 2];
    int k;
    srand(11);
    for (k = 0; k < W * H * 4; ++k) px[k] = (float)rand() / (float)RAND_MAX;
    for (k = 0; k < NQ; ++k) {
        queries[k].s = 2.0f * (float)rand() / (float)RAND_MAX - 0.5f;
        queries[k].t = 2.0f * (float)rand() / (float)RAND_MAX - 0.5f;
        queries[k].dsdx = 0.2f * (float)rand() / (float)RAND_MAX;
        queries[k].dtdx = 0.05f * (float)rand() / (float)RAND_MAX;
        queries[k].dsdy = -0.03f * (float)rand() / (float)RAND_MAX;
        queries[k].dtdy = 0.1f * (float)rand() / (float)RAND_MAX;
    }
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &shared_tex, NULL) == SAMPLE_OK, "create");
    for (k = 0; k < NSAMPLERS; ++k) {
        sample_batch_args a;
        sample_sampler_init(&samplers[k]);
        samplers[k].wrap_s = (sample_wrap)(k % SAMPLE_WRAP_COUNT);
        samplers[k].min_filter = (sample_filter)(SAMPLE_NEAREST_MIPMAP_NEAREST + k % 4);
        samplers[k].mag_filter = k == 5 ? SAMPLE_CUBIC : SAMPLE_LINEAR;
        samplers[k].footprint = (sample_footprint)(k % SAMPLE_FOOTPRINT_COUNT);
        samplers[k].max_anisotropy = 8.0f;
        memset(&a, 0, sizeof a);
        a.count = NQ;
        a.queries = queries;
        a.rgba = expected[k];
        sample_batch(shared_tex, &samplers[k], &a);
    }
    for (k = 0; k < NTHREADS + 2; ++k) {
        jobs[k].id = k;
        jobs[k].mismatches = 0;
        CHECK(pthread_create(&th[k], NULL, k < NTHREADS ? sampler_thread : churn_thread, &jobs[k]) == 0, "spawn");
    }
    for (k = 0; k < NTHREADS + 2; ++k) {
        pthread_join(th[k], NULL);
        CHECK(jobs[k].mismatches == 0, "thread %d saw %d differing runs", k, jobs[k].mismatches);
    }
    sample_texture_destroy(shared_tex);
    free(px);
}

int main(void)
{
    RUN(concurrent_sampling);
    return check_finish();
}
