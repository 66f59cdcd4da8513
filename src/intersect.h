/* intersect.h - ray-object intersection and surface normals (kernel internal). */
#ifndef RT_INTERSECT_H
#define RT_INTERSECT_H

#include <stdint.h>

#include "scene_internal.h"

typedef struct rt_hit {
    double t;    /* distance along the unit direction */
    double u, v; /* triangle barycentrics of vertices 1 and 2 (else unused) */
} rt_hit;

/* 1 if the ray origin + t * dir (dir unit) meets object `index` at
 * t_min < t < t_max; *hit then holds the nearest such t. */
int rt_intersect_object(const rt_scene *scene, uint32_t index, rt_vec3 origin, rt_vec3 dir, double t_min, double t_max,
                        rt_hit *hit);

/* A `pp` triangle's interpolated normal sum shorter than this times the sum
 * of the weights (the vertex normals are unit, the weights sum to 1) is taken
 * as cancelled: the face normal shades instead. */
#define RT_PATCH_MIN_NORMAL 1e-3

/* Normals at a hit point: n_geo is the unit outward normal that decides
 * entering or leaving (vertex order for polygons); n_shade the normal used
 * for shading (interpolated for `pp` triangles, else n_geo). */
void rt_object_normals(const rt_scene *scene, uint32_t index, rt_vec3 point, const rt_hit *hit, rt_vec3 *n_geo,
                       rt_vec3 *n_shade);

#endif
