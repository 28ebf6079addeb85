/*
 * OpenGL through EGL as a backend (backend.h, doc/backends.md).
 *
 * One OpenGL 3.3 core context without a window: Mesa's surfaceless platform
 * (EGL_MESA_platform_surfaceless) by default, which is llvmpipe on a
 * machine without a GPU, or an EGL device (EGL_EXT_platform_device) chosen
 * by name. Queries go in as an RGBA32F texture, two texels per query
 * (s, t, ds/dx, dt/dx) and (ds/dy, dt/dy, 0, 0), read with texelFetch
 * (exact floats); one fragment per query calls textureGrad (GLSL 4.60
 * §8.9.2) on an RGBA32F texture holding libsample's own levels, so both
 * sides filter the same texels; the results come back from an RGBA32F
 * framebuffer with glReadPixels. Query k is fragment (k mod FB_W, k / FB_W):
 * a driver that shares one LOD per 2 × 2 quad (llvmpipe does unless
 * GALLIVM_PERF=no_quad_lod) lets neighbouring queries in that layout
 * influence each other, as it would on screen.
 *
 * Sampler state maps one to one (GL 4.6 §8.14 and table 23.18): wrap
 * modes, min and mag filters, border colour, LOD bias and clamps, base and
 * max level, and — for libsample's anisotropic footprint filter —
 * GL_TEXTURE_MAX_ANISOTROPY (GL 4.6 §8.14.1; ARB/EXT_texture_filter_anisotropic
 * before 4.6), whose sampling pattern the specification leaves to the
 * implementation. What GL's core profile lacks (GL_CLAMP, the mirror-clamp
 * pair of EXT_texture_mirror_clamp, cubic filters, the other footprint
 * filters, cube maps and volumes here) is TOOL_BACKEND_NA with the reason.
 */
#define _POSIX_C_SOURCE 200809L
#include "backend.h"

#ifdef TEXSAMPLE_HAVE_GL
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define FB_W 1024    /* framebuffer width: queries per row */
#define FB_ROWS 256  /* rows per draw: at most 262,144 queries a draw */

#ifndef GL_TEXTURE_MAX_ANISOTROPY
#define GL_TEXTURE_MAX_ANISOTROPY 0x84FE
#define GL_MAX_TEXTURE_MAX_ANISOTROPY 0x84FF
#endif
#ifndef GL_MIRROR_CLAMP_TO_EDGE
#define GL_MIRROR_CLAMP_TO_EDGE 0x8743
#endif

typedef struct gl_impl {
    EGLDisplay dpy;
    EGLContext ctx;
    GLuint prog, vao, fbo, rt, qtex;
    GLint loc_rows;
    float max_aniso; /* 0: no anisotropic filtering */
    int mirror_clamp_to_edge, max_size;
    float *qbuf, *obuf; /* FB_W × FB_ROWS × 8 and × 4 floats */
} gl_impl;

struct tool_backend_tex {
    GLuint tex;
};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char vs_src[] =
    "#version 330 core\n"
    "void main() {\n"
    "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
    "  gl_Position = vec4(p, 0.0, 1.0);\n"
    "}\n";

static const char fs_src[] =
    "#version 330 core\n"
    "uniform sampler2D tex;\n"
    "uniform sampler2D qtex;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  vec4 a = texelFetch(qtex, ivec2(2 * p.x, p.y), 0);\n"
    "  vec4 b = texelFetch(qtex, ivec2(2 * p.x + 1, p.y), 0);\n"
    "  color = textureGrad(tex, a.xy, a.zw, b.xy);\n"
    "}\n";

