/* grid_update.c - the incremental update of the cell lists between two frames of a moving
 * scene: only the objects that moved are listed again (grid_list.c's subdivision, counted by
 * the grid's rule); the entries of every other object are kept.
 *
 * The new lists are merged from two ascending sequences per cell: the old entries of the
 * objects that stayed, and the new entries of the moved ones (listed in object order, so they
 * ascend too). The result is exactly a from-scratch build over the same object space. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid_build.h"
#include "scene_internal.h"

/* The moved objects' new cells, in object order: cell[i] belongs to object[i]. */
typedef struct moved_pairs {
    uint32_t *cell;
    uint32_t *object;
    size_t count;
} moved_pairs;

static rt_status fail(char *msg, size_t msg_len, rt_status st, const char *text)
{
    if (msg && msg_len) snprintf(msg, msg_len, "%s", text);
    return st;
}

/* Lists every moved object again; its units go to units[o]. RT_ERR_NOMEM on failure. */
static rt_status list_moved(rt_grid *g, const rt_scene *s, const uint8_t *moved, uint64_t *units, moved_pairs *out)
{
    build bd;
    grid_build_init(&bd, s, g, g->rule);
    bd.max_entries = SIZE_MAX / ENTRY_BYTES; /* the budget is checked on the merged lists */
    const int root[3] = {0, 0, 0};
    size_t owners_cap = 0;
    rt_status st = RT_OK;
    for (size_t o = 0; o < s->object_count && st == RT_OK; o++) {
        if (!moved[o]) continue;
        units[o] = 0;
        if (g->empty || grid_box_is_empty(&s->objects[o].bounds)) continue;
        size_t before = bd.cell_n;
        if (!grid_build_prepare(&bd, o)) st = RT_ERR_NOMEM;
        bd.units = 0;
        if (st == RT_OK) grid_build_subdivide(&bd, 0, root);
        if (st == RT_OK && bd.nomem) st = RT_ERR_NOMEM;
        if (st == RT_OK && bd.cell_n > owners_cap) {
            size_t cap = bd.cell_cap;
            uint32_t *p = realloc(out->object, (cap ? cap : 1) * sizeof *p);
            if (!p) st = RT_ERR_NOMEM;
            else out->object = p, owners_cap = cap;
        }
        if (st != RT_OK) break;
        for (size_t i = before; i < bd.cell_n; i++) out->object[i] = (uint32_t)o;
        units[o] = bd.units;
    }
    free(bd.loop);
    out->cell = bd.cells;
    out->count = bd.cell_n;
    return st;
}

/* Counts each cell's new list: kept old entries plus moved ones; start[] gets the offsets
 * (cells + 1) and pair_start[] the offsets of the moved pairs sorted by cell. */
static void count_lists(const rt_grid *g, const uint8_t *moved, const moved_pairs *mp, size_t cells, uint32_t *start,
                        uint32_t *pair_start)
{
    for (size_t c = 0; c < cells; c++) {
        uint32_t kept = 0;
        for (uint32_t i = g->list_start[c]; i < g->list_start[c + 1]; i++) kept += !moved[g->list_objects[i]];
        start[c + 1] = kept;
    }
    for (size_t i = 0; i < mp->count; i++) {
        start[mp->cell[i] + 1]++;
        pair_start[mp->cell[i] + 1]++;
    }
    for (size_t c = 0; c < cells; c++) {
        start[c + 1] += start[c];
        pair_start[c + 1] += pair_start[c];
    }
}

/* Fills the merged lists: per cell, the kept old entries and the moved ones, both ascending. */
static void merge_lists(const rt_grid *g, const uint8_t *moved, const moved_pairs *mp, size_t cells,
                        const uint32_t *start, uint32_t *pair_start, uint32_t *sorted, uint32_t *objects)
{
    /* Moved pairs by cell (a stable counting sort keeps object order within a cell). */
    for (size_t i = 0; i < mp->count; i++) sorted[pair_start[mp->cell[i]]++] = mp->object[i];
    for (size_t c = cells; c > 0; c--) pair_start[c] = pair_start[c - 1];
    pair_start[0] = 0;
    for (size_t c = 0; c < cells; c++) {
        uint32_t i = g->list_start[c], i_end = g->list_start[c + 1];
        uint32_t j = pair_start[c], j_end = pair_start[c + 1], out = start[c];
        for (;;) {
            while (i < i_end && moved[g->list_objects[i]]) i++;
            if (i == i_end && j == j_end) break;
            if (j == j_end || (i < i_end && g->list_objects[i] < sorted[j])) objects[out++] = g->list_objects[i++];
            else objects[out++] = sorted[j++];
        }
    }
}

