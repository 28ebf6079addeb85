/*
 * Strict JSON (RFC 8259) into compact pre-order nodes (rn_json.h): the
 * scene parser's memory is 16 bytes per value plus the decoded strings,
 * bounded by a node count, instead of a general tree's ~80.
 */
#include "rn_internal.h"
#include "rn_json.h"

#include <locale.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

/* Nesting deeper than this is refused (the parser recurses per level). */
#define JSON_MAX_DEPTH 512
/* Longest number token: far more digits than a double holds. */
#define JSON_MAX_NUMBER 100

typedef struct jparser {
    rn_json *j;
    size_t at;
    uint32_t max_nodes;
    char *err;
    size_t errlen;
    int failed;
} jparser;

void rn_json_line_col(const char *text, size_t len, size_t pos, int *line, int *column)
{
    size_t k;
    int l = 1, c = 1;
    for (k = 0; k < pos && k < len; ++k) {
        if (text[k] == '\n') {
            ++l;
            c = 1;
        } else {
            ++c;
        }
    }
    *line = l;
    *column = c;
}

void rn_json_where(const rn_json *j, uint32_t n, int *line, int *column)
{
    rn_json_line_col(j->text, j->len, n < j->count ? j->node[n].type_pos >> 3 : j->len, line,
                     column);
}

static int fail_at(jparser *p, size_t pos, const char *fmt, ...)
{
    char msg[160];
    va_list ap;
    int line, col;
    if (p->failed) return 0;
    p->failed = 1;
    rn_json_line_col(p->j->text, p->j->len, pos, &line, &col);
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    rn_seterr(p->err, p->errlen, "line %d, column %d: %s", line, col, msg);
    return 0;
}

static void skip_ws(jparser *p)
{
    const char *s = p->j->text;
    while (p->at < p->j->len &&
           (s[p->at] == ' ' || s[p->at] == '\t' || s[p->at] == '\n' || s[p->at] == '\r'))
        ++p->at;
}

static uint32_t new_node(jparser *p, rn_jtype type, uint32_t key, size_t pos)
{
    rn_json *j = p->j;
    rn_jnode *nd;
    if (j->count >= p->max_nodes) {
        fail_at(p, p->at, "more than %u JSON values (the scene limit)", (unsigned)p->max_nodes);
        return RN_JNONE;
    }
    if (j->count == j->cap) {
        uint32_t cap = j->cap ? (j->cap > p->max_nodes / 2 ? p->max_nodes : 2 * j->cap) : 64;
        rn_jnode *nn = realloc(j->node, (size_t)cap * sizeof *nn);
        if (!nn) {
            fail_at(p, p->at, "out of memory");
            return RN_JNONE;
        }
        j->node = nn;
        j->cap = cap;
    }
    nd = &j->node[j->count];
    nd->type_pos = (uint32_t)type | (uint32_t)(pos << 3);
    nd->span = 1;
    nd->key = key;
    nd->val = 0;
    return j->count++;
}

static int pool_put(jparser *p, const char *bytes, size_t n)
{
    rn_json *j = p->j;
    if (j->pool_len + n > j->pool_cap) {
        size_t cap = j->pool_cap ? j->pool_cap : 256;
        char *np;
        while (cap < j->pool_len + n) cap *= 2;
        if (!(np = realloc(j->pool, cap))) return fail_at(p, p->at, "out of memory");
        j->pool = np;
        j->pool_cap = cap;
    }
    memcpy(j->pool + j->pool_len, bytes, n);
    j->pool_len += n;
    return 1;
}

static int hex4(const char *s, unsigned *out)
{
    unsigned v = 0;
    int k;
    for (k = 0; k < 4; ++k) {
        char c = s[k];
        v <<= 4;
        if (c >= '0' && c <= '9') v |= (unsigned)(c - '0');
        else if (c >= 'a' && c <= 'f') v |= (unsigned)(c - 'a' + 10);
        else if (c >= 'A' && c <= 'F') v |= (unsigned)(c - 'A' + 10);
        else return 0;
    }
    *out = v;
    return 1;
}

/* Length of the valid UTF-8 sequence at s (at most n bytes), 0 if invalid
 * (overlong forms, surrogates and code points past U+10FFFF included). */
