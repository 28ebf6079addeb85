/*
 * OSMesa plumbing of the Mesa cross-checks (mesa_gl.h).
 */
#include "mesa_gl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *vs_src =
    "#version 330 core\n"
    "layout(location = 0) in vec2 pos;\n"
    "void main() { gl_Position = vec4(pos, 0.0, 1.0); }\n";

static GLuint compile(const mesa_gl *g, GLenum kind, const char *src)
{
    GLuint s = glCreateShader(kind);
    GLint ok = 0;
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "%s: shader: %s\n", g->who, log);
        return 0;
    }
    return s;
}

int mesa_gl_init(mesa_gl *g, const char *who, const char *fs_src, int qw, int rows)
{
    static const int attr[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE,
                               OSMESA_COMPAT_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                               OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint vs, fs;
    GLint ok = 0;
    memset(g, 0, sizeof *g);
    g->who = who;
    g->qw = qw;
    g->rows = rows;
    g->ctx = OSMesaCreateContextAttribs(attr, NULL);
    if (!g->ctx) {
        fprintf(stderr, "%s: OSMesaCreateContextAttribs (3.3 compatibility) failed\n", who);
        return 0;
    }
    if (!OSMesaMakeCurrent(g->ctx, g->dummy, GL_UNSIGNED_BYTE, 1, 1)) {
        fprintf(stderr, "%s: OSMesaMakeCurrent failed\n", who);
        return 0;
    }
    fprintf(stderr, "%s: %s, %s\n", who, (const char *)glGetString(GL_RENDERER), (const char *)glGetString(GL_VERSION));
    if (!(vs = compile(g, GL_VERTEX_SHADER, vs_src)) || !(fs = compile(g, GL_FRAGMENT_SHADER, fs_src))) return 0;
    g->prog = glCreateProgram();
    glAttachShader(g->prog, vs);
    glAttachShader(g->prog, fs);
    glLinkProgram(g->prog);
    glGetProgramiv(g->prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        fprintf(stderr, "%s: program link failed\n", who);
        return 0;
    }
    glGenVertexArrays(1, &g->vao);
    glBindVertexArray(g->vao);
    glGenBuffers(1, &g->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, g->vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);

    glGenTextures(1, &g->rt);
    glBindTexture(GL_TEXTURE_2D, g->rt);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, qw, rows, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &g->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g->rt, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        fprintf(stderr, "%s: RGBA32F framebuffer incomplete\n", who);
        return 0;
    }
    /* No colour clamping anywhere (compatibility profile). */
    glClampColor(GL_CLAMP_READ_COLOR, GL_FALSE);
    glViewport(0, 0, qw, rows);

    glGenTextures(1, &g->qtex);
    glUseProgram(g->prog);
    glUniform1i(glGetUniformLocation(g->prog, "tex"), 0);
    glUniform1i(glGetUniformLocation(g->prog, "qtex"), 1);
    return glGetError() == GL_NO_ERROR;
}

int mesa_gl_render(mesa_gl *g, const float *queries, int per, float *out)
{
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, g->qtex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, per * g->qw, g->rows, 0, GL_RGBA, GL_FLOAT, queries);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glActiveTexture(GL_TEXTURE0);
    glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glReadPixels(0, 0, g->qw, g->rows, GL_RGBA, GL_FLOAT, out);
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "%s: GL error while rendering\n", g->who);
        return 0;
    }
    return 1;
}

static GLenum gl_wrap(sample_wrap w)
{
    static const GLenum m[SAMPLE_WRAP_COUNT] = {
        [SAMPLE_WRAP_REPEAT] = GL_REPEAT,
        [SAMPLE_WRAP_MIRRORED_REPEAT] = GL_MIRRORED_REPEAT,
        [SAMPLE_WRAP_CLAMP_TO_EDGE] = GL_CLAMP_TO_EDGE,
        [SAMPLE_WRAP_CLAMP_TO_BORDER] = GL_CLAMP_TO_BORDER,
        [SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE] = GL_MIRROR_CLAMP_TO_EDGE_EXT,
        [SAMPLE_WRAP_CLAMP] = GL_CLAMP,
        [SAMPLE_WRAP_MIRROR_CLAMP] = GL_MIRROR_CLAMP_EXT,
        [SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER] = GL_MIRROR_CLAMP_TO_BORDER_EXT,
    };
    return m[w];
}

static GLenum gl_filter(sample_filter f)
{
    static const GLenum m[6] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    return m[f];
}

