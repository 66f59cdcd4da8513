/* grid_list.c - listing one object in the cells it meets.
 *
 * Cell lists follow the paper's recursive factor subdivision (docs/design.md section 4):
 * each axis' cell count is factorised into primes in ascending order, the
 * shorter factor lists padded with 1s, so level l splits a sub-space by
 * factor[l] along x, y and z at once. Per axis the object's extent is
 * located among the f slabs by sequential half-space tests, one UNIT each:
 *   (a) k = 1..f-1: "lo <= plane_k + tol?"; the first yes gives first = k-1,
 *       none gives first = f-1;
 *   (b) k = first+1..f-1: "hi >= plane_k - tol?"; the first no gives
 *       last = k-1, all yes give last = f-1.
 * (RT_COUNT_SEQUENTIAL; PER_PLANE: one unit a plane, BOUNDING_SPHERE: the
 * same on the bounding sphere's box; the lists never depend on the rule).
 * A factor of 1 costs nothing. Each sub-space in the product of the three
 * ranges is then kept only if an exact overlap test (not counted in units)
 * says the object meets it, and kept ones are split again down to single
 * cells. Objects with empty bounds cost nothing and are listed nowhere.
 *
 * Overlap tolerance: tol = 1e-9 x the object-space diagonal. Every test
 * (half-space and exact) uses the cell or sub-space box grown by tol on
 * every side, so an object touching a face, within rounding, is listed in
 * both neighbours. An extra listing costs one intersection test; a missing
 * one would lose a hit, because a hit is accepted only inside its cell.
 *
 * Exact tests on the grown box:
 *   sphere   - squared distance from the centre to the box <= r^2 (Arvo);
 *   polygon  - the plane meets the box and the even-odd region meets it: an
 *              edge of the loop meets the box, or else (the boundary misses
 *              the box, so plane-and-box lies wholly in or out) one point of
 *              plane-and-box is inside. The loop is first moved onto the
 *              stored plane along the dropped axis, which is exactly the
 *              region intersect.c hits (plane + 2D even-odd test), so a
 *              slightly non-planar file polygon is still listed correctly;
 *   triangle - the same test on the `pp` triangle;
 *   cone     - its bounds box overlaps the box: conservative (a cell may
 *              list a cone that misses it), never drops a hit.
 * Sutherland-Hodgman non-emptiness is not used: for concave polygons its
 * zero-width bridge edges along a clip plane keep cells lying in a notch.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grid_build.h"
#include "polygon_inside.h"

int grid_box_is_empty(const rt_box *b) { return !(b->lo.x <= b->hi.x && b->lo.y <= b->hi.y && b->lo.z <= b->hi.z); }

int grid_box_inside(const rt_box *a, const rt_box *b)
{
    return a->lo.x >= b->lo.x && a->lo.y >= b->lo.y && a->lo.z >= b->lo.z && a->hi.x <= b->hi.x && a->hi.y <= b->hi.y &&
           a->hi.z <= b->hi.z;
}

static double axis_of(rt_vec3 v, int a) { return rt_vec_axis(v, a); }

static void set_axis(rt_vec3 *v, int a, double x)
{
    if (a == 0) v->x = x;
    else if (a == 1) v->y = x;
    else v->z = x;
}

/* Prime factors of n in ascending order; returns how many. */
static int factorise(int n, int out[MAX_LEVELS])
{
    int count = 0;
    for (int p = 2; n > 1 && count < MAX_LEVELS; p++) {
        while (n % p == 0 && count < MAX_LEVELS) {
            out[count++] = p;
            n /= p;
        }
    }
    return count;
}

/* Arvo: squared distance from the centre to the box against r^2. */
static int sphere_meets(const rt_sphere_data *s, const rt_box *b)
{
    double d2 = 0.0;
    for (int a = 0; a < 3; a++) {
        double c = axis_of(s->center, a), lo = axis_of(b->lo, a), hi = axis_of(b->hi, a);
        if (c < lo) d2 += (lo - c) * (lo - c);
        else if (c > hi) d2 += (c - hi) * (c - hi);
    }
    return d2 <= s->radius * s->radius;
}

