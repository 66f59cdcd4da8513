/* packet.c - primary rays: the camera of docs/design.md section 3. */
#include <math.h>

#include "grid_internal.h"
#include "rt_packet.h"
#include "scene_internal.h"

rt_vec3 rt_primary_direction(const rt_camera *cam, uint32_t x, uint32_t y)
{
    rt_vec3 w = rt_vec_normalize(rt_vec_sub(cam->at, cam->from));
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(w, cam->up));
    rt_vec3 v = rt_vec_cross(u, w);
    uint32_t longest = cam->width > cam->height ? cam->width : cam->height;
    double span = longest > 1 ? (double)(longest - 1) : 1.0;
    /* NFF: the angle spans the centres of the first and last pixel columns. */
    double s = 2.0 * tan(cam->angle * (3.14159265358979323846 / 360.0)) / span;
    double px = ((double)x - (cam->width - 1) * 0.5) * s;
    double py = ((double)y - (cam->height - 1) * 0.5) * s;
    return rt_vec_normalize(rt_vec_sub(rt_vec_add(w, rt_vec_scale(u, px)), rt_vec_scale(v, py)));
}

rt_status rt_primary_packet(const rt_scene *scene, const rt_grid *grid, uint32_t x, uint32_t y, rt_packet *out,
                            int *enters)
{
    const rt_camera *cam = &scene->camera;
    if (x >= cam->width || y >= cam->height) return RT_ERR_INVALID;
    rt_packet p = {0};
    p.origin = cam->from;
    p.dir = rt_primary_direction(cam, x, y);
    p.weight = rt_vec(1, 1, 1);
    p.t_light = INFINITY;
    p.x = x;
    p.y = y;
    p.depth = 0;
    p.kind = RT_PACKET_RAY;
    *enters = rt_dda_start(grid, p.origin, p.dir, 0.0, &p.dda);
    *out = p;
    return RT_OK;
}
