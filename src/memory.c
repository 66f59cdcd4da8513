/* memory.c - data memory an owner of cells needs: its objects (once each),
 * their materials (once each) and the lists of its cells. */
#include <stdlib.h>

#include "grid_internal.h"
#include "rt_memory.h"
#include "scene_internal.h"

uint32_t rt_memory_object_bytes(const rt_scene *scene, size_t i, const rt_memory_layout *layout)
{
    if (layout && layout->object_record_bytes) return layout->object_record_bytes;
    return rt_scene_object_bytes(scene, i);
}

rt_status rt_memory_per_owner(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int owners,
                              rt_memory_use *use)
{
    return rt_memory_per_owner_layout(scene, grid, owner, owners, NULL, use);
}

rt_memory_use rt_memory_whole_scene(const rt_scene *scene, const rt_grid *grid)
{
    return rt_memory_whole_scene_layout(scene, grid, NULL);
}

rt_status rt_memory_per_owner_layout(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int owners,
                                     const rt_memory_layout *layout, rt_memory_use *use)
{
    return rt_memory_per_owner_replicas(scene, grid, owner, NULL, owners, layout, use);
}

/* Adds one (owner, cell) pair to the grouping: counting (by_owner NULL) or placing. */
static void group_pair(int32_t o, uint32_t c, int owners, size_t *start, uint32_t *by_owner)
{
    if (o < 0 || o >= owners) return;
    if (by_owner) by_owner[start[o]++] = c;
    else start[o + 1]++;
}

rt_status rt_memory_per_owner_replicas(const rt_scene *scene, const rt_grid *grid, const int32_t *owner,
                                       const rt_replicas *replicas, int owners, const rt_memory_layout *layout,
                                       rt_memory_use *use)
{
    rt_memory_layout l = layout ? *layout : rt_memory_layout_default();
    if (!scene || !grid || !owner || !use || owners < 1) return RT_ERR_INVALID;
    /* The grid must have been built from this scene. */
    if (grid->object_count != scene->object_count) return RT_ERR_INVALID;
    size_t cells = rt_grid_cell_count(grid), n = scene->object_count;
    for (int o = 0; o < owners; o++) use[o] = (rt_memory_use){0, 0, 0, 0};

    /* (owner, cell) pairs grouped by owner (counting sort), so each owner's objects can be
     * de-duplicated with a single "last owner seen" stamp per object; a replicated cell is in
     * the group of every one of its owners. */
    size_t pairs = cells + (replicas ? replicas->first[cells] : 0);
    size_t *start = calloc((size_t)owners + 1, sizeof *start);
    uint32_t *by_owner = malloc((pairs ? pairs : 1) * sizeof *by_owner);
    int32_t *obj_seen = malloc((n ? n : 1) * sizeof *obj_seen);
    int32_t *mat_seen = malloc((scene->material_count ? scene->material_count : 1) * sizeof *mat_seen);
    if (!start || !by_owner || !obj_seen || !mat_seen) {
        free(start);
        free(by_owner);
        free(obj_seen);
        free(mat_seen);
        return RT_ERR_NOMEM;
    }
    for (int pass = 0; pass < 2; pass++) {
        uint32_t *place = pass ? by_owner : NULL;
        for (uint32_t c = 0; c < (uint32_t)cells; c++) {
            group_pair(owner[c], c, owners, start, place);
            for (uint32_t k = 0; k < rt_replicas_extra_count(replicas, c); k++)
                group_pair(replicas->extra[replicas->first[c] + k], c, owners, start, place);
        }
        if (!pass)
            for (int o = 0; o < owners; o++) start[o + 1] += start[o];
    }
    /* The fill pass moved each start to the next owner's: shift back. */
    for (int o = owners; o > 0; o--) start[o] = start[o - 1];
    start[0] = 0;

    for (size_t i = 0; i < n; i++) obj_seen[i] = -1;
    for (size_t i = 0; i < scene->material_count; i++) mat_seen[i] = -1;
    for (int o = 0; o < owners; o++) {
        rt_memory_use *u = &use[o];
        for (size_t k = start[o]; k < start[o + 1]; k++) {
            size_t count;
            const uint32_t *list = rt_grid_cell_objects(grid, by_owner[k], &count);
            u->list_bytes += l.cell_header_bytes + l.list_entry_bytes * (uint64_t)count;
            for (size_t j = 0; j < count; j++) {
                uint32_t ob = list[j];
                if (obj_seen[ob] == o) continue;
                obj_seen[ob] = o;
                u->objects++;
                u->object_bytes += rt_memory_object_bytes(scene, ob, &l);
                uint32_t m = scene->objects[ob].material;
                if (mat_seen[m] == o) continue;
                mat_seen[m] = o;
                u->material_bytes += rt_scene_material_bytes();
            }
        }
    }
    free(start);
    free(by_owner);
    free(obj_seen);
    free(mat_seen);
    return RT_OK;
}

rt_memory_use rt_memory_whole_scene_layout(const rt_scene *scene, const rt_grid *grid, const rt_memory_layout *layout)
{
    rt_memory_layout l = layout ? *layout : rt_memory_layout_default();
    rt_memory_use u = {0, 0, 0, 0};
    size_t n = scene->object_count;
    u.objects = n;
    for (size_t i = 0; i < n; i++) u.object_bytes += rt_memory_object_bytes(scene, i, &l);

    unsigned char *used = calloc(scene->material_count ? scene->material_count : 1, 1);
    uint64_t materials = 0;
    if (used) {
        for (size_t i = 0; i < n; i++) {
            uint32_t m = scene->objects[i].material;
            if (!used[m]) {
                used[m] = 1;
                materials++;
            }
        }
        free(used);
    } else {
        /* No memory for the marks: every material is an upper bound. */
        materials = scene->material_count;
    }
    u.material_bytes = materials * rt_scene_material_bytes();
    u.list_bytes = (uint64_t)l.cell_header_bytes * rt_grid_cell_count(grid) +
                   (uint64_t)l.list_entry_bytes * rt_grid_list_entries(grid);
    return u;
}
