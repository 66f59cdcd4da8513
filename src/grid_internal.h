/* grid_internal.h - the grid's storage, shared by the kernel's own files only. */
#ifndef RT_GRID_INTERNAL_H
#define RT_GRID_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "rt_grid.h"
#include "scene_internal.h"

struct rt_grid {
    int dims[3];            /* cells per axis */
    int empty;              /* no objects: no ray enters */
    rt_box bounds;          /* padded object space */
    rt_vec3 cell_size;      /* edge lengths of a cell */
    double tolerance;       /* overlap tests grow cells by this much (scene units) */
    uint32_t *list_start;   /* cells + 1 offsets into list_objects (compressed rows) */
    uint32_t *list_objects; /* object indices, ascending within a cell */
    uint64_t *units;        /* preprocessing units per object */
    uint64_t units_serial;  /* sum of units */
    size_t object_count;
    rt_preprocess_count rule; /* how the units are counted (the update counts the same way) */
    size_t entries_reserved;  /* most list entries the budget has been charged for */
};

/* Coordinate of boundary plane k (0..dims[axis]) on an axis: every part of
 * the kernel uses this one formula, so cell faces agree bit for bit. */
static inline double rt_grid_plane(const struct rt_grid *g, int axis, int k)
{
    double lo = rt_vec_axis(g->bounds.lo, axis), hi = rt_vec_axis(g->bounds.hi, axis);
    if (k <= 0) return lo;
    if (k >= g->dims[axis]) return hi;
    return lo + (hi - lo) * ((double)k / (double)g->dims[axis]);
}

/* The padded object space of a scene's objects in *out; 0 when no object has bounds. */
int rt_grid_object_space(const rt_scene *s, rt_box *out);
/* The bounding box of a scene's objects (unpadded) in *out; 0 when no object has bounds. */
int rt_grid_objects_box(const rt_scene *s, rt_box *out);
/* A box padded as the object space is (see grid.c); 0 when the box is empty. */
int rt_grid_pad_space(rt_box raw, rt_box *out);

/* 1 if two objects are the same sphere, triangle or cone, so they meet the same cells. */
int rt_grid_same_shape(const rt_object *a, const rt_object *b);

#endif
