// torusrt_render.cpp - the sequential reference renderer: the golden image for every model run.
#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animation_options.h"
#include "cli_main.h"
#include "common_options.h"
#include "frame_pattern.h"
#include "kernel_handles.h"
#include "option_registration.h"
#include "output_files.h"
#include "progress.h"
#include "rt_budget.h"
#include "rt_render.h"
#include "rt_timing.h"
#include "run_stage.h"
#include "motion_options.h"
#include "scene_motion.h"
#include "scene_setup.h"
#include "setting_checks.h"
#include "signal_cleanup.h"
#include "stats_json.h"
#include "cost_image.h"
#include "user_error.h"

using namespace torusrt;

namespace {

struct RenderOptions {
    CommonOptions common;  // scene, -o, --stats, cells, size, step limits, memory, timing, -q
    std::string cost_image;
    bool brute_force = false;
    AnimationOptions anim;
};

void on_progress(void *ctx, uint64_t done, uint64_t total) { static_cast<Progress *>(ctx)->update(done, total); }

// One frame's image and counts, rendered with the scene's current camera.
struct FrameResult {
    rt_render_stats st;
    std::vector<uint8_t> rgb;
    double t1_s;
};

// The settings every run shares, prepared once (the grid is built once for every frame, or,
// with --motion, over every frame's object space and updated frame by frame).
struct RenderSetup {
    CommonSettings settings;  // cells, step limits, timing
    rt_budget budget;         // outlives every frame: ro.budget points at it
    LoadedScene loaded;
    std::unique_ptr<SceneMotion> motion;  // --motion: owns the scene file's objects and the frame's copy
    rt_scene *scene = nullptr;            // what is rendered: the scene, or the motion's frame copy
    rt_render_options ro;
};

FrameResult render_frame(RenderSetup &setup, const std::string &label, const RenderOptions &opt,
                         CostImage *cost = nullptr)
{
    const rt_camera *cam = rt_scene_camera(setup.scene);
    FramebufferPtr fb(rt_framebuffer_new(cam->width, cam->height));
    if (!fb)
        throw UserError("out of memory for a " + std::to_string(cam->width) + "x" + std::to_string(cam->height) +
                        " image");
    Progress progress(label, ProgressSettings{opt.common.quiet, 0, false});
    rt_render_options ro = setup.ro;
    ro.progress = on_progress;
    ro.progress_ctx = &progress;
    if (cost) cost->attach(&ro);
    FrameResult fr;
    char msg[RT_MSG_LEN] = "";
    if (rt_render(setup.scene, setup.loaded.grid.get(), &ro, fb.get(), &fr.st, msg, sizeof msg) != RT_OK)
        throw UserError(shown_path(opt.common.scene) + ": " + msg);
    progress.finish();
    fr.rgb.resize(static_cast<size_t>(cam->width) * cam->height * 3);
    rt_framebuffer_to_rgb8(fb.get(), fr.rgb.data());
    fr.t1_s = rt_timing_step_us(&setup.settings.timing, &fr.st.ops) * 1e-6;
    if (!std::isfinite(fr.t1_s)) throw UserError("T(1) is not a finite time: the timing values are too large");
    return fr;
}

uint64_t rays_of(const rt_render_stats &st)
{
    return st.packets.created[RT_PACKET_RAY] + st.packets.created[RT_PACKET_SHADOW];
}

nlohmann::json stats_json(const RenderOptions &opt, const RenderSetup &setup, const rt_render_stats &st, double t1_s,
                          double wall)
{
    const rt_scene *scene = setup.scene;
    const rt_camera *cam = rt_scene_camera(scene);
    return {{"scene", opt.common.scene},
            {"width", cam->width},
            {"height", cam->height},
            {"cells", setup.settings.cells},
            {"objects", rt_scene_object_count(scene)},
            {"lights", rt_scene_light_count(scene)},
            {"max_depth", setup.settings.step.max_depth},
            {"min_weight", setup.settings.step.min_weight},
            {"brute_force", opt.brute_force},
            {"ops", ops_json(st.ops)},
            {"packets", packets_json(st.packets)},
            {"queue_high_water", st.queue_high_water},
            {"preprocess", preprocess_json(setup.loaded.grid.get(), 0)},
            {"t1_s", t1_s},
            {"timing_profile", setup.settings.timing_label},
            {"packet_bytes_in_memory", sizeof(rt_packet)},
            {"wall_s", wall},
            {"rays_per_s", wall > 0 ? rays_of(st) / wall : 0.0}};
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Every output of the run (every frame's included), registered and checked against the inputs
// and each other before the scene is read.
struct RenderOutputs {
    OutputSet set;
    OutputSet::Id png = 0;  // the image, or frame 0 (the frames' ids follow it)
    std::optional<OutputSet::Id> stats, cost;
};

void stage_outputs(const RenderOptions &opt, size_t frames, RenderOutputs &outs)
{
    if (!opt.anim.animated()) outs.png = outs.set.add("-o", opt.common.output);
    for (size_t k = 0; k < frames; k++) {
        OutputSet::Id id = outs.set.add("-o", frame_file_name(opt.common.output, k));
        if (k == 0) outs.png = id;
    }
    if (!opt.common.stats.empty()) outs.stats = outs.set.add("--stats", opt.common.stats);
    if (!opt.cost_image.empty()) outs.cost = outs.set.add("--cost-image", opt.cost_image);
    outs.set.add_input("scene", opt.common.scene);
    outs.set.add_input("--timing", opt.common.timing_file);
    outs.set.add_input("--camera-path", opt.anim.camera_path);
    outs.set.add_input("--motion", opt.anim.motion);
    outs.set.check();
    if (outs.set.writes_stream(1) && !opt.common.quiet)  // the summary would follow the file on the stream
        throw UserError("an output on standard output needs -q: the summary is written there too", 2);
    if (outs.set.writes_stream(2) && !opt.common.quiet)  // warnings and notes would come before the file on the stream
        throw UserError("an output on standard error needs -q: warnings and notes are written there too", 2);
}

// An animation's frame record in memory, its staged file with its signal-cleanup entry, and with
// --stats its JSON object, per frame: measured as the growth of the peak resident size from 2000
// to 20000 frames of 1x1 (4.2 KiB, and 5.5 KiB more with --stats), rounded up; the file names
// are counted apart.
constexpr uint64_t kFrameRecordBytes = 5120;
constexpr uint64_t kFrameReportBytes = 6144;

// Holds an animation's frame records (and their JSON with --stats) from the memory budget before
// the first frame, so that frames that cannot fit are refused at once (docs/memory.md).
void reserve_frame_records(const RenderOptions &opt, const RenderOutputs &outs, size_t frames, rt_budget &budget)
{
    if (!opt.anim.animated()) return;
    bool report = !opt.common.stats.empty();
    uint64_t name_bytes = 0;
    for (size_t k = 0; k < frames; k++) name_bytes += outs.set.path(outs.png + k).size();
    uint64_t bytes = frames * (kFrameRecordBytes + (report ? kFrameReportBytes : 0)) + (report ? 3 : 1) * name_bytes;
    std::string what =
        "the records of " + std::to_string(frames) + " frames" + (report ? " and their JSON (--stats)" : "");
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&budget, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(msg);
}

// The report's text: a file name that is not UTF-8 has its bytes shown as U+FFFD, rather than
// failing the run at its end.
std::string json_text(const nlohmann::json &js)
{
    return js.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

int run_single(const RenderOptions &opt, RenderSetup &setup, RenderOutputs &outs,
               std::chrono::steady_clock::time_point t0)
{
    OutputSet &outputs = outs.set;
    const rt_camera *cam = rt_scene_camera(setup.scene);
    if (!opt.cost_image.empty()) {  // from what the frame buffer and cell lists left (docs/memory.md)
        std::string what =
            "the --cost-image of " + std::to_string(cam->width) + "x" + std::to_string(cam->height) + " pixels";
        char msg[RT_MSG_LEN] = "";
        if (rt_budget_reserve(&setup.budget, CostImage::bytes(cam->width, cam->height), what.c_str(), msg,
                              sizeof msg) != RT_OK)
            throw UserError(msg);
    }
    CostImage cost(opt.cost_image, cam->width, cam->height, &setup.settings.timing);
    set_run_stage("rendering the image");
    FrameResult fr = render_frame(setup, "torusrt-render", opt, &cost);
    double wall = seconds_since(t0);
    nlohmann::json js;
    if (!opt.common.stats.empty()) {
        js = stats_json(opt, setup, fr.st, fr.t1_s, wall);
        js["cost_image"] = cost.json();
    }
    set_run_stage("writing the outputs");
    write_png_file(outputs.staged(outs.png), opt.common.output, cam->width, cam->height, fr.rgb);
    if (outs.cost) cost.write(outputs.staged(*outs.cost));
    if (outs.stats) write_text_file(outputs.staged(*outs.stats), opt.common.stats, json_text(js));
    outputs.commit();
    if (!opt.common.quiet)
        std::printf("%s: %ux%u, %zu objects, %llu packets, T(1) %.3f s (%s timing), wall %.3f s\n",
                    opt.common.scene.c_str(), cam->width, cam->height, rt_scene_object_count(setup.scene),
                    static_cast<unsigned long long>(rays_of(fr.st)), fr.t1_s, setup.settings.timing_label.c_str(),
                    wall);
    if (!opt.common.quiet) {
        std::printf("  wrote        %s", opt.common.output.c_str());
        for (const std::string *f : {&opt.common.stats, &opt.cost_image})
            if (!f->empty()) std::printf(", %s", f->c_str());
        std::printf("\n");
    }
    return 0;
}

// Adds one frame's counts to the run's.
void add_frame_stats(rt_render_stats &total, const rt_render_stats &st)
{
    rt_ops_add(&total.ops, &st.ops);
    for (int kind = 0; kind < RT_PACKET_KINDS; kind++) {
        total.packets.created[kind] += st.packets.created[kind];
        total.packets.consumed[kind] += st.packets.consumed[kind];
    }
    total.packets.forwarded += st.packets.forwarded;
    total.packets.primary_missed += st.packets.primary_missed;
    if (st.queue_high_water > total.queue_high_water) total.queue_high_water = st.queue_high_water;
}

// Moves the scene to frame k (with --motion): its objects, then its cell lists; the cost in `sum`.
nlohmann::json move_scene(RenderSetup &setup, size_t k, MotionFrameCost &sum)
{
    if (!setup.motion) return nullptr;
    const std::array<int, 3> &c = setup.settings.cells;
    const int cells[3] = {c[0], c[1], c[2]};
    MotionFrameCost cost = setup.motion->move_to(static_cast<uint32_t>(k), setup.loaded.grid, cells,
                                                 setup.settings.preprocess_count, &setup.budget);
    sum.objects_moved += cost.objects_moved;
    sum.update_units += cost.update_units;
    sum.rebuild_units += cost.rebuild_units;
    return motion_frame_json(cost);
}

// The run's motion for the JSON report: the file and entries, and the units summed over frames.
nlohmann::json motion_json(const RenderSetup &setup, const MotionFrameCost &sum)
{
    nlohmann::json js = setup.motion->json();
    js["objects_moved"] = sum.objects_moved;
    js["update_units"] = sum.update_units;
    js["rebuild_units"] = sum.rebuild_units;
    return js;
}

// Every frame's PNG (and the statistics) is staged and committed together at the end.
int run_frames(const RenderOptions &opt, RenderSetup &setup, RenderOutputs &outs, CameraPathPtr file,
               std::chrono::steady_clock::time_point t0)
{
    rt_scene *scene = setup.scene;
    CameraPathPtr path = make_camera_path(opt.anim, scene, std::move(file));  // null: the camera stays
    size_t n = animation_frame_count(opt.anim, path.get());
    OutputSet &outputs = outs.set;
    rt_render_stats total{};
    MotionFrameCost moved{};
    double t1_total = 0.0;
    nlohmann::json frames = nlohmann::json::array();
    char msg[RT_MSG_LEN] = "";
    for (size_t k = 0; k < n; k++) {
        if (path && rt_scene_set_camera(scene, rt_camera_path_pose(path.get(), k), msg, sizeof msg) != RT_OK)
            throw UserError("frame " + std::to_string(k) + ": " + msg);
        nlohmann::json motion = move_scene(setup, k, moved);
        std::string label = "torusrt-render frame " + std::to_string(k + 1) + "/" + std::to_string(n);
        set_run_stage("rendering frame " + std::to_string(k));
        FrameResult fr = render_frame(setup, label, opt);
        const rt_camera *cam = rt_scene_camera(scene);
        const std::string &file = outputs.path(outs.png + k);
        write_png_file(outputs.staged(outs.png + k), file, cam->width, cam->height, fr.rgb);
        add_frame_stats(total, fr.st);
        t1_total += fr.t1_s;
        frames.push_back({{"index", k},
                          {"file", file},
                          {"camera", camera_pose_json(rt_camera_pose_of(cam))},
                          {"ops", ops_json(fr.st.ops)},
                          {"packets", packets_json(fr.st.packets)},
                          {"t1_s", fr.t1_s}});
        if (setup.motion) frames.back()["motion"] = motion;
    }
    double wall = seconds_since(t0);
    if (!opt.common.stats.empty()) {
        nlohmann::json js = stats_json(opt, setup, total, t1_total, wall);
        js["frame_count"] = n;
        js["camera_source"] = !opt.anim.orbit.empty() ? "orbit" : path ? "camera-path" : "scene";
        if (setup.motion) js["motion"] = motion_json(setup, moved);
        js["output_pattern"] = opt.common.output;
        js["frames"] = frames;
        write_text_file(outputs.staged(*outs.stats), opt.common.stats, json_text(js));
    }
    outputs.commit();
    if (!opt.common.quiet)
        std::printf("%s: %zu frames of %ux%u, %zu objects, %llu packets, "
                    "T(1) %.3f s in all (%s timing), wall %.3f s\n",
                    opt.common.scene.c_str(), n, rt_scene_camera(scene)->width, rt_scene_camera(scene)->height,
                    rt_scene_object_count(scene), static_cast<unsigned long long>(rays_of(total)), t1_total,
                    setup.settings.timing_label.c_str(), wall);
    if (!opt.common.quiet && setup.motion)
        std::printf("  motion       %llu objects moved, %llu preprocessing units updating the lists "
                    "(%llu rebuilding them every frame)\n",
                    static_cast<unsigned long long>(moved.objects_moved),
                    static_cast<unsigned long long>(moved.update_units),
                    static_cast<unsigned long long>(moved.rebuild_units));
    if (!opt.common.quiet) {
        std::printf("  wrote        %zu frames %s", n, opt.common.output.c_str());
        if (!opt.common.stats.empty()) std::printf(", %s", opt.common.stats.c_str());
        std::printf("\n");
    }
    return 0;
}

// Every check of the options, before the scene is read (UserError, exit 2).
void validate_render(const CommonSettings &settings, RenderOptions &opt)
{
    check_cells(settings.cells);
    check_image_size("--size", settings.size[0], settings.size[1]);
    check_step_limits(settings.step);
    check_animation_options(opt.anim);
    if (opt.anim.animated()) check_frame_pattern("-o", opt.common.output);
    if (opt.anim.animated() && !opt.cost_image.empty())
        throw UserError("--cost-image: not available for an animation (one image per run)", 2);
}

int run(RenderOptions &opt)
{
    auto t0 = std::chrono::steady_clock::now();
    require_scene_and_output(opt.common);
    RenderSetup setup;
    setup.settings = parse_common_options(opt.common);
    MotionPtr motion = read_motion_file(opt.anim.motion);
    take_motion_frame_count(opt.anim, motion.get());
    validate_render(setup.settings, opt);
    warn_about_settings("torusrt-render", setup.settings.step, opt.common.quiet);
    CameraPathPtr file = read_camera_path_file(opt.anim);
    if (motion) check_motion_frames(opt.anim, motion.get(), file.get());
    RenderOutputs outs;
    size_t frames = opt.anim.animated() ? animation_frame_count(opt.anim, file.get()) : 0;
    stage_outputs(opt, frames, outs);

    set_run_stage("loading the scene and building its cell lists");
    setup.budget = rt_budget_make(setup.settings.memory_bytes);
    reserve_frame_records(opt, outs, frames, setup.budget);
    // With --motion the grid is built over every frame's object space at frame 0: the scene's own
    // is then one cell, so that it takes next to nothing of the memory budget.
    const std::array<int, 3> one_cell = {1, 1, 1};
    setup.loaded = load_scene(opt.common.scene, setup.settings.size[0], setup.settings.size[1],
                              motion ? one_cell : setup.settings.cells, opt.common.quiet, &setup.budget,
                              setup.settings.preprocess_count);
    setup.scene = setup.loaded.scene.get();
    if (motion) {
        setup.motion = std::make_unique<SceneMotion>(std::move(motion), std::move(setup.loaded.scene), opt.anim.motion,
                                                     opt.common.quiet);
        setup.scene = setup.motion->frame_scene();
    }
    check_shade_tree(opt.common.scene, setup.scene, setup.settings.step, setup.budget, sizeof(rt_packet));
    setup.ro = rt_render_options_default();
    setup.ro.step = setup.settings.step;
    setup.ro.step.brute_force = opt.brute_force;
    setup.ro.budget = &setup.budget;
    return opt.anim.animated() ? run_frames(opt, setup, outs, std::move(file), t0) : run_single(opt, setup, outs, t0);
}

// The renderer's own options.
std::vector<OptionSpec> render_option_specs()
{
    return {{"--brute-force", "", ValueKind::flag, "", 0, 0, "", "test every object for every ray (the test oracle)",
             OptionGroup::workload, ""},
            {"--cost-image", "FILE", ValueKind::file, "", 0, 0, "",
             "write each pixel's modelled microseconds as a heat-map PNG", OptionGroup::outputs, ""}};
}

void declare_options(CLI::App &app)
{
    const std::string output_help =
        "PNG image to write; with --frames/--camera-path/--motion a pattern like out_%04d.png";
    add_common_options(app, output_help, {"scene", "--size"});
    add_spec_option(app, render_option_specs()[0]);
    add_common_options(
        app, output_help,
        {"--cells", "--max-depth", "--min-weight", "--timing-profile", "--timing", "--preprocess-count"});
    add_common_options(app, output_help, {"--output", "--stats"});
    add_spec_option(app, render_option_specs()[1]);
    for (const OptionSpec &spec : animation_option_specs()) add_spec_option(app, spec);
    add_spec_option(app, motion_option_spec());
    add_common_options(app, output_help, {"--memory-budget", "--quiet"});
    set_help_layout(
        app, "Usage: torusrt-render SCENE -o FILE [OPTIONS]", "A bare number is decimal: 010 and 0x10 are refused.",
        "  torusrt-render scenes/paper-image1.nff -o ref.png\n"
        "  torusrt-render scenes/paper-image2.nff -o ref.png --size 64x64 --stats ref.json\n"
        "  torusrt-render scenes/bouncing-balls.nff -o 'b_%02d.png' --motion scenes/bouncing-balls.motion\n");
}

}  // namespace

int main(int argc, char **argv)
{
    stop_on_signals("torusrt-render");  // before anything else: an early signal gets the message
    RenderOptions opt;
    CLI::App app{"torusrt-render: the sequential reference renderer (the golden image).\n"
                 "Runs the kernel's packet step over one work queue with one owner for every cell."};
    declare_options(app);
    return run_cli("torusrt-render", app, argc, argv, [&] {
        std::map<std::string, std::string> given = given_options(app);
        opt.common = common_options_given(given);
        opt.anim = animation_options_given(given);
        opt.brute_force = given.count("--brute-force") > 0;
        if (given.count("--cost-image")) opt.cost_image = given["--cost-image"];
        return run(opt);
    });
}
