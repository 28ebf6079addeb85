/*
 * The OSMesa plumbing of the Mesa cross-checks (mesa_check.c,
 * mesa_cube.c): a GL 3.3 compatibility context, a program of the shared
 * full-screen vertex shader and the caller's fragment shader, an RGBA32F
 * framebuffer of qw × rows fragments (one query each), and the query
 * texture on unit 1 (uniform "qtex"), from which fragment (x, y) fetches
 * its query's `per` RGBA32F texels at (per·x … per·x + per − 1, y)
 * exactly, no interpolation. The texture under test is the caller's, on
 * unit 0 (uniform "tex").
 */
#ifndef SAMPLE_TEST_MESA_GL_H
#define SAMPLE_TEST_MESA_GL_H

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include "sample/sample.h"

#include <stddef.h>
#include <stdint.h>

typedef struct mesa_gl {
    OSMesaContext ctx;
    unsigned char dummy[4];
    GLuint prog, vao, vbo, fbo, rt, qtex;
    int qw, rows;
    const char *who; /* the program's name, for messages */
} mesa_gl;

/* 0 when OSMesa cannot give a GL 3.3 context or the shader does not
 * compile (the caller skips, exit 77). The compatibility profile is asked
 * for because it is the one that still has GL_CLAMP; softpipe gives 3.3
 * either way. Prints the renderer. */
int mesa_gl_init(mesa_gl *g, const char *who, const char *fs_src, int qw, int rows);

/* Upload qw·rows queries of `per` RGBA32F texels each (4·per floats per
 * query, query i at fragment (i mod qw, i / qw)), draw, and read the
 * qw·rows RGBA float results into out. 0 on a GL error. */
int mesa_gl_render(mesa_gl *g, const float *queries, int per, float *out);

/* Set the sampler state s on the texture bound to `target` of the
 * active unit: wrap s, t, r, the filters (OpenGL's six), border colour,
 * GL_TEXTURE_LOD_BIAS, min/max lod, base/max level. */
void mesa_gl_sampler(GLenum target, const sample_sampler *s);

/* glTexImage2D(image_target, level) of layer `layer` (a cube face) of
 * level `level` of tex, as RGBA32F: the texels libsample reads
 * (sample_texture_texel_layer), so that both sides sample the same. */
void mesa_gl_upload(GLenum image_target, const sample_texture *tex, int level, int layer);

void mesa_gl_destroy(mesa_gl *g);

/* `texsample lookup` by files (the checks' --texsample): write and read
 * whole files (1 on success); every level of tex as DIR/tex.raw and
 * DIR/tex.K.raw, each level's `layers` layers (a cube map's six faces)
 * one after the other, float32 RGBA; the sampler state as lookup options
 * (wraps, filters, border, bias, lod clamps, base/max level, and Mesa's
 * ⌊λ + ½⌋ rounding) appended to buf; and running a command line that
 * writes DIR/ours.bin, read into out (n RGBA results; 0 on failure,
 * reported; the command printed when verbose). */
int mesa_write_file(const char *path, const void *p, size_t n);
int mesa_read_file(const char *path, void *p, size_t n);
void mesa_dump_levels(const char *dir, const sample_texture *tex, int layers);
void mesa_sampler_args(char *buf, size_t size, const sample_sampler *s);
int mesa_lookup_run(const char *cmd, const char *dir, int verbose, float *out, int n);

/* The checks' random numbers: xorshift32 on *state, a float in [0, 1)
 * from its top 24 bits, and a texel-space scale 2^e·(1 + m/256) with e in
 * [emin, emax] — 8 mantissa bits, so that ρ and its logarithm are exact in
 * softpipe's 16-bit log2 table as well. */
uint32_t mesa_rnd_u32(uint32_t *state);
float mesa_rnd01(uint32_t *state);
float mesa_grad_scale(uint32_t *state, int emin, int emax);

/* The fragment shader of the checks whose queries are 9 floats (cube
 * maps, 3D textures), for a texture of GLSL type SAMPLER: query i sits at
 * fragment (i mod width, i / width) and is three RGBA32F texels of qtex,
 * (p, λ), (dP/dx, 0), (dP/dy, 0); use_lod picks textureLod(p, λ) over
 * textureGrad. */
#define MESA_FS_QUERY3(SAMPLER)                                                \
    "#version 330 core\n"                                                     \
    "uniform " SAMPLER " tex;\n"                                              \
    "uniform sampler2D qtex;\n"                                               \
    "uniform int use_lod;\n"                                                  \
    "out vec4 color;\n"                                                       \
    "void main() {\n"                                                         \
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"                                   \
    "  vec4 a = texelFetch(qtex, ivec2(3 * p.x, p.y), 0);\n"                  \
    "  vec4 b = texelFetch(qtex, ivec2(3 * p.x + 1, p.y), 0);\n"              \
    "  vec4 c = texelFetch(qtex, ivec2(3 * p.x + 2, p.y), 0);\n"              \
    "  if (use_lod != 0) color = textureLod(tex, a.xyz, a.w);\n"              \
    "  else color = textureGrad(tex, a.xyz, b.xyz, c.xyz);\n"                 \
    "}\n"

#endif /* SAMPLE_TEST_MESA_GL_H */