/* Checks the update's input; RT_OK or RT_ERR_INVALID with a message. */
static rt_status check_input(const rt_grid *g, const rt_scene *s, const uint8_t *moved, char *msg, size_t msg_len)
{
    /* A scene without objects has no flags to give (an empty array may be a null pointer). */
    if (!s || (!moved && s->object_count))
        return fail(msg, msg_len, RT_ERR_INVALID, "no scene or no moved flags given for the update");
    if (s->object_count != g->object_count) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "the scene holds %zu objects, the grid was built for %zu", s->object_count,
                     g->object_count);
        return RT_ERR_INVALID;
    }
    for (size_t o = 0; o < s->object_count; o++) {
        const rt_box *b = &s->objects[o].bounds;
        if (!moved[o] || grid_box_is_empty(b) || grid_box_inside(b, &g->bounds)) continue;
        if (msg && msg_len) snprintf(msg, msg_len, "object %zu moved out of the object space", o);
        return RT_ERR_INVALID;
    }
    return RT_OK;
}

/* Charges the budget for list entries above the most it was charged for. */
static rt_status reserve_growth(rt_grid *g, size_t entries, rt_budget *budget, char *msg, size_t msg_len)
{
    if (entries <= g->entries_reserved) return RT_OK;
    uint64_t grow = (uint64_t)(entries - g->entries_reserved) * ENTRY_BYTES;
    rt_status st = rt_budget_reserve(budget, grow, "the moved objects' cell-list entries", msg, msg_len);
    if (st == RT_OK) g->entries_reserved = entries;
    return st;
}

rt_status rt_grid_update(rt_grid *g, const rt_scene *s, const uint8_t *moved, rt_budget *budget,
                         rt_grid_update_stats *stats, char *msg, size_t msg_len)
{
    rt_status st = check_input(g, s, moved, msg, msg_len);
    if (st != RT_OK) return st;
    size_t cells = rt_grid_cell_count(g), n = g->object_count;
    moved_pairs mp = {NULL, NULL, 0};
    uint64_t *units = malloc((n ? n : 1) * sizeof *units);
    uint32_t *start = calloc(cells + 1, sizeof *start), *pair_start = calloc(cells + 1, sizeof *pair_start);
    uint32_t *sorted = NULL, *objects = NULL;
    if (!units || !start || !pair_start) st = RT_ERR_NOMEM;
    if (st == RT_OK) {
        memcpy(units, g->units, n * sizeof *units);
        st = list_moved(g, s, moved, units, &mp);
    }
    if (st == RT_OK && rt_grid_list_entries(g) + mp.count > UINT32_MAX)
        st = fail(msg, msg_len, RT_ERR_LIMIT, "the updated cell lists would pass 2^32 - 1 entries");
    if (st == RT_OK) {
        count_lists(g, moved, &mp, cells, start, pair_start);
        st = reserve_growth(g, start[cells], budget, msg, msg_len);
    }
    if (st == RT_OK) {
        sorted = malloc((mp.count ? mp.count : 1) * sizeof *sorted);
        objects = malloc((start[cells] ? start[cells] : 1) * sizeof *objects);
        if (!sorted || !objects) st = RT_ERR_NOMEM;
    }
    if (st == RT_OK) {
        merge_lists(g, moved, &mp, cells, start, pair_start, sorted, objects);
        rt_grid_update_stats out = {0, 0, 0, start[cells]};
        for (size_t o = 0; o < n; o++) {
            out.objects_moved += moved[o] != 0;
            if (moved[o]) out.units += units[o];
            out.rebuild_units += units[o];
        }
        free(g->list_start);
        free(g->list_objects);
        free(g->units);
        g->list_start = start, g->list_objects = objects, g->units = units;
        g->units_serial = out.rebuild_units;
        start = NULL, objects = NULL, units = NULL;
        if (stats) *stats = out;
    } else if (st == RT_ERR_NOMEM) {
        fail(msg, msg_len, st, "out of memory updating the cell lists");
    }
    free(units);
    free(start);
    free(pair_start);
    free(sorted);
    free(objects);
    free(mp.cell);
    free(mp.object);
    return st;
}