static GLuint compile(GLenum kind, const char *src, char *err, size_t errlen)
{
    GLuint s = glCreateShader(kind);
    GLint ok = 0;
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        snprintf(err, errlen, "OpenGL: shader does not compile: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static int has_extension(const char *name)
{
    GLint n = 0, k;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (k = 0; k < n; ++k)
        if (strcmp((const char *)glGetStringi(GL_EXTENSIONS, (GLuint)k), name) == 0) return 1;
    return 0;
}

/* A 3.3 core context on an initialized display, made current. */
static EGLContext make_context(EGLDisplay dpy)
{
    static const EGLint attr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx;
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
    ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attr);
    if (ctx != EGL_NO_CONTEXT && !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        eglDestroyContext(dpy, ctx);
        return EGL_NO_CONTEXT;
    }
    return ctx;
}

/* The EGL devices (EGL_EXT_device_enumeration), up to max. */
static int list_devices(EGLDeviceEXT *dev, int max)
{
    PFNEGLQUERYDEVICESEXTPROC query =
        (PFNEGLQUERYDEVICESEXTPROC)eglGetProcAddress("eglQueryDevicesEXT");
    EGLint n = 0;
    if (!query || !query(max, dev, &n)) return 0;
    return n;
}

/* The device's DRM node (render node first), or its kind. */
static const char *device_node(EGLDeviceEXT dev)
{
    PFNEGLQUERYDEVICESTRINGEXTPROC qs =
        (PFNEGLQUERYDEVICESTRINGEXTPROC)eglGetProcAddress("eglQueryDeviceStringEXT");
    const char *s = NULL, *ext;
    if (!qs) return "";
    ext = qs(dev, EGL_EXTENSIONS);
#ifdef EGL_DRM_RENDER_NODE_FILE_EXT
    if (ext && strstr(ext, "EGL_EXT_device_drm_render_node")) s = qs(dev, EGL_DRM_RENDER_NODE_FILE_EXT);
#endif
    if (!s && ext && strstr(ext, "EGL_EXT_device_drm")) s = qs(dev, EGL_DRM_DEVICE_FILE_EXT);
    if (!s && ext && strstr(ext, "EGL_MESA_device_software")) s = "software";
    return s ? s : "";
}

/* Case-insensitive: does hay contain needle? */
static int contains(const char *hay, const char *needle)
{
    size_t n = strlen(needle), k;
    for (; *hay; ++hay) {
        for (k = 0; k < n && hay[k] && tolower((unsigned char)hay[k]) == tolower((unsigned char)needle[k]); ++k) {}
        if (k == n) return 1;
    }
    return 0;
}

/* Open device dev's display with a current context; the renderer into
 * renderer. Returns 0 or −1. */
static int open_device(EGLDeviceEXT dev, EGLDisplay *dpy, EGLContext *ctx, char *renderer,
                       size_t len)
{
    *dpy = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, dev, NULL);
    *ctx = EGL_NO_CONTEXT;
    if (*dpy == EGL_NO_DISPLAY || !eglInitialize(*dpy, NULL, NULL)) return -1;
    if ((*ctx = make_context(*dpy)) == EGL_NO_CONTEXT) {
        eglTerminate(*dpy);
        return -1;
    }
    snprintf(renderer, len, "%s", (const char *)glGetString(GL_RENDERER));
    return 0;
}

static void close_display(EGLDisplay dpy, EGLContext ctx)
{
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (ctx != EGL_NO_CONTEXT) eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    eglReleaseThread();
}

int tool_backend_gl_available(void) { return 1; }

int tool_backend_gl_list(FILE *out, char *err, size_t errlen)
{
    EGLDeviceEXT dev[32];
    int n = list_devices(dev, 32), k;
    if (n == 0) {
        snprintf(err, errlen, "EGL lists no devices (no EGL_EXT_device_enumeration, or no driver)");
        return -1;
    }
    for (k = 0; k < n; ++k) {
        EGLDisplay dpy;
        EGLContext ctx;
        char renderer[256];
        if (open_device(dev[k], &dpy, &ctx, renderer, sizeof renderer) == 0) {
            fprintf(out, "%d  %s  %s; %s\n", k, device_node(dev[k]), renderer,
                    (const char *)glGetString(GL_VERSION));
            close_display(dpy, ctx);
        } else {
            fprintf(out, "%d  %s  (no OpenGL 3.3 core context)\n", k, device_node(dev[k]));
        }
    }
    return n;
}

/* The display: surfaceless, or the device that matches `name`. */
static int open_display(gl_impl *g, const char *name, char *err, size_t errlen)
{
    EGLDeviceEXT dev[32];
    int n, k;
    if (!name || !*name) {
        g->dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
        if (g->dpy == EGL_NO_DISPLAY || !eglInitialize(g->dpy, NULL, NULL)) {
            snprintf(err, errlen,
                     "EGL: no display on Mesa's surfaceless platform (EGL error 0x%x); is Mesa's "
                     "EGL driver (libegl-mesa0) installed?",
                     (unsigned)eglGetError());
            g->dpy = EGL_NO_DISPLAY;
            return -1;
        }
        if ((g->ctx = make_context(g->dpy)) == EGL_NO_CONTEXT) {
            snprintf(err, errlen, "EGL: no OpenGL 3.3 core context (EGL error 0x%x)",
                     (unsigned)eglGetError());
            return -1;
        }
        return 0;
    }
    n = list_devices(dev, 32);
    for (k = 0; k < n; ++k) {
        char renderer[256], idx[16];
        EGLDisplay dpy;
        EGLContext ctx;
        snprintf(idx, sizeof idx, "%d", k);
        if (open_device(dev[k], &dpy, &ctx, renderer, sizeof renderer) != 0) continue;
        if (strcmp(name, idx) == 0 || strcmp(name, device_node(dev[k])) == 0 ||
            contains(renderer, name)) {
            g->dpy = dpy;
            g->ctx = ctx;
            return 0;
        }
        close_display(dpy, ctx);
    }
    snprintf(err, errlen,
             "EGL: no device matches '%s' (%d device%s; --gl-device list shows them)", name, n,
             n == 1 ? "" : "s");
    return -1;
}

