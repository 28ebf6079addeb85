/*
 * Scene files are strict and bounded (doc/renderer.md, "Scene file" and
 * "Limits"): unknown keys name the closest valid one, duplicates, wrong
 * types and trailing text are errors with line and column; a huge text
 * fails early in bounded memory; only regular files are read, so that
 * /dev/zero and a FIFO are refused at once. argv[1]: the texsample program.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "render.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static char dir[64];
static const char *texsample;

/* Processor time of this process: what a refusal costs, unaffected by how
 * busy the machine is. A refusal that blocks (a FIFO's open) costs none
 * and is caught by the alarm in test_files instead. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Parse json; expect failure with every one of the NULL-terminated words. */
static void fails_with(const char *json, const char *const *words)
{
    render_scene *sc = NULL;
    char err[512] = "";
    int r = render_scene_parse(json, strlen(json), 0, 0, &sc, err, sizeof err), k;
    render_scene_destroy(sc);
    CHECK(r != 0, "accepted: %s", json);
    for (k = 0; words[k]; ++k)
        CHECK(strstr(err, words[k]) != NULL, "'%s' not in the message '%s'", words[k], err);
}

#define FAILS(json, ...)                                                                           \
    do {                                                                                           \
        static const char *const w_[] = {__VA_ARGS__, NULL};                                       \
        fails_with(json, w_);                                                                      \
    } while (0)

#define SPHERE "\"objects\":[{\"type\":\"sphere\"}]"

static void test_unknown_keys(void)
{
    FAILS("{\"materials\":[{\"name\":\"m\",\"reflekt\":0.5}]," SPHERE "}",
          "materials[0]", "unknown key 'reflekt'", "did you mean 'reflect'", "line 1, column 27");
    FAILS("{\"textures\":[{\"name\":\"g\",\"type\":\"grid\"}],\n"
          "\"materials\":[{\"texure\":\"g\"}]," SPHERE "}",
          "unknown key 'texure'", "'texture'", "line 2, column 15");
    FAILS("{\"lights\":[{\"dir\":[0,0,1],\"colour\":[1,1,1]}]," SPHERE "}",
          "unknown key 'colour'", "did you mean 'color'");
    FAILS("{\"camra\":{}," SPHERE "}", "unknown key 'camra'", "did you mean 'camera'");
    FAILS("{\"sampler\":{\"wrap\":\"repeat\"}," SPHERE "}", "unknown key 'wrap'");
    /* A key of another kind of the same thing. */
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"height\":2}]}", "'height' does not apply to a sphere");
    FAILS("{\"textures\":[{\"type\":\"image\",\"file\":\"x.png\",\"freq\":4}]," SPHERE "}",
          "'freq' does not apply to image textures");
    FAILS("{\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],[0,1,0]],"
          "\"st\":[[0,0],[1,0],[0,1]],\"n\":[0,0,1]}]}]}",
          "polygon 0", "unknown key 'n'");
    /* Environments: an unknown key, and a file's key on the procedural sky. */
    FAILS("{\"environment\":{\"type\":\"cube\",\"file\":\"sky.exr\",\"radios\":3}," SPHERE "}",
          "environment", "unknown key 'radios'", "did you mean 'radius'");
    FAILS("{\"environment\":{\"type\":\"cube\",\"colorspace\":\"srgb\"}," SPHERE "}",
          "'colorspace' does not apply to the procedural environment");
}

static void test_types_and_duplicates(void)
{
    FAILS("{\"camera\":[1,2,3]," SPHERE "}", "'camera' must be an object", "line 1, column 2");
    FAILS("{\"sampler\":\"trilinear\"," SPHERE "}", "'sampler' must be an object");
    FAILS("{\"environment\":1," SPHERE "}", "'environment' must be an object");
    FAILS("{\"objects\":[{\"type\":5}]}", "'type' must be a string");
    FAILS("{\"textures\":[{\"name\":7,\"type\":\"grid\"}]," SPHERE "}", "'name' must be a string");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"radius\":\"1\"}]}", "'radius' must be a number");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"centre\":{\"x\":1}}]}", "'centre' must be an array");
    /* Duplicate keys, in the scene and deeper. */
    FAILS("{" SPHERE ",\n  " SPHERE "}", "duplicate key 'objects'", "first at line 1, column 2",
          "line 2, column 3");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"radius\":1,\"radius\":2}]}", "objects[0]",
          "duplicate key 'radius'");
    /* Duplicate names. */
    FAILS("{\"textures\":[{\"name\":\"g\",\"type\":\"grid\"},{\"name\":\"g\",\"type\":\"checker\"}],"
          SPHERE "}",
          "textures[1]", "name 'g' is already used by textures[0]");
    FAILS("{\"materials\":[{\"name\":\"m\"},{\"name\":\"x\"},{\"name\":\"m\"}]," SPHERE "}",
          "materials[2]", "already used by materials[0]");
    FAILS("{\"materials\":[{\"name\":\"\"}]," SPHERE "}", "'name' must not be empty");
    /* A Fourier texture's bake is charged per term: 2048² texels × 2² samples
     * × 64 terms = 2^30 evaluations, over the 2^28 budget (at 1 term a
     * sample it would be 2^24, under it). */
    FAILS("{\"textures\":[{\"name\":\"f\",\"type\":\"fourier\",\"size\":2048,\"samples\":2,"
          "\"terms\":64}]," SPHERE "}",
          "exceed the limits");
}

