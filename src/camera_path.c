/* camera_path.c - camera poses, orbit paths and replacing a scene's camera per frame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "camera_path_internal.h"
#include "rt_camera_path.h"

static const double DEG_TO_RAD = 3.14159265358979323846 / 180.0;

rt_camera_pose rt_camera_pose_of(const rt_camera *camera)
{
    rt_camera_pose p = {camera->from, camera->at, camera->up, camera->angle};
    return p;
}

static rt_status pose_fail(char *msg, size_t msg_len, const char *text)
{
    if (msg && msg_len) snprintf(msg, msg_len, "%s", text);
    return RT_ERR_INVALID;
}

rt_status rt_camera_pose_check(const rt_camera_pose *p, char *msg, size_t msg_len)
{
    if (!rt_vec_is_finite(p->from) || !rt_vec_is_finite(p->at) || !rt_vec_is_finite(p->up) || !isfinite(p->angle))
        return pose_fail(msg, msg_len, "camera numbers must be finite");
    if (!(p->angle > 0.0 && p->angle < 180.0))
        return pose_fail(msg, msg_len, "camera angle must be in (0, 180) degrees");
    /* The same tests as rt_scene_finish, so a pose is accepted here exactly when a `v` block
     * with it would be. */
    rt_vec3 w = rt_vec_sub(p->at, p->from);
    double wl = rt_vec_length(w);
    if (!(wl > 0.0) || !isfinite(wl))
        return pose_fail(msg, msg_len, "degenerate camera: 'from' and 'at' are the same point");
    rt_vec3 u = rt_vec_cross(rt_vec_scale(w, 1.0 / wl), rt_vec_normalize(rt_vec_rescaled(p->up)));
    if (!(rt_vec_length(u) > 1e-12))
        return pose_fail(msg, msg_len, "degenerate camera: 'up' is zero or parallel to the view direction");
    return RT_OK;
}

/* Sine and cosine of an angle in degrees, exact at whole multiples of 90 degrees (so a half
 * turn mirrors the eye through the axis exactly). */
static void sincos_deg(double deg, double *s, double *c)
{
    double r = fmod(deg, 360.0);
    if (r < 0.0) r += 360.0;
    double q = floor(r / 90.0);
    double rem = r - q * 90.0;
    double rs = 0.0, rc = 1.0;
    if (rem != 0.0) {
        rs = sin(rem * DEG_TO_RAD);
        rc = cos(rem * DEG_TO_RAD);
    }
    switch ((int)q & 3) {
    case 0:
        *s = rs;
        *c = rc;
        break;
    case 1:
        *s = rc;
        *c = -rs;
        break;
    case 2:
        *s = -rs;
        *c = -rc;
        break;
    default:
        *s = -rc;
        *c = rs;
        break;
    }
}

rt_camera_pose rt_camera_orbit_pose(const rt_camera_pose *start, double degrees, uint32_t frames, uint32_t k)
{
    double s = 0.0, c = 1.0;
    if (frames > 0) sincos_deg((double)k * degrees / (double)frames, &s, &c);
    if (s == 0.0 && c == 1.0) return *start; /* no turn: the start pose bit for bit */
    /* Rodrigues: v' = v cos + (axis x v) sin + axis (axis . v)(1 - cos), v = from - at. */
    rt_vec3 axis = rt_vec_normalize(start->up);
    rt_vec3 v = rt_vec_sub(start->from, start->at);
    rt_vec3 turned = rt_vec_add(rt_vec_add(rt_vec_scale(v, c), rt_vec_scale(rt_vec_cross(axis, v), s)),
                                rt_vec_scale(axis, rt_vec_dot(axis, v) * (1.0 - c)));
    rt_camera_pose p = *start;
    p.from = rt_vec_add(start->at, turned);
    return p; /* `up` is the axis: turning it about itself leaves it as it is */
}

rt_status camera_path_new(size_t count, rt_camera_path **out)
{
    rt_camera_path *path = calloc(1, sizeof *path);
    rt_camera_pose *poses = count ? calloc(count, sizeof *poses) : NULL;
    if (!path || (count && !poses)) {
        free(path);
        free(poses);
        return RT_ERR_NOMEM;
    }
    path->poses = poses;
    path->count = count;
    *out = path;
    return RT_OK;
}

rt_status rt_camera_path_orbit(const rt_camera_pose *start, double degrees, uint32_t frames, rt_camera_path **out,
                               char *msg, size_t msg_len)
{
    *out = NULL;
    if (frames == 0 || frames > RT_CAMERA_PATH_MAX_FRAMES) {
        if (msg && msg_len) snprintf(msg, msg_len, "frames must be 1 to %u", RT_CAMERA_PATH_MAX_FRAMES);
        return RT_ERR_INVALID;
    }
    if (!isfinite(degrees)) return pose_fail(msg, msg_len, "orbit degrees must be finite");
    rt_status st = rt_camera_pose_check(start, msg, msg_len);
    if (st != RT_OK) return st;
    rt_camera_path *path;
    if (camera_path_new(frames, &path) != RT_OK) {
        pose_fail(msg, msg_len, "out of memory");
        return RT_ERR_NOMEM;
    }
    for (uint32_t k = 0; k < frames; k++) path->poses[k] = rt_camera_orbit_pose(start, degrees, frames, k);
    *out = path;
    return RT_OK;
}

size_t rt_camera_path_count(const rt_camera_path *path) { return path ? path->count : 0; }

const rt_camera_pose *rt_camera_path_pose(const rt_camera_path *path, size_t k)
{
    return path && k < path->count ? &path->poses[k] : NULL;
}

void rt_camera_path_free(rt_camera_path *path)
{
    if (!path) return;
    free(path->poses);
    free(path);
}

rt_status rt_scene_set_camera(rt_scene *scene, const rt_camera_pose *pose, char *msg, size_t msg_len)
{
    rt_status st = rt_camera_pose_check(pose, msg, msg_len);
    if (st != RT_OK) return st;
    const rt_camera *cam = rt_scene_camera(scene);
    st = rt_scene_set_view(scene, pose->from, pose->at, pose->up, pose->angle, cam->width, cam->height);
    if (st != RT_OK) return pose_fail(msg, msg_len, "camera rejected by the scene");
    return RT_OK;
}
