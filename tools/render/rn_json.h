/*
 * A strict JSON reader for scene files (RFC 8259), built for bounded memory.
 *
 * The whole document becomes one array of 16-byte nodes in pre-order
 * (a general-purpose tree such as cJSON's costs ~80 bytes per value: 40×
 * the text of a number array). Strings are decoded once into a pool;
 * numbers stay in the text and are converted when read. Every node keeps
 * its byte offset, so errors can say line and column.
 *
 * Strict: one value, then only white space (RFC 8259 §2); no comments,
 * trailing commas, NaN or leading zeros; strings valid UTF-8 without
 * control characters or U+0000. The parse stops at the first error, and
 * when the document holds more than max_nodes values.
 */
#ifndef TEXSAMPLE_RN_JSON_H
#define TEXSAMPLE_RN_JSON_H

#include <stddef.h>
#include <stdint.h>

typedef enum rn_jtype {
    RN_JNULL = 0,
    RN_JFALSE,
    RN_JTRUE,
    RN_JNUMBER,
    RN_JSTRING,
    RN_JARRAY,
    RN_JOBJECT
} rn_jtype;

#define RN_JNONE UINT32_MAX /* "no node", "no key" */

typedef struct rn_jnode {
    uint32_t type_pos; /* rn_jtype in the low 3 bits; above, the byte offset of the
                          value, or of its name for an object member (for messages) */
    uint32_t span;     /* nodes in this subtree, itself included: next sibling at index + span */
    uint32_t key;      /* object members: pool offset of the decoded name; else RN_JNONE */
    uint32_t val;      /* strings: pool offset; numbers: text offset; arrays, objects:
                          element count */
} rn_jnode;

typedef struct rn_json {
    const char *text;
    size_t len;
    rn_jnode *node; /* node[0] is the root */
    uint32_t count, cap;
    char *pool; /* NUL-terminated decoded strings */
    size_t pool_len, pool_cap;
} rn_json;

/* Texts are at most this long (the byte offset fits next to the type). */
#define RN_JSON_MAX_TEXT ((size_t)1 << 29)

/* Parse text[0, len) (no terminator needed). Returns 1, or 0 with a
 * message "line L, column C: ..." in err; j is freed either way on 0.
 * Memory: 16 bytes per value (at most max_nodes) plus the decoded strings. */
int rn_json_parse(rn_json *j, const char *text, size_t len, uint32_t max_nodes, char *err,
                  size_t errlen);
void rn_json_free(rn_json *j);

static inline rn_jtype rn_json_type(const rn_json *j, uint32_t n)
{
    return (rn_jtype)(j->node[n].type_pos & 7u);
}
/* 1-based line and column (in bytes) of byte offset pos of a text. */
void rn_json_line_col(const char *text, size_t len, size_t pos, int *line, int *column);
/* The same where node n starts: its value, or for an object member its name
 * (RN_JNONE: the end of the text). */
void rn_json_where(const rn_json *j, uint32_t n, int *line, int *column);
/* First element or member of an array or object (RN_JNONE if empty), and
 * the one after n within its parent (RN_JNONE after the last). */
uint32_t rn_json_first(const rn_json *j, uint32_t n);
uint32_t rn_json_next(const rn_json *j, uint32_t parent, uint32_t n);
/* Elements of an array, members of an object, 0 otherwise. */
uint32_t rn_json_size(const rn_json *j, uint32_t n);
/* Member name of n (NULL if n is not an object member). */
const char *rn_json_key(const rn_json *j, uint32_t n);
/* The member of object n called key, RN_JNONE if none (or n not an object). */
uint32_t rn_json_get(const rn_json *j, uint32_t n, const char *key);
/* Element k of array n, RN_JNONE if out of range. */
uint32_t rn_json_at(const rn_json *j, uint32_t n, uint32_t k);
/* A number's value (the text converted, correctly rounded by strtod). */
double rn_json_number(const rn_json *j, uint32_t n);
/* A string's decoded value, NULL if n is not a string. */
const char *rn_json_string(const rn_json *j, uint32_t n);

#endif