/* Liang-Barsky clip of segment p-q against the closed box. */
static int segment_meets(rt_vec3 p, rt_vec3 q, const rt_box *b)
{
    double t0 = 0.0, t1 = 1.0;
    for (int a = 0; a < 3; a++) {
        double o = axis_of(p, a), d = axis_of(q, a) - o;
        double lo = axis_of(b->lo, a), hi = axis_of(b->hi, a);
        if (d == 0.0) {
            if (o < lo || o > hi) return 0;
            continue;
        }
        double ta = (lo - o) / d, tb = (hi - o) / d;
        if (ta > tb) {
            double s = ta;
            ta = tb;
            tb = s;
        }
        if (ta > t0) t0 = ta;
        if (tb < t1) t1 = tb;
        if (t0 > t1) return 0;
    }
    return 1;
}

/* Planar even-odd region (b->loop on b's plane) against the box. */
static int flat_meets(const build *bd, const rt_box *b)
{
    /* Box corners nearest and farthest along the normal: the plane meets
     * the box iff their signed distances bracket 0. */
    rt_vec3 cmin = bd->normal, cmax = bd->normal;
    for (int a = 0; a < 3; a++) {
        int pos = axis_of(bd->normal, a) >= 0.0;
        set_axis(&cmin, a, pos ? axis_of(b->lo, a) : axis_of(b->hi, a));
        set_axis(&cmax, a, pos ? axis_of(b->hi, a) : axis_of(b->lo, a));
    }
    double dmin = rt_vec_dot(bd->normal, cmin) - bd->offset;
    double dmax = rt_vec_dot(bd->normal, cmax) - bd->offset;
    if (dmin > 0.0 || dmax < 0.0) return 0;

    for (size_t i = 0, j = bd->loop_n - 1; i < bd->loop_n; j = i++)
        if (segment_meets(bd->loop[j], bd->loop[i], b)) return 1;

    /* The boundary misses the box, so one point of plane-and-box decides:
     * take it on the diagonal cmin-cmax, which crosses the plane. */
    double span = dmax - dmin;
    double t = span > 0.0 ? -dmin / span : 0.0;
    rt_vec3 p = rt_vec_add(cmin, rt_vec_scale(rt_vec_sub(cmax, cmin), t));
    return rt_polygon_inside(bd->loop, bd->loop_n, bd->drop, p);
}

/* 1 if the object holds the whole box, so every cell in it meets the object (the counting
 * pass then counts them without splitting the box); spheres and cones only. */
static int object_holds(const build *bd, const rt_box *b)
{
    const rt_object *o = bd->obj;
    if (o->kind == RT_OBJ_SPHERE) {
        /* The farthest corner inside the ball: the ball is convex. */
        const rt_sphere_data *sp = &o->u.sphere;
        double d2 = 0.0;
        for (int a = 0; a < 3; a++) {
            double c = axis_of(sp->center, a);
            double far = fmax(fabs(axis_of(b->lo, a) - c), fabs(axis_of(b->hi, a) - c));
            d2 += far * far;
        }
        return d2 <= sp->radius * sp->radius;
    }
    if (o->kind == RT_OBJ_CONE) /* its exact test is the bounds' overlap */
        return o->bounds.lo.x <= b->lo.x && o->bounds.hi.x >= b->hi.x && o->bounds.lo.y <= b->lo.y &&
               o->bounds.hi.y >= b->hi.y && o->bounds.lo.z <= b->lo.z && o->bounds.hi.z >= b->hi.z;
    return 0;
}

static int object_meets(const build *bd, const rt_box *b)
{
    switch (bd->obj->kind) {
    case RT_OBJ_SPHERE: return sphere_meets(&bd->obj->u.sphere, b);
    case RT_OBJ_POLYGON:
    case RT_OBJ_TRIANGLE: return flat_meets(bd, b);
    case RT_OBJ_CONE: break;
    }
    /* Cone (conservative): the bounds overlap the box. */
    const rt_box *o = &bd->obj->bounds;
    return o->lo.x <= b->hi.x && o->hi.x >= b->lo.x && o->lo.y <= b->hi.y && o->hi.y >= b->lo.y && o->lo.z <= b->hi.z &&
           o->hi.z >= b->lo.z;
}

