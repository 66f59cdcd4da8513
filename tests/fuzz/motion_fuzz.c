/* motion_fuzz.c - libFuzzer target: the motion-file reader (rt_motion_parse, what
 * rt_motion_load runs on a file's text), and for an accepted motion on a scene of two spheres,
 * a triangle and a cone: the object space over every frame (at most 64 are checked), every
 * frame inside it, and the incremental update of a 4x3x2 grid equal in size to a fresh build.
 * Built by bench/fuzz.sh with libFuzzer and, beside replay_main.c, for the CTest replay of
 * tests/fuzz/motion_corpus. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "rt_grid.h"
#include "rt_motion.h"
#include "rt_scene.h"

#define FUZZ_MAX_INPUT (64u * 1024u)
#define FUZZ_MAX_FRAMES 64u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static rt_scene *small_scene(void)
{
    rt_scene *s = rt_scene_new();
    if (!s) abort();
    rt_scene_set_view(s, rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 4, 4);
    rt_scene_add_sphere(s, rt_vec(-2, 0, 0), 1);
    rt_scene_add_sphere(s, rt_vec(2, 0, 0), 0.5);
    const rt_vec3 v[3] = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(0, 1, 0)};
    const rt_vec3 n[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    rt_scene_add_patch(s, v, n, 3);
    rt_scene_add_cone(s, rt_vec(0, -1, 0), 0.5, rt_vec(0, -3, 0), 0.2);
    rt_scene_finish(s, NULL, 0);
    return s;
}

static int inside(rt_box a, rt_box b)
{
    return a.lo.x >= b.lo.x && a.lo.y >= b.lo.y && a.lo.z >= b.lo.z && a.hi.x <= b.hi.x && a.hi.y <= b.hi.y &&
           a.hi.z <= b.hi.z;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > FUZZ_MAX_INPUT) return 0;
    char msg[256];
    rt_motion *m = NULL;
    if (rt_motion_parse("fuzz.motion", (const char *)data, size, &m, msg, sizeof msg) != RT_OK) return 0;
    uint32_t frames = rt_motion_frame_count(m);
    if (frames < 1 || frames > RT_MOTION_MAX_FRAMES) abort(); /* an accepted file has a frame count */
    rt_scene *s = small_scene(), *f = rt_scene_clone(s);
    rt_box space;
    uint8_t moved[4];
    rt_grid *g = NULL;
    if (frames <= FUZZ_MAX_FRAMES && rt_motion_space(m, s, &space, msg, sizeof msg) == RT_OK) {
        for (uint32_t k = 0; k < frames; k++) {
            if (rt_motion_apply(m, s, f, k, moved, msg, sizeof msg) != RT_OK) abort(); /* space passed */
            for (size_t o = 0; o < rt_scene_object_count(f); o++) {
                rt_box b = rt_scene_object_bounds(f, o);
                if (b.lo.x <= b.hi.x && !inside(b, space)) abort(); /* no object leaves the space */
            }
            if (!g) g = rt_grid_new_in_space(f, 4, 3, 2, &space, RT_COUNT_SEQUENTIAL, NULL, msg, sizeof msg);
            else if (rt_grid_update(g, f, moved, NULL, NULL, msg, sizeof msg) != RT_OK) abort();
            if (!g) abort();
            rt_grid *fresh = rt_grid_new_in_space(f, 4, 3, 2, &space, RT_COUNT_SEQUENTIAL, NULL, msg, sizeof msg);
            if (!fresh || rt_grid_list_entries(fresh) != rt_grid_list_entries(g) ||
                rt_grid_units_serial(fresh) != rt_grid_units_serial(g))
                abort(); /* the update equals a fresh build */
            rt_grid_free(fresh);
        }
    }
    rt_grid_free(g);
    rt_scene_free(f);
    rt_scene_free(s);
    rt_motion_free(m);
    return 0;
}
