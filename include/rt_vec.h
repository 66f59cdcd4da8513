/* rt_vec.h - double-precision 3-vectors and axis-aligned boxes.
 *
 * Usage:
 *   rt_vec3 d = rt_vec_normalize(rt_vec_sub(at, from));
 *
 * All functions are static inline and cannot fail; rt_vec_normalize of the
 * zero vector returns the zero vector.
 */
#ifndef RT_VEC_H
#define RT_VEC_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_vec3 {
    double x, y, z; /* scene units (or colour channels r, g, b) */
} rt_vec3;

typedef struct rt_box {
    rt_vec3 lo; /* smallest corner, scene units */
    rt_vec3 hi; /* largest corner, scene units */
} rt_box;

static inline rt_vec3 rt_vec(double x, double y, double z)
{
    rt_vec3 v = {x, y, z};
    return v;
}
static inline rt_vec3 rt_vec_add(rt_vec3 a, rt_vec3 b) { return rt_vec(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline rt_vec3 rt_vec_sub(rt_vec3 a, rt_vec3 b) { return rt_vec(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline rt_vec3 rt_vec_scale(rt_vec3 a, double s) { return rt_vec(a.x * s, a.y * s, a.z * s); }
static inline rt_vec3 rt_vec_mul(rt_vec3 a, rt_vec3 b) { return rt_vec(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline double rt_vec_dot(rt_vec3 a, rt_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline rt_vec3 rt_vec_cross(rt_vec3 a, rt_vec3 b)
{
    return rt_vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double rt_vec_length(rt_vec3 a) { return sqrt(rt_vec_dot(a, a)); }
static inline rt_vec3 rt_vec_normalize(rt_vec3 a)
{
    double len = rt_vec_length(a);
    return len > 0.0 ? rt_vec_scale(a, 1.0 / len) : rt_vec(0.0, 0.0, 0.0);
}
/* A as a direction whose length can be computed: A itself when its largest component is from
 * 1e-100 to 1e100, else A divided by that component, so that 1e-300 or 1e300 keeps its direction
 * (the squares of the length would underflow or overflow); the zero vector stays zero. */
static inline rt_vec3 rt_vec_rescaled(rt_vec3 a)
{
    double big = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(big > 0.0) || (big >= 1e-100 && big <= 1e100)) return a;
    return rt_vec(a.x / big, a.y / big, a.z / big); /* 1 / big overflows for a subnormal big */
}
/* Component by axis index 0, 1, 2. */
static inline double rt_vec_axis(rt_vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline double rt_vec_max_component(rt_vec3 a)
{
    double m = a.x > a.y ? a.x : a.y;
    return m > a.z ? m : a.z;
}
/* Largest absolute component: the scale of a point for rounding bounds. */
static inline double rt_vec_max_abs(rt_vec3 a)
{
    double m = fabs(a.x) > fabs(a.y) ? fabs(a.x) : fabs(a.y);
    return m > fabs(a.z) ? m : fabs(a.z);
}
static inline int rt_vec_is_zero(rt_vec3 a) { return a.x == 0.0 && a.y == 0.0 && a.z == 0.0; }
static inline int rt_vec_is_finite(rt_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

#ifdef __cplusplus
}
#endif
#endif
