/* grid_space.c - the object space the grid cuts: the objects' bounding box, padded so that no
 * object touches its faces. */
#include <math.h>

#include "grid_internal.h"
#include "scene_internal.h"

static int box_is_empty(const rt_box *b) { return !(b->lo.x <= b->hi.x && b->lo.y <= b->hi.y && b->lo.z <= b->hi.z); }

static void set_axis(rt_vec3 *v, int a, double x)
{
    if (a == 0) v->x = x;
    else if (a == 1) v->y = x;
    else v->z = x;
}

int rt_grid_objects_box(const rt_scene *s, rt_box *out)
{
    rt_box b = {rt_vec(INFINITY, INFINITY, INFINITY), rt_vec(-INFINITY, -INFINITY, -INFINITY)};
    int any = 0;
    for (size_t o = 0; o < s->object_count; o++) {
        const rt_box *ob = &s->objects[o].bounds;
        if (box_is_empty(ob)) continue;
        any = 1;
        b.lo = rt_vec(fmin(b.lo.x, ob->lo.x), fmin(b.lo.y, ob->lo.y), fmin(b.lo.z, ob->lo.z));
        b.hi = rt_vec(fmax(b.hi.x, ob->hi.x), fmax(b.hi.y, ob->hi.y), fmax(b.hi.z, ob->hi.z));
    }
    *out = b;
    return any;
}

int rt_grid_pad_space(rt_box b, rt_box *out)
{
    if (box_is_empty(&b)) return 0;
    rt_vec3 e = rt_vec_sub(b.hi, b.lo);
    double pad = 1e-6 * hypot(hypot(e.x, e.y), e.z);
    if (!(pad > 0.0)) pad = 1e-6 * fmax(1.0, fmax(rt_vec_max_abs(b.lo), rt_vec_max_abs(b.hi)));
    for (int a = 0; a < 3; a++) {
        double lo = rt_vec_axis(b.lo, a), hi = rt_vec_axis(b.hi, a);
        double plo = lo - pad, phi = hi + pad;
        /* Far from the origin the pad can vanish in rounding: one ulp at least. */
        if (!(plo < lo)) plo = nextafter(lo, -INFINITY);
        if (!(phi > hi)) phi = nextafter(hi, INFINITY);
        set_axis(&out->lo, a, plo);
        set_axis(&out->hi, a, phi);
    }
    return 1;
}

int rt_grid_object_space(const rt_scene *s, rt_box *out)
{
    rt_box raw;
    return rt_grid_objects_box(s, &raw) && rt_grid_pad_space(raw, out);
}
