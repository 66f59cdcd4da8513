// scene_setup.cpp - loading a scene file and building its grid.
#include "scene_setup.h"

#include <cstdio>
#include <new>

#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_nff.h"
#include "rt_shade_tree.h"
#include "rt_text.h"
#include "user_error.h"

namespace torusrt {

namespace {
void print_warning(void *ctx, const char *message)
{
    if (!*static_cast<bool *>(ctx)) std::fprintf(stderr, "%s\n", message);
}
}  // namespace

std::string shown_path(const std::string &path)
{
    std::string buf(4 * path.size() + 8, '\0');
    return rt_escape_bytes(path.data(), path.size(), 0, &buf[0], buf.size());
}

LoadedScene load_scene(const std::string &path, unsigned width, unsigned height, const std::array<int, 3> &cells,
                       bool quiet, rt_budget *budget, rt_preprocess_count count)
{
    char msg[RT_MSG_LEN] = "";
    rt_scene *raw = nullptr;
    bool q = quiet;
    rt_status loaded = rt_nff_load(path.c_str(), &raw, msg, sizeof msg, print_warning, &q);
    if (loaded == RT_ERR_NOMEM) throw std::bad_alloc();  // cli_main's message: the stage and --memory-budget
    if (loaded != RT_OK) throw UserError(msg);
    LoadedScene out;
    out.scene.reset(raw);
    if (width || height) {
        const rt_camera *cam = rt_scene_camera(raw);
        unsigned w = width ? width : cam->width, h = height ? height : cam->height;
        if (rt_scene_set_resolution(raw, w, h) != RT_OK)
            throw UserError("--size " + std::to_string(w) + "x" + std::to_string(h) + ": each side must be 1 to " +
                                std::to_string(RT_SCENE_MAX_RESOLUTION),
                            2);
    }
    const rt_camera *cam = rt_scene_camera(raw);
    std::string fb_what =
        "the frame buffer of " + std::to_string(cam->width) + "x" + std::to_string(cam->height) + " pixels";
    if (rt_budget_reserve(budget, rt_framebuffer_bytes(cam->width, cam->height), fb_what.c_str(), msg, sizeof msg) !=
        RT_OK)
        throw UserError(shown_path(path) + ": " + msg);
    out.grid.reset(rt_grid_new_counted(raw, cells[0], cells[1], cells[2], count, budget, msg, sizeof msg));
    if (!out.grid && std::string(msg).rfind("memory budget", 0) == 0) throw UserError(shown_path(path) + ": " + msg);
    if (!out.grid && std::string(msg).rfind("out of memory", 0) == 0) throw std::bad_alloc();  // cli_main's message
    if (!out.grid) throw UserError(std::string("--cells: ") + msg, 2);
    return out;
}

void check_shade_tree(const std::string &path, const rt_scene *scene, const rt_step_params &step,
                      const rt_budget &budget, uint64_t packet_bytes)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_shade_tree_check(scene, &step, &budget, packet_bytes, msg, sizeof msg) != RT_OK)
        throw UserError(shown_path(path) + ": " + msg);
}

}  // namespace torusrt
