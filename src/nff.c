/* nff.c - reader for NFF (Eric Haines' Neutral File Format) scenes, plus `am`.
 *
 * The input is read as a stream of whitespace-separated tokens, not lines:
 * SPD generators put all eight numbers of a `c` on one line, `b` may come
 * before `v`, and so on. Every token remembers its line for messages.
 * Numbers are strict decimal floats (no nan, inf, hex or "1.2.3"); the
 * scene is built only through the public builder of rt_scene.h.
 *
 * Decisions (for the NFF section of the project README):
 *  - a negative sphere or cone radius (NFF's "inside only") is rejected;
 *  - `hither` is read and ignored;
 *  - a `#` starts a comment to the end of the line, also right after a token;
 *  - a leading UTF-8 byte-order mark is skipped; other control bytes are
 *    "binary data".
 */
#include <errno.h>
#include <locale.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "rt_nff.h"

/* Longest number token accepted: far beyond any real NFF file, and it keeps
 * the NUL-terminated copy strtod needs on the stack. */
#define NFF_MAX_NUMBER_CHARS 400

/* Tokens are quoted in messages up to this many bytes. */
#define NFF_SHOW_CHARS 40

typedef struct nff_token {
    const char *text; /* points into the input, not NUL-terminated */
    size_t len;       /* bytes */
    size_t line;      /* 1-based line of the first byte */
} nff_token;

/* The entity being read, for messages ("'s' at line 4 is missing ..."). */
typedef struct nff_entity {
    const char *keyword;
    size_t line;
} nff_entity;

typedef struct nff_parser {
    const char *name;      /* file name used in messages */
    const char *p, *end;   /* unread input */
    size_t line;           /* line of *p */
    size_t last_line;      /* line the input ends on: EOF messages point here */
    nff_token peeked;      /* one token of look-ahead (for `l`'s optional colour) */
    int has_peek;
    size_t token_line;     /* line of the last token consumed */
    nff_token last;        /* the last token consumed, to quote it */
    nff_entity prev;       /* last complete entity, to explain stray numbers */
    rt_scene *scene;
    char *msg;
    size_t msg_len;
    rt_nff_warn_fn warn;
    void *warn_ctx;
    int have_material;     /* an `f` was seen */
    int warned_default;    /* the default-material warning was given */
    size_t view_line;      /* line of the `v`; 0 = none yet */
    rt_vec3 *vertices;     /* scratch for `p` and `pp`, reused between entities */
    rt_vec3 *normals;
    size_t scratch_capacity;
} nff_parser;

/* ------------------------------------------------------------------ messages */

