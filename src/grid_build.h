/* grid_build.h - listing one object in the grid's cells: the paper's recursive factor
 * subdivision with its half-space tests (grid_list.c), shared by the full build (grid.c) and
 * the incremental update (grid_update.c). Kernel-internal. */
#ifndef RT_GRID_BUILD_H
#define RT_GRID_BUILD_H

#include <stddef.h>
#include <stdint.h>

#include "grid_internal.h"
#include "scene_internal.h"

/* 1024 = 2^10: no axis has more prime factors. */
#define MAX_LEVELS 10

/* 1024 = 2^10: no axis has more prime factors. */
#define MAX_LEVELS 10

typedef struct build {
    const rt_scene *scene;
    rt_grid *g;
    int levels;
    int factor[3][MAX_LEVELS];   /* split factor per axis and level (1 = no split) */
    int span[3][MAX_LEVELS + 1]; /* cells per sub-space along an axis at each level */

    /* The object being listed. */
    const rt_object *obj;
    rt_box extent; /* what the half-space tests see */
    rt_vec3 *loop; /* polygon or triangle vertices on the plane */
    size_t loop_n, loop_cap;
    rt_vec3 normal; /* plane: dot(normal, p) == offset */
    double offset;
    int drop;                 /* axis dropped for the 2D inside test */
    rt_preprocess_count rule; /* how half-space tests are counted */
    uint64_t units;

    /* Cells met, in object order; pair_start[o] is object o's first. */
    uint32_t *cells;
    size_t cell_n, cell_cap;
    size_t *pair_start;
    int nomem;
    size_t max_entries; /* what the memory budget allows */
    int over_budget;    /* listing stopped at max_entries */
    int counting;       /* the counting pass: cell_n counts, nothing is stored */
} build;

/* Clears *bd and sets its levels for the grid's dimensions (the grid's bounds must be set). */
void grid_build_init(build *bd, const rt_scene *scene, rt_grid *g, rt_preprocess_count rule);
/* Sets up the plane, loop and extent of object o; 0 if memory runs out. */
int grid_build_prepare(build *bd, size_t o);
/* Lists the prepared object in every cell it meets below the sub-space at cell c0 of `level`
 * (level 0, c0 = 0: the whole grid), adding its half-space tests to bd->units. */
void grid_build_subdivide(build *bd, int level, const int c0[3]);
/* 1 if the box is empty (lo > hi on some axis). */
int grid_box_is_empty(const rt_box *b);
/* 1 if box a lies inside box b (faces may touch). */
int grid_box_inside(const rt_box *a, const rt_box *b);

/* Entries are 8 bytes while the lists are built (4 staged, 4 listed): the budget's unit. */
#define ENTRY_BYTES 8u

#endif
