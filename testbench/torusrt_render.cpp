// torusrt_render.cpp - the sequential reference renderer: the golden image for every model run.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "animation_options.h"
#include "cli_main.h"
#include "frame_pattern.h"
#include "kernel_handles.h"
#include "option_parsing.h"
#include "output_files.h"
#include "progress.h"
#include "rt_render.h"
#include "rt_timing.h"
#include "scene_setup.h"
#include "stats_json.h"
#include "cost_image.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

using namespace torusrt;

namespace {

struct RenderOptions {
    std::string scene_path, output_path, stats_path, timing_path, timing_profile, cost_image;
    std::string cells = "24", size, min_weight = "1/512", memory_budget = "4G";
    int max_depth = 8;
    bool brute_force = false, quiet = false;
    AnimationOptions anim;
};

void on_progress(void *ctx, uint64_t done, uint64_t total)
{
    static_cast<Progress *>(ctx)->update(done, total);
}

// One frame's image and counts, rendered with the scene's current camera.
struct FrameResult {
    rt_render_stats st;
    std::vector<uint8_t> rgb;
    double t1_s;
};

// The settings every run shares, prepared once (the grid is built once for every frame).
struct RenderSetup {
    std::array<int, 3> cells;
    double min_weight;
    rt_timing timing;
    std::string profile; // the timing profile's name (or the timing file's)
    rt_budget budget; // outlives every frame: ro.budget points at it
    LoadedScene loaded;
    rt_render_options ro;
};

FrameResult render_frame(RenderSetup &setup, const std::string &label, const RenderOptions &opt,
                         CostImage *cost = nullptr)
{
    const rt_camera *cam = rt_scene_camera(setup.loaded.scene.get());
    FramebufferPtr fb(rt_framebuffer_new(cam->width, cam->height));
    if (!fb)
        throw UserError("out of memory for a " + std::to_string(cam->width) + "x" +
                        std::to_string(cam->height) + " image");
    Progress progress(label, opt.quiet);
    rt_render_options ro = setup.ro;
    ro.progress = on_progress;
    ro.progress_ctx = &progress;
    if (cost) cost->attach(&ro);
    FrameResult fr;
    char msg[RT_MSG_LEN] = "";
    if (rt_render(setup.loaded.scene.get(), setup.loaded.grid.get(), &ro, fb.get(), &fr.st, msg,
                  sizeof msg) != RT_OK)
        throw UserError(shown_path(opt.scene_path) + ": " + msg);
    progress.finish();
    fr.rgb.resize(static_cast<size_t>(cam->width) * cam->height * 3);
    rt_framebuffer_to_rgb8(fb.get(), fr.rgb.data());
    fr.t1_s = rt_timing_step_us(&setup.timing, &fr.st.ops) * 1e-6;
    if (!std::isfinite(fr.t1_s)) throw UserError("T(1) is not a finite time: the timing values are too large");
    return fr;
}

uint64_t rays_of(const rt_render_stats &st)
{
    return st.packets.created[RT_PACKET_RAY] + st.packets.created[RT_PACKET_SHADOW];
}

nlohmann::json stats_json(const RenderOptions &opt, const RenderSetup &setup, const rt_render_stats &st,
                          double t1_s, double wall)
{
    const rt_scene *scene = setup.loaded.scene.get();
    const rt_camera *cam = rt_scene_camera(scene);
    return {{"scene", opt.scene_path},
            {"width", cam->width},
            {"height", cam->height},
            {"cells", setup.cells},
            {"objects", rt_scene_object_count(scene)},
            {"lights", rt_scene_light_count(scene)},
            {"max_depth", opt.max_depth},
            {"min_weight", setup.min_weight},
            {"brute_force", opt.brute_force},
            {"ops", ops_json(st.ops)},
            {"packets", packets_json(st.packets)},
            {"queue_high_water", st.queue_high_water},
            {"preprocess", preprocess_json(setup.loaded.grid.get(), 0)},
            {"t1_s", t1_s},
            {"timing_profile", setup.profile},
            {"packet_bytes_in_memory", sizeof(rt_packet)},
            {"wall_s", wall},
            {"rays_per_s", wall > 0 ? rays_of(st) / wall : 0.0}};
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int run_single(const RenderOptions &opt, RenderSetup &setup, std::chrono::steady_clock::time_point t0)
{
    OutputSet outputs;
    std::string png_path = outputs.add("-o", opt.output_path, opt.scene_path);
    std::string stats_path = opt.stats_path.empty() ? "" : outputs.add("--stats", opt.stats_path, opt.scene_path);
    std::string cost_path = opt.cost_image.empty() ? "" : outputs.add("--cost-image", opt.cost_image, opt.scene_path);
    const rt_camera *cam = rt_scene_camera(setup.loaded.scene.get());
    CostImage cost(opt.cost_image, cam->width, cam->height, &setup.timing);
    FrameResult fr = render_frame(setup, "torusrt-render", opt, &cost);
    double wall = seconds_since(t0);
    nlohmann::json js;
    if (!opt.stats_path.empty()) {
        js = stats_json(opt, setup, fr.st, fr.t1_s, wall);
        js["cost_image"] = cost.json();
    }
    write_png_file(png_path, opt.output_path, cam->width, cam->height, fr.rgb);
    if (!cost_path.empty()) cost.write(cost_path);
    if (!opt.stats_path.empty()) write_text_file(stats_path, opt.stats_path, js.dump(2) + "\n");
    outputs.commit();
    if (!opt.quiet)
        std::printf("%s: %ux%u, %zu objects, %llu packets, T(1) %.3f s (%s timing), wall %.3f s\n",
                    opt.scene_path.c_str(), cam->width, cam->height,
                    rt_scene_object_count(setup.loaded.scene.get()),
                    static_cast<unsigned long long>(rays_of(fr.st)),
                    fr.t1_s, setup.profile.c_str(), wall);
    return 0;
}

// Every frame's PNG (and the statistics) is staged and committed together at the end.
int run_frames(const RenderOptions &opt, RenderSetup &setup, std::chrono::steady_clock::time_point t0)
{
    rt_scene *scene = setup.loaded.scene.get();
    CameraPathPtr path = make_camera_path(opt.anim, scene);
    size_t n = rt_camera_path_count(path.get());
    OutputSet outputs;
    std::vector<std::string> frame_paths;
    for (size_t k = 0; k < n; k++)
        frame_paths.push_back(outputs.add("-o", frame_file_name(opt.output_path, k), opt.scene_path));
    std::string stats_path = opt.stats_path.empty() ? "" : outputs.add("--stats", opt.stats_path, opt.scene_path);
    rt_render_stats total{};
    double t1_total = 0.0;
    nlohmann::json frames = nlohmann::json::array();
    char msg[RT_MSG_LEN] = "";
    for (size_t k = 0; k < n; k++) {
        const rt_camera_pose *pose = rt_camera_path_pose(path.get(), k);
        if (rt_scene_set_camera(scene, pose, msg, sizeof msg) != RT_OK)
            throw UserError("frame " + std::to_string(k) + ": " + msg);
        std::string label = "torusrt-render frame " + std::to_string(k + 1) + "/" + std::to_string(n);
        FrameResult fr = render_frame(setup, label, opt);
        const rt_camera *cam = rt_scene_camera(scene);
        std::string file = frame_file_name(opt.output_path, k);
        write_png_file(frame_paths[k], file, cam->width, cam->height, fr.rgb);
        rt_ops_add(&total.ops, &fr.st.ops);
        for (int kind = 0; kind < RT_PACKET_KINDS; kind++) {
            total.packets.created[kind] += fr.st.packets.created[kind];
            total.packets.consumed[kind] += fr.st.packets.consumed[kind];
        }
        total.packets.forwarded += fr.st.packets.forwarded;
        total.packets.primary_missed += fr.st.packets.primary_missed;
        if (fr.st.queue_high_water > total.queue_high_water) total.queue_high_water = fr.st.queue_high_water;
        t1_total += fr.t1_s;
        frames.push_back({{"index", k}, {"file", file}, {"camera", camera_pose_json(*pose)},
                          {"ops", ops_json(fr.st.ops)}, {"packets", packets_json(fr.st.packets)},
                          {"t1_s", fr.t1_s}});
    }
    double wall = seconds_since(t0);
    if (!opt.stats_path.empty()) {
        nlohmann::json js = stats_json(opt, setup, total, t1_total, wall);
        js["frame_count"] = n;
        js["camera_source"] = opt.anim.orbit.empty() ? "camera-path" : "orbit";
        js["output_pattern"] = opt.output_path;
        js["frames"] = frames;
        write_text_file(stats_path, opt.stats_path, js.dump(2) + "\n");
    }
    outputs.commit();
    if (!opt.quiet)
        std::printf("%s: %zu frames of %ux%u, %zu objects, %llu packets, "
                    "T(1) %.3f s in all (%s timing), wall %.3f s\n",
                    opt.scene_path.c_str(), n, rt_scene_camera(scene)->width, rt_scene_camera(scene)->height,
                    rt_scene_object_count(scene), static_cast<unsigned long long>(rays_of(total)),
                    t1_total, setup.profile.c_str(), wall);
    return 0;
}

int run(RenderOptions &opt)
{
    auto t0 = std::chrono::steady_clock::now();
    RenderSetup setup;
    setup.cells = parse_triple("--cells", opt.cells, 1, RT_GRID_MAX_CELLS_PER_AXIS);
    std::array<unsigned, 2> size{0, 0};
    if (!opt.size.empty()) size = parse_size("--size", opt.size);
    if (opt.max_depth < 0 || opt.max_depth > 1000)
        throw UserError("--max-depth " + std::to_string(opt.max_depth) + ": must be 0 to 1000", 2);
    setup.min_weight = parse_fraction("--min-weight", opt.min_weight);
    check_animation_options(opt.anim);
    if (opt.anim.animated()) check_frame_pattern("-o", opt.output_path);

    if (opt.anim.animated() && !opt.cost_image.empty())
        throw UserError("--cost-image: not available for an animation (one image per run)", 2);

    setup.profile = choose_timing(opt.timing_profile, opt.timing_path, &setup.timing);
    std::string problem = timing_limit_problem(setup.timing);
    if (!problem.empty()) throw UserError((opt.timing_path.empty() ? setup.profile : opt.timing_path) + ": " + problem);
    if (setup.min_weight > 1 && !opt.quiet)
        std::fprintf(stderr, "torusrt-render: warning: --min-weight %g is above 1: every secondary ray is dropped\n",
                     setup.min_weight);

    setup.budget = rt_budget_make(parse_memory_size("--memory-budget", opt.memory_budget));
    setup.loaded = load_scene(opt.scene_path, size[0], size[1], setup.cells, opt.quiet, &setup.budget);
    setup.ro = rt_render_options_default();
    setup.ro.step.max_depth = opt.max_depth;
    setup.ro.step.min_weight = setup.min_weight;
    setup.ro.step.brute_force = opt.brute_force;
    setup.ro.budget = &setup.budget;
    return opt.anim.animated() ? run_frames(opt, setup, t0) : run_single(opt, setup, t0);
}

}  // namespace

int main(int argc, char **argv)
{
    RenderOptions opt;
    CLI::App app{"torusrt-render: the sequential reference renderer (the golden image).\n"
                 "Runs the kernel's packet step over one work queue with one owner for every cell."};
    app.add_option("scene", opt.scene_path, "scene file (NFF, with the 'am' extension)")->required()->type_name("FILE");
    app.add_option("-o,--output", opt.output_path,
                   "PNG image to write; with --frames/--camera-path a pattern like out_%04d.png")
        ->required()
        ->type_name("FILE");
    app.add_option("--cells", opt.cells, "grid cells: N or NXxNYxNZ (default 24)")->type_name("DIMS");
    app.add_option("--size", opt.size, "image size WxH, overriding the scene's resolution")->type_name("WxH");
    app.add_option("--max-depth", opt.max_depth, "deepest shade-tree depth of a ray (default 8)")->type_name("N");
    app.add_option("--min-weight", opt.min_weight, "smallest ray weight, e.g. 1/512 (default)")->type_name("W");
    app.add_option("--memory-budget", opt.memory_budget,
                   "memory the run may use for cell lists, frame buffer and packets, e.g. 512M or 4G; 0 = no limit (default 4G)")->type_name("SIZE");
    app.add_flag("--brute-force", opt.brute_force, "test every object for every ray (the test oracle)");
    app.add_option("--stats", opt.stats_path, "write statistics as JSON to this file")->type_name("FILE");
    app.add_option("--timing", opt.timing_path, "timing file overriding the paper's table (for t1_s)")->type_name("FILE");
    add_animation_options(app, opt.anim);
    // Timing profiles and load pictures.
    app.add_option("--timing-profile", opt.timing_profile,
                   std::string("timing profile: calibrated or literal (default ") + rt_timing_default_profile() + ")")
        ->type_name("NAME");
    app.add_option("--cost-image", opt.cost_image, "write each pixel's modelled microseconds as a heat-map PNG")
        ->type_name("FILE");
    app.add_flag("-q,--quiet", opt.quiet, "print nothing but errors; no progress");
    return run_cli("torusrt-render", app, argc, argv, [&] { return run(opt); });
}