static void test_syntax(void)
{
    FAILS("{" SPHERE "} x", "line 1, column 33", "unexpected text after the JSON value");
    FAILS("{" SPHERE "}{}", "unexpected text after");
    FAILS("{" SPHERE ",}", "expected a member name");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"radius\":01}]}", "leading zeros");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"radius\":NaN}]}", "expected a JSON value");
    FAILS("{\"objects\":[{\"type\":\"sphere\",\"radius\":1e999}]}", "out of the range");
    FAILS("{\"objects\":[{\"type\":\"sph\\u0000ere\"}]}", "U+0000");
    FAILS("{\"objects\":[{\"type\":\"\xC0\xAF\"}]}", "invalid UTF-8");
    FAILS("\n\n  [1, 2]", "line 3, column 3", "must be a JSON object");
    FAILS("{\"objects\":\n[{\"type\":\"sphere\"}", "line 2, column 19",
          "expected ',' or ']', found the end of the text");
    /* Escapes decode: "sph\u0065re" is "sphere"; a UTF-8 byte order mark is fine. */
    {
        static const char ok1[] = "{\"objects\":[{\"type\":\"sph\\u0065re\"}]}";
        static const char ok2[] = "\xEF\xBB\xBF{\"objects\":[{\"type\":\"sphere\"}]}";
        render_scene *sc = NULL;
        char err[256] = "";
        CHECK(render_scene_parse(ok1, strlen(ok1), 4, 4, &sc, err, sizeof err) == 0, "%s", err);
        render_scene_destroy(sc);
        sc = NULL;
        CHECK(render_scene_parse(ok2, strlen(ok2), 4, 4, &sc, err, sizeof err) == 0, "%s", err);
        render_scene_destroy(sc);
    }
}

