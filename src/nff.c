/* nff.c - reader for NFF (Eric Haines' Neutral File Format) scenes, plus `am`.
 *
 * The input is read as a stream of whitespace-separated tokens, not lines:
 * SPD generators put all eight numbers of a `c` on one line, `b` may come
 * before `v`, and so on. Every token remembers its line for messages.
 * Numbers are strict decimal floats (no nan, inf, hex or "1.2.3"). Tokens
 * and numbers are read by nff_tokens.c; this file reads the entities and
 * builds the scene only through the public builder of rt_scene.h.
 *
 * Decisions (as docs/scenes.md gives them):
 *  - a negative sphere or cone radius (NFF's "inside only") is rejected;
 *  - `hither` is read and ignored;
 *  - Shine >= 0 of any size; ior is checked (> 0) only when T > 0; colours and
 *    coefficients are not bounded (NFF bounds none of them);
 *  - a `#` starts a comment to the end of the line, also right after a token;
 *  - a leading UTF-8 byte-order mark is skipped; other control bytes are
 *    "binary data".
 */
#include <locale.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_file_read.h"
#include "nff_tokens.h"
#include "rt_nff.h"

typedef struct nff_parser {
    rt_nff_stream in;   /* tokens, their lines, and the message buffer */
    rt_nff_entity prev; /* last complete entity, to explain stray numbers */
    rt_scene *scene;
    rt_nff_warn_fn warn;
    void *warn_ctx;
    int have_material;  /* an `f` was seen */
    int warned_default; /* the default-material warning was given */
    size_t view_line;   /* line of the `v`; 0 = none yet */
    rt_vec3 *vertices;  /* scratch for `p` and `pp`, reused between entities */
    rt_vec3 *normals;
    size_t scratch_capacity;
} nff_parser;

/* ------------------------------------------------------------------ messages */

/* Turns a builder failure into a file:line message. */
static rt_status builder_fail(nff_parser *P, size_t line, rt_status st, const char *invalid_text)
{
    if (st == RT_ERR_NOMEM) return rt_nff_fail(&P->in, line, RT_ERR_NOMEM, "out of memory");
    if (st == RT_ERR_LIMIT) return rt_nff_fail(&P->in, line, RT_ERR_LIMIT, "%s", invalid_text);
    return rt_nff_fail(&P->in, line, RT_ERR_PARSE, "%s", invalid_text);
}

/* ------------------------------------------------------------------ entities */

/* Requires the next token to be the keyword `word` (inside the `v` block). */
static rt_status expect_keyword(nff_parser *P, const rt_nff_entity *e, const char *word)
{
    rt_nff_token t;
    char shown[RT_NFF_SHOW_CHARS + 4];
    if (!rt_nff_next_token(&P->in, &t)) {
        char what[48];
        snprintf(what, sizeof what, "'%s' line", word);
        return rt_nff_fail_eof(&P->in, e, what);
    }
    if (!rt_nff_token_is(&t, word))
        return rt_nff_fail(&P->in, t.line, RT_ERR_PARSE,
                           "expected '%s' in the 'v' block (line %zu), got '%s' (the order is "
                           "from, at, up, angle, hither, resolution)",
                           word, e->line, rt_nff_show(&t, shown));
    return RT_OK;
}