/* Writes "NAME:LINE: message" into the caller's buffer and returns `status`. */
static rt_status fail(nff_parser *P, size_t line, rt_status status, const char *fmt, ...)
{
    if (P->msg && P->msg_len > 0) {
        int n = snprintf(P->msg, P->msg_len, "%s:%zu: ", P->name, line);
        if (n >= 0 && (size_t)n < P->msg_len) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(P->msg + n, P->msg_len - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return status;
}

/* Copies a token for quoting in a message, shortened if long. */
static const char *show(const nff_token *t, char buf[NFF_SHOW_CHARS + 4])
{
    size_t n = t->len > NFF_SHOW_CHARS ? NFF_SHOW_CHARS : t->len;
    memcpy(buf, t->text, n);
    if (t->len > NFF_SHOW_CHARS) memcpy(buf + n, "...", 3), n += 3;
    buf[n] = '\0';
    return buf;
}

/* The end-of-file error: the entity's line is named because the message
 * points at the last line of the file. */
static rt_status fail_eof(nff_parser *P, const nff_entity *e, const char *what)
{
    return fail(P, P->last_line, RT_ERR_PARSE,
                "unexpected end of file: '%s' at line %zu is missing its %s", e->keyword, e->line,
                what);
}

/* Turns a builder failure into a file:line message. */
static rt_status builder_fail(nff_parser *P, size_t line, rt_status st, const char *invalid_text)
{
    if (st == RT_ERR_NOMEM) return fail(P, line, RT_ERR_NOMEM, "out of memory");
    if (st == RT_ERR_LIMIT) return fail(P, line, RT_ERR_LIMIT, "%s", invalid_text);
    return fail(P, line, RT_ERR_PARSE, "%s", invalid_text);
}

/* ------------------------------------------------------------------- lexing */

static int is_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* Skips whitespace and comments, counting lines ("\n", "\r\n" and a lone "\r"). */
static void skip_blank(nff_parser *P)
{
    while (P->p < P->end) {
        char c = *P->p;
        if (c == '\n') {
            P->line++;
            P->p++;
        } else if (c == '\r') {
            P->p++;
            if (P->p >= P->end || *P->p != '\n') P->line++;
        } else if (is_space((unsigned char)c)) {
            P->p++;
        } else if (c == '#') {
            while (P->p < P->end && *P->p != '\n' && *P->p != '\r') P->p++;
        } else {
            break;
        }
    }
}

/* Reads the next token; 0 at end of input. A token ends at whitespace or '#'. */
static int next_token(nff_parser *P, nff_token *t)
{
    if (P->has_peek) {
        *t = P->peeked;
        P->has_peek = 0;
        P->token_line = t->line;
        P->last = *t;
        return 1;
    }
    skip_blank(P);
    if (P->p >= P->end) return 0;
    t->text = P->p;
    t->line = P->line;
    while (P->p < P->end && !is_space((unsigned char)*P->p) && *P->p != '#') P->p++;
    t->len = (size_t)(P->p - t->text);
    P->token_line = t->line;
    P->last = *t;
    return 1;
}

/* Looks at the next token without consuming it; 0 at end of input. */
static int peek_token(nff_parser *P, nff_token *t)
{
    if (!P->has_peek) {
        size_t keep_line = P->token_line;
        nff_token keep = P->last;
        if (!next_token(P, &P->peeked)) return 0;
        P->token_line = keep_line;
        P->last = keep;
        P->has_peek = 1;
    }
    *t = P->peeked;
    return 1;
}

static int token_is(const nff_token *t, const char *word)
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
static int looks_numeric(const nff_token *t)
{
    char c = t->text[0];
    if (is_digit(c) || c == '+' || c == '-' || c == '.') return 1;
    if (t->len >= 3) {
        char w[4] = {(char)(t->text[0] | 0x20), (char)(t->text[1] | 0x20),
                     (char)(t->text[2] | 0x20), 0};
        return strcmp(w, "nan") == 0 || strcmp(w, "inf") == 0;
    }
    return 0;
}

/* --------------------------------------------------------- reading values */

/* Formats "the WHAT[ COMP] of 'KW'[ (line N)]" for value messages. */
static void describe(char *buf, size_t len, const nff_entity *e, const char *what,
                     const char *comp, size_t token_line)
{
    if (token_line == e->line)
        snprintf(buf, len, "%s%s%s of '%s'", what, comp ? " " : "", comp ? comp : "", e->keyword);
    else
        snprintf(buf, len, "%s%s%s of '%s' (line %zu)", what, comp ? " " : "", comp ? comp : "",
                 e->keyword, e->line);
}

/* Reads one finite double; `what` and `comp` name it in messages. */
static rt_status read_number(nff_parser *P, const nff_entity *e, const char *what,
                             const char *comp, double *out)
{
    nff_token t;
    char desc[160], shown[NFF_SHOW_CHARS + 4];
    if (!next_token(P, &t)) {
        char full[96];
        snprintf(full, sizeof full, "%s%s%s", what, comp ? " " : "", comp ? comp : "");
        return fail_eof(P, e, full);
    }
    describe(desc, sizeof desc, e, what, comp, t.line);
    if (!number_syntax(t.text, t.len)) {
        if (looks_numeric(&t))
            return fail(P, t.line, RT_ERR_PARSE,
                        "bad %s: '%s' is not a finite decimal number", desc, show(&t, shown));
        return fail(P, t.line, RT_ERR_PARSE, "bad %s: expected a number, got '%s'", desc,
                    show(&t, shown));
    }
    if (t.len > NFF_MAX_NUMBER_CHARS)
        return fail(P, t.line, RT_ERR_PARSE, "bad %s: number '%s' is longer than %d characters",
                    desc, show(&t, shown), NFF_MAX_NUMBER_CHARS);
    char buf[NFF_MAX_NUMBER_CHARS + 1];
    memcpy(buf, t.text, t.len);
    buf[t.len] = '\0';
    char *stop = NULL;
    errno = 0;
    double v = strtod(buf, &stop);
    if (stop != buf + t.len)
        return fail(P, t.line, RT_ERR_PARSE, "bad %s: '%s' is not a finite decimal number", desc,
                    show(&t, shown));
    /* ERANGE with a tiny result is underflow: 1e-400 reads as (nearly) zero. */
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0))
        return fail(P, t.line, RT_ERR_PARSE, "bad %s: '%s' is out of the range of a double",
                    desc, show(&t, shown));
    *out = v;
    return RT_OK;
}

