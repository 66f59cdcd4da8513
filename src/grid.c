/* grid.c - the uniform grid over the object space and its cell lists.
 *
 * Object space: the bounding box of every object with non-empty bounds
 * (zero-area polygons have none), padded on every side by 1e-6 x its
 * diagonal (1e-6 x max(1, largest |coordinate|) when all objects sit in one
 * point), and by at least one ulp, so that no axis has zero thickness.
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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid_internal.h"
#include "polygon_inside.h"
#include "scene_internal.h"

/* 1024 = 2^10: no axis has more prime factors. */
#define MAX_LEVELS 10

typedef struct build {
    const rt_scene *scene;
    rt_grid *g;
    int levels;
    int factor[3][MAX_LEVELS];    /* split factor per axis and level (1 = no split) */
    int span[3][MAX_LEVELS + 1];  /* cells per sub-space along an axis at each level */

    /* The object being listed. */
    const rt_object *obj;
    rt_box extent;                /* what the half-space tests see */
    rt_vec3 *loop;                /* polygon or triangle vertices on the plane */
    size_t loop_n, loop_cap;
    rt_vec3 normal;               /* plane: dot(normal, p) == offset */
    double offset;
    int drop;                     /* axis dropped for the 2D inside test */
    rt_preprocess_count rule;     /* how half-space tests are counted */
    uint64_t units;

    /* Cells met, in object order; pair_start[o] is object o's first. */
    uint32_t *cells;
    size_t cell_n, cell_cap;
    size_t *pair_start;
    int nomem;
    size_t max_entries;           /* what the memory budget allows */
    int over_budget;              /* listing stopped at max_entries */
    int counting;                 /* the counting pass: cell_n counts, nothing is stored */
} build;