/* v / from / at / up / angle / hither / resolution, in that order. */
static rt_status parse_view(nff_parser *P, const rt_nff_entity *e)
{
    rt_vec3 from, at, up;
    double angle = 0.0, hither = 0.0;
    long long w = 0, h = 0;
    rt_status st;
    if (P->view_line)
        return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE,
                           "second 'v' block (the first is at line %zu): a file has one view", P->view_line);
    if ((st = expect_keyword(P, e, "from")) || (st = rt_nff_read_vec(&P->in, e, "from", &from))) return st;
    if ((st = expect_keyword(P, e, "at")) || (st = rt_nff_read_vec(&P->in, e, "at", &at))) return st;
    if ((st = expect_keyword(P, e, "up")) || (st = rt_nff_read_vec(&P->in, e, "up", &up))) return st;
    if ((st = expect_keyword(P, e, "angle")) || (st = rt_nff_read_number(&P->in, e, "angle", NULL, &angle))) return st;
    if (!(angle > 0.0 && angle < 180.0))
        return rt_nff_fail(&P->in, P->in.token_line, RT_ERR_PARSE, "view angle must be in (0, 180) degrees, got %g",
                           angle);
    if ((st = expect_keyword(P, e, "hither")) || (st = rt_nff_read_number(&P->in, e, "hither", NULL, &hither)))
        return st;
    (void)hither; /* ignored: the design has no near clipping plane */
    if ((st = expect_keyword(P, e, "resolution")) || (st = rt_nff_read_integer(&P->in, e, "resolution width", &w)))
        return st;
    rt_nff_token w_tok = P->in.last;
    if ((st = rt_nff_read_integer(&P->in, e, "resolution height", &h))) return st;
    rt_nff_token h_tok = P->in.last;
    char w_shown[RT_NFF_SHOW_CHARS + 4], h_shown[RT_NFF_SHOW_CHARS + 4];
    rt_nff_show(&w_tok, w_shown);
    rt_nff_show(&h_tok, h_shown);
    if (w < 1 || h < 1)
        return rt_nff_fail(&P->in, w < 1 ? w_tok.line : h_tok.line, RT_ERR_PARSE,
                           "resolution must be at least 1 x 1 pixels, got %s x %s", w_shown, h_shown);
    if (w > (long long)RT_SCENE_MAX_RESOLUTION || h > (long long)RT_SCENE_MAX_RESOLUTION)
        return rt_nff_fail(&P->in, w > (long long)RT_SCENE_MAX_RESOLUTION ? w_tok.line : h_tok.line, RT_ERR_LIMIT,
                           "resolution %s x %s exceeds the limit of %u pixels a side", w_shown, h_shown,
                           RT_SCENE_MAX_RESOLUTION);
    st = rt_scene_set_view(P->scene, from, at, up, angle, (uint32_t)w, (uint32_t)h);
    if (st) return builder_fail(P, e->line, st, "view rejected by the scene builder");
    P->view_line = e->line;
    return RT_OK;
}

/* The first object before any `f` gets the default material (the builder
 * applies it); say so once. */
static void note_object(nff_parser *P, const rt_nff_entity *e)
{
    if (P->have_material || P->warned_default) return;
    P->warned_default = 1;
    if (!P->warn) return;
    char text[RT_MSG_LEN];
    snprintf(text, sizeof text, "%s:%zu: warning: object before any 'f': using f 1 1 1 1 0 0 0 1", P->in.name, e->line);
    P->warn(P->warn_ctx, text);
}

static rt_status object_limit(nff_parser *P, size_t line, rt_status st)
{
    char text[160];
    snprintf(text, sizeof text, "too many objects or vertices in the scene (the limit is %u objects)",
             RT_SCENE_MAX_OBJECTS);
    return builder_fail(P, line, st, text);
}

static rt_status parse_light(nff_parser *P, const rt_nff_entity *e)
{
    rt_vec3 pos, rgb;
    rt_nff_token t;
    rt_status st = rt_nff_read_vec(&P->in, e, "position", &pos);
    if (st) return st;
    /* The colour is optional: present when the next token is a number. */
    int colored = rt_nff_peek_token(&P->in, &t) && rt_nff_looks_numeric(&t);
    if (colored && (st = rt_nff_read_color(&P->in, e, "colour", &rgb))) return st;
    st = rt_scene_add_light(P->scene, pos, colored ? &rgb : NULL);
    if (st == RT_ERR_LIMIT)
        return rt_nff_fail(&P->in, e->line, RT_ERR_LIMIT, "too many lights (the limit is %u)", RT_SCENE_MAX_LIGHTS);
    if (st) return builder_fail(P, e->line, st, "light rejected by the scene builder");
    return RT_OK;
}

