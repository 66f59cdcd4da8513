/* polygon_inside.c - even-odd crossing test: concave and self-crossing polygons work. One
 * function serves hits and cell lists so both always agree on what is inside. */
#include "polygon_inside.h"

#include <math.h>

int rt_dominant_axis(rt_vec3 n)
{
    double ax = fabs(n.x), ay = fabs(n.y), az = fabs(n.z);
    if (ax >= ay && ax >= az) return 0;
    return ay >= az ? 1 : 2;
}

int rt_polygon_inside(const rt_vec3 *v, size_t n, int drop, rt_vec3 p)
{
    int ia = drop == 0 ? 1 : 0, ib = drop == 2 ? 1 : 2;
    double px = rt_vec_axis(p, ia), py = rt_vec_axis(p, ib);
    int inside = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        double xi = rt_vec_axis(v[i], ia), yi = rt_vec_axis(v[i], ib);
        double xj = rt_vec_axis(v[j], ia), yj = rt_vec_axis(v[j], ib);
        if ((yi > py) != (yj > py)) {
            double x = xi + (py - yi) / (yj - yi) * (xj - xi);
            if (px < x) inside = !inside;
        }
    }
    return inside;
}