static rt_status read_vec(nff_parser *P, const nff_entity *e, const char *what, rt_vec3 *out)
{
    rt_status st;
    if ((st = read_number(P, e, what, "x", &out->x)) != RT_OK) return st;
    if ((st = read_number(P, e, what, "y", &out->y)) != RT_OK) return st;
    return read_number(P, e, what, "z", &out->z);
}

static rt_status read_color(nff_parser *P, const nff_entity *e, const char *what, rt_vec3 *out)
{
    rt_status st;
    if ((st = read_number(P, e, what, "red", &out->x)) != RT_OK) return st;
    if ((st = read_number(P, e, what, "green", &out->y)) != RT_OK) return st;
    return read_number(P, e, what, "blue", &out->z);
}

/* Reads a decimal integer ([+-]digits), saturated to +-2^53 so huge counts
 * compare as huge without overflow. */
static rt_status read_integer(nff_parser *P, const nff_entity *e, const char *what,
                              long long *out)
{
    nff_token t;
    char desc[160], shown[NFF_SHOW_CHARS + 4];
    if (!next_token(P, &t)) return fail_eof(P, e, what);
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
        return fail(P, t.line, RT_ERR_PARSE, "bad %s: '%s' is not a whole number", desc,
                    show(&t, shown));
    return fail(P, t.line, RT_ERR_PARSE, "bad %s: expected a whole number, got '%s'", desc,
                show(&t, shown));
}

/* Requires the next token to be the keyword `word` (inside the `v` block). */
static rt_status expect_keyword(nff_parser *P, const nff_entity *e, const char *word)
{
    nff_token t;
    char shown[NFF_SHOW_CHARS + 4];
    if (!next_token(P, &t)) {
        char what[48];
        snprintf(what, sizeof what, "'%s' line", word);
        return fail_eof(P, e, what);
    }
    if (!token_is(&t, word))
        return fail(P, t.line, RT_ERR_PARSE,
                    "expected '%s' in the 'v' block (line %zu), got '%s' (the order is from, at, "
                    "up, angle, hither, resolution)",
                    word, e->line, show(&t, shown));
    return RT_OK;
}

/* ------------------------------------------------------------------ entities */

/* v / from / at / up / angle / hither / resolution, in that order. */
static rt_status parse_view(nff_parser *P, const nff_entity *e)
{
    rt_vec3 from, at, up;
    double angle = 0.0, hither = 0.0;
    long long w = 0, h = 0;
    rt_status st;
    if (P->view_line)
        return fail(P, e->line, RT_ERR_PARSE,
                    "second 'v' block (the first is at line %zu): a file has one view",
                    P->view_line);
    if ((st = expect_keyword(P, e, "from")) || (st = read_vec(P, e, "from", &from))) return st;
    if ((st = expect_keyword(P, e, "at")) || (st = read_vec(P, e, "at", &at))) return st;
    if ((st = expect_keyword(P, e, "up")) || (st = read_vec(P, e, "up", &up))) return st;
    if ((st = expect_keyword(P, e, "angle")) || (st = read_number(P, e, "angle", NULL, &angle)))
        return st;
    if (!(angle > 0.0 && angle < 180.0))
        return fail(P, P->token_line, RT_ERR_PARSE,
                    "view angle must be in (0, 180) degrees, got %g", angle);
    if ((st = expect_keyword(P, e, "hither")) ||
        (st = read_number(P, e, "hither", NULL, &hither)))
        return st;
    (void)hither; /* ignored: the design has no near clipping plane */
    if ((st = expect_keyword(P, e, "resolution")) ||
        (st = read_integer(P, e, "resolution width", &w)))
        return st;
    nff_token w_tok = P->last;
    if ((st = read_integer(P, e, "resolution height", &h))) return st;
    nff_token h_tok = P->last;
    char w_shown[NFF_SHOW_CHARS + 4], h_shown[NFF_SHOW_CHARS + 4];
    show(&w_tok, w_shown);
    show(&h_tok, h_shown);
    if (w < 1 || h < 1)
        return fail(P, w < 1 ? w_tok.line : h_tok.line, RT_ERR_PARSE,
                    "resolution must be at least 1 x 1 pixels, got %s x %s", w_shown, h_shown);
    if (w > (long long)RT_SCENE_MAX_RESOLUTION || h > (long long)RT_SCENE_MAX_RESOLUTION)
        return fail(P, w > (long long)RT_SCENE_MAX_RESOLUTION ? w_tok.line : h_tok.line,
                    RT_ERR_LIMIT, "resolution %s x %s exceeds the limit of %u pixels a side",
                    w_shown, h_shown, RT_SCENE_MAX_RESOLUTION);
    st = rt_scene_set_view(P->scene, from, at, up, angle, (uint32_t)w, (uint32_t)h);
    if (st) return builder_fail(P, e->line, st, "view rejected by the scene builder");
    P->view_line = e->line;
    return RT_OK;
}