static int box_is_empty(const rt_box *b)
{
    return !(b->lo.x <= b->hi.x && b->lo.y <= b->hi.y && b->lo.z <= b->hi.z);
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
        if (ta > tb) { double s = ta; ta = tb; tb = s; }
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
    return o->lo.x <= b->hi.x && o->hi.x >= b->lo.x && o->lo.y <= b->hi.y && o->hi.y >= b->lo.y &&
           o->lo.z <= b->hi.z && o->hi.z >= b->lo.z;
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
            if (found && !(hi >= rt_grid_plane(g, axis, c0 + k * m) - tol)) { *last = k - 1; break; }
        }
        return;
    }
    for (int k = 1; k < f; k++) {
        bd->units++;
        if (lo <= rt_grid_plane(g, axis, c0 + k * m) + tol) { *first = k - 1; break; }
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
static void subdivide(build *bd, int level, const int c0[3])
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
                b.hi = rt_vec(rt_grid_plane(g, 0, c[0] + m[0]) + tol,
                              rt_grid_plane(g, 1, c[1] + m[1]) + tol,
                              rt_grid_plane(g, 2, c[2] + m[2]) + tol);
                if (!object_meets(bd, &b)) continue;
                if (bd->counting && object_holds(bd, &b)) {
                    /* Every cell of the sub-space is listed: count them at once. */
                    size_t all = (size_t)m[0] * (size_t)m[1] * (size_t)m[2];
                    bd->cell_n += all;
                    if (bd->cell_n > bd->max_entries) bd->over_budget = bd->nomem = 1;
                    continue;
                }
                subdivide(bd, level + 1, c);
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

/* Sets up the plane, loop and extent of object o; 0 if memory runs out. */
static int prepare_object(build *bd, size_t o)
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
            bd->extent.lo = rt_vec(fmin(bd->extent.lo.x, v.x), fmin(bd->extent.lo.y, v.y),
                                   fmin(bd->extent.lo.z, v.z));
            bd->extent.hi = rt_vec(fmax(bd->extent.hi.x, v.x), fmax(bd->extent.hi.y, v.y),
                                   fmax(bd->extent.hi.z, v.z));
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

static void set_msg(char *msg, size_t len, const char *text)
{
    if (msg && len) snprintf(msg, len, "%s", text);
}


/* Entries are 8 bytes while the lists are built (4 staged, 4 listed). */
#define ENTRY_BYTES 8u

/* The counting pass passed what the budget allows in object `object`: the entries counted so
 * far already exceed it. */
static void over_budget_msg(const build *bd, size_t object, const rt_budget *budget, char *msg,
                            size_t msg_len)
{
    const rt_grid *g = bd->g;
    size_t n = bd->scene->object_count;
    char need_s[32], left_s[32], limit_s[32];
    double need = (double)bd->cell_n * ENTRY_BYTES;
    rt_budget_format(need < 1.8e19 ? (uint64_t)need : UINT64_MAX, need_s, sizeof need_s);
    rt_budget_format(rt_budget_left(budget), left_s, sizeof left_s);
    rt_budget_format(budget ? budget->limit : 0, limit_s, sizeof limit_s);
    if (msg && msg_len)
        snprintf(msg, msg_len,
                 "memory budget exceeded: the cell lists of the %dx%dx%d grid would take more "
                 "than %zu entries (%u bytes each while they are built), at least %s, counted "
                 "before any is made with %zu of %zu objects still to count: more than the %s left "
                 "of the %s budget (raise it with --memory-budget)",
                 g->dims[0], g->dims[1], g->dims[2], bd->cell_n, ENTRY_BYTES, need_s,
                 n - object - 1, n, left_s, limit_s);
}

/* The counting pass: how many entries the lists will have, without storing any; 0 when
 * they pass what the budget allows (the message is set). */
static int count_entries(build *bd, const rt_budget *budget, char *msg, size_t msg_len)
{
    const rt_scene *s = bd->scene;
    int root[3] = {0, 0, 0};
    bd->counting = 1;
    size_t last = 0, last_count = 0; /* the last object counted (last_count: its entries) */
    int have_last = 0;
    for (size_t o = 0; o < s->object_count && !bd->g->empty; o++) {
        if (box_is_empty(&s->objects[o].bounds)) continue;
        size_t before = bd->cell_n;
        if (have_last && rt_grid_same_shape(&s->objects[last], &s->objects[o])) {
            /* The same shape meets the same cells (many coincident copies are what fill a
             * budget): its count is the last one's. */
            bd->cell_n += last_count;
            if (bd->cell_n > bd->max_entries || bd->cell_n < before) bd->over_budget = 1;
        } else {
            if (!prepare_object(bd, o)) {
                set_msg(msg, msg_len, "out of memory building the cell lists");
                return 0;
            }
            subdivide(bd, 0, root);
        }
        last = o;
        last_count = bd->cell_n - before;
        have_last = 1;
        if (bd->over_budget) {
            over_budget_msg(bd, o, budget, msg, msg_len);
            return 0;
        }
    }
    bd->counting = 0;
    bd->nomem = 0;
    return 1;
}

/* Runs the subdivision for every object and fills the grid's lists. */
static int build_lists(build *bd, rt_budget *budget, char *msg, size_t msg_len)
{
    rt_grid *g = bd->g;
    const rt_scene *s = bd->scene;
    size_t n = s->object_count, cells = rt_grid_cell_count(g);

    /* Count first, then allocate: a scene whose lists cannot fit is refused before they
     * take any memory, and the entries are allocated once, at their size. */
    if (!count_entries(bd, budget, msg, msg_len)) return 0;
    size_t entries = bd->cell_n;
    bd->cell_n = 0;
    bd->units = 0;
    bd->pair_start = malloc((n + 1) * sizeof *bd->pair_start);
    g->list_start = calloc(cells + 1, sizeof *g->list_start);
    bd->cells = malloc((entries ? entries : 1) * sizeof *bd->cells);
    if (!bd->pair_start || !g->list_start || !bd->cells) goto nomem;
    bd->cell_cap = entries ? entries : 1;

    int root[3] = {0, 0, 0};
    for (size_t o = 0; o < n; o++) {
        bd->pair_start[o] = bd->cell_n;
        if (g->empty || box_is_empty(&s->objects[o].bounds)) continue;
        if (!prepare_object(bd, o)) goto nomem;
        bd->units = 0;
        subdivide(bd, 0, root);
        if (bd->over_budget) {
            over_budget_msg(bd, o, budget, msg, msg_len);
            return 0;
        }
        if (bd->nomem) goto nomem;
        g->units[o] = bd->units;
        g->units_serial += bd->units;
    }
    bd->pair_start[n] = bd->cell_n;
    if (bd->cell_n > UINT32_MAX) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "%zu cell-list entries: at most %u are supported", bd->cell_n,
                     (unsigned)UINT32_MAX);
        return 0;
    }

    /* Counting sort by cell; objects arrive in order, so lists ascend. */
    for (size_t i = 0; i < bd->cell_n; i++) g->list_start[bd->cells[i] + 1]++;
    for (size_t c = 0; c < cells; c++) g->list_start[c + 1] += g->list_start[c];
    g->list_objects = malloc((bd->cell_n ? bd->cell_n : 1) * sizeof *g->list_objects);
    uint32_t *fill = malloc((cells ? cells : 1) * sizeof *fill);
    if (!g->list_objects || !fill) {
        free(fill);
        goto nomem;
    }
    if (budget) rt_budget_reserve(budget, (uint64_t)bd->cell_n * ENTRY_BYTES, "", NULL, 0);
    memcpy(fill, g->list_start, cells * sizeof *fill);
    for (size_t o = 0; o < n; o++)
        for (size_t i = bd->pair_start[o]; i < bd->pair_start[o + 1]; i++)
            g->list_objects[fill[bd->cells[i]]++] = (uint32_t)o;
    free(fill);
    return 1;