static rt_status parse_material(nff_parser *P, const rt_nff_entity *e)
{
    rt_material m;
    rt_status st;
    if ((st = rt_nff_read_color(&P->in, e, "colour", &m.color)) ||
        (st = rt_nff_read_number(&P->in, e, "Kd", NULL, &m.kd)) ||
        (st = rt_nff_read_number(&P->in, e, "Ks", NULL, &m.ks)) ||
        (st = rt_nff_read_number(&P->in, e, "Shine", NULL, &m.shine)) ||
        (st = rt_nff_read_number(&P->in, e, "T", NULL, &m.t)) ||
        (st = rt_nff_read_number(&P->in, e, "ior", NULL, &m.ior)))
        return st;
    if (m.shine < 0.0)
        return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE,
                           "bad Shine of 'f': %g is negative (the Phong exponent must be >= 0)", m.shine);
    if (m.t > 0.0 && !(m.ior > 0.0))
        return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE,
                           "bad ior of 'f': %g with T = %g (a transmitting surface needs ior > 0)", m.ior, m.t);
    st = rt_scene_set_material(P->scene, &m);
    if (st) return builder_fail(P, e->line, st, "material values out of range (|Kd|, |Ks| and |T| must be <= 1e30)");
    P->have_material = 1;
    return RT_OK;
}

static rt_status parse_sphere(nff_parser *P, const rt_nff_entity *e)
{
    rt_vec3 c;
    double r = 0.0;
    rt_status st;
    if ((st = rt_nff_read_vec(&P->in, e, "centre", &c)) || (st = rt_nff_read_number(&P->in, e, "radius", NULL, &r)))
        return st;
    if (r < 0.0)
        return rt_nff_fail(&P->in, P->in.token_line, RT_ERR_PARSE,
                           "negative sphere radius (inside-only spheres) is not supported");
    if (!(r > 0.0)) return rt_nff_fail(&P->in, P->in.token_line, RT_ERR_PARSE, "sphere radius must be > 0, got 0");
    note_object(P, e);
    st = rt_scene_add_sphere(P->scene, c, r);
    if (st == RT_ERR_INVALID) return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE, "sphere rejected by the scene builder");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

static rt_status parse_cone(nff_parser *P, const rt_nff_entity *e)
{
    rt_vec3 base, apex;
    double rb = 0.0, ra = 0.0;
    rt_status st;
    if ((st = rt_nff_read_vec(&P->in, e, "base", &base)) ||
        (st = rt_nff_read_number(&P->in, e, "base radius", NULL, &rb)))
        return st;
    size_t rb_line = P->in.token_line;
    if ((st = rt_nff_read_vec(&P->in, e, "apex", &apex)) ||
        (st = rt_nff_read_number(&P->in, e, "apex radius", NULL, &ra)))
        return st;
    if (rb < 0.0 || ra < 0.0)
        return rt_nff_fail(&P->in, rb < 0.0 ? rb_line : P->in.token_line, RT_ERR_PARSE,
                           "negative cone radius (inside-only cones) is not supported");
    if (rb == 0.0 && ra == 0.0) return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE, "cone with both radii zero");
    if (base.x == apex.x && base.y == apex.y && base.z == apex.z)
        return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE, "cone base and apex are the same point");
    note_object(P, e);
    st = rt_scene_add_cone(P->scene, base, rb, apex, ra);
    if (st == RT_ERR_INVALID) return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE, "cone rejected by the scene builder");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

/* Reads a vertex count and makes room for that many vertices (and normals):
 * the count is checked against the limit before anything is allocated. */
