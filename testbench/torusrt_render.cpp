// torusrt_render.cpp - the sequential reference renderer: the golden image for every model run.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_main.h"
#include "kernel_handles.h"
#include "option_parsing.h"
#include "output_files.h"
#include "progress.h"
#include "rt_render.h"
#include "rt_timing.h"
#include "scene_setup.h"
#include "stats_json.h"
#include "timing_choice.h"
#include "cost_image.h"
#include "user_error.h"

using namespace torusrt;

namespace {

struct RenderOptions {
    std::string scene_path, output_path, stats_path, timing_path, timing_profile, cost_image;
    std::string cells = "24", size, min_weight = "1/512";
    int max_depth = 8;
    bool brute_force = false, quiet = false;
};

void on_progress(void *ctx, uint64_t done, uint64_t total)
{
    static_cast<Progress *>(ctx)->update(done, total);
}

int run(const RenderOptions &opt)
{
    auto t0 = std::chrono::steady_clock::now();
    auto cells = parse_triple("--cells", opt.cells, 1, RT_GRID_MAX_CELLS_PER_AXIS);
    std::array<unsigned, 2> size{0, 0};
    if (!opt.size.empty()) size = parse_size("--size", opt.size);
    if (opt.max_depth < 0 || opt.max_depth > 1000)
        throw UserError("--max-depth " + std::to_string(opt.max_depth) + ": must be 0 to 1000", 2);
    double min_weight = parse_fraction("--min-weight", opt.min_weight);
    check_output_folder("-o", opt.output_path);
    if (!opt.cost_image.empty()) check_output_folder("--cost-image", opt.cost_image);
    if (!opt.stats_path.empty()) check_output_folder("--stats", opt.stats_path);

    rt_timing timing;
    std::string profile = choose_timing(opt.timing_profile, opt.timing_path, &timing);
    char msg[RT_MSG_LEN] = "";

    LoadedScene loaded = load_scene(opt.scene_path, size[0], size[1], cells, opt.quiet);
    const rt_camera *cam = rt_scene_camera(loaded.scene.get());
    FramebufferPtr fb(rt_framebuffer_new(cam->width, cam->height));
    if (!fb) throw UserError("out of memory for a " + std::to_string(cam->width) + "x" + std::to_string(cam->height) + " image");

    rt_render_options ro = rt_render_options_default();
    ro.step.max_depth = opt.max_depth;
    ro.step.min_weight = min_weight;
    ro.step.brute_force = opt.brute_force;
    Progress progress("torusrt-render", opt.quiet);
    ro.progress = on_progress;
    ro.progress_ctx = &progress;
    CostImage cost(opt.cost_image, cam->width, cam->height, &timing);
    cost.attach(&ro);
    rt_render_stats st;
    if (rt_render(loaded.scene.get(), loaded.grid.get(), &ro, fb.get(), &st, msg, sizeof msg) != RT_OK)
        throw UserError(opt.scene_path + ": " + msg);
    progress.finish();

    std::vector<uint8_t> rgb(static_cast<size_t>(cam->width) * cam->height * 3);
    rt_framebuffer_to_rgb8(fb.get(), rgb.data());
    double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double t1_s = rt_timing_step_us(&timing, &st.ops) * 1e-6;
    uint64_t rays = st.packets.created[RT_PACKET_RAY] + st.packets.created[RT_PACKET_SHADOW];

    nlohmann::json js;
    if (!opt.stats_path.empty()) {
        js = {{"scene", opt.scene_path},
              {"width", cam->width},
              {"height", cam->height},
              {"cells", cells},
              {"objects", rt_scene_object_count(loaded.scene.get())},
              {"lights", rt_scene_light_count(loaded.scene.get())},
              {"max_depth", opt.max_depth},
              {"min_weight", min_weight},
              {"brute_force", opt.brute_force},
              {"ops", ops_json(st.ops)},
              {"packets", packets_json(st.packets)},
              {"queue_high_water", st.queue_high_water},
              {"preprocess", preprocess_json(loaded.grid.get(), 0)},
              {"t1_s", t1_s},
              {"timing_profile", profile},
              {"cost_image", cost.json()},
              {"packet_bytes_in_memory", sizeof(rt_packet)},
              {"wall_s", wall},
              {"rays_per_s", wall > 0 ? rays / wall : 0.0}};
    }
    write_png_file(opt.output_path, cam->width, cam->height, rgb);
    try {
        cost.write();
        if (!opt.stats_path.empty()) write_text_file(opt.stats_path, js.dump(2) + "\n");
    } catch (...) {
        remove_file(opt.output_path);
        if (!opt.cost_image.empty()) remove_file(opt.cost_image);
        throw;
    }
    if (!opt.quiet)
        std::printf("%s: %ux%u, %zu objects, %llu packets, T(1) %.3f s (%s timing), wall %.3f s\n",
                    opt.scene_path.c_str(), cam->width, cam->height,
                    rt_scene_object_count(loaded.scene.get()), static_cast<unsigned long long>(rays), t1_s, profile.c_str(), wall);
    return 0;
}

}  // namespace

int main(int argc, char **argv)
{
    RenderOptions opt;
    CLI::App app{"torusrt-render: the sequential reference renderer (the golden image).\n"
                 "Runs the kernel's packet step over one work queue with one owner for every cell."};
    app.add_option("scene", opt.scene_path, "scene file (NFF, with the 'am' extension)")->required();
    app.add_option("-o,--output", opt.output_path, "PNG image to write")->required();
    app.add_option("--cells", opt.cells, "grid cells: N or NXxNYxNZ (default 24)");
    app.add_option("--size", opt.size, "image size WxH, overriding the scene's resolution");
    app.add_option("--max-depth", opt.max_depth, "deepest shade-tree depth of a ray (default 8)");
    app.add_option("--min-weight", opt.min_weight, "smallest ray weight, e.g. 1/512 (default)");
    app.add_flag("--brute-force", opt.brute_force, "test every object for every ray (the test oracle)");
    app.add_option("--stats", opt.stats_path, "write statistics as JSON to this file");
    app.add_option("--timing", opt.timing_path, "timing file overriding the paper's table (for t1_s)");
    app.add_flag("-q,--quiet", opt.quiet, "print nothing but errors; no progress");
    // Timing profiles and load pictures.
    app.add_option("--timing-profile", opt.timing_profile,
                   std::string("timing profile: calibrated or literal (default ") + rt_timing_default_profile() + ")");
    app.add_option("--cost-image", opt.cost_image, "write each pixel's modelled microseconds as a heat-map PNG");
    return run_cli("torusrt-render", app, argc, argv, [&] { return run(opt); });
}
