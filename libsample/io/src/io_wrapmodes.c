/* The "wrapmodes" attribute's words (io_internal.h). maketx and OpenImageIO's
 * TextureSystem spell the modes black, clamp, periodic, mirror (OIIO
 * texture.h, Tex::Wrap); "default" and the power-of-two and shared-border
 * variants have no libsample equivalent. */
#include "io_internal.h"

#include <stdio.h>
#include <string.h>

static const struct {
    const char *word;
    sample_wrap wrap;
} words[] = {
    {"black", SAMPLE_WRAP_CLAMP_TO_BORDER},
    {"clamp", SAMPLE_WRAP_CLAMP_TO_EDGE},
    {"periodic", SAMPLE_WRAP_REPEAT},
    {"mirror", SAMPLE_WRAP_MIRRORED_REPEAT},
};

const char *io_wrap_word(sample_wrap w)
{
    size_t k;
    for (k = 0; k < sizeof words / sizeof words[0]; ++k)
        if (words[k].wrap == w) return words[k].word;
    return "clamp";
}

static int parse_word(const char *s, size_t n, sample_wrap *out)
{
    size_t k;
    for (k = 0; k < sizeof words / sizeof words[0]; ++k)
        if (strlen(words[k].word) == n && strncmp(words[k].word, s, n) == 0) {
            *out = words[k].wrap;
            return 1;
        }
    return 0;
}

int io_wrapmodes_parse(const char *s, sample_wrap *wrap_s, sample_wrap *wrap_t)
{
    const char *comma = strchr(s, ',');
    sample_wrap a, b;
    if (!comma) {
        if (!parse_word(s, strlen(s), &a)) return 0;
        *wrap_s = *wrap_t = a;
        return 1;
    }
    if (!parse_word(s, (size_t)(comma - s), &a) || !parse_word(comma + 1, strlen(comma + 1), &b)) return 0;
    *wrap_s = a;
    *wrap_t = b;
    return 1;
}
