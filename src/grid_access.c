/* grid_access.c - what the grid tells about itself, freeing it, and which objects meet the
 * same cells. */
#include <stdlib.h>
#include <string.h>

#include "grid_internal.h"
#include "scene_internal.h"

static int same_point(rt_vec3 a, rt_vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* 1 if two objects are the same sphere, triangle or cone (polygons keep their vertices apart,
 * so they are never taken as the same). */
int rt_grid_same_shape(const rt_object *a, const rt_object *b)
{
    if (a->kind != b->kind || a->kind == RT_OBJ_POLYGON) return 0;
    switch (a->kind) {
    case RT_OBJ_SPHERE:
        return same_point(a->u.sphere.center, b->u.sphere.center) && a->u.sphere.radius == b->u.sphere.radius;
    case RT_OBJ_TRIANGLE:
        return same_point(a->u.triangle.v[0], b->u.triangle.v[0]) &&
               same_point(a->u.triangle.v[1], b->u.triangle.v[1]) && same_point(a->u.triangle.v[2], b->u.triangle.v[2]);
    case RT_OBJ_CONE: return memcmp(&a->bounds, &b->bounds, sizeof a->bounds) == 0;
    case RT_OBJ_POLYGON: break;
    }
    return 0;
}

void rt_grid_free(rt_grid *g)
{
    if (!g) return;
    free(g->list_start);
    free(g->list_objects);
    free(g->units);
    free(g);
}

void rt_grid_dims(const rt_grid *g, int dims[3]) { memcpy(dims, g->dims, sizeof g->dims); }

size_t rt_grid_cell_count(const rt_grid *g) { return (size_t)g->dims[0] * (size_t)g->dims[1] * (size_t)g->dims[2]; }

int rt_grid_is_empty(const rt_grid *g) { return g->empty; }
rt_box rt_grid_bounds(const rt_grid *g) { return g->bounds; }
rt_vec3 rt_grid_cell_size(const rt_grid *g) { return g->cell_size; }

rt_box rt_grid_cell_box(const rt_grid *g, int ix, int iy, int iz)
{
    rt_box b;
    b.lo = rt_vec(rt_grid_plane(g, 0, ix), rt_grid_plane(g, 1, iy), rt_grid_plane(g, 2, iz));
    b.hi = rt_vec(rt_grid_plane(g, 0, ix + 1), rt_grid_plane(g, 1, iy + 1), rt_grid_plane(g, 2, iz + 1));
    return b;
}

const uint32_t *rt_grid_cell_objects(const rt_grid *g, size_t cell, size_t *count)
{
    if (cell >= rt_grid_cell_count(g)) {
        *count = 0;
        return NULL;
    }
    *count = g->list_start[cell + 1] - g->list_start[cell];
    return g->list_objects + g->list_start[cell];
}

uint64_t rt_grid_list_entries(const rt_grid *g) { return g->list_start[rt_grid_cell_count(g)]; }
double rt_grid_overlap_tolerance(const rt_grid *g) { return g->tolerance; }
uint64_t rt_grid_units_serial(const rt_grid *g) { return g->units_serial; }

uint64_t rt_grid_units_of_object(const rt_grid *g, size_t object)
{
    return object < g->object_count ? g->units[object] : 0;
}

uint64_t rt_grid_units_parallel(const rt_grid *g, int processors)
{
    size_t p = processors < 1 ? 1 : (size_t)processors;
    size_t busy = p < g->object_count ? p : g->object_count;
    uint64_t worst = 0;
    /* Processor q handles objects q, q + P, q + 2P, ...: no buffer needed. */
    for (size_t q = 0; q < busy; q++) {
        uint64_t sum = 0;
        for (size_t o = q; o < g->object_count; o += p) sum += g->units[o];
        if (sum > worst) worst = sum;
    }
    return worst;
}