static size_t utf8_len(const unsigned char *s, size_t n)
{
    unsigned char c = s[0], lo = 0x80, hi = 0xBF;
    size_t len, k;
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF) len = 2;
    else if (c >= 0xE0 && c <= 0xEF) len = 3;
    else if (c >= 0xF0 && c <= 0xF4) len = 4;
    else return 0;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
    if (n < len || s[1] < lo || s[1] > hi) return 0;
    for (k = 2; k < len; ++k)
        if (s[k] < 0x80 || s[k] > 0xBF) return 0;
    return len;
}

static size_t utf8_put(unsigned cp, char out[4])
{
    if (cp < 0x80) {
        out[0] = (char)cp;
        return 1;
    }
    if (cp < 0x800) {
        out[0] = (char)(0xC0 | (cp >> 6));
        out[1] = (char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if (cp < 0x10000) {
        out[0] = (char)(0xE0 | (cp >> 12));
        out[1] = (char)(0x80 | ((cp >> 6) & 0x3F));
        out[2] = (char)(0x80 | (cp & 0x3F));
        return 3;
    }
    out[0] = (char)(0xF0 | (cp >> 18));
    out[1] = (char)(0x80 | ((cp >> 12) & 0x3F));
    out[2] = (char)(0x80 | ((cp >> 6) & 0x3F));
    out[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}

/* A string at p->at (the opening quote), decoded into the pool; its pool
 * offset in *off. */
static int parse_string(jparser *p, uint32_t *off)
{
    const char *s = p->j->text;
    size_t n = p->j->len, start = p->at;
    *off = (uint32_t)p->j->pool_len;
    ++p->at;
    for (;;) {
        size_t run = p->at;
        unsigned char c;
        while (p->at < n && s[p->at] != '"' && s[p->at] != '\\' &&
               (unsigned char)s[p->at] >= 0x20 && (unsigned char)s[p->at] < 0x80)
            ++p->at;
        if (p->at > run && !pool_put(p, s + run, p->at - run)) return 0;
        if (p->at >= n) return fail_at(p, start, "unterminated string");
        c = (unsigned char)s[p->at];
        if (c == '"') {
            ++p->at;
            return pool_put(p, "", 1);
        }
        if (c < 0x20) return fail_at(p, p->at, "control character in a string (escape it)");
        if (c >= 0x80) {
            size_t len = utf8_len((const unsigned char *)s + p->at, n - p->at);
            if (!len) return fail_at(p, p->at, "invalid UTF-8 in a string");
            if (!pool_put(p, s + p->at, len)) return 0;
            p->at += len;
            continue;
        }
        /* A backslash escape. */
        if (p->at + 1 >= n) return fail_at(p, start, "unterminated string");
        {
            static const char from[] = "\"\\/bfnrt", to[] = "\"\\/\b\f\n\r\t";
            const char *e = strchr(from, s[p->at + 1]);
            unsigned cp, lo;
            char buf[4];
            if (s[p->at + 1] != 'u') {
                if (!e || !s[p->at + 1]) return fail_at(p, p->at, "invalid escape in a string");
                if (!pool_put(p, &to[e - from], 1)) return 0;
                p->at += 2;
                continue;
            }
            if (p->at + 6 > n || !hex4(s + p->at + 2, &cp))
                return fail_at(p, p->at, "\\u needs four hex digits");
            p->at += 6;
            if (cp >= 0xD800 && cp <= 0xDBFF) {
                /* UTF-16 surrogate pair (RFC 8259 §7). */
                if (p->at + 6 > n || s[p->at] != '\\' || s[p->at + 1] != 'u' ||
                    !hex4(s + p->at + 2, &lo) || lo < 0xDC00 || lo > 0xDFFF)
                    return fail_at(p, p->at - 6, "unpaired UTF-16 surrogate in a string");
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                p->at += 6;
            } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
                return fail_at(p, p->at - 6, "unpaired UTF-16 surrogate in a string");
            }
            if (cp == 0) return fail_at(p, p->at - 6, "U+0000 in a string");
            if (!pool_put(p, buf, utf8_put(cp, buf))) return 0;
        }
    }
}

/* Copy the number token at pos into buf for strtod, the decimal point as
 * the C library's locale spells it. */
static double number_at(const char *s, size_t len, size_t pos)
{
    char buf[JSON_MAX_NUMBER + 1];
    const char *dp = localeconv()->decimal_point;
    size_t k = 0;
    while (pos + k < len && k < JSON_MAX_NUMBER && strchr("+-0123456789.eE", s[pos + k]) &&
           s[pos + k]) {
        buf[k] = s[pos + k] == '.' && dp && dp[0] ? dp[0] : s[pos + k];
        ++k;
    }
    buf[k] = '\0';
    return strtod(buf, NULL);
}

static int digits(jparser *p)
{
    size_t from = p->at;
    while (p->at < p->j->len && p->j->text[p->at] >= '0' && p->j->text[p->at] <= '9') ++p->at;
    return p->at > from;
}

/* -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)? (RFC 8259 §6), finite. */
static int parse_number(jparser *p)
{
    const char *s = p->j->text;
    size_t n = p->j->len, start = p->at;
    int exponent = 0;
    if (p->at < n && s[p->at] == '-') ++p->at;
    if (p->at < n && s[p->at] == '0') {
        ++p->at;
        if (p->at < n && s[p->at] >= '0' && s[p->at] <= '9')
            return fail_at(p, start, "numbers have no leading zeros");
    } else if (!digits(p)) {
        return fail_at(p, start, "invalid number");
    }
    if (p->at < n && s[p->at] == '.') {
        ++p->at;
        if (!digits(p)) return fail_at(p, start, "invalid number (digits must follow '.')");
    }
    if (p->at < n && (s[p->at] == 'e' || s[p->at] == 'E')) {
        exponent = 1;
        ++p->at;
        if (p->at < n && (s[p->at] == '+' || s[p->at] == '-')) ++p->at;
        if (!digits(p)) return fail_at(p, start, "invalid number (digits must follow 'e')");
    }
    if (p->at - start > JSON_MAX_NUMBER)
        return fail_at(p, start, "number longer than %d characters", JSON_MAX_NUMBER);
    /* Without an exponent, at most 100 digits stay far below DBL_MAX. */
    if (exponent && !isfinite(number_at(s, n, start)))
        return fail_at(p, start, "number out of the range of a double");
    return 1;
}

static int parse_value(jparser *p, uint32_t key, size_t pos, int depth);

/* Array or object at p->at (its opening bracket) as node nd. */
static int parse_container(jparser *p, uint32_t nd, int object, int depth)
{
    const char *s = p->j->text;
    char close = object ? '}' : ']';
    uint32_t count = 0;
    if (depth >= JSON_MAX_DEPTH)
        return fail_at(p, p->at, "nested deeper than %d levels", JSON_MAX_DEPTH);
    ++p->at;
    skip_ws(p);
    if (p->at < p->j->len && s[p->at] == close) {
        ++p->at;
        return 1;
    }
    for (;;) {
        uint32_t key = RN_JNONE;
        size_t pos;
        skip_ws(p);
        pos = p->at;
        if (object) {
            if (p->at >= p->j->len || s[p->at] != '"')
                return fail_at(p, p->at, "expected a member name in double quotes");
            if (!parse_string(p, &key)) return 0;
            skip_ws(p);
            if (p->at >= p->j->len || s[p->at] != ':')
                return fail_at(p, p->at, "expected ':' after the member name");
            ++p->at;
            skip_ws(p);
        }
        if (!parse_value(p, key, pos, depth + 1)) return 0;
        ++count;
        skip_ws(p);
        if (p->at < p->j->len && s[p->at] == ',') {
            ++p->at;
            continue;
        }
        if (p->at < p->j->len && s[p->at] == close) {
            ++p->at;
            break;
        }
        return fail_at(p, p->at, "expected ',' or '%c'%s", close,
                       p->at >= p->j->len ? ", found the end of the text" : "");
    }
    p->j->node[nd].val = count;
    return 1;
}

static int literal(jparser *p, const char *word)
{
    size_t n = strlen(word);
    if (p->at + n > p->j->len || memcmp(p->j->text + p->at, word, n) != 0)
        return fail_at(p, p->at, "expected a JSON value");
    p->at += n;
    return 1;
}

/* A value at p->at; its node records pos (an object member's: its name). */
static int parse_value(jparser *p, uint32_t key, size_t pos, int depth)
{
    const char *s = p->j->text;
    uint32_t nd;
    char c;
    int ok;
    if (p->at >= p->j->len) return fail_at(p, p->at, "expected a JSON value, found the end");
    c = s[p->at];
    if (c == '{' || c == '[') {
        if ((nd = new_node(p, c == '{' ? RN_JOBJECT : RN_JARRAY, key, pos)) == RN_JNONE) return 0;
        ok = parse_container(p, nd, c == '{', depth);
        p->j->node[nd].span = p->j->count - nd;
        return ok;
    }
    if (c == '"') {
        uint32_t off;
        if ((nd = new_node(p, RN_JSTRING, key, pos)) == RN_JNONE || !parse_string(p, &off)) return 0;
        p->j->node[nd].val = off;
        return 1;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
        if ((nd = new_node(p, RN_JNUMBER, key, pos)) == RN_JNONE) return 0;
        p->j->node[nd].val = (uint32_t)p->at;
        return parse_number(p);
    }
    if (c == 't') return new_node(p, RN_JTRUE, key, pos) != RN_JNONE && literal(p, "true");
    if (c == 'f') return new_node(p, RN_JFALSE, key, pos) != RN_JNONE && literal(p, "false");
    if (c == 'n') return new_node(p, RN_JNULL, key, pos) != RN_JNONE && literal(p, "null");
    return fail_at(p, p->at, "expected a JSON value");
}

int rn_json_parse(rn_json *j, const char *text, size_t len, uint32_t max_nodes, char *err,
                  size_t errlen)
{
    jparser p;
    memset(j, 0, sizeof *j);
    memset(&p, 0, sizeof p);
    j->text = text;
    j->len = len;
    p.j = j;
    p.max_nodes = max_nodes;
    p.err = err;
    p.errlen = errlen;
    if (len >= RN_JSON_MAX_TEXT) {
        rn_seterr(err, errlen, "JSON text longer than %zu bytes", RN_JSON_MAX_TEXT);
        return 0;
    }
    /* A UTF-8 byte order mark is tolerated (RFC 8259 §8.1 lets parsers). */
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) p.at = 3;
    skip_ws(&p);
    if (parse_value(&p, RN_JNONE, p.at, 0)) {
        skip_ws(&p);
        if (p.at == len) return 1;
        fail_at(&p, p.at, "unexpected text after the JSON value");
    }
    rn_json_free(j);
    return 0;
}

void rn_json_free(rn_json *j)
{
    free(j->node);
    free(j->pool);
    memset(j, 0, sizeof *j);
}

uint32_t rn_json_first(const rn_json *j, uint32_t n)
{
    return n < j->count && j->node[n].span > 1 ? n + 1 : RN_JNONE;
}

uint32_t rn_json_next(const rn_json *j, uint32_t parent, uint32_t n)
{
    uint32_t next = n + j->node[n].span;
    return next < parent + j->node[parent].span ? next : RN_JNONE;
}

uint32_t rn_json_size(const rn_json *j, uint32_t n)
{
    rn_jtype t;
    if (n >= j->count) return 0;
    t = rn_json_type(j, n);
    return t == RN_JARRAY || t == RN_JOBJECT ? j->node[n].val : 0;
}

const char *rn_json_key(const rn_json *j, uint32_t n)
{
    return n < j->count && j->node[n].key != RN_JNONE ? j->pool + j->node[n].key : NULL;
}

uint32_t rn_json_get(const rn_json *j, uint32_t n, const char *key)
{
    uint32_t e;
    if (n >= j->count || rn_json_type(j, n) != RN_JOBJECT) return RN_JNONE;
    for (e = rn_json_first(j, n); e != RN_JNONE; e = rn_json_next(j, n, e))
        if (strcmp(j->pool + j->node[e].key, key) == 0) return e;
    return RN_JNONE;
}

uint32_t rn_json_at(const rn_json *j, uint32_t n, uint32_t k)
{
    uint32_t e;
    if (n >= j->count || rn_json_type(j, n) != RN_JARRAY || k >= j->node[n].val) return RN_JNONE;
    for (e = rn_json_first(j, n); k > 0; --k) e = rn_json_next(j, n, e);
    return e;
}

double rn_json_number(const rn_json *j, uint32_t n)
{
    if (n >= j->count || rn_json_type(j, n) != RN_JNUMBER) return NAN;
    return number_at(j->text, j->len, j->node[n].val);
}

const char *rn_json_string(const rn_json *j, uint32_t n)
{
    return n < j->count && rn_json_type(j, n) == RN_JSTRING ? j->pool + j->node[n].val : NULL;
}
