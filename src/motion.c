/* motion.c - applying a motion to a scene: each entry's keyframes interpolated at a frame,
 * its transform applied to the scene file's geometry of its objects, and the object space
 * over every frame.
 *
 * A point p moves to p + (S R d - d) + move, d = p - pivot: the same as pivot + S R d + move,
 * written so that an identity turn and scale (R = I exactly, S = 1) leave p + move exactly,
 * and an identity key leaves every object bit for bit where the scene file put it. Turns that
 * are whole multiples of 90 degrees use exact sines and cosines, so 0 and 360 degrees are the
 * identity exactly. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "motion_internal.h"
#include "scene_internal.h"

#define MAX_MAGNITUDE 1e30 /* the scene's limit on coordinates (scene.c) */

typedef struct transform {
    double r[3][3]; /* rotation */
    double scale;
    rt_vec3 pivot, move;
} transform;

/* The entry's key values at `frame`: held outside the keys, linear between two. */
static rt_motion_key interpolate(const motion_entry *e, uint32_t frame)
{
    const rt_motion_key *k = e->keys;
    size_t n = e->key_count;
    if (frame <= k[0].frame) return k[0];
    if (frame >= k[n - 1].frame) return k[n - 1];
    size_t lo = 0, hi = n - 1; /* k[lo].frame < frame < k[hi].frame */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (k[mid].frame <= frame) lo = mid;
        else hi = mid;
    }
    if (k[lo].frame == frame) return k[lo];
    const rt_motion_key *a = &k[lo], *b = &k[hi];
    double w = (double)(frame - a->frame) / (double)(b->frame - a->frame);
    rt_motion_key out;
    out.frame = frame;
    out.move = rt_vec(a->move.x + (b->move.x - a->move.x) * w, a->move.y + (b->move.y - a->move.y) * w,
                      a->move.z + (b->move.z - a->move.z) * w);
    out.turn = a->turn + (b->turn - a->turn) * w;
    out.scale = a->scale + (b->scale - a->scale) * w;
    return out;
}

/* Sine and cosine of an angle in degrees, exact at whole multiples of 90. */
static void sin_cos_degrees(double degrees, double *s, double *c)
{
    double a = fmod(degrees, 360.0);
    if (a < 0.0) a += 360.0;
    static const double quarter_sin[4] = {0, 1, 0, -1}, quarter_cos[4] = {1, 0, -1, 0};
    double q = a / 90.0;
    if (q == floor(q) && q < 4.0) {
        *s = quarter_sin[(int)q];
        *c = quarter_cos[(int)q];
        return;
    }
    double rad = a * (3.14159265358979323846 / 180.0);
    *s = sin(rad);
    *c = cos(rad);
}

/* Rodrigues' rotation matrix about a unit axis. */
static transform make_transform(const motion_entry *e, const rt_motion_key *k)
{
    transform t;
    double s, c;
    sin_cos_degrees(k->turn, &s, &c);
    double a[3] = {e->axis.x, e->axis.y, e->axis.z}, v = 1.0 - c;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) t.r[i][j] = (i == j ? c : 0.0) + v * a[i] * a[j];
    t.r[0][1] -= s * a[2], t.r[1][0] += s * a[2];
    t.r[0][2] += s * a[1], t.r[2][0] -= s * a[1];
    t.r[1][2] -= s * a[0], t.r[2][1] += s * a[0];
    t.scale = k->scale;
    t.pivot = e->pivot;
    t.move = k->move;
    return t;
}

static rt_vec3 rotate(const transform *t, rt_vec3 v)
{
    return rt_vec(t->r[0][0] * v.x + t->r[0][1] * v.y + t->r[0][2] * v.z,
                  t->r[1][0] * v.x + t->r[1][1] * v.y + t->r[1][2] * v.z,
                  t->r[2][0] * v.x + t->r[2][1] * v.y + t->r[2][2] * v.z);
}

static rt_vec3 move_point(const transform *t, rt_vec3 p)
{
    rt_vec3 d = rt_vec_sub(p, t->pivot);
    rt_vec3 moved = rt_vec_scale(rotate(t, d), t->scale);
    return rt_vec_add(rt_vec_add(p, rt_vec_sub(moved, d)), t->move);
}