static int current(const gl_impl *g)
{
    return eglMakeCurrent(g->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, g->ctx) ? 0 : -1;
}

static int gl_setup(gl_impl *g, char *err, size_t errlen)
{
    GLuint vs, fs;
    GLint ok = 0, v[2] = {0, 0};
    if (!(vs = compile(GL_VERTEX_SHADER, vs_src, err, errlen))) return -1;
    if (!(fs = compile(GL_FRAGMENT_SHADER, fs_src, err, errlen))) return -1;
    g->prog = glCreateProgram();
    glAttachShader(g->prog, vs);
    glAttachShader(g->prog, fs);
    glLinkProgram(g->prog);
    glDeleteShader(vs);
    glDeleteShader(fs);
    glGetProgramiv(g->prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        snprintf(err, errlen, "OpenGL: the program does not link");
        return -1;
    }
    glUseProgram(g->prog);
    glUniform1i(glGetUniformLocation(g->prog, "tex"), 0);
    glUniform1i(glGetUniformLocation(g->prog, "qtex"), 1);
    glGenVertexArrays(1, &g->vao);
    glBindVertexArray(g->vao);

    glGenTextures(1, &g->rt);
    glBindTexture(GL_TEXTURE_2D, g->rt);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, FB_W, FB_ROWS, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &g->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g->rt, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "OpenGL: no RGBA32F framebuffer");
        return -1;
    }
    glGenTextures(1, &g->qtex);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, g->qtex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 2 * FB_W, FB_ROWS, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
    /* Results leave unclamped and tightly packed. */
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

    glGetIntegerv(GL_MAJOR_VERSION, &v[0]);
    glGetIntegerv(GL_MINOR_VERSION, &v[1]);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &g->max_size);
    if (v[0] * 10 + v[1] >= 46 || has_extension("GL_ARB_texture_filter_anisotropic") ||
        has_extension("GL_EXT_texture_filter_anisotropic"))
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &g->max_aniso);
    g->mirror_clamp_to_edge = v[0] * 10 + v[1] >= 44 ||
                              has_extension("GL_ARB_texture_mirror_clamp_to_edge") ||
                              has_extension("GL_EXT_texture_mirror_clamp");
    if (glGetError() != GL_NO_ERROR) {
        snprintf(err, errlen, "OpenGL: an error while setting up");
        return -1;
    }
    return 0;
}

static void gl_close(tool_backend *b)
{
    gl_impl *g = b->impl;
    if (!g) return;
    if (g->ctx != EGL_NO_CONTEXT && current(g) == 0) {
        glDeleteTextures(1, &g->rt);
        glDeleteTextures(1, &g->qtex);
        glDeleteFramebuffers(1, &g->fbo);
        glDeleteVertexArrays(1, &g->vao);
        glDeleteProgram(g->prog);
    }
    if (g->dpy != EGL_NO_DISPLAY) close_display(g->dpy, g->ctx);
    free(g->qbuf);
    free(g->obuf);
    free(g);
    b->impl = NULL;
}

/* GL's name for a wrap mode the core profile has, else 0. */
static GLenum gl_wrap(const gl_impl *g, sample_wrap w)
{
    switch (w) {
    case SAMPLE_WRAP_REPEAT: return GL_REPEAT;
    case SAMPLE_WRAP_MIRRORED_REPEAT: return GL_MIRRORED_REPEAT;
    case SAMPLE_WRAP_CLAMP_TO_EDGE: return GL_CLAMP_TO_EDGE;
    case SAMPLE_WRAP_CLAMP_TO_BORDER: return GL_CLAMP_TO_BORDER;
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE: return g->mirror_clamp_to_edge ? GL_MIRROR_CLAMP_TO_EDGE : 0;
    default: return 0;
    }
}

