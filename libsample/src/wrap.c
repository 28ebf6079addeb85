/*
 * Texel addressing: the one function every filter uses (DESIGN §3,
 * OpenGL 4.6 §8.14.2 table 8.20, EXT_texture_mirror_clamp).
 *
 * Indices arrive as integral doubles: every float coordinate's floor is
 * exactly representable there, so the modulo below is exact even for 1e30,
 * and nothing out of int range is ever converted (that would be UB).
 */
#include "wrap.h"

#include <float.h>

float ls_wrap_coord(sample_wrap mode, float s, int n)
{
    float lo = 0.5f / (float)n, a = fabsf(s);
    switch (mode) {
    case SAMPLE_WRAP_CLAMP:
        /* GL_CLAMP: u is clamped to [0, n] before texel selection. */
        return s < 0.0f ? 0.0f : (s > 1.0f ? 1.0f : s);
    case SAMPLE_WRAP_MIRROR_CLAMP:
        /* s' = min(1, max(1/(2n), |s|)), then as CLAMP. */
        return a < lo ? lo : (a > 1.0f ? 1.0f : a);
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER: {
        /* s' = min(1 + 1/(2n), max(1/(2n), |s|)), then as CLAMP_TO_BORDER. */
        float hi = 1.0f + lo;
        return a < lo ? lo : (a > hi ? hi : a);
    }
    default:
        return s;
    }
}

static double clampd(double i, double lo, double hi) { return i < lo ? lo : (i > hi ? hi : i); }

/* mirror(a) of table 8.20: reflects negative indices about −½. */
static double mirror(double a) { return a >= 0.0 ? a : -(1.0 + a); }

int ls_wrap_index(sample_wrap mode, double i, int n, int linear)
{
    double nd = (double)n;
    /* Every mode maps an in-range index to itself; most reads are in range,
     * so they skip the per-mode work (and fmod). */
    if (i >= 0.0 && i < nd) return (int)i;
    /* s·n can overflow float to ±inf for |s| near FLT_MAX; fmod(inf) is NaN
     * and NaN → int is undefined, so saturate first. */
    if (!(i >= -DBL_MAX)) i = -DBL_MAX;
    if (!(i <= DBL_MAX)) i = DBL_MAX;
    switch (mode) {
    case SAMPLE_WRAP_REPEAT: {
        /* True modulo, also for negative i (fmod is exact on doubles). */
        double r = fmod(i, nd);
        if (r < 0.0) r += nd;
        return (int)r;
    }
    case SAMPLE_WRAP_MIRRORED_REPEAT: {
        double m = fmod(i, 2.0 * nd);
        if (m < 0.0) m += 2.0 * nd;
        return (int)((nd - 1.0) - mirror(m - nd));
    }
    case SAMPLE_WRAP_CLAMP_TO_EDGE:
        return (int)clampd(i, 0.0, nd - 1.0);
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE:
        return (int)clampd(mirror(i), 0.0, nd - 1.0);
    case SAMPLE_WRAP_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP:
        /* Legacy clamp: NEAREST clamps to the edge texel; LINEAR (and every
         * footprint filter) may reach −1 or n, which read the border. */
        if (!linear) return (int)clampd(i, 0.0, nd - 1.0);
        return (i < 0.0 || i >= nd) ? -1 : (int)i;
    case SAMPLE_WRAP_CLAMP_TO_BORDER:
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER:
    default:
        return (i < 0.0 || i >= nd) ? -1 : (int)i;
    }
}
