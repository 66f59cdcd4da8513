/* nff_tokens.c - the NFF reader's token stream: whitespace and comments, line counting,
 * one token of look-ahead, strict decimal numbers, and "file:line: message" errors. */
#include "nff_tokens.h"

#include "rt_file_read.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Longest number token accepted: far beyond any real NFF file, and it keeps
 * the NUL-terminated copy strtod needs on the stack. */
#define NFF_MAX_NUMBER_CHARS 400

/* ------------------------------------------------------------------ stream */

void rt_nff_stream_init(rt_nff_stream *S, const char *name, const char *text, size_t length, char *msg, size_t msg_len)
{
    memset(S, 0, sizeof *S);
    S->name = name;
    S->msg = msg;
    S->msg_len = msg_len;
    S->p = text;
    S->end = text + length;
    S->line = 1;
    S->last_line = 1;
}

/* ------------------------------------------------------------------ messages */

/* Writes "NAME:LINE: message" into the caller's buffer and returns `status`. */
rt_status rt_nff_fail(rt_nff_stream *S, size_t line, rt_status status, const char *fmt, ...)
{
    if (S->msg && S->msg_len > 0) {
        char name[256];
        rt_escape_bytes(S->name, strlen(S->name), 0, name, sizeof name);
        int n = snprintf(S->msg, S->msg_len, "%s:%zu: ", name, line);
        if (n >= 0 && (size_t)n < S->msg_len) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(S->msg + n, S->msg_len - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return status;
}

/* Copies a token for quoting in a message, shortened if long; bytes outside
 * printable ASCII are escaped (NFF is ASCII text). */
const char *rt_nff_show(const rt_nff_token *t, char buf[RT_NFF_SHOW_CHARS + 4])
{
    return rt_escape_bytes(t->text, t->len, 1, buf, RT_NFF_SHOW_CHARS + 4);
}

/* The end-of-file error: the entity's line is named because the message
 * points at the last line of the file. */
rt_status rt_nff_fail_eof(rt_nff_stream *S, const rt_nff_entity *e, const char *what)
{
    return rt_nff_fail(S, S->last_line, RT_ERR_PARSE, "unexpected end of file: '%s' at line %zu is missing its %s",
                       e->keyword, e->line, what);
}

/* ------------------------------------------------------------------- lexing */

static int is_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* Skips whitespace and comments, counting lines ("\n", "\r\n" and a lone "\r"). */
static void skip_blank(rt_nff_stream *S)
{
    while (S->p < S->end) {
        char c = *S->p;
        if (c == '\n') {
            S->line++;
            S->p++;
        } else if (c == '\r') {
            S->p++;
            if (S->p >= S->end || *S->p != '\n') S->line++;
        } else if (is_space((unsigned char)c)) {
            S->p++;
        } else if (c == '#') {
            while (S->p < S->end && *S->p != '\n' && *S->p != '\r') S->p++;
        } else {
            break;
        }
    }
}

/* Reads the next token; 0 at end of input. A token ends at whitespace or '#'. */
int rt_nff_next_token(rt_nff_stream *S, rt_nff_token *t)
{
    if (S->has_peek) {
        *t = S->peeked;
        S->has_peek = 0;
        S->token_line = t->line;
        S->last = *t;
        return 1;
    }
    skip_blank(S);
    if (S->p >= S->end) return 0;
    t->text = S->p;
    t->line = S->line;
    while (S->p < S->end && !is_space((unsigned char)*S->p) && *S->p != '#') S->p++;
    t->len = (size_t)(S->p - t->text);
    S->token_line = t->line;
    S->last = *t;
    return 1;
}

/* Looks at the next token without consuming it; 0 at end of input. */
int rt_nff_peek_token(rt_nff_stream *S, rt_nff_token *t)
{
    if (!S->has_peek) {
        size_t keep_line = S->token_line;
        rt_nff_token keep = S->last;
        if (!rt_nff_next_token(S, &S->peeked)) return 0;
        S->token_line = keep_line;
        S->last = keep;
        S->has_peek = 1;
    }
    *t = S->peeked;
    return 1;
}

int rt_nff_token_is(const rt_nff_token *t, const char *word)
{
    size_t n = strlen(word);
    return t->len == n && memcmp(t->text, word, n) == 0;
}

/* Strict decimal syntax: [+-] digits [. digits] [e [+-] digits], at least one
 * mantissa digit. Rules out nan, inf, hex floats, "1.2.3" and "1e". */
static int number_syntax(const char *s, size_t n)
{
    size_t i = 0, digits = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) i++;
    while (i < n && is_digit(s[i])) i++, digits++;
    if (i < n && s[i] == '.') {
        i++;
        while (i < n && is_digit(s[i])) i++, digits++;
    }
    if (digits == 0) return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t exp_digits = 0;
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-')) i++;
        while (i < n && is_digit(s[i])) i++, exp_digits++;
        if (exp_digits == 0) return 0;
    }
    return i == n;
}

/* Whether a token is meant as a number (so `l`'s colour is present, or a
 * stray value gets a better message than "unknown keyword"). */
int rt_nff_looks_numeric(const rt_nff_token *t)
{
    char c = t->text[0];
    if (is_digit(c) || c == '+' || c == '-' || c == '.') return 1;
    if (t->len >= 3) {
        char w[4] = {(char)(t->text[0] | 0x20), (char)(t->text[1] | 0x20), (char)(t->text[2] | 0x20), 0};
        return strcmp(w, "nan") == 0 || strcmp(w, "inf") == 0;
    }
    return 0;
}