/* Can this context run the state? 0, or TOOL_BACKEND_NA with the reason. */
static int gl_check(const gl_impl *g, const sample_texture_info *info, const sample_sampler *s,
                    char *err, size_t errlen)
{
    if (info->kind != SAMPLE_TEXTURE_2D) {
        snprintf(err, errlen, "this backend samples 2D textures only, not %s",
                 sample_texture_kind_name(info->kind));
        return TOOL_BACKEND_NA;
    }
    if (info->width > g->max_size || info->height > g->max_size) {
        snprintf(err, errlen, "%d x %d is over GL_MAX_TEXTURE_SIZE %d", info->width, info->height,
                 g->max_size);
        return TOOL_BACKEND_NA;
    }
    if (!gl_wrap(g, s->wrap_s) || !gl_wrap(g, s->wrap_t)) {
        snprintf(err, errlen, "OpenGL's core profile has no wrap mode %s",
                 sample_wrap_name(gl_wrap(g, s->wrap_s) ? s->wrap_t : s->wrap_s));
        return TOOL_BACKEND_NA;
    }
    if (s->min_filter > SAMPLE_LINEAR_MIPMAP_LINEAR || s->mag_filter > SAMPLE_LINEAR) {
        snprintf(err, errlen, "OpenGL has no %s filter",
                 sample_filter_name(s->min_filter > SAMPLE_LINEAR_MIPMAP_LINEAR ? s->min_filter
                                                                                : s->mag_filter));
        return TOOL_BACKEND_NA;
    }
    if ((s->footprint != SAMPLE_FOOTPRINT_NONE && s->footprint != SAMPLE_FOOTPRINT_ANISOTROPIC) ||
        s->options) {
        snprintf(err, errlen, "OpenGL has no %s footprint filter", sample_footprint_name(s->footprint));
        return TOOL_BACKEND_NA;
    }
    if (s->footprint == SAMPLE_FOOTPRINT_ANISOTROPIC && s->max_anisotropy > 1.0f &&
        s->max_anisotropy > g->max_aniso) {
        snprintf(err, errlen, "the driver's GL_MAX_TEXTURE_MAX_ANISOTROPY is %g, not %g",
                 (double)g->max_aniso, (double)s->max_anisotropy);
        return TOOL_BACKEND_NA;
    }
    return 0;
}

static int gl_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *s,
                      tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    static const GLenum filter[6] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                     GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR,
                                     GL_LINEAR_MIPMAP_LINEAR};
    gl_impl *g = b->impl;
    sample_texture_info info;
    tool_backend_tex *x;
    float *d;
    double t0;
    int k, i, j, rc, w0, h0;
    sample_texture_info_get(tex, &info);
    if ((rc = gl_check(g, &info, s, err, errlen)) != 0) return rc;
    if (current(g) != 0) {
        snprintf(err, errlen, "EGL: cannot make the context current");
        return TOOL_BACKEND_ERROR;
    }
    sample_texture_level_size(tex, 0, &w0, &h0);
    x = malloc(sizeof *x);
    d = malloc((size_t)w0 * (size_t)h0 * 4 * sizeof *d);
    if (!x || !d) {
        free(x);
        free(d);
        snprintf(err, errlen, "out of memory for a %d x %d texture", w0, h0);
        return TOOL_BACKEND_ERROR;
    }
    t0 = now_s();
    glGenTextures(1, &x->tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, x->tex);
    /* libsample's levels, texel for texel (decoded to linear float). */
    for (k = 0; k < info.levels; ++k) {
        int w, h;
        sample_texture_level_size(tex, k, &w, &h);
        for (j = 0; j < h; ++j)
            for (i = 0; i < w; ++i)
                sample_texture_texel(tex, k, i, j, d + 4 * ((size_t)j * (size_t)w + (size_t)i));
        glTexImage2D(GL_TEXTURE_2D, k, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, d);
    }
    free(d);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)gl_wrap(g, s->wrap_s));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)gl_wrap(g, s->wrap_t));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filter[s->min_filter]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)filter[s->mag_filter]);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, s->border_color);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, s->lod_bias);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, s->min_lod);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, s->max_lod);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, s->base_level);
    /* A texture holding fewer levels than its full chain is complete
     * only up to its last level (GL 4.6 §8.17). */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL,
                    s->max_level < info.levels - 1 ? s->max_level : info.levels - 1);
    if (g->max_aniso > 0.0f)
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY,
                        s->footprint == SAMPLE_FOOTPRINT_ANISOTROPIC && s->max_anisotropy > 1.0f
                            ? s->max_anisotropy
                            : 1.0f);
    glFinish();
    t->upload += now_s() - t0;
    if (glGetError() != GL_NO_ERROR) {
        glDeleteTextures(1, &x->tex);
        free(x);
        snprintf(err, errlen, "OpenGL: an error while uploading the texture");
        return TOOL_BACKEND_ERROR;
    }
    *out = x;
    return 0;
}