/* Slabs [first, last] of f (each m cells from cell c0) that the extent
 * reaches on one axis, counted by the build's rule. */
static void slab_range(build *bd, int axis, int c0, int f, int m, int *first, int *last)
{
    const rt_grid *g = bd->g;
    double lo = axis_of(bd->extent.lo, axis), hi = axis_of(bd->extent.hi, axis);
    double tol = g->tolerance;
    *first = *last = f - 1;
    if (bd->rule != RT_COUNT_SEQUENTIAL) { /* one test a plane: above, across or below */
        for (int k = 1, found = 0; k < f; k++) {
            bd->units++;
            if (!found && lo <= rt_grid_plane(g, axis, c0 + k * m) + tol) *first = k - 1, found = 1;
            if (found && !(hi >= rt_grid_plane(g, axis, c0 + k * m) - tol)) {
                *last = k - 1;
                break;
            }
        }
        return;
    }
    for (int k = 1; k < f; k++) {
        bd->units++;
        if (lo <= rt_grid_plane(g, axis, c0 + k * m) + tol) {
            *first = k - 1;
            break;
        }
    }
    for (int k = *first + 1; k < f; k++) {
        bd->units++;
        if (!(hi >= rt_grid_plane(g, axis, c0 + k * m) - tol)) {
            *last = k - 1;
            break;
        }
    }
}

static void add_cell(build *bd, const int c[3])
{
    if (bd->counting) {
        if (++bd->cell_n > bd->max_entries) bd->over_budget = bd->nomem = 1;
        return;
    }
    if (bd->cell_n == bd->max_entries) {
        bd->over_budget = bd->nomem = 1;
        return;
    }
    if (bd->cell_n == bd->cell_cap) {
        size_t cap = bd->cell_cap ? 2 * bd->cell_cap : 1024;
        if (cap > bd->max_entries) cap = bd->max_entries;
        uint32_t *p = realloc(bd->cells, cap * sizeof *p);
        if (!p) {
            bd->nomem = 1;
            return;
        }
        bd->cells = p;
        bd->cell_cap = cap;
    }
    const int32_t cell[3] = {c[0], c[1], c[2]};
    bd->cells[bd->cell_n++] = rt_grid_index(bd->g->dims, cell);
}

/* Splits the sub-space starting at cell c0 (span[.][level] cells per axis). */
void grid_build_subdivide(build *bd, int level, const int c0[3])
{
    if (level == bd->levels) {
        add_cell(bd, c0);
        return;
    }
    int first[3], last[3], m[3];
    for (int a = 0; a < 3; a++) {
        m[a] = bd->span[a][level + 1];
        slab_range(bd, a, c0[a], bd->factor[a][level], m[a], &first[a], &last[a]);
    }
    const rt_grid *g = bd->g;
    double tol = g->tolerance;
    for (int iz = first[2]; iz <= last[2]; iz++)
        for (int iy = first[1]; iy <= last[1]; iy++)
            for (int ix = first[0]; ix <= last[0]; ix++) {
                if (bd->nomem) return;
                int c[3] = {c0[0] + ix * m[0], c0[1] + iy * m[1], c0[2] + iz * m[2]};
                rt_box b;
                b.lo = rt_vec(rt_grid_plane(g, 0, c[0]) - tol, rt_grid_plane(g, 1, c[1]) - tol,
                              rt_grid_plane(g, 2, c[2]) - tol);
                b.hi = rt_vec(rt_grid_plane(g, 0, c[0] + m[0]) + tol, rt_grid_plane(g, 1, c[1] + m[1]) + tol,
                              rt_grid_plane(g, 2, c[2] + m[2]) + tol);
                if (!object_meets(bd, &b)) continue;
                if (bd->counting && object_holds(bd, &b)) {
                    /* Every cell of the sub-space is listed: count them at once. */
                    size_t all = (size_t)m[0] * (size_t)m[1] * (size_t)m[2];
                    bd->cell_n += all;
                    if (bd->cell_n > bd->max_entries) bd->over_budget = bd->nomem = 1;
                    continue;
                }
                grid_build_subdivide(bd, level + 1, c);
            }
}