/* The virtual memory of this process now, in bytes (/proc/self/statm). */
static double vm_bytes(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    double pages = -1.0;
    if (!f) return -1.0;
    if (fscanf(f, "%lf", &pages) != 1) pages = -1.0;
    fclose(f);
    return pages * (double)sysconf(_SC_PAGESIZE);
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define UNDER_SANITIZER 1
#endif
#endif

/* Big texts fail early and in bounded memory: a 24 MB JSON array (a
 * general-purpose tree took 2.6 GB and 21 s for 60 MB of it), and a scene
 * whose one list holds 6 million numbers (refused at the value cap after
 * 8 MB of text, with 64 MiB of nodes). Under a limit of 256 MiB of address
 * space above what the process holds now, where a tree of 80-byte nodes
 * would need 1 GB (not under sanitizers, which reserve terabytes of
 * address space). */
static void test_big_texts(void)
{
    const size_t n = 24u << 20;
    char *a = malloc(n);
    size_t k;
    struct rlimit old, lim;
    int limited = 0;
    if (!a) return;
    for (k = 0; k + 1 < n; k += 2) {
        a[k] = '0';
        a[k + 1] = ',';
    }
#ifndef UNDER_SANITIZER
    if (getrlimit(RLIMIT_AS, &old) == 0 && vm_bytes() > 0) {
        lim = old;
        lim.rlim_cur = (rlim_t)(vm_bytes() + 256.0 * 1048576.0);
        if (old.rlim_cur == RLIM_INFINITY || lim.rlim_cur < old.rlim_cur)
            limited = setrlimit(RLIMIT_AS, &lim) == 0;
    }
#endif
    {
        render_scene *sc = NULL;
        char err[256] = "";
        double t0 = now();
        int r;
        a[0] = '[';
        a[n - 1] = ']';
        r = render_scene_parse(a, n, 0, 0, &sc, err, sizeof err);
        CHECK(r != 0 && strstr(err, "line 1, column 1: the scene must be a JSON object"),
              "array: r = %d, '%s'", r, err);
        CHECK(now() - t0 < 0.5, "array refused after %.2f s", now() - t0);
        render_scene_destroy(sc);
    }
    {
        render_scene *sc = NULL;
        char err[256] = "";
        double t0 = now();
        int r;
        memcpy(a, "{\"objects\":[", 12);
        memcpy(a + n - 3, "0]}", 3);
        r = render_scene_parse(a, n, 0, 0, &sc, err, sizeof err);
        CHECK(r != 0 && strstr(err, "more than 4194304 JSON values"), "list: r = %d, '%s'", r, err);
        CHECK(now() - t0 < 2.0, "list refused after %.2f s", now() - t0);
        printf("6 million numbers refused after %.3f s of processor time\n", now() - t0);
        render_scene_destroy(sc);
    }
    if (limited) setrlimit(RLIMIT_AS, &old);
    free(a);
}

static void on_alarm(int sig)
{
    static const char msg[] = "render_scene: hung on a FIFO or device\n";
    (void)sig;
    if (write(2, msg, sizeof msg - 1) < 0) {
    }
    _exit(1);
}

/* Load path; expect failure mentioning words within a second. */
static void load_fails(const char *path, const char *words)
{
    render_scene *sc = NULL;
    char err[512] = "";
    double t0 = now();
    int r = render_scene_load(path, 0, 0, &sc, err, sizeof err);
    CHECK(r != 0 && strstr(err, words) && strstr(err, path), "%s: r = %d, '%s'", path, r, err);
    CHECK(now() - t0 < 1.0, "%s: refused after %.2f s", path, now() - t0);
    render_scene_destroy(sc);
}

static void test_files(void)
{
    char fifo[128], big[128], scene[128], cmd[1024];
    int fd;
    signal(SIGALRM, on_alarm);
    alarm(20);
    load_fails("/dev/zero", "is a character device; only regular files are read");
    snprintf(fifo, sizeof fifo, "%s/pipe.json", dir);
    CHECK(mkfifo(fifo, 0600) == 0, "mkfifo");
    load_fails(fifo, "is a FIFO; only regular files are read");
    load_fails(dir, "is a directory; only regular files are read");
    /* 64 MiB + 1 byte, sparse: refused by its size before a byte is read. */
    snprintf(big, sizeof big, "%s/big.json", dir);
    fd = open(big, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    CHECK(fd >= 0 && ftruncate(fd, (off_t)RENDER_MAX_SCENE_BYTES + 1) == 0, "sparse file");
    if (fd >= 0) close(fd);
    load_fails(big, "larger than 64 MiB");
    /* A scene naming a FIFO as its image texture. */
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    {
        FILE *f = fopen(scene, "w");
        if (f) {
            fputs("{\"textures\":[{\"name\":\"p\",\"type\":\"image\",\"file\":\"pipe.json\"}],"
                  "\"materials\":[{\"texture\":\"p\"}],\"objects\":[{\"type\":\"plane\"}]}",
                  f);
            fclose(f);
        }
    }
#ifdef TEXSAMPLE_HAVE_IO
    load_fails(scene, "is a FIFO; only regular files are read");
#endif
    /* The command line: any --scene that is not a built-in name is a file. */
    if (texsample) {
        snprintf(cmd, sizeof cmd,
                 "cd '%s' && '%s' render --scene /dev/zero --out x.png 2> err.txt; echo $? > rc.txt",
                 dir, texsample);
        CHECK(check_shell(cmd) == 0, "%s", cmd);
        {
            char *rc = check_slurp_in(dir, "rc.txt"), *msg = check_slurp_in(dir, "err.txt");
            CHECK(rc && atoi(rc) == 1, "exit %s", rc ? rc : "?");
            CHECK(msg && strstr(msg, "'/dev/zero' is a character device"), "message '%s'",
                  msg ? msg : "");
            free(rc);
            free(msg);
        }
    }
    alarm(0);
    unlink(fifo);
    unlink(big);
    unlink(scene);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    check_shell(cmd);
}

int main(int argc, char **argv)
{
    texsample = argc > 1 ? argv[1] : NULL;
    snprintf(dir, sizeof dir, "/tmp/render_scene_XXXXXX");
    if (!mkdtemp(dir)) {
        fprintf(stderr, "cannot make a temporary folder\n");
        return 1;
    }
    RUN(test_unknown_keys);
    RUN(test_types_and_duplicates);
    RUN(test_syntax);
    RUN(test_big_texts);
    RUN(test_files);
    return check_finish();
}
