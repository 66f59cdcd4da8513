/* nff_fuzz.c - libFuzzer target: the NFF reader, then the grid build and a tiny render of
 * whatever it accepts. Built with clang -fsanitize=fuzzer,address,undefined by
 * bench/fuzz.sh, and with the normal compiler, beside replay_main.c, for the CTest replay of
 * tests/fuzz/corpus and tests/fuzz/regressions.
 *
 * Sizes are bounded so that no input can run out of memory or time: inputs over 64 KiB are
 * skipped, the grid has 6 x 6 x 6 cells and 32 MiB of memory budget, and a render of 3 x 3
 * pixels at depth 3 runs only for scenes of at most 2000 objects. */
#include <stddef.h>
#include <stdint.h>

#include "rt_budget.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_nff.h"
#include "rt_render.h"

#define FUZZ_MAX_INPUT (64u * 1024u)
#define FUZZ_CELLS 6
#define FUZZ_BUDGET (32u * 1024u * 1024u)
#define FUZZ_MAX_RENDER_OBJECTS 2000u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* A 3 x 3 render at depth 3: shading, intersection and the packet step on the scene. */
static void render_small(rt_scene *scene, const rt_grid *grid, rt_budget *budget)
{
    if (rt_scene_object_count(scene) > FUZZ_MAX_RENDER_OBJECTS) return;
    if (rt_scene_set_resolution(scene, 3, 3) != RT_OK) return;
    rt_framebuffer *fb = rt_framebuffer_new(3, 3);
    if (!fb) return;
    rt_render_options o = rt_render_options_default();
    o.step.max_depth = 3;
    o.budget = budget;
    rt_render_stats st;
    char msg[RT_MSG_LEN];
    rt_render(scene, grid, &o, fb, &st, msg, sizeof msg);
    uint8_t rgb[3 * 3 * 3];
    rt_framebuffer_to_rgb8(fb, rgb);
    rt_framebuffer_free(fb);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > FUZZ_MAX_INPUT) return 0;
    rt_scene *scene = NULL;
    char msg[RT_MSG_LEN];
    if (rt_nff_parse("fuzz.nff", (const char *)data, size, &scene, msg, sizeof msg, NULL, NULL) != RT_OK) return 0;
    rt_budget budget = rt_budget_make(FUZZ_BUDGET);
    rt_grid *grid = rt_grid_new_budget(scene, FUZZ_CELLS, FUZZ_CELLS, FUZZ_CELLS, &budget, msg, sizeof msg);
    if (grid) render_small(scene, grid, &budget);
    rt_grid_free(grid);
    rt_scene_free(scene);
    return 0;
}