nomem:
    set_msg(msg, msg_len, "out of memory building the cell lists");
    return 0;
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

rt_grid *rt_grid_new(const rt_scene *scene, int nx, int ny, int nz, char *msg, size_t msg_len)
{
    return rt_grid_new_budget(scene, nx, ny, nz, NULL, msg, msg_len);
}

rt_grid *rt_grid_new_budget(const rt_scene *scene, int nx, int ny, int nz, rt_budget *budget,
                            char *msg, size_t msg_len)
{
    return rt_grid_new_counted(scene, nx, ny, nz, RT_COUNT_SEQUENTIAL, budget, msg, msg_len);
}

rt_grid *rt_grid_new_counted(const rt_scene *scene, int nx, int ny, int nz, rt_preprocess_count rule,
                             rt_budget *budget, char *msg, size_t msg_len)
{
    if (!scene) {
        set_msg(msg, msg_len, "no scene given for the grid");
        return NULL;
    }
    int dims[3] = {nx, ny, nz};
    for (int a = 0; a < 3; a++)
        if (dims[a] < 1 || dims[a] > RT_GRID_MAX_CELLS_PER_AXIS) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "cells %dx%dx%d: each axis needs 1 to %d cells", nx, ny, nz,
                         RT_GRID_MAX_CELLS_PER_AXIS);
            return NULL;
        }
    uint64_t total = (uint64_t)nx * (uint64_t)ny * (uint64_t)nz;
    if (total > RT_GRID_MAX_CELLS) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "cells %dx%dx%d: at most %u cells in all", nx, ny, nz,
                     (unsigned)RT_GRID_MAX_CELLS);
        return NULL;
    }

    /* The per-cell and per-object arrays, reserved before any is allocated. */
    size_t objects = scene->object_count;
    uint64_t fixed = (total + 1) * 4u + total * 4u + ((uint64_t)objects + 1) * 8u + objects * 8u;
    if (rt_budget_reserve(budget, fixed, "the grid's cell and object tables", msg, msg_len))
        return NULL;
    rt_grid *g = calloc(1, sizeof *g);
    if (!g) {
        set_msg(msg, msg_len, "out of memory creating the grid");
        return NULL;
    }
    memcpy(g->dims, dims, sizeof dims);
    g->object_count = scene->object_count;
    g->units = calloc(g->object_count ? g->object_count : 1, sizeof *g->units);
    if (!g->units) {
        set_msg(msg, msg_len, "out of memory creating the grid");
        rt_grid_free(g);
        return NULL;
    }

    if (!rt_grid_object_space(scene, &g->bounds)) {
        /* Nothing to list: a unit box that no ray is ever sent into. */
        g->empty = 1;
        g->bounds.lo = rt_vec(-0.5, -0.5, -0.5);
        g->bounds.hi = rt_vec(0.5, 0.5, 0.5);
    }
    rt_vec3 e = rt_vec_sub(g->bounds.hi, g->bounds.lo);
    double diag = hypot(hypot(e.x, e.y), e.z);
    if (!rt_vec_is_finite(e) || !isfinite(diag)) {
        set_msg(msg, msg_len, "object space too large: its extent overflows a double");
        rt_grid_free(g);
        return NULL;
    }
    g->tolerance = 1e-9 * diag;
    g->cell_size = rt_vec(e.x / nx, e.y / ny, e.z / nz);

    build bd;
    memset(&bd, 0, sizeof bd);
    bd.scene = scene;
    bd.g = g;
    bd.rule = rule;
    setup_levels(&bd, dims);

    uint64_t allowed = rt_budget_left(budget) / ENTRY_BYTES;
    bd.max_entries = allowed > (uint64_t)SIZE_MAX / ENTRY_BYTES ? SIZE_MAX / ENTRY_BYTES : (size_t)allowed;
    int ok = build_lists(&bd, budget, msg, msg_len);
    free(bd.loop);
    free(bd.cells);
    free(bd.pair_start);
    if (!ok) {
        rt_grid_free(g);
        return NULL;
    }
    return g;
}