static rt_status read_vertex_count(nff_parser *P, const rt_nff_entity *e, size_t *count)
{
    long long n = 0;
    char shown[RT_NFF_SHOW_CHARS + 4];
    rt_status st = rt_nff_read_integer(&P->in, e, "vertex count", &n);
    if (st) return st;
    if (n < 3)
        return rt_nff_fail(&P->in, P->in.token_line, RT_ERR_PARSE, "'%s' needs at least 3 vertices, got %lld",
                           e->keyword, n);
    if (n > (long long)RT_SCENE_MAX_VERTICES)
        return rt_nff_fail(&P->in, P->in.token_line, RT_ERR_LIMIT, "'%s' with %s vertices exceeds the limit of %u",
                           e->keyword, rt_nff_show(&P->in.last, shown), RT_SCENE_MAX_VERTICES);
    if ((size_t)n > P->scratch_capacity) {
        rt_vec3 *v = realloc(P->vertices, (size_t)n * sizeof *v);
        if (!v) return rt_nff_fail(&P->in, e->line, RT_ERR_NOMEM, "out of memory");
        P->vertices = v;
        rt_vec3 *nv = realloc(P->normals, (size_t)n * sizeof *nv);
        if (!nv) return rt_nff_fail(&P->in, e->line, RT_ERR_NOMEM, "out of memory");
        P->normals = nv;
        P->scratch_capacity = (size_t)n;
    }
    *count = (size_t)n;
    return RT_OK;
}

/* `p N` then N vertices; `pp N` then N (vertex, normal) pairs. */
static rt_status parse_polygon(nff_parser *P, const rt_nff_entity *e, int patch)
{
    size_t n = 0;
    rt_status st = read_vertex_count(P, e, &n);
    if (st) return st;
    for (size_t i = 0; i < n; i++) {
        char what[48];
        snprintf(what, sizeof what, "vertex %zu", i + 1);
        if ((st = rt_nff_read_vec(&P->in, e, what, &P->vertices[i]))) return st;
        if (patch) {
            snprintf(what, sizeof what, "normal %zu", i + 1);
            if ((st = rt_nff_read_vec(&P->in, e, what, &P->normals[i]))) return st;
        }
    }
    note_object(P, e);
    st = patch ? rt_scene_add_patch(P->scene, P->vertices, P->normals, n)
               : rt_scene_add_polygon(P->scene, P->vertices, n);
    if (st == RT_ERR_INVALID)
        return rt_nff_fail(&P->in, e->line, RT_ERR_PARSE, "%s rejected by the scene builder",
                           patch ? "patch" : "polygon");
    if (st) return object_limit(P, e->line, st);
    return RT_OK;
}

/* Reads entities until the end of the input. */
static rt_status parse_entities(nff_parser *P)
{
    rt_nff_token t;
    char shown[RT_NFF_SHOW_CHARS + 4];
    while (rt_nff_next_token(&P->in, &t)) {
        rt_nff_entity e = {NULL, t.line};
        rt_status st;
        rt_vec3 rgb;
        if (rt_nff_token_is(&t, "v")) {
            e.keyword = "v";
            st = parse_view(P, &e);
        } else if (rt_nff_token_is(&t, "b")) {
            e.keyword = "b";
            st = rt_nff_read_color(&P->in, &e, "colour", &rgb);
            if (!st && (st = rt_scene_set_background(P->scene, rgb)))
                st = builder_fail(P, e.line, st, "background rejected by the scene builder");
        } else if (rt_nff_token_is(&t, "am")) {
            e.keyword = "am";
            st = rt_nff_read_color(&P->in, &e, "colour", &rgb);
            if (!st && (st = rt_scene_set_ambient(P->scene, rgb)))
                st = builder_fail(P, e.line, st, "ambient light rejected by the scene builder");
        } else if (rt_nff_token_is(&t, "l")) {
            e.keyword = "l";
            st = parse_light(P, &e);
        } else if (rt_nff_token_is(&t, "f")) {
            e.keyword = "f";
            st = parse_material(P, &e);
        } else if (rt_nff_token_is(&t, "s")) {
            e.keyword = "s";
            st = parse_sphere(P, &e);
        } else if (rt_nff_token_is(&t, "p")) {
            e.keyword = "p";
            st = parse_polygon(P, &e, 0);
        } else if (rt_nff_token_is(&t, "pp")) {
            e.keyword = "pp";
            st = parse_polygon(P, &e, 1);
        } else if (rt_nff_token_is(&t, "c")) {
            e.keyword = "c";
            st = parse_cone(P, &e);
        } else if (rt_nff_looks_numeric(&t)) {
            if (P->prev.keyword)
                return rt_nff_fail(&P->in, t.line, RT_ERR_PARSE,
                                   "unexpected value '%s' where a keyword belongs (too many values "
                                   "for the '%s' at line %zu?)",
                                   rt_nff_show(&t, shown), P->prev.keyword, P->prev.line);
            return rt_nff_fail(&P->in, t.line, RT_ERR_PARSE, "unexpected value '%s' where a keyword belongs",
                               rt_nff_show(&t, shown));
        } else {
            return rt_nff_fail(&P->in, t.line, RT_ERR_PARSE, "unknown keyword '%s'", rt_nff_show(&t, shown));
        }
        if (st) return st;
        P->prev = e;
    }
    return RT_OK;
}

