/* polygon_inside.h - the even-odd inside rule shared by polygon hits and polygon-cell overlap (kernel internal). */
#ifndef RT_POLYGON_INSIDE_H
#define RT_POLYGON_INSIDE_H

#include <stddef.h>

#include "rt_vec.h"

/* The axis (0 x, 1 y, 2 z) along which the normal n is largest: the one a polygon drops to be
 * tested in 2D with the least shrinking (ties go to the lower axis). */
int rt_dominant_axis(rt_vec3 n);

/* 1 if p lies inside the loop v[0..n) by the even-odd rule, in the plane with axis `drop` removed. */
int rt_polygon_inside(const rt_vec3 *v, size_t n, int drop, rt_vec3 p);

#endif
