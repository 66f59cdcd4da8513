/* grid.c - the uniform grid over the object space and its cell lists.
 *
 * Object space: the bounding box of every object with non-empty bounds
 * (zero-area polygons have none), padded on every side by 1e-6 x its
 * diagonal (1e-6 x max(1, largest |coordinate|) when all objects sit in one
 * point), and by at least one ulp, so that no axis has zero thickness.
 *
 * Cell lists: see grid_list.c (the subdivision, its units and its exact tests).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid_build.h"
#include "scene_internal.h"

static void set_msg(char *msg, size_t len, const char *text)
{
    if (msg && len) snprintf(msg, len, "%s", text);
}

/* The counting pass passed what the budget allows in object `object`: the entries counted so
 * far already exceed it. */
static void over_budget_msg(const build *bd, size_t object, const rt_budget *budget, char *msg, size_t msg_len)
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
                 g->dims[0], g->dims[1], g->dims[2], bd->cell_n, ENTRY_BYTES, need_s, n - object - 1, n, left_s,
                 limit_s);
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
        if (grid_box_is_empty(&s->objects[o].bounds)) continue;
        size_t before = bd->cell_n;
        if (have_last && rt_grid_same_shape(&s->objects[last], &s->objects[o])) {
            /* The same shape meets the same cells (many coincident copies are what fill a
             * budget): its count is the last one's. */
            bd->cell_n += last_count;
            if (bd->cell_n > bd->max_entries || bd->cell_n < before) bd->over_budget = 1;
        } else {
            if (!grid_build_prepare(bd, o)) {
                set_msg(msg, msg_len, "out of memory building the cell lists");
                return 0;
            }
            grid_build_subdivide(bd, 0, root);
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
        if (g->empty || grid_box_is_empty(&s->objects[o].bounds)) continue;
        if (!grid_build_prepare(bd, o)) goto nomem;
        bd->units = 0;
        grid_build_subdivide(bd, 0, root);
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
            snprintf(msg, msg_len, "%zu cell-list entries: at most %u are supported", bd->cell_n, (unsigned)UINT32_MAX);
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

rt_grid *rt_grid_new(const rt_scene *scene, int nx, int ny, int nz, char *msg, size_t msg_len)
{
    return rt_grid_new_budget(scene, nx, ny, nz, NULL, msg, msg_len);
}

rt_grid *rt_grid_new_budget(const rt_scene *scene, int nx, int ny, int nz, rt_budget *budget, char *msg, size_t msg_len)
{
    return rt_grid_new_counted(scene, nx, ny, nz, RT_COUNT_SEQUENTIAL, budget, msg, msg_len);
}

rt_grid *rt_grid_new_counted(const rt_scene *scene, int nx, int ny, int nz, rt_preprocess_count rule, rt_budget *budget,
                             char *msg, size_t msg_len)
{
    return rt_grid_new_in_space(scene, nx, ny, nz, NULL, rule, budget, msg, msg_len);
}

/* Checks the cells per axis and in all; 0 (and a message) if they are out of range. */
static int dims_valid(const int dims[3], char *msg, size_t msg_len)
{
    for (int a = 0; a < 3; a++)
        if (dims[a] < 1 || dims[a] > RT_GRID_MAX_CELLS_PER_AXIS) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "cells %dx%dx%d: each axis needs 1 to %d cells", dims[0], dims[1], dims[2],
                         RT_GRID_MAX_CELLS_PER_AXIS);
            return 0;
        }
    uint64_t total = (uint64_t)dims[0] * (uint64_t)dims[1] * (uint64_t)dims[2];
    if (total > RT_GRID_MAX_CELLS) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "cells %dx%dx%d: at most %u cells in all", dims[0], dims[1], dims[2],
                     (unsigned)RT_GRID_MAX_CELLS);
        return 0;
    }
    return 1;
}

/* Sets the grid's padded object space from `space` (NULL: the scene's own box), its tolerance
 * and cell size; 0 (and a message) if an object lies outside `space` or the extent overflows. */
static int set_space(rt_grid *g, const rt_scene *scene, const rt_box *space, char *msg, size_t msg_len)
{
    rt_box own;
    int any = rt_grid_objects_box(scene, &own);
    if (space && any) {
        for (size_t o = 0; o < scene->object_count; o++)
            if (!grid_box_is_empty(&scene->objects[o].bounds) && !grid_box_inside(&scene->objects[o].bounds, space)) {
                if (msg && msg_len) snprintf(msg, msg_len, "object %zu lies outside the given object space", o);
                return 0;
            }
    }
    if (!rt_grid_pad_space(space ? *space : own, &g->bounds)) {
        /* Nothing to list: a unit box that no ray is ever sent into. */
        g->empty = 1;
        g->bounds.lo = rt_vec(-0.5, -0.5, -0.5);
        g->bounds.hi = rt_vec(0.5, 0.5, 0.5);
    }
    rt_vec3 e = rt_vec_sub(g->bounds.hi, g->bounds.lo);
    double diag = hypot(hypot(e.x, e.y), e.z);
    if (!rt_vec_is_finite(e) || !isfinite(diag)) {
        set_msg(msg, msg_len, "object space too large: its extent overflows a double");
        return 0;
    }
    g->tolerance = 1e-9 * diag;
    g->cell_size = rt_vec(e.x / g->dims[0], e.y / g->dims[1], e.z / g->dims[2]);
    return 1;
}

rt_grid *rt_grid_new_in_space(const rt_scene *scene, int nx, int ny, int nz, const rt_box *space,
                              rt_preprocess_count rule, rt_budget *budget, char *msg, size_t msg_len)
{
    if (!scene) {
        set_msg(msg, msg_len, "no scene given for the grid");
        return NULL;
    }
    int dims[3] = {nx, ny, nz};
    if (!dims_valid(dims, msg, msg_len)) return NULL;
    uint64_t total = (uint64_t)nx * (uint64_t)ny * (uint64_t)nz;

    /* The per-cell and per-object arrays, reserved before any is allocated. */
    size_t objects = scene->object_count;
    uint64_t fixed = (total + 1) * 4u + total * 4u + ((uint64_t)objects + 1) * 8u + objects * 8u;
    if (rt_budget_reserve(budget, fixed, "the grid's cell and object tables", msg, msg_len)) return NULL;
    rt_grid *g = calloc(1, sizeof *g);
    if (!g) {
        set_msg(msg, msg_len, "out of memory creating the grid");
        return NULL;
    }
    memcpy(g->dims, dims, sizeof dims);
    g->object_count = scene->object_count;
    g->rule = rule;
    g->units = calloc(g->object_count ? g->object_count : 1, sizeof *g->units);
    if (!g->units) {
        set_msg(msg, msg_len, "out of memory creating the grid");
        rt_grid_free(g);
        return NULL;
    }
    if (!set_space(g, scene, space, msg, msg_len)) {
        rt_grid_free(g);
        return NULL;
    }

    build bd;
    grid_build_init(&bd, scene, g, rule);
    uint64_t allowed = rt_budget_left(budget) / ENTRY_BYTES;
    bd.max_entries = allowed > (uint64_t)SIZE_MAX / ENTRY_BYTES ? SIZE_MAX / ENTRY_BYTES : (size_t)allowed;
    int ok = build_lists(&bd, budget, msg, msg_len);
    g->entries_reserved = bd.cell_n;
    free(bd.loop);
    free(bd.cells);
    free(bd.pair_start);
    if (!ok) {
        rt_grid_free(g);
        return NULL;
    }
    return g;
}
