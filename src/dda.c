/* dda.c - 3D-DDA cell walk. Boundary t values are computed from the grid's
 * planes (rt_grid_plane) each time rather than accumulated, so a ray's cell
 * intervals are the same whichever processor walks it. */
#include <math.h>

#include "grid_internal.h"
#include "rt_dda.h"

/* t at which the ray crosses the boundary it meets next along `axis`. */
static double next_boundary(const rt_grid *g, const rt_dda *d, double o, double dir, int axis)
{
    if (d->step[axis] == 0) return INFINITY;
    int k = d->step[axis] > 0 ? d->cell[axis] + 1 : d->cell[axis];
    return (rt_grid_plane(g, axis, k) - o) / dir;
}

int rt_dda_start(const rt_grid *g, rt_vec3 origin, rt_vec3 dir, double t_min, rt_dda *out)
{
    if (g->empty || !rt_vec_is_finite(origin) || !rt_vec_is_finite(dir) || rt_vec_is_zero(dir)) return 0;
    double t_in = t_min, t_out = INFINITY;
    const double o[3] = {origin.x, origin.y, origin.z};
    const double d[3] = {dir.x, dir.y, dir.z};
    for (int a = 0; a < 3; a++) {
        double lo = rt_vec_axis(g->bounds.lo, a), hi = rt_vec_axis(g->bounds.hi, a);
        if (d[a] == 0.0) {
            if (o[a] < lo || o[a] > hi) return 0;
            continue;
        }
        double t0 = (lo - o[a]) / d[a], t1 = (hi - o[a]) / d[a];
        if (t0 > t1) {
            double t = t0;
            t0 = t1;
            t1 = t;
        }
        if (t0 > t_in) t_in = t0;
        if (t1 < t_out) t_out = t1;
    }
    if (!(t_in <= t_out)) return 0;
    rt_dda s;
    s.t_enter = t_in;
    for (int a = 0; a < 3; a++) {
        double lo = rt_vec_axis(g->bounds.lo, a), hi = rt_vec_axis(g->bounds.hi, a);
        /* An axis with no motion keeps the origin's coordinate exactly. */
        double p = d[a] == 0.0 ? o[a] : o[a] + t_in * d[a];
        double f = floor((p - lo) / (hi - lo) * g->dims[a]);
        int c = f < 0.0 ? 0 : f >= g->dims[a] ? g->dims[a] - 1 : (int)f;
        s.cell[a] = c;
        s.step[a] = d[a] > 0.0 ? 1 : d[a] < 0.0 ? -1 : 0;
        s.t_delta[a] = d[a] == 0.0 ? INFINITY : (hi - lo) / g->dims[a] / fabs(d[a]);
    }
    for (int a = 0; a < 3; a++) s.t_next[a] = next_boundary(g, &s, o[a], d[a], a);
    *out = s;
    return 1;
}

int rt_dda_advance(const rt_grid *g, rt_dda *d, rt_vec3 origin, rt_vec3 dir)
{
    int a = 0;
    if (d->t_next[1] < d->t_next[a]) a = 1;
    if (d->t_next[2] < d->t_next[a]) a = 2;
    if (!isfinite(d->t_next[a])) return 0;
    int c = d->cell[a] + d->step[a];
    if (c < 0 || c >= g->dims[a]) return 0;
    d->cell[a] = c;
    /* Rounding may put a boundary a hair before the entry point: keep t monotone. */
    if (d->t_next[a] > d->t_enter) d->t_enter = d->t_next[a];
    d->t_next[a] = next_boundary(g, d, rt_vec_axis(origin, a), rt_vec_axis(dir, a), a);
    return 1;
}
