/* rt_dda.h - 3D-DDA traversal of the grid's cells (Fujimoto's ARTS).
 *
 * Usage:
 *   rt_dda d;
 *   if (rt_dda_start(grid, origin, dir, 0.0, &d)) {
 *       do { visit(d.cell, d.t_enter, rt_dda_t_exit(&d)); }
 *       while (rt_dda_advance(grid, &d, origin, dir));
 *   }
 *
 * t is measured along the ray as origin + t * dir from the ray's own origin,
 * so every cell interval [t_enter, t_exit] is comparable with hit distances.
 * Each advance moves to a face neighbour (ties between axes go x, then y,
 * then z), so a ray through an edge or corner visits the in-between cells
 * with zero-length intervals. Traversal ends after at most nx + ny + nz
 * advances.
 */
#ifndef RT_DDA_H
#define RT_DDA_H

#include <stdint.h>

#include "rt_grid.h"
#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_dda {
    int32_t cell[3];   /* current cell index per axis */
    int32_t step[3];   /* -1, 0 or +1 per axis (0: direction component is zero) */
    double t_next[3];  /* t at which the ray crosses the next boundary per axis (+inf if none) */
    double t_delta[3]; /* t between successive boundaries per axis (+inf if none) */
    double t_enter;    /* t at which the ray entered the current cell */
} rt_dda;

/* Starts a walk for the ray from t_min on. Returns 1 and fills *out when the
 * part of the ray with t >= t_min meets the object space, 0 otherwise
 * (also for an empty grid or a zero or non-finite direction). */
int rt_dda_start(const rt_grid *grid, rt_vec3 origin, rt_vec3 dir, double t_min, rt_dda *out);

/* Moves to the next cell of the ray (origin, dir) the walk was started
 * with. Returns 0 (leaving *d unchanged) when the ray leaves the object
 * space instead. */
int rt_dda_advance(const rt_grid *grid, rt_dda *d, rt_vec3 origin, rt_vec3 dir);

/* t at which the ray leaves the current cell. */
static inline double rt_dda_t_exit(const rt_dda *d)
{
    double t = d->t_next[0];
    if (d->t_next[1] < t) t = d->t_next[1];
    if (d->t_next[2] < t) t = d->t_next[2];
    return t;
}

#ifdef __cplusplus
}
#endif
#endif
