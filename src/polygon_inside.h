/* polygon_inside.h - the even-odd inside rule shared by polygon hits and polygon-cell overlap (kernel internal). */
#ifndef RT_POLYGON_INSIDE_H
#define RT_POLYGON_INSIDE_H

#include <stddef.h>

#include "rt_vec.h"

/* 1 if p lies inside the loop v[0..n) by the even-odd rule, in the plane with axis `drop` removed. */
int rt_polygon_inside(const rt_vec3 *v, size_t n, int drop, rt_vec3 p);

#endif