static int gl_sample(tool_backend *b, tool_backend_tex *x, const sample_query *q, size_t n,
                     float *rgba, double *texels, tool_backend_times *t, char *err, size_t errlen)
{
    gl_impl *g = b->impl;
    size_t done = 0;
    (void)texels;
    if (current(g) != 0) {
        snprintf(err, errlen, "EGL: cannot make the context current");
        return TOOL_BACKEND_ERROR;
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, x->tex);
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
    while (done < n) {
        size_t m = n - done < (size_t)FB_W * FB_ROWS ? n - done : (size_t)FB_W * FB_ROWS, k;
        int rows = (int)((m + FB_W - 1) / FB_W);
        double t0, t1, t2, t3;
        /* Fragments past the last query sample (0, 0) and are dropped. */
        memset(g->qbuf, 0, (size_t)rows * FB_W * 8 * sizeof *g->qbuf);
        for (k = 0; k < m; ++k) {
            const sample_query *r = &q[done + k];
            float *o = g->qbuf + 8 * k;
            o[0] = r->s;
            o[1] = r->t;
            o[2] = r->dsdx;
            o[3] = r->dtdx;
            o[4] = r->dsdy;
            o[5] = r->dtdy;
        }
        t0 = now_s();
        glActiveTexture(GL_TEXTURE1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2 * FB_W, rows, GL_RGBA, GL_FLOAT, g->qbuf);
        glActiveTexture(GL_TEXTURE0);
        glFinish();
        t1 = now_s();
        glViewport(0, 0, FB_W, rows);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
        t2 = now_s();
        glReadPixels(0, 0, FB_W, rows, GL_RGBA, GL_FLOAT, g->obuf);
        t3 = now_s();
        t->upload += t1 - t0;
        t->sample += t2 - t1;
        t->readback += t3 - t2;
        memcpy(rgba + 4 * done, g->obuf, m * 4 * sizeof *rgba);
        done += m;
    }
    if (glGetError() != GL_NO_ERROR) {
        snprintf(err, errlen, "OpenGL: an error while sampling");
        return TOOL_BACKEND_ERROR;
    }
    return 0;
}

static void gl_release(tool_backend *b, tool_backend_tex *x)
{
    if (current(b->impl) == 0) glDeleteTextures(1, &x->tex);
    free(x);
}

static const tool_backend_ops gl_ops = {
    .prepare = gl_prepare, .sample = gl_sample, .release = gl_release, .close = gl_close};

int tool_backend_gl_open(tool_backend *b, const char *device, char *err, size_t errlen)
{
    gl_impl *g = calloc(1, sizeof *g);
    memset(b, 0, sizeof *b);
    if (!g) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    g->dpy = EGL_NO_DISPLAY;
    g->ctx = EGL_NO_CONTEXT;
    b->ops = &gl_ops;
    b->impl = g;
    g->qbuf = malloc((size_t)FB_W * FB_ROWS * 8 * sizeof *g->qbuf);
    g->obuf = malloc((size_t)FB_W * FB_ROWS * 4 * sizeof *g->obuf);
    if (!g->qbuf || !g->obuf) {
        snprintf(err, errlen, "out of memory");
        tool_backend_close(b);
        return TOOL_BACKEND_ERROR;
    }
    if (open_display(g, device, err, errlen) != 0 || gl_setup(g, err, errlen) != 0) {
        tool_backend_close(b);
        return TOOL_BACKEND_ERROR;
    }
    snprintf(b->driver, sizeof b->driver, "%s; OpenGL %s", (const char *)glGetString(GL_RENDERER),
             (const char *)glGetString(GL_VERSION));
    return 0;
}

#else /* no EGL in this build */

#include <string.h>

int tool_backend_gl_available(void) { return 0; }

int tool_backend_gl_open(tool_backend *b, const char *device, char *err, size_t errlen)
{
    (void)device;
    memset(b, 0, sizeof *b);
    snprintf(err, errlen, "this build has no OpenGL backend (EGL was not found when it was configured)");
    return TOOL_BACKEND_ERROR;
}

int tool_backend_gl_list(FILE *out, char *err, size_t errlen)
{
    (void)out;
    snprintf(err, errlen, "this build has no OpenGL backend (EGL was not found when it was configured)");
    return -1;
}

#endif