void mesa_gl_sampler(GLenum target, const sample_sampler *s)
{
    glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)gl_wrap(s->wrap_s));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)gl_wrap(s->wrap_t));
    glTexParameteri(target, GL_TEXTURE_WRAP_R, (GLint)gl_wrap(s->wrap_r));
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)gl_filter(s->min_filter));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)gl_filter(s->mag_filter));
    glTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, s->border_color);
    glTexParameterf(target, GL_TEXTURE_LOD_BIAS, s->lod_bias);
    glTexParameterf(target, GL_TEXTURE_MIN_LOD, s->min_lod);
    glTexParameterf(target, GL_TEXTURE_MAX_LOD, s->max_lod);
    glTexParameteri(target, GL_TEXTURE_BASE_LEVEL, s->base_level);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, s->max_level);
}

void mesa_gl_upload(GLenum image_target, const sample_texture *tex, int level, int layer)
{
    int w, h, i, j;
    float *d;
    sample_texture_level_size(tex, level, &w, &h);
    d = (float *)malloc((size_t)w * h * 4 * sizeof(float));
    if (!d) return;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) sample_texture_texel_layer(tex, level, layer, i, j, d + 4 * ((size_t)j * w + i));
    glTexImage2D(image_target, level, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, d);
    free(d);
}

void mesa_gl_destroy(mesa_gl *g)
{
    if (g->ctx) OSMesaDestroyContext(g->ctx);
    g->ctx = NULL;
}

uint32_t mesa_rnd_u32(uint32_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 17;
    *state ^= *state << 5;
    return *state;
}

float mesa_rnd01(uint32_t *state) { return (float)(mesa_rnd_u32(state) >> 8) * (1.0f / 16777216.0f); }

float mesa_grad_scale(uint32_t *state, int emin, int emax)
{
    int e = (int)(mesa_rnd_u32(state) % (uint32_t)(emax - emin + 1)) + emin, m = (int)(mesa_rnd_u32(state) % 256);
    return ldexpf(1.0f + (float)m / 256.0f, e);
}

int mesa_write_file(const char *path, const void *p, size_t n)
{
    FILE *f = fopen(path, "wb");
    int ok = f && fwrite(p, 1, n, f) == n;
    if (f && fclose(f) != 0) ok = 0;
    return ok;
}

int mesa_read_file(const char *path, void *p, size_t n)
{
    FILE *f = fopen(path, "rb");
    int ok = f && fread(p, 1, n, f) == n;
    if (f) fclose(f);
    return ok;
}

void mesa_dump_levels(const char *dir, const sample_texture *tex, int layers)
{
    sample_texture_info info;
    int k, i, j, l;
    sample_texture_info_get(tex, &info);
    for (k = 0; k < info.levels; ++k) {
        char path[4096];
        int w, h;
        float *d;
        sample_texture_level_size(tex, k, &w, &h);
        d = (float *)malloc((size_t)layers * w * h * 4 * sizeof(float));
        if (!d) return;
        for (l = 0; l < layers; ++l)
            for (j = 0; j < h; ++j)
                for (i = 0; i < w; ++i)
                    sample_texture_texel_layer(tex, k, l, i, j, d + 4 * (((size_t)l * h + j) * w + i));
        if (k == 0) snprintf(path, sizeof path, "%s/tex.raw", dir);
        else snprintf(path, sizeof path, "%s/tex.%d.raw", dir, k);
        mesa_write_file(path, d, (size_t)layers * w * h * 4 * sizeof(float));
        free(d);
    }
}

void mesa_sampler_args(char *buf, size_t size, const sample_sampler *s)
{
    snprintf(buf, size,
             "--wrap-s %s --wrap-t %s --min %s --mag %s --border %g,%g,%g,%g --lod-bias %g --min-lod %g "
             "--max-lod %g --base-level %d --max-level %d --nearest-level-floor",
             sample_wrap_name(s->wrap_s), sample_wrap_name(s->wrap_t), sample_filter_name(s->min_filter),
             sample_filter_name(s->mag_filter), s->border_color[0], s->border_color[1], s->border_color[2],
             s->border_color[3], s->lod_bias, s->min_lod, s->max_lod, s->base_level, s->max_level);
}

int mesa_lookup_run(const char *cmd, const char *dir, int verbose, float *out, int n)
{
    char path[4096];
    if (verbose) fprintf(stderr, "%s\n", cmd);
    if (system(cmd) != 0) {
        fprintf(stderr, "texsample lookup failed: %s\n", cmd);
        return 0;
    }
    snprintf(path, sizeof path, "%s/ours.bin", dir);
    return mesa_read_file(path, out, (size_t)n * 4 * sizeof(float));
}