static rt_status parse_all(nff_parser *P)
{
    rt_status st = rt_nff_scan_text(&P->in);
    if (st) return st;
    if ((st = parse_entities(P))) return st;
    if (!P->view_line)
        return rt_nff_fail(&P->in, P->in.last_line, RT_ERR_PARSE,
                           "no 'v' (viewpoint) block in the file: the scene has no camera");
    char why[RT_MSG_LEN];
    why[0] = '\0';
    st = rt_scene_finish(P->scene, why, sizeof why);
    if (st == RT_ERR_NOMEM) return rt_nff_fail(&P->in, P->view_line, st, "out of memory");
    if (st) return rt_nff_fail(&P->in, P->view_line, RT_ERR_PARSE, "%s", why[0] ? why : "invalid view");
    return RT_OK;
}

/* ------------------------------------------------------------------ public */

rt_status rt_nff_parse(const char *name, const char *text, size_t length, rt_scene **out, char *msg, size_t msg_len,
                       rt_nff_warn_fn warn, void *warn_ctx)
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
    rt_nff_stream_init(&P.in, name, text ? text : "", length, msg, msg_len);
    P.warn = warn;
    P.warn_ctx = warn_ctx;
    if (length > RT_NFF_MAX_FILE_BYTES)
        return rt_nff_fail(&P.in, 1, RT_ERR_LIMIT, "the input is %zu bytes, more than the limit of %u", length,
                           RT_NFF_MAX_FILE_BYTES);
    /* A UTF-8 byte-order mark is harmless: skip it. */
    if (length >= 3 && memcmp(P.in.p, "\xEF\xBB\xBF", 3) == 0) P.in.p += 3;
    P.scene = rt_scene_new();
    if (!P.scene) return rt_nff_fail(&P.in, 1, RT_ERR_NOMEM, "out of memory");

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

rt_status rt_nff_load(const char *path, rt_scene **out, char *msg, size_t msg_len, rt_nff_warn_fn warn, void *warn_ctx)
{
    if (out) *out = NULL;
    if (msg && msg_len) msg[0] = '\0';
    if (!path || !out) {
        if (msg && msg_len) snprintf(msg, msg_len, "rt_nff_load: null argument");
        return RT_ERR_INVALID;
    }
    char *text = NULL;
    size_t length = 0;
    rt_status st = rt_read_regular_file(path, RT_NFF_MAX_FILE_BYTES, &text, &length, msg, msg_len);
    if (st) return st;
    st = rt_nff_parse(path, text, length, out, msg, msg_len, warn, warn_ctx);
    free(text);
    return st;
}
