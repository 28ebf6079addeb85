/*
 * The bench's timer (tools/bench/timing.c) as `bench` uses it: engines'
 * 1-thread passes taking turns (cmd_bench.c, measure), a pool of two
 * threads, and the failure paths — a pass past the runs asked for, a
 * timer closed early, an engine whose row cannot be prepared (OIIO here,
 * linked without OpenImageIO). Under ASan and LeakSanitizer in CI, so a timer
 * that leaks threads or memory on any path fails. No speed is asserted.
 */
#include "bench_no_oiio.h"
#include "check.h"

#include <stdlib.h>

enum { N = 1000, SIZE = 32 };

static sample_texture *tex;
static sample_query q[N];
static bench_engine eng[32];
static int neng;

static const bench_engine *engine(const char *name, int oiio)
{
    int k;
    for (k = 0; k < neng; ++k)
        if (eng[k].oiio == oiio && !strcmp(eng[k].name, name)) return &eng[k];
    return NULL;
}

static int timing_ok(const bench_timing *t, int runs)
{
    return t->runs == runs && t->min > 0.0 && t->min <= t->median && t->median <= t->max;
}

/* Two engines' passes alternated, as measure() runs them. */
static void taking_turns(void)
{
    const bench_engine *a = engine("trilinear", 0), *b = engine("ewa", 0);
    bench_texture t = {.ours = tex};
    bench_timer *ta, *tb;
    bench_timing ra, rb;
    int r;
    CHECK(a && b, "bench has trilinear and ewa");
    if (!a || !b) return;
    ta = bench_timer_open(a, &t, q, N, 1, 3, 64);
    tb = bench_timer_open(b, &t, q, N, 1, 3, 64);
    CHECK(ta && tb, "timers open (warm-up passes ran)");
    for (r = 0; r < 3; ++r) {
        CHECK(bench_timer_pass(ta) == 0, "trilinear pass %d", r);
        CHECK(bench_timer_pass(tb) == 0, "ewa pass %d", r);
    }
    CHECK(bench_timer_pass(ta) == -1, "a fourth pass of three is refused");
    CHECK(bench_timer_close(ta, &ra) == 0 && timing_ok(&ra, 3), "trilinear timing %g %g %g", ra.min, ra.median,
          ra.max);
    CHECK(bench_timer_close(tb, &rb) == 0 && timing_ok(&rb, 3), "ewa timing");
}

static void pool_and_failures(void)
{
    const bench_engine *a = engine("bilinear", 0), *o = engine("bilinear", 1);
    bench_texture t = {.ours = tex};
    bench_timing r2, early;
    bench_timer *tm;
    memset(&early, 0, sizeof early);
    CHECK(bench_time(a, &t, q, N, 2, 3, 16, &r2) == 0 && timing_ok(&r2, 3), "two threads, three runs");
    tm = bench_timer_open(a, &t, q, N, 2, 4, 16);
    CHECK(tm && bench_timer_pass(tm) == 0, "one pass of four");
    CHECK(bench_timer_close(tm, &early) == -1 && early.runs == 0, "closed after 1 of 4 passes: no timing");
    CHECK(bench_timer_open(a, &t, q, N, 1, 0, 16) == NULL, "zero runs refused");
    CHECK(bench_timer_open(a, &t, q, N, 0, 3, 16) == NULL, "zero threads refused");
    CHECK(o != NULL, "bench has OIIO's bilinear");
    if (o) {
        fprintf(stderr, "(the next two lines are the expected OIIO failures)\n");
        CHECK(bench_engines_open_oiio(eng, neng, NULL) == -1 && !o->backend,
              "OIIO's backends cannot open without OpenImageIO");
        CHECK(bench_timer_open(o, &t, q, N, 2, 3, 16) == NULL, "a row that cannot be prepared fails the open");
    }
    CHECK(bench_timer_close(NULL, &early) == -1, "closing nothing");
}

int main(void)
{
    float *content = malloc((size_t)SIZE * SIZE * 4 * sizeof *content);
    sample_image img;
    sample_mip_params mip;
    sample_error err;
    size_t i;
    if (!content) return 1;
    for (i = 0; i < (size_t)SIZE * SIZE * 4; ++i) content[i] = (float)(i % 7) / 7.0f;
    img = (sample_image){SIZE, SIZE, 4, SAMPLE_FORMAT_F32, content, 0};
    sample_mip_params_init(&mip);
    if (sample_texture_create(&img, &mip, &tex, &err) != SAMPLE_OK) return 1;
    bench_queries(BENCH_SET_ANISO, SIZE, q, N);
    neng = bench_engines(eng, 32);
    RUN(taking_turns);
    RUN(pool_and_failures);
    sample_texture_destroy(tex);
    free(content);
    return check_finish();
}
