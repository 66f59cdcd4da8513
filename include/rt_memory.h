/* rt_memory.h - data memory requirement of a cell-to-processor mapping.
 *
 * Usage:
 *   rt_memory_use *use = calloc(owners, sizeof *use);
 *   rt_memory_per_owner(scene, grid, owner, owners, use);
 *
 * An owner stores every object listed in any of its cells (once), the
 * materials those objects use (once each) and the cell lists of its cells
 * (a 4-byte header per cell plus 4 bytes per entry). Object sizes come from
 * rt_scene_object_bytes. Returns RT_ERR_NOMEM or RT_ERR_INVALID.
 * The _layout forms count with other sizes (rt_memory_layout): the paper does not say what a
 * cell list or an object record costs (docs/fidelity.md).
 */
#ifndef RT_MEMORY_H
#define RT_MEMORY_H

#include <stddef.h>
#include <stdint.h>

#include "rt_grid.h"
#include "rt_replicas.h"
#include "rt_scene.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_memory_use {
    uint64_t objects;        /* distinct objects stored */
    uint64_t object_bytes;   /* their data */
    uint64_t material_bytes; /* materials they use */
    uint64_t list_bytes;     /* cell lists of the owned cells */
} rt_memory_use;

/* What the accounting charges; rt_memory_layout_default() is the 4 / 4 / natural above. */
typedef struct rt_memory_layout {
    uint32_t cell_header_bytes;   /* per cell list, bytes */
    uint32_t list_entry_bytes;    /* per object index in a cell list, bytes */
    uint32_t object_record_bytes; /* per object, bytes; 0 = rt_scene_object_bytes of its kind */
} rt_memory_layout;

static inline rt_memory_layout rt_memory_layout_default(void)
{
    rt_memory_layout l = {4u, 4u, 0u};
    return l;
}

/* Bytes of object i's record under the layout (NULL: the default). */
uint32_t rt_memory_object_bytes(const rt_scene *scene, size_t i, const rt_memory_layout *layout);

static inline uint64_t rt_memory_total(const rt_memory_use *u)
{
    return u->object_bytes + u->material_bytes + u->list_bytes;
}

/* Per-owner use; owner[cell] in 0..owners-1 (cells with other values are skipped). */
rt_status rt_memory_per_owner(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int owners,
                              rt_memory_use *use);

/* The whole scene with all cell lists: what each processor of a
 * pixel-partitioned system holds. */
rt_memory_use rt_memory_whole_scene(const rt_scene *scene, const rt_grid *grid);

/* The same under a layout (NULL: the default); errors as rt_memory_per_owner. */
rt_status rt_memory_per_owner_layout(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int owners,
                                     const rt_memory_layout *layout, rt_memory_use *use);
rt_memory_use rt_memory_whole_scene_layout(const rt_scene *scene, const rt_grid *grid, const rt_memory_layout *layout);

/* The same with replicated cells (replicas NULL: none): each owner of a cell, primary or extra,
 * holds its list and its objects, so a copy is counted at every owner. */
rt_status rt_memory_per_owner_replicas(const rt_scene *scene, const rt_grid *grid, const int32_t *owner,
                                       const rt_replicas *replicas, int owners, const rt_memory_layout *layout,
                                       rt_memory_use *use);

#ifdef __cplusplus
}
#endif
#endif