static int same_point(rt_vec3 a, rt_vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* Moves object o of `frame` (whose geometry the scene file gave in `base`); 1 if it changed. */
static int move_object(const transform *t, const rt_scene *base, rt_scene *frame, size_t o)
{
    const rt_object *from = &base->objects[o];
    rt_object *to = &frame->objects[o];
    int changed = 0;
    switch (from->kind) {
    case RT_OBJ_SPHERE: {
        rt_sphere_data sp = {move_point(t, from->u.sphere.center), from->u.sphere.radius * t->scale};
        if (same_point(sp.center, to->u.sphere.center) && sp.radius == to->u.sphere.radius) return 0;
        to->u.sphere = sp;
        rt_scene_derive_sphere(to);
        return 1;
    }
    case RT_OBJ_POLYGON: {
        const rt_polygon_data *p = &from->u.polygon;
        for (uint32_t i = 0; i < p->count; i++) {
            rt_vec3 v = move_point(t, base->vertices[p->first_vertex + i]);
            if (same_point(v, frame->vertices[p->first_vertex + i])) continue;
            frame->vertices[p->first_vertex + i] = v;
            changed = 1;
        }
        if (changed) rt_scene_derive_polygon(frame, to);
        return changed;
    }
    case RT_OBJ_TRIANGLE: {
        rt_triangle_data tri = from->u.triangle;
        for (int k = 0; k < 3; k++) {
            tri.v[k] = move_point(t, from->u.triangle.v[k]);
            tri.n[k] = rotate(t, from->u.triangle.n[k]);
            changed |= !same_point(tri.v[k], to->u.triangle.v[k]) || !same_point(tri.n[k], to->u.triangle.n[k]);
        }
        if (!changed) return 0;
        to->u.triangle = tri;
        rt_scene_derive_triangle(to);
        return 1;
    }
    case RT_OBJ_CONE: {
        rt_cone_data c = from->u.cone;
        c.base = move_point(t, c.base);
        c.apex = move_point(t, c.apex);
        c.base_radius *= t->scale;
        c.apex_radius *= t->scale;
        changed = !same_point(c.base, to->u.cone.base) || !same_point(c.apex, to->u.cone.apex) ||
                  c.base_radius != to->u.cone.base_radius || c.apex_radius != to->u.cone.apex_radius;
        if (!changed) return 0;
        to->u.cone = c;
        rt_scene_derive_cone(to);
        return 1;
    }
    }
    return 0;
}

rt_status rt_motion_apply(const rt_motion *m, const rt_scene *base, rt_scene *frame, uint32_t k, uint8_t *moved,
                          char *msg, size_t msg_len)
{
    if (base->object_count != frame->object_count || base->vertex_count != frame->vertex_count) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: the frame's scene is not a copy of the scene moved", m->file);
        return RT_ERR_INVALID;
    }
    if (moved) memset(moved, 0, base->object_count);
    for (size_t i = 0; i < m->entry_count; i++) {
        const motion_entry *e = &m->entries[i];
        if (e->last >= base->object_count) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "%s:%zu: objects %u-%u: the scene has %zu objects (numbered from 0)", m->file,
                         e->line, e->first, e->last, base->object_count);
            return RT_ERR_INVALID;
        }
        rt_motion_key key = interpolate(e, k);
        transform t = make_transform(e, &key);
        for (size_t o = e->first; o <= e->last; o++) {
            int changed = move_object(&t, base, frame, o);
            if (moved) moved[o] = (uint8_t)changed;
        }
    }
    return RT_OK;
}

static int sane(double x) { return isfinite(x) && fabs(x) <= MAX_MAGNITUDE; }

