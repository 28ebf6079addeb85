/*
 * Many threads sampling textures of one texture system while its cache,
 * a fraction of the working set, evicts (doc/texture-system.md,
 * "Threads"): every result must be the resident texture's, bit for bit,
 * and ThreadSanitizer (CI) must see no race; evicted tiles are freed only
 * when no batch that could read them is running.
 */
#include "texsys_util.h"

#include <pthread.h>

enum { NTHREADS = 4, NTEX = 3, ROUNDS = 12, NQ = 64 };

static sample_texsys *sys;
static const sample_texture *cached[NTEX];
static sample_texture *resident[NTEX];
static int failures[NTHREADS];

static void *worker(void *arg)
{
    const int id = (int)(intptr_t)arg;
    sample_query q[NQ];
    float a[NQ * 4], b[NQ * 4];
    uint32_t x = 0x9E3779B9u * (uint32_t)(id + 1);
    int r;
    for (r = 0; r < ROUNDS; ++r) {
        const int k = (r + id) % NTEX;
        sample_sampler s;
        sample_batch_args args;
        int i;
        sample_sampler_init(&s);
        s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
        if (r % 3 == 2) {
            s.footprint = SAMPLE_FOOTPRINT_ANISOTROPIC;
            s.max_anisotropy = 16.0f;
        }
        for (i = 0; i < NQ; ++i) {
            /* A thread-local sequence: rnd() is not thread-safe. */
            x ^= x << 13, x ^= x >> 17, x ^= x << 5;
            q[i].s = (float)(x & 0xffff) / 65536.0f;
            q[i].t = (float)(x >> 16) / 65536.0f;
            q[i].dsdx = (float)(x % 97) / 2000.0f;
            q[i].dtdx = 0.0f;
            q[i].dsdy = 0.0f;
            q[i].dtdy = (float)(x % 89) / 3000.0f;
        }
        memset(&args, 0, sizeof args);
        args.count = NQ;
        args.queries = q;
        args.rgba = a;
        if (sample_texsys_batch(sys, cached[k], &s, &args) != SAMPLE_OK) failures[id]++;
        args.rgba = b;
        if (sample_batch(resident[k], &s, &args) != SAMPLE_OK) failures[id]++;
        if (memcmp(a, b, sizeof a)) failures[id]++;
    }
    return NULL;
}

static void test_threads_while_evicting(void)
{
    sample_texsys_options o;
    sample_texsys_stats st;
    pthread_t th[NTHREADS];
    sample_error e;
    int k, t;
    sample_texsys_options_init(&o);
    o.max_memory_mb = 1.0 / 32.0; /* 32 KiB of a working set of about 200 KiB */
    o.max_open_files = 2;
    CHECK(sample_texsys_create(&o, &sys, &e) == SAMPLE_OK, "create: %s", e.message);
    for (k = 0; k < NTEX; ++k) {
        char path[1024], name[32];
        sample_texture *src = io_test_texture(64, 64, 4, SAMPLE_FORMAT_F16, 11u + (unsigned)k, SAMPLE_MIPGEN_BOX, 0);
        snprintf(name, sizeof name, "t%d.exr", k);
        io_path(path, sizeof path, io_scratch, name);
        ts_write(path, src, 8, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT, 0);
        sample_texture_destroy(src);
        resident[k] = ts_resident(path);
        CHECK(sample_texsys_open(sys, path, &cached[k], &e) == SAMPLE_OK, "open: %s", e.message);
    }
    for (t = 0; t < NTHREADS; ++t) pthread_create(&th[t], NULL, worker, (void *)(intptr_t)t);
    for (t = 0; t < NTHREADS; ++t) pthread_join(th[t], NULL);
    for (t = 0; t < NTHREADS; ++t) CHECK(failures[t] == 0, "thread %d: %d batches differ or failed", t, failures[t]);
    sample_texsys_stats_get(sys, &st);
    CHECK(st.evictions > 0 && st.errors == 0 && st.peak_open_files <= 2 + NTHREADS,
          "%llu evictions, %llu errors, %d files open at most", (unsigned long long)st.evictions,
          (unsigned long long)st.errors, st.peak_open_files);
    /* No batch runs: what is held is under the limit. */
    CHECK(st.memory <= 32768, "memory %zu after the threads", st.memory);
    for (k = 0; k < NTEX; ++k) sample_texture_destroy(resident[k]);
    sample_texsys_destroy(sys);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: texsys_threads TESTIMAGES SCRATCH\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    RUN(test_threads_while_evicting);
    io_colour_close(ts_col);
    return check_finish();
}