/* The first object before any `f` gets the default material (the builder
 * applies it); say so once. */
static void note_object(nff_parser *P, const nff_entity *e)
{
    if (P->have_material || P->warned_default) return;
    P->warned_default = 1;
    if (!P->warn) return;
    char text[RT_MSG_LEN];
    snprintf(text, sizeof text,
             "%s:%zu: warning: object before any 'f': using f 1 1 1 1 0 0 0 1", P->name, e->line);
    P->warn(P->warn_ctx, text);
}

static rt_status object_limit(nff_parser *P, size_t line, rt_status st)
{
    char text[160];
    snprintf(text, sizeof text,
             "too many objects or vertices in the scene (the limit is %u objects)",
             RT_SCENE_MAX_OBJECTS);
    return builder_fail(P, line, st, text);
}

static rt_status parse_light(nff_parser *P, const nff_entity *e)
{
    rt_vec3 pos, rgb;
    nff_token t;
    rt_status st = read_vec(P, e, "position", &pos);
    if (st) return st;
    /* The colour is optional: present when the next token is a number. */
    int colored = peek_token(P, &t) && looks_numeric(&t);
    if (colored && (st = read_color(P, e, "colour", &rgb))) return st;
    st = rt_scene_add_light(P->scene, pos, colored ? &rgb : NULL);
    if (st == RT_ERR_LIMIT)
        return fail(P, e->line, RT_ERR_LIMIT, "too many lights (the limit is %u)",
                    RT_SCENE_MAX_LIGHTS);
    if (st) return builder_fail(P, e->line, st, "light rejected by the scene builder");
    return RT_OK;
}

static rt_status parse_material(nff_parser *P, const nff_entity *e)
{
    rt_material m;
    rt_status st;
    if ((st = read_color(P, e, "colour", &m.color)) ||
        (st = read_number(P, e, "Kd", NULL, &m.kd)) ||
        (st = read_number(P, e, "Ks", NULL, &m.ks)) ||
        (st = read_number(P, e, "Shine", NULL, &m.shine)) ||
        (st = read_number(P, e, "T", NULL, &m.t)) ||
        (st = read_number(P, e, "ior", NULL, &m.ior)))
        return st;
    st = rt_scene_set_material(P->scene, &m);
    if (st)
        return builder_fail(P, e->line, st,
                            "material values out of range (Shine must be >= 0 and ior > 0)");
    P->have_material = 1;
    return RT_OK;
}

