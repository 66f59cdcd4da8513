/* memory.c - data memory an owner of cells needs: its objects (once each),
 * their materials (once each) and the lists of its cells. */
#include <stdlib.h>

#include "grid_internal.h"
#include "rt_memory.h"
#include "scene_internal.h"

rt_status rt_memory_per_owner(const rt_scene *scene, const rt_grid *grid, const int32_t *owner,
                              int owners, rt_memory_use *use)
{
    if (!scene || !grid || !owner || !use || owners < 1) return RT_ERR_INVALID;
    /* The grid must have been built from this scene. */
    if (grid->object_count != scene->object_count) return RT_ERR_INVALID;
    size_t cells = rt_grid_cell_count(grid), n = scene->object_count;
    for (int o = 0; o < owners; o++) use[o] = (rt_memory_use){0, 0, 0, 0};

    /* Cells grouped by owner (counting sort), so each owner's objects can be
     * de-duplicated with a single "last owner seen" stamp per object. */
    size_t *start = calloc((size_t)owners + 1, sizeof *start);
    uint32_t *by_owner = malloc((cells ? cells : 1) * sizeof *by_owner);
    int32_t *obj_seen = malloc((n ? n : 1) * sizeof *obj_seen);
    int32_t *mat_seen = malloc((scene->material_count ? scene->material_count : 1) * sizeof *mat_seen);
    if (!start || !by_owner || !obj_seen || !mat_seen) {
        free(start);
        free(by_owner);
        free(obj_seen);
        free(mat_seen);
        return RT_ERR_NOMEM;
    }
    for (size_t c = 0; c < cells; c++)
        if (owner[c] >= 0 && owner[c] < owners) start[owner[c] + 1]++;
    for (int o = 0; o < owners; o++) start[o + 1] += start[o];
    for (size_t c = 0; c < cells; c++)
        if (owner[c] >= 0 && owner[c] < owners) by_owner[start[owner[c]]++] = (uint32_t)c;
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
            u->list_bytes += 4u + 4u * (uint64_t)count;
            for (size_t j = 0; j < count; j++) {
                uint32_t ob = list[j];
                if (obj_seen[ob] == o) continue;
                obj_seen[ob] = o;
                u->objects++;
                u->object_bytes += rt_scene_object_bytes(scene, ob);
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

rt_memory_use rt_memory_whole_scene(const rt_scene *scene, const rt_grid *grid)
{
    rt_memory_use u = {0, 0, 0, 0};
    size_t n = scene->object_count;
    u.objects = n;
    for (size_t i = 0; i < n; i++) u.object_bytes += rt_scene_object_bytes(scene, i);

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
    u.list_bytes = 4u * (uint64_t)rt_grid_cell_count(grid) + 4u * rt_grid_list_entries(grid);
    return u;
}
