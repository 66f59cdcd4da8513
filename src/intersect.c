/* intersect.c - ray-object intersection tests for spheres, polygons, `pp`
 * triangles and open cones. Roots are computed in forms that avoid
 * cancellation, so tiny and huge objects are hit as reliably as unit ones. */
#include <math.h>

#include "intersect.h"
#include "polygon_inside.h"

/* Picks the nearest of two roots inside (t_min, t_max). */
static int pick_root(double t0, double t1, double t_min, double t_max, double *t)
{
    if (t0 > t1) {
        double s = t0;
        t0 = t1;
        t1 = s;
    }
    if (t0 > t_min && t0 < t_max) {
        *t = t0;
        return 1;
    }
    if (t1 > t_min && t1 < t_max) {
        *t = t1;
        return 1;
    }
    return 0;
}

static int hit_sphere(const rt_sphere_data *s, rt_vec3 o, rt_vec3 d, double t_min, double t_max, double *t)
{
    rt_vec3 oc = rt_vec_sub(o, s->center);
    double b = rt_vec_dot(oc, d);
    /* Discriminant from the perpendicular distance (Ray Tracing Gems, ch. 7):
     * r^2 - |oc - b d|^2 keeps its precision when the sphere is tiny and far. */
    rt_vec3 perp = rt_vec_sub(oc, rt_vec_scale(d, b));
    double r2 = s->radius * s->radius;
    double disc = r2 - rt_vec_dot(perp, perp);
    if (disc < 0.0) return 0;
    double c = rt_vec_dot(oc, oc) - r2;
    double q = -b - copysign(sqrt(disc), b);
    if (q == 0.0) return 0;
    return pick_root(c / q, q, t_min, t_max, t);
}

static int hit_polygon(const rt_scene *s, const rt_polygon_data *p, rt_vec3 o, rt_vec3 d, double t_min, double t_max,
                       double *t)
{
    if (p->degenerate) return 0;
    double denom = rt_vec_dot(p->normal, d);
    if (denom == 0.0) return 0; /* edge-on: a plane of zero thickness is never hit */
    double tt = (p->offset - rt_vec_dot(p->normal, o)) / denom;
    if (!(tt > t_min && tt < t_max)) return 0;
    rt_vec3 hp = rt_vec_add(o, rt_vec_scale(d, tt));
    if (!rt_polygon_inside(s->vertices + p->first_vertex, p->count, p->drop_axis, hp)) return 0;
    *t = tt;
    return 1;
}

/* Moller-Trumbore; shared edges are accepted by both triangles (ties go to the lower index). */
static int hit_triangle(const rt_triangle_data *tr, rt_vec3 o, rt_vec3 d, double t_min, double t_max, rt_hit *hit)
{
    if (tr->degenerate) return 0;
    rt_vec3 e1 = rt_vec_sub(tr->v[1], tr->v[0]), e2 = rt_vec_sub(tr->v[2], tr->v[0]);
    rt_vec3 pv = rt_vec_cross(d, e2);
    double det = rt_vec_dot(e1, pv);
    if (det == 0.0) return 0;
    double inv = 1.0 / det;
    rt_vec3 tv = rt_vec_sub(o, tr->v[0]);
    double u = rt_vec_dot(tv, pv) * inv;
    if (u < 0.0 || u > 1.0) return 0;
    rt_vec3 qv = rt_vec_cross(tv, e1);
    double v = rt_vec_dot(d, qv) * inv;
    if (v < 0.0 || u + v > 1.0) return 0;
    double tt = rt_vec_dot(e2, qv) * inv;
    if (!(tt > t_min && tt < t_max)) return 0;
    hit->t = tt;
    hit->u = u;
    hit->v = v;
    return 1;
}

static int hit_cone(const rt_cone_data *c, rt_vec3 o, rt_vec3 d, double t_min, double t_max, double *t)
{
    /* Solve from the point of the ray nearest the cone's middle: the quadratic's terms then
     * have the cone's own size, so a tiny cone far away keeps its precision. */
    rt_vec3 mid = rt_vec_scale(rt_vec_add(c->base, c->apex), 0.5);
    double shift = rt_vec_dot(rt_vec_sub(mid, o), d);
    o = rt_vec_add(o, rt_vec_scale(d, shift));
    t_min -= shift;
    t_max -= shift;
    rt_vec3 co = rt_vec_sub(o, c->base);
    double d_par = rt_vec_dot(d, c->axis), o_par = rt_vec_dot(co, c->axis);
    rt_vec3 d_perp = rt_vec_sub(d, rt_vec_scale(c->axis, d_par));
    rt_vec3 o_perp = rt_vec_sub(co, rt_vec_scale(c->axis, o_par));
    double k = c->slope;
    double r0 = c->base_radius + k * o_par; /* radius at the origin's axial position */
    double a = rt_vec_dot(d_perp, d_perp) - k * k * d_par * d_par;
    double b = 2.0 * (rt_vec_dot(o_perp, d_perp) - r0 * k * d_par);
    double cc = rt_vec_dot(o_perp, o_perp) - r0 * r0;
    double roots[2];
    int nroots = 0;
    if (fabs(a) < 1e-300) {
        if (b == 0.0) return 0;
        roots[nroots++] = -cc / b;
    } else {
        double disc = b * b - 4.0 * a * cc;
        if (disc < 0.0) return 0;
        double q = -0.5 * (b + copysign(sqrt(disc), b));
        if (q != 0.0) roots[nroots++] = cc / q;
        roots[nroots++] = q / a;
    }
    double best = INFINITY;
    for (int i = 0; i < nroots; i++) {
        double r = roots[i];
        if (!(r > t_min && r < t_max) || !(r < best)) continue;
        double h = o_par + r * d_par; /* axial position of the hit */
        /* The double cone's mirror nappe has negative radius there: not part of the surface. */
        if (h < 0.0 || h > c->height || c->base_radius + k * h < 0.0) continue;
        best = r;
    }
    if (!isfinite(best)) return 0;
    *t = best + shift;
    return 1;
}