static rt_status parse_sphere(nff_parser *P, const nff_entity *e)
{
    rt_vec3 c;
    double r = 0.0;
    rt_status st;
    if ((st = read_vec(P, e, "centre", &c)) || (st = read_number(P, e, "radius", NULL, &r)))
        return st;
    if (r < 0.0)
        return fail(P, P->token_line, RT_ERR_PARSE,
                    "negative sphere radius (inside-only spheres) is not supported");
    if (!(r > 0.0))
        return fail(P, P->token_line, RT_ERR_PARSE, "sphere radius must be > 0, got 0");
    note_object(P, e);
    st = rt_scene_add_sphere(P->scene, c, r);
    if (st == RT_ERR_INVALID)
        return fail(P, e->line, RT_ERR_PARSE, "sphere rejected by the scene builder");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

static rt_status parse_cone(nff_parser *P, const nff_entity *e)
{
    rt_vec3 base, apex;
    double rb = 0.0, ra = 0.0;
    rt_status st;
    if ((st = read_vec(P, e, "base", &base)) ||
        (st = read_number(P, e, "base radius", NULL, &rb)))
        return st;
    size_t rb_line = P->token_line;
    if ((st = read_vec(P, e, "apex", &apex)) ||
        (st = read_number(P, e, "apex radius", NULL, &ra)))
        return st;
    if (rb < 0.0 || ra < 0.0)
        return fail(P, rb < 0.0 ? rb_line : P->token_line, RT_ERR_PARSE,
                    "negative cone radius (inside-only cones) is not supported");
    if (rb == 0.0 && ra == 0.0)
        return fail(P, e->line, RT_ERR_PARSE, "cone with both radii zero");
    if (base.x == apex.x && base.y == apex.y && base.z == apex.z)
        return fail(P, e->line, RT_ERR_PARSE, "cone base and apex are the same point");
    note_object(P, e);
    st = rt_scene_add_cone(P->scene, base, rb, apex, ra);
    if (st == RT_ERR_INVALID)
        return fail(P, e->line, RT_ERR_PARSE, "cone rejected by the scene builder");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

/* Reads a vertex count and makes room for that many vertices (and normals):
 * the count is checked against the limit before anything is allocated. */
static rt_status read_vertex_count(nff_parser *P, const nff_entity *e, size_t *count)
{
    long long n = 0;
    char shown[NFF_SHOW_CHARS + 4];
    rt_status st = read_integer(P, e, "vertex count", &n);
    if (st) return st;
    if (n < 3)
        return fail(P, P->token_line, RT_ERR_PARSE, "'%s' needs at least 3 vertices, got %lld",
                    e->keyword, n);
    if (n > (long long)RT_SCENE_MAX_VERTICES)
        return fail(P, P->token_line, RT_ERR_LIMIT,
                    "'%s' with %s vertices exceeds the limit of %u", e->keyword,
                    show(&P->last, shown), RT_SCENE_MAX_VERTICES);
    if ((size_t)n > P->scratch_capacity) {
        rt_vec3 *v = realloc(P->vertices, (size_t)n * sizeof *v);
        if (!v) return fail(P, e->line, RT_ERR_NOMEM, "out of memory");
        P->vertices = v;
        rt_vec3 *nv = realloc(P->normals, (size_t)n * sizeof *nv);
        if (!nv) return fail(P, e->line, RT_ERR_NOMEM, "out of memory");
        P->normals = nv;
        P->scratch_capacity = (size_t)n;
    }
    *count = (size_t)n;
    return RT_OK;
}

/* `p N` then N vertices; `pp N` then N (vertex, normal) pairs. */
static rt_status parse_polygon(nff_parser *P, const nff_entity *e, int patch)
{
    size_t n = 0;
    rt_status st = read_vertex_count(P, e, &n);
    if (st) return st;
    for (size_t i = 0; i < n; i++) {
        char what[48];
        snprintf(what, sizeof what, "vertex %zu", i + 1);
        if ((st = read_vec(P, e, what, &P->vertices[i]))) return st;
        if (patch) {
            snprintf(what, sizeof what, "normal %zu", i + 1);
            if ((st = read_vec(P, e, what, &P->normals[i]))) return st;
        }
    }
    note_object(P, e);
    st = patch ? rt_scene_add_patch(P->scene, P->vertices, P->normals, n)
               : rt_scene_add_polygon(P->scene, P->vertices, n);
    if (st == RT_ERR_INVALID)
        return fail(P, e->line, RT_ERR_PARSE, "%s rejected by the scene builder",
                    patch ? "patch" : "polygon");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

/* Reads entities until the end of the input. */
static rt_status parse_entities(nff_parser *P)
{
    nff_token t;
    char shown[NFF_SHOW_CHARS + 4];
    while (next_token(P, &t)) {
        nff_entity e = {NULL, t.line};
        rt_status st;
        rt_vec3 rgb;
        if (token_is(&t, "v")) {
            e.keyword = "v";
            st = parse_view(P, &e);
        } else if (token_is(&t, "b")) {
            e.keyword = "b";
            st = read_color(P, &e, "colour", &rgb);
            if (!st && (st = rt_scene_set_background(P->scene, rgb)))
                st = builder_fail(P, e.line, st, "background rejected by the scene builder");
        } else if (token_is(&t, "am")) {
            e.keyword = "am";
            st = read_color(P, &e, "colour", &rgb);
            if (!st && (st = rt_scene_set_ambient(P->scene, rgb)))
                st = builder_fail(P, e.line, st, "ambient light rejected by the scene builder");
        } else if (token_is(&t, "l")) {
            e.keyword = "l";
            st = parse_light(P, &e);
        } else if (token_is(&t, "f")) {
            e.keyword = "f";
            st = parse_material(P, &e);
        } else if (token_is(&t, "s")) {
            e.keyword = "s";
            st = parse_sphere(P, &e);
        } else if (token_is(&t, "p")) {
            e.keyword = "p";
            st = parse_polygon(P, &e, 0);
        } else if (token_is(&t, "pp")) {
            e.keyword = "pp";
            st = parse_polygon(P, &e, 1);
        } else if (token_is(&t, "c")) {
            e.keyword = "c";
            st = parse_cone(P, &e);
        } else if (looks_numeric(&t)) {
            if (P->prev.keyword)
                return fail(P, t.line, RT_ERR_PARSE,
                            "unexpected value '%s' where a keyword belongs (too many values "
                            "for the '%s' at line %zu?)",
                            show(&t, shown), P->prev.keyword, P->prev.line);
            return fail(P, t.line, RT_ERR_PARSE,
                        "unexpected value '%s' where a keyword belongs", show(&t, shown));
        } else {
            return fail(P, t.line, RT_ERR_PARSE, "unknown keyword '%s'", show(&t, shown));
        }
        if (st) return st;
        P->prev = e;
    }
    return RT_OK;
}

/* Rejects control bytes (a binary file, UTF-16, ...) up front and finds the
 * line the input ends on (a final newline ends the last line, not a new one). */
static rt_status scan_text(nff_parser *P)
{
    size_t line = 1;
    for (const char *q = P->p; q < P->end; q++) {
        unsigned char c = (unsigned char)*q;
        if (c == '\n' || (c == '\r' && (q + 1 >= P->end || q[1] != '\n'))) {
            if (q + 1 < P->end) line++;
        } else if ((c < 0x20 && !is_space(c)) || c == 0x7f) {
            return fail(P, line, RT_ERR_PARSE,
                        "binary data (byte 0x%02x at offset %zu): not an NFF text file", c,
                        (size_t)(q - P->p));
        }
    }
    P->last_line = line;
    return RT_OK;
}

static rt_status parse_all(nff_parser *P)
{
    rt_status st = scan_text(P);
    if (st) return st;
    if ((st = parse_entities(P))) return st;
    if (!P->view_line)
        return fail(P, P->last_line, RT_ERR_PARSE,
                    "no 'v' (viewpoint) block in the file: the scene has no camera");
    char why[RT_MSG_LEN];
    why[0] = '\0';
    st = rt_scene_finish(P->scene, why, sizeof why);
    if (st == RT_ERR_NOMEM) return fail(P, P->view_line, st, "out of memory");
    if (st) return fail(P, P->view_line, RT_ERR_PARSE, "%s", why[0] ? why : "invalid view");
    return RT_OK;
}

/* ------------------------------------------------------------------ public */

rt_status rt_nff_parse(const char *name, const char *text, size_t length, rt_scene **out,
                       char *msg, size_t msg_len, rt_nff_warn_fn warn, void *warn_ctx)
{
    if (msg && msg_len) msg[0] = '\0';
    if (!name) name = "<input>";
    if (!out || (!text && length > 0)) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: rt_nff_parse: null argument", name);
        if (out) *out = NULL;
        return RT_ERR_INVALID;
    }
    *out = NULL;
    nff_parser P;
    memset(&P, 0, sizeof P);
    P.name = name;
    P.msg = msg;
    P.msg_len = msg_len;
    P.warn = warn;
    P.warn_ctx = warn_ctx;
    P.p = text ? text : "";
    P.end = P.p + length;
    P.line = 1;
    P.last_line = 1;
    if (length > RT_NFF_MAX_FILE_BYTES)
        return fail(&P, 1, RT_ERR_LIMIT, "the input is %zu bytes, more than the limit of %u",
                    length, RT_NFF_MAX_FILE_BYTES);
    /* A UTF-8 byte-order mark is harmless: skip it. */
    if (length >= 3 && memcmp(P.p, "\xEF\xBB\xBF", 3) == 0) P.p += 3;
    P.scene = rt_scene_new();
    if (!P.scene) return fail(&P, 1, RT_ERR_NOMEM, "out of memory");

    /* strtod follows LC_NUMERIC; NFF's decimal point is always '.'. */
    locale_t c_locale = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
    locale_t previous = c_locale ? uselocale(c_locale) : (locale_t)0;
    rt_status st = parse_all(&P);
    if (c_locale) {
        uselocale(previous);
        freelocale(c_locale);
    }

    free(P.vertices);
    free(P.normals);
    if (st) {
        rt_scene_free(P.scene);
        return st;
    }
    *out = P.scene;
    return RT_OK;
}

/* Writes a message without a line number (the file as a whole is at fault). */
static rt_status file_fail(char *msg, size_t msg_len, rt_status status, const char *fmt, ...)
{
    if (msg && msg_len) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msg_len, fmt, ap);
        va_end(ap);
    }
    return status;
}

