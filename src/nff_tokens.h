/* nff_tokens.h - the NFF reader's token stream and strict number parsing (kernel internal).
 *
 * Usage (nff.c is the one user):
 *   rt_nff_stream in;
 *   rt_nff_stream_init(&in, "scene.nff", text, length, msg, sizeof msg);
 *   if (rt_nff_scan_text(&in)) return ...;          // binary data; sets in.last_line
 *   rt_nff_token t;
 *   while (rt_nff_next_token(&in, &t)) { ... rt_nff_read_vec(&in, &entity, "centre", &c) ... }
 *
 * The input is whitespace-separated tokens, not lines; `#` starts a comment to the end of the
 * line, also right after a token; "\n", "\r\n" and a lone "\r" each end a line. Every token
 * remembers its line. Numbers are strict decimal floats (no nan, inf, hex or "1.2.3"), read
 * with strtod: the caller selects the C locale for LC_NUMERIC.
 *
 * Every rt_status function returns RT_OK, or RT_ERR_PARSE after writing "NAME:LINE: message"
 * into the stream's message buffer.
 */
#ifndef RT_NFF_TOKENS_H
#define RT_NFF_TOKENS_H

#include <stddef.h>

#include "rt_status.h"
#include "rt_vec.h"

/* Tokens are quoted in messages up to this many bytes (a buffer needs 4 more). */
#define RT_NFF_SHOW_CHARS 40

typedef struct rt_nff_token {
    const char *text; /* points into the input, not NUL-terminated */
    size_t len;       /* bytes */
    size_t line;      /* 1-based line of the first byte */
} rt_nff_token;

/* The entity being read, for messages ("'s' at line 4 is missing ..."). */
typedef struct rt_nff_entity {
    const char *keyword;
    size_t line;
} rt_nff_entity;

typedef struct rt_nff_stream {
    const char *name;    /* file name used in messages */
    const char *p, *end; /* unread input */
    size_t line;         /* line of *p */
    size_t last_line;    /* line the input ends on: EOF messages point here */
    rt_nff_token peeked; /* one token of look-ahead (for `l`'s optional colour) */
    int has_peek;
    size_t token_line; /* line of the last token consumed */
    rt_nff_token last; /* the last token consumed, to quote it */
    char *msg;         /* the caller's message buffer (may be NULL) */
    size_t msg_len;    /* bytes */
} rt_nff_stream;

/* Starts reading `length` bytes of `text` at line 1; never fails. */
void rt_nff_stream_init(rt_nff_stream *S, const char *name, const char *text, size_t length, char *msg, size_t msg_len);

/* Writes "NAME:LINE: message" into the message buffer and returns `status`. */
rt_status rt_nff_fail(rt_nff_stream *S, size_t line, rt_status status, const char *fmt, ...);

/* The end-of-file error for entity `e` missing its `what`; returns RT_ERR_PARSE. */
rt_status rt_nff_fail_eof(rt_nff_stream *S, const rt_nff_entity *e, const char *what);

/* Copies a token into buf for quoting, shortened with "..." if long; returns buf. */
const char *rt_nff_show(const rt_nff_token *t, char buf[RT_NFF_SHOW_CHARS + 4]);

/* Rejects control bytes (binary data) and finds the input's last line; RT_ERR_PARSE if binary. */
rt_status rt_nff_scan_text(rt_nff_stream *S);

/* Reads the next token; returns 0 at end of input. */
int rt_nff_next_token(rt_nff_stream *S, rt_nff_token *t);

/* Looks at the next token without consuming it; returns 0 at end of input. */
int rt_nff_peek_token(rt_nff_stream *S, rt_nff_token *t);

/* Returns 1 if the token is exactly `word`, else 0. */
int rt_nff_token_is(const rt_nff_token *t, const char *word);

/* Returns 1 if the token is meant as a number (also nan, inf, "1.2.3"), else 0. */
int rt_nff_looks_numeric(const rt_nff_token *t);

/* Reads one finite double; `what` and `comp` (may be NULL) name it in messages. */
rt_status rt_nff_read_number(rt_nff_stream *S, const rt_nff_entity *e, const char *what, const char *comp, double *out);

/* Reads x y z, or red green blue; RT_ERR_PARSE names the bad component. */
rt_status rt_nff_read_vec(rt_nff_stream *S, const rt_nff_entity *e, const char *what, rt_vec3 *out);
rt_status rt_nff_read_color(rt_nff_stream *S, const rt_nff_entity *e, const char *what, rt_vec3 *out);

/* Reads a decimal integer ([+-]digits), saturated to +-2^53; RT_ERR_PARSE if not one. */
rt_status rt_nff_read_integer(rt_nff_stream *S, const rt_nff_entity *e, const char *what, long long *out);

#endif