/* 1 if the object's geometry stays within the scene's limits after a move. */
static int object_sane(const rt_scene *s, const rt_object *o)
{
    const rt_box *b = &o->bounds;
    if (b->lo.x <= b->hi.x &&
        !(sane(b->lo.x) && sane(b->lo.y) && sane(b->lo.z) && sane(b->hi.x) && sane(b->hi.y) && sane(b->hi.z)))
        return 0;
    if (o->kind == RT_OBJ_SPHERE) return o->u.sphere.radius > 0.0;
    if (o->kind == RT_OBJ_CONE) return o->u.cone.height > 0.0 && isfinite(o->u.cone.slope);
    if (o->kind == RT_OBJ_POLYGON)
        for (uint32_t i = 0; i < o->u.polygon.count; i++) {
            rt_vec3 v = s->vertices[o->u.polygon.first_vertex + i];
            if (!(sane(v.x) && sane(v.y) && sane(v.z))) return 0;
        }
    return 1;
}

static void box_union(rt_box *b, const rt_box *o)
{
    if (!(o->lo.x <= o->hi.x && o->lo.y <= o->hi.y && o->lo.z <= o->hi.z)) return;
    b->lo = rt_vec(fmin(b->lo.x, o->lo.x), fmin(b->lo.y, o->lo.y), fmin(b->lo.z, o->lo.z));
    b->hi = rt_vec(fmax(b->hi.x, o->hi.x), fmax(b->hi.y, o->hi.y), fmax(b->hi.z, o->hi.z));
}

rt_status rt_motion_space(const rt_motion *m, const rt_scene *base, rt_box *space, char *msg, size_t msg_len)
{
    rt_box b = {rt_vec(INFINITY, INFINITY, INFINITY), rt_vec(-INFINITY, -INFINITY, -INFINITY)};
    for (size_t o = 0; o < base->object_count; o++) box_union(&b, &base->objects[o].bounds);
    rt_scene *frame = rt_scene_clone(base);
    if (!frame) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: out of memory", m->file);
        return RT_ERR_NOMEM;
    }
    rt_status st = RT_OK;
    for (uint32_t k = 0; k < m->frames && st == RT_OK; k++) {
        st = rt_motion_apply(m, base, frame, k, NULL, msg, msg_len);
        if (st != RT_OK) {
            st = RT_ERR_PARSE;
            break;
        }
        for (size_t i = 0; i < m->entry_count && st == RT_OK; i++) {
            const motion_entry *e = &m->entries[i];
            for (size_t o = e->first; o <= e->last; o++) {
                if (!object_sane(frame, &frame->objects[o])) {
                    if (msg && msg_len)
                        snprintf(msg, msg_len, "%s:%zu: frame %u moves object %zu past 1e30 in magnitude or to size 0",
                                 m->file, e->line, k, o);
                    st = RT_ERR_PARSE;
                    break;
                }
                box_union(&b, &frame->objects[o].bounds);
            }
        }
    }
    rt_scene_free(frame);
    if (st == RT_OK) *space = b;
    return st;
}

static const char *kind_name(rt_object_kind kind, int plural)
{
    static const char *names[4][2] = {
        {"sphere", "spheres"}, {"polygon", "polygons"}, {"patch triangle", "patch triangles"}, {"cone", "cones"}};
    return names[kind][plural];
}

void rt_motion_describe(const rt_motion *m, const rt_scene *s, size_t i, char *buf, size_t len)
{
    if (!buf || !len) return;
    buf[0] = '\0';
    if (i >= m->entry_count) return;
    const motion_entry *e = &m->entries[i];
    size_t count[4] = {0, 0, 0, 0};
    for (size_t o = e->first; o <= e->last && o < s->object_count; o++) count[s->objects[o].kind]++;
    int n = snprintf(buf, len, "%s:%zu: objects %u-%u (", m->file, e->line, e->first, e->last);
    const char *sep = "";
    for (int k = 0; k < 4 && n >= 0 && (size_t)n < len; k++) {
        if (!count[k]) continue;
        n += snprintf(buf + n, len - (size_t)n, "%s%zu %s", sep, count[k], kind_name((rt_object_kind)k, count[k] != 1));
        sep = ", ";
    }
    if (n >= 0 && (size_t)n < len)
        snprintf(buf + n, len - (size_t)n, "), %zu key%s", e->key_count, e->key_count == 1 ? "" : "s");
}
