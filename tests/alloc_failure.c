/*
 * Allocation failure (DESIGN §10, doc/guarantees.md): every malloc/calloc
 * made while creating a texture (copy, pyramid, explicit levels) is made to
 * fail in turn. Each time the call must return SAMPLE_E_OUT_OF_MEMORY with
 * *out == NULL and a message, and leave nothing allocated (LeakSanitizer
 * checks that in the sanitizer build; the counters below check it
 * everywhere).
 * Linked with -Wl,--wrap=malloc,--wrap=calloc,--wrap=free.
 */
#include "check.h"
#include "sample/sample.h"

#include <stdlib.h>

void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t k);
void __real_free(void *p);

static int countdown = -1; /* fail the allocation when it reaches 0 */
static long live;          /* allocations not yet freed */

void *__wrap_malloc(size_t n)
{
    void *p;
    if (countdown >= 0 && countdown-- == 0) return NULL;
    p = __real_malloc(n);
    if (p) ++live;
    return p;
}

void *__wrap_calloc(size_t n, size_t k)
{
    void *p;
    if (countdown >= 0 && countdown-- == 0) return NULL;
    p = __real_calloc(n, k);
    if (p) ++live;
    return p;
}

void __wrap_free(void *p)
{
    if (p) --live;
    __real_free(p);
}

static void each_failure_point(int levels_api, sample_mipgen gen)
{
    static float px[37 * 23 * 4];
    sample_image lv[6];
    int k, fail, ok_seen = 0;
    for (k = 0; k < 37 * 23 * 4; ++k) px[k] = (float)(k % 13);
    for (k = 0; k < 6; ++k) {
        lv[k].width = 37 >> k > 0 ? 37 >> k : 1;
        lv[k].height = 23 >> k > 0 ? 23 >> k : 1;
        lv[k].channels = 4;
        lv[k].format = SAMPLE_FORMAT_F32;
        lv[k].data = px;
        lv[k].row_stride = 0;
    }
    for (fail = 0; fail < 64 && !ok_seen; ++fail) {
        sample_texture *t = (sample_texture *)px; /* must become NULL on failure */
        sample_error err;
        sample_status st;
        sample_mip_params mp;
        long before = live;
        sample_mip_params_init(&mp);
        mp.filter = gen;
        countdown = fail;
        st = levels_api ? sample_texture_create_levels(lv, 6, &t, &err) : sample_texture_create(&lv[0], &mp, &t, &err);
        countdown = -1;
        if (st == SAMPLE_OK) {
            ok_seen = 1; /* more allocation points than this call makes */
            sample_texture_destroy(t);
        } else {
            CHECK(st == SAMPLE_E_OUT_OF_MEMORY, "failure %d: status %s", fail, sample_strerror(st));
            CHECK(t == NULL, "failure %d: *out not NULL", fail);
            CHECK(strlen(err.message) > 0, "failure %d: no message", fail);
        }
        CHECK(live == before, "failure %d: %ld allocations left behind", fail, live - before);
    }
    CHECK(ok_seen, "creation never succeeded within 64 allocations");
    CHECK(fail > 2, "too few allocation points exercised (%d)", fail);
}

static void create_with_box_pyramid(void) { each_failure_point(0, SAMPLE_MIPGEN_BOX); }
static void create_with_lanczos_pyramid(void) { each_failure_point(0, SAMPLE_MIPGEN_LANCZOS3); }
static void create_from_levels(void) { each_failure_point(1, SAMPLE_MIPGEN_NONE); }

int main(void)
{
    RUN(create_with_box_pyramid);
    RUN(create_with_lanczos_pyramid);
    RUN(create_from_levels);
    return check_finish();
}