/* --------------------------------------------------------- reading values */

/* Formats "the WHAT[ COMP] of 'KW'[ (line N)]" for value messages. */
static void describe(char *buf, size_t len, const rt_nff_entity *e, const char *what, const char *comp,
                     size_t token_line)
{
    if (token_line == e->line)
        snprintf(buf, len, "%s%s%s of '%s'", what, comp ? " " : "", comp ? comp : "", e->keyword);
    else snprintf(buf, len, "%s%s%s of '%s' (line %zu)", what, comp ? " " : "", comp ? comp : "", e->keyword, e->line);
}

/* Reads one finite double; `what` and `comp` name it in messages. */
rt_status rt_nff_read_number(rt_nff_stream *S, const rt_nff_entity *e, const char *what, const char *comp, double *out)
{
    rt_nff_token t;
    char desc[160], shown[RT_NFF_SHOW_CHARS + 4];
    if (!rt_nff_next_token(S, &t)) {
        char full[96];
        snprintf(full, sizeof full, "%s%s%s", what, comp ? " " : "", comp ? comp : "");
        return rt_nff_fail_eof(S, e, full);
    }
    describe(desc, sizeof desc, e, what, comp, t.line);
    if (!number_syntax(t.text, t.len)) {
        if (rt_nff_looks_numeric(&t))
            return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: '%s' is not a finite decimal number", desc,
                               rt_nff_show(&t, shown));
        return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: expected a number, got '%s'", desc,
                           rt_nff_show(&t, shown));
    }
    if (t.len > NFF_MAX_NUMBER_CHARS)
        return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: number '%s' is longer than %d characters", desc,
                           rt_nff_show(&t, shown), NFF_MAX_NUMBER_CHARS);
    char buf[NFF_MAX_NUMBER_CHARS + 1];
    memcpy(buf, t.text, t.len);
    buf[t.len] = '\0';
    char *stop = NULL;
    errno = 0;
    double v = strtod(buf, &stop);
    if (stop != buf + t.len)
        return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: '%s' is not a finite decimal number", desc,
                           rt_nff_show(&t, shown));
    /* ERANGE with a tiny result is underflow: 1e-400 reads as (nearly) zero. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0))
        return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: '%s' is out of the range of a double", desc,
                           rt_nff_show(&t, shown));
    *out = v;
    return RT_OK;
}

rt_status rt_nff_read_vec(rt_nff_stream *S, const rt_nff_entity *e, const char *what, rt_vec3 *out)
{
    rt_status st;
    if ((st = rt_nff_read_number(S, e, what, "x", &out->x)) != RT_OK) return st;
    if ((st = rt_nff_read_number(S, e, what, "y", &out->y)) != RT_OK) return st;
    return rt_nff_read_number(S, e, what, "z", &out->z);
}

rt_status rt_nff_read_color(rt_nff_stream *S, const rt_nff_entity *e, const char *what, rt_vec3 *out)
{
    rt_status st;
    if ((st = rt_nff_read_number(S, e, what, "red", &out->x)) != RT_OK) return st;
    if ((st = rt_nff_read_number(S, e, what, "green", &out->y)) != RT_OK) return st;
    return rt_nff_read_number(S, e, what, "blue", &out->z);
}

/* Reads a decimal integer ([+-]digits), saturated to +-2^53 so huge counts
 * compare as huge without overflow. */
rt_status rt_nff_read_integer(rt_nff_stream *S, const rt_nff_entity *e, const char *what, long long *out)
{
    rt_nff_token t;
    char desc[160], shown[RT_NFF_SHOW_CHARS + 4];
    if (!rt_nff_next_token(S, &t)) return rt_nff_fail_eof(S, e, what);
    describe(desc, sizeof desc, e, what, NULL, t.line);
    size_t i = 0;
    int negative = 0, ok;
    if (t.len > 0 && (t.text[0] == '+' || t.text[0] == '-')) negative = t.text[0] == '-', i = 1;
    long long v = 0;
    const long long cap = 1LL << 53;
    ok = i < t.len;
    for (; ok && i < t.len; i++) {
        if (!is_digit(t.text[i])) ok = 0;
        else if (v < cap) v = v * 10 + (t.text[i] - '0');
    }
    if (ok) {
        *out = negative ? -(v > cap ? cap : v) : (v > cap ? cap : v);
        return RT_OK;
    }
    if (number_syntax(t.text, t.len))
        return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: '%s' is not a whole number", desc, rt_nff_show(&t, shown));
    return rt_nff_fail(S, t.line, RT_ERR_PARSE, "bad %s: expected a whole number, got '%s'", desc,
                       rt_nff_show(&t, shown));
}

/* ------------------------------------------------------------------- text */

/* Rejects control bytes (a binary file, UTF-16, ...) up front and finds the
 * line the input ends on (a final newline ends the last line, not a new one). */
rt_status rt_nff_scan_text(rt_nff_stream *S)
{
    size_t line = 1;
    for (const char *q = S->p; q < S->end; q++) {
        unsigned char c = (unsigned char)*q;
        if (c == '\n' || (c == '\r' && (q + 1 >= S->end || q[1] != '\n'))) {
            if (q + 1 < S->end) line++;
        } else if ((c < 0x20 && !is_space(c)) || c == 0x7f) {
            return rt_nff_fail(S, line, RT_ERR_PARSE, "binary data (byte 0x%02x at offset %zu): not an NFF text file",
                               c, (size_t)(q - S->p));
        }
    }
    S->last_line = line;
    return RT_OK;
}