/* Reads a whole file into a malloc'd buffer, refusing more than the limit.
 * The size check comes before reading, so a huge regular file costs nothing;
 * the read loop still stops at the limit for pipes and growing files. */
static rt_status read_file(const char *path, FILE *f, char **text, size_t *length, char *msg,
                           size_t msg_len)
{
    struct stat info;
    size_t capacity = 65536, used = 0;
    const size_t cap_max = (size_t)RT_NFF_MAX_FILE_BYTES + 1;
    if (fstat(fileno(f), &info) == 0) {
        if (S_ISDIR(info.st_mode))
            return file_fail(msg, msg_len, RT_ERR_IO, "%s: cannot read: %s", path,
                             strerror(EISDIR));
        if (S_ISREG(info.st_mode)) {
            if ((uintmax_t)info.st_size > RT_NFF_MAX_FILE_BYTES)
                return file_fail(msg, msg_len, RT_ERR_LIMIT,
                                 "%s:1: the file is %jd bytes, more than the limit of %u", path,
                                 (intmax_t)info.st_size, RT_NFF_MAX_FILE_BYTES);
            capacity = (size_t)info.st_size + 1; /* + 1: end of file is seen in one read */
        }
    }
    char *buf = malloc(capacity);
    if (!buf) return file_fail(msg, msg_len, RT_ERR_NOMEM, "%s: out of memory", path);
    for (;;) {
        if (used == capacity) {
            if (capacity >= cap_max) break; /* one byte over the limit: stop */
            size_t grown = capacity > cap_max / 2 ? cap_max : capacity * 2;
            char *bigger = realloc(buf, grown);
            if (!bigger) {
                free(buf);
                return file_fail(msg, msg_len, RT_ERR_NOMEM, "%s: out of memory", path);
            }
            buf = bigger;
            capacity = grown;
        }
        size_t got = fread(buf + used, 1, capacity - used, f);
        used += got;
        if (got == 0) break;
    }
    if (ferror(f)) {
        int saved = errno;
        free(buf);
        return file_fail(msg, msg_len, RT_ERR_IO, "%s: cannot read: %s", path, strerror(saved));
    }
    if (used > RT_NFF_MAX_FILE_BYTES) {
        free(buf);
        return file_fail(msg, msg_len, RT_ERR_LIMIT,
                         "%s:1: the file is more than the limit of %u bytes", path,
                         RT_NFF_MAX_FILE_BYTES);
    }
    *text = buf;
    *length = used;
    return RT_OK;
}

rt_status rt_nff_load(const char *path, rt_scene **out, char *msg, size_t msg_len,
                      rt_nff_warn_fn warn, void *warn_ctx)
{
    if (out) *out = NULL;
    if (msg && msg_len) msg[0] = '\0';
    if (!path || !out)
        return file_fail(msg, msg_len, RT_ERR_INVALID, "rt_nff_load: null argument");
    FILE *f = fopen(path, "rb");
    if (!f)
        return file_fail(msg, msg_len, RT_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    char *text = NULL;
    size_t length = 0;
    rt_status st = read_file(path, f, &text, &length, msg, msg_len);
    fclose(f);
    if (st) return st;
    st = rt_nff_parse(path, text, length, out, msg, msg_len, warn, warn_ctx);
    free(text);
    return st;
}