static int reserve_loop(build *bd, size_t n)
{
    if (n <= bd->loop_cap) return 1;
    rt_vec3 *p = realloc(bd->loop, n * sizeof *p);
    if (!p) return 0;
    bd->loop = p;
    bd->loop_cap = n;
    return 1;
}

int grid_build_prepare(build *bd, size_t o)
{
    const rt_scene *s = bd->scene;
    const rt_object *ob = &s->objects[o];
    bd->obj = ob;
    bd->extent = ob->bounds;
    if (bd->rule == RT_COUNT_BOUNDING_SPHERE && ob->kind != RT_OBJ_SPHERE) { /* the sphere's box */
        rt_vec3 c = rt_vec_scale(rt_vec_add(ob->bounds.lo, ob->bounds.hi), 0.5);
        rt_vec3 e = rt_vec_sub(ob->bounds.hi, ob->bounds.lo);
        double r = 0.5 * hypot(hypot(e.x, e.y), e.z);
        bd->extent = (rt_box){rt_vec(c.x - r, c.y - r, c.z - r), rt_vec(c.x + r, c.y + r, c.z + r)};
    }
    if (ob->kind == RT_OBJ_POLYGON) {
        const rt_polygon_data *p = &ob->u.polygon;
        if (!reserve_loop(bd, p->count)) return 0;
        bd->normal = p->normal;
        bd->offset = p->offset;
        bd->drop = p->drop_axis;
        bd->loop_n = p->count;
        double nd = axis_of(p->normal, p->drop_axis);
        for (uint32_t i = 0; i < p->count; i++) {
            /* Onto the plane along the dropped axis: the 2D shape is kept. */
            rt_vec3 v = s->vertices[p->first_vertex + i];
            set_axis(&v, p->drop_axis, axis_of(v, p->drop_axis) + (p->offset - rt_vec_dot(p->normal, v)) / nd);
            bd->loop[i] = v;
            bd->extent.lo = rt_vec(fmin(bd->extent.lo.x, v.x), fmin(bd->extent.lo.y, v.y), fmin(bd->extent.lo.z, v.z));
            bd->extent.hi = rt_vec(fmax(bd->extent.hi.x, v.x), fmax(bd->extent.hi.y, v.y), fmax(bd->extent.hi.z, v.z));
        }
    } else if (ob->kind == RT_OBJ_TRIANGLE) {
        const rt_triangle_data *t = &ob->u.triangle;
        if (!reserve_loop(bd, 3)) return 0;
        bd->normal = t->normal;
        bd->offset = rt_vec_dot(t->normal, t->v[0]);
        bd->drop = rt_dominant_axis(t->normal);
        bd->loop_n = 3;
        memcpy(bd->loop, t->v, 3 * sizeof *bd->loop);
    }
    return 1;
}

/* Split factors per axis and level (shorter factor lists padded with 1s) and spans. */
static void setup_levels(build *bd, const int dims[3])
{
    int count[3];
    for (int a = 0; a < 3; a++) {
        count[a] = factorise(dims[a], bd->factor[a]);
        if (count[a] > bd->levels) bd->levels = count[a];
    }
    for (int a = 0; a < 3; a++) {
        for (int l = count[a]; l < bd->levels; l++) bd->factor[a][l] = 1;
        bd->span[a][0] = dims[a];
        for (int l = 0; l < bd->levels; l++) bd->span[a][l + 1] = bd->span[a][l] / bd->factor[a][l];
    }
}

void grid_build_init(build *bd, const rt_scene *scene, rt_grid *g, rt_preprocess_count rule)
{
    memset(bd, 0, sizeof *bd);
    bd->scene = scene;
    bd->g = g;
    bd->rule = rule;
    setup_levels(bd, g->dims);
}