int rt_intersect_object(const rt_scene *s, uint32_t index, rt_vec3 o, rt_vec3 d, double t_min, double t_max,
                        rt_hit *hit)
{
    const rt_object *ob = &s->objects[index];
    hit->u = hit->v = 0.0;
    switch (ob->kind) {
    case RT_OBJ_SPHERE: return hit_sphere(&ob->u.sphere, o, d, t_min, t_max, &hit->t);
    case RT_OBJ_POLYGON: return hit_polygon(s, &ob->u.polygon, o, d, t_min, t_max, &hit->t);
    case RT_OBJ_TRIANGLE: return hit_triangle(&ob->u.triangle, o, d, t_min, t_max, hit);
    case RT_OBJ_CONE: return hit_cone(&ob->u.cone, o, d, t_min, t_max, &hit->t);
    }
    return 0;
}

/* The interpolated `pp` normal, computed so that it cannot speckle. The
 * barycentrics are the hit test's own (u, v), so the weights agree with the
 * point that was hit. Vertex normals that nearly cancel (a pole of Haines'
 * teapot: (-0.90, 0, -0.43) beside (0.90, 0, 0.43)) leave a sum whose
 * direction is rounding noise: the face normal shades instead. A sum on the
 * other side of the face is kept, turned to the vertex normals' side: vertex
 * normals lying in the face's plane (the spout of the teapot at size 1 is a
 * flat fin whose normals are the tube's) fall on either side by rounding, and
 * replacing those by the face normal would make them speckle. */
static rt_vec3 patch_normal(const rt_triangle_data *t, const rt_hit *hit)
{
    double w[3] = {fmax(0.0, 1.0 - hit->u - hit->v), fmax(0.0, hit->u), fmax(0.0, hit->v)};
    rt_vec3 n = rt_vec(0, 0, 0);
    for (int k = 0; k < 3; k++) n = rt_vec_add(n, rt_vec_scale(t->n[k], w[k]));
    rt_vec3 face = rt_vec_scale(t->normal, t->side);
    double len = rt_vec_length(n);
    if (!(len > RT_PATCH_MIN_NORMAL * (w[0] + w[1] + w[2]))) return face;
    /* On the vertex normals' side of the face; shading turns it toward the ray. */
    return rt_vec_scale(n, (rt_vec_dot(n, face) < 0.0 ? -1.0 : 1.0) / len);
}

void rt_object_normals(const rt_scene *s, uint32_t index, rt_vec3 p, const rt_hit *hit, rt_vec3 *n_geo,
                       rt_vec3 *n_shade)
{
    const rt_object *ob = &s->objects[index];
    switch (ob->kind) {
    case RT_OBJ_SPHERE:
        *n_geo = rt_vec_normalize(rt_vec_sub(p, ob->u.sphere.center));
        *n_shade = *n_geo;
        return;
    case RT_OBJ_POLYGON:
        *n_geo = ob->u.polygon.normal;
        *n_shade = *n_geo;
        return;
    case RT_OBJ_TRIANGLE:
        *n_geo = ob->u.triangle.normal;
        *n_shade = patch_normal(&ob->u.triangle, hit);
        return;
    case RT_OBJ_CONE: {
        const rt_cone_data *c = &ob->u.cone;
        rt_vec3 cp = rt_vec_sub(p, c->base);
        rt_vec3 radial = rt_vec_sub(cp, rt_vec_scale(c->axis, rt_vec_dot(cp, c->axis)));
        if (rt_vec_is_zero(radial)) {
            /* At the apex of a true cone: any perpendicular will do. */
            rt_vec3 other = fabs(c->axis.x) < 0.9 ? rt_vec(1, 0, 0) : rt_vec(0, 1, 0);
            radial = rt_vec_cross(c->axis, other);
        }
        *n_geo = rt_vec_normalize(rt_vec_sub(rt_vec_normalize(radial), rt_vec_scale(c->axis, c->slope)));
        *n_shade = *n_geo;
        return;
    }
    }
    *n_geo = *n_shade = rt_vec(0, 0, 1);
}
