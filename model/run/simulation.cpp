// simulation.cpp - one invocation: outputs staged, scene loaded and mapped, frames run, files
// committed together.
#include "simulation.h"

#include <array>
#include <cstdio>
#include <memory>
#include <optional>

#include "frame_report.h"
#include "mapping.h"
#include "mapping_setup.h"
#include "model_run.h"
#include "output_files.h"
#include "packet_pool.h"
#include "run_frames.h"
#include "run_stage.h"
#include "scene_setup.h"
#include "user_error.h"

namespace torusrt {

namespace {

// Every output of the run (every frame's included), registered and checked against the inputs
// and each other before the scene is read.
struct StagedOutputs {
    OutputSet set;
    std::optional<OutputSet::Id> png, stats, write_map, load_map, frames_csv, series;
    OutputSet::Id first_frame = 0;  // frame k is first_frame + k
};

// --stats-series, or X.series.csv beside --stats X.json (a stream or device has no "beside").
std::string series_path(const SimRequest &r, bool stats_special)
{
    if (r.config.stats_interval_s <= 0) throw UserError("--stats-series: only with --stats-interval", 2);
    if (!r.stats_series.empty()) return r.stats_series;
    if (r.stats.empty() || stats_special)
        throw UserError("--stats-interval: give --stats-series FILE (or --stats X.json, for X.series.csv)", 2);
    const std::string ext = ".json";
    bool has_ext = r.stats.size() > ext.size() && r.stats.compare(r.stats.size() - ext.size(), ext.size(), ext) == 0;
    return (has_ext ? r.stats.substr(0, r.stats.size() - ext.size()) : r.stats) + ".series.csv";
}

void stage_outputs(SimRequest &r, StagedOutputs &out)
{
    SimConfig &config = r.config;
    if (!r.animated()) out.png = out.set.add("-o", r.image);
    for (size_t k = 0; k < r.frame_files.size(); k++) {
        OutputSet::Id id = out.set.add("-o", r.frame_files[k]);
        if (k == 0) out.first_frame = id;
    }
    if (!r.stats.empty()) out.stats = out.set.add("--stats", r.stats);
    std::optional<OutputSet::Id> vcd, gtkw;
    if (!config.vcd_path.empty()) {
        vcd = out.set.add("--vcd", config.vcd_path);
        if (!out.set.special(*vcd)) {  // no save file beside /dev/null
            config.gtkw_path = save_file_path(config.vcd_path);
            gtkw = out.set.add("--vcd (save file)", config.gtkw_path);
        }
    }
    if (!config.write_map.empty()) out.write_map = out.set.add("--write-map", config.write_map);
    if (!r.load_map.empty()) out.load_map = out.set.add("--load-map", r.load_map);
    if (!r.frames_csv.empty()) out.frames_csv = out.set.add("--frames-csv", r.frames_csv);
    if (config.stats_interval_s > 0 || !r.stats_series.empty()) {
        r.stats_series = series_path(r, out.stats ? out.set.special(*out.stats) : false);
        out.series = out.set.add("--stats-series", r.stats_series);
    }
    for (const auto &input : r.inputs) out.set.add_input(input.first, input.second);
    out.set.check();
    if (out.set.writes_stream(1) && !config.quiet)  // the summary would follow the file on the stream
        throw UserError("an output on standard output needs -q: the summary is written there too", 2);
    if (out.set.writes_stream(2) && !config.quiet)  // warnings and notes would come before the file on the stream
        throw UserError("an output on standard error needs -q: warnings and notes are written there too", 2);
    config.stderr_is_output = out.set.writes_stream(2);
    if (vcd) config.vcd_write_path = out.set.staged(*vcd);
    if (gtkw) config.gtkw_write_path = out.set.staged(*gtkw);
}

// The summary's last line: every output written, FIRST (the image or the frames) first.
void print_written(const SimRequest &r, const std::string &first)
{
    std::printf("  wrote        %s", first.c_str());
    for (const std::string *path :
         {&r.stats, &r.stats_series, &r.frames_csv, &r.config.write_map, &r.load_map, &r.config.vcd_path})
        if (!path->empty()) std::printf(", %s", path->c_str());
    if (!r.config.gtkw_path.empty()) std::printf(" (gtkwave %s)", r.config.gtkw_path.c_str());
    std::printf("\n");
}

void report_deadlock(const SimConfig &config, double sim_time_s, const std::string &details)
{
    std::fprintf(stderr,
                 "torusrt-sim: deadlock: the network stalled at %.6f s simulated with packets still "
                 "outstanding (queue capacity %u)\n%s",
                 sim_time_s, config.queue_capacity, details.c_str());
}

void write_stats(StagedOutputs &outputs, const SimRequest &r, const RunReport &report)
{
    if (!outputs.stats) return;
    // The tree is freed before the file is written. A file name that is not UTF-8 has its bytes
    // shown as U+FFFD, rather than failing the run at its end.
    std::string text = to_json(report).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    text += '\n';
    write_text_file(outputs.set.staged(*outputs.stats), r.stats, text);
}

// The frames' camera poses: the file's, or the orbit from the scene's own camera; null when the
// camera stays (a moving scene without --orbit or --camera-path).
CameraPathPtr camera_path(SimRequest &r, const rt_scene *scene)
{
    if (r.camera_file) return std::move(r.camera_file);
    if (r.camera_source == "scene") return nullptr;
    char msg[RT_MSG_LEN] = "";
    rt_camera_path *raw = nullptr;
    rt_camera_pose start = rt_camera_pose_of(rt_scene_camera(scene));
    if (rt_camera_path_orbit(&start, r.orbit_degrees, static_cast<uint32_t>(r.frame_count), &raw, msg, sizeof msg) !=
        RT_OK)
        throw UserError(std::string("--orbit: ") + msg);
    return CameraPathPtr(raw);
}

// The scene the frames render and its grid: the loaded ones, or a moving scene's frame 0 and its
// grid over every frame's object space.
struct FrameScene {
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    std::unique_ptr<SceneMotion> motion;  // null: the objects stay
};

// Loads the scene; with --motion its grid is built at frame 0 over every frame's object space
// (the scene's own grid is then one cell, taking next to nothing of the memory budget).
FrameScene load_frame_scene(SimRequest &r, LoadedScene &loaded)
{
    SimConfig &config = r.config;
    const std::array<int, 3> one_cell = {1, 1, 1};
    loaded = load_scene(config.scene_path, config.width, config.height, r.motion ? one_cell : config.cells,
                        config.quiet, &config.memory, config.preprocess_count);
    FrameScene fs;
    fs.scene = loaded.scene.get();
    if (r.motion) {
        fs.motion =
            std::make_unique<SceneMotion>(std::move(r.motion), std::move(loaded.scene), r.motion_path, config.quiet);
        const int cells[3] = {config.cells[0], config.cells[1], config.cells[2]};
        fs.motion->move_to(0, loaded.grid, cells, config.preprocess_count, &config.memory);
        fs.scene = fs.motion->frame_scene();
    }
    fs.grid = loaded.grid.get();
    return fs;
}

// The plan of the frames: a single image's T(1) (--t1, or a one-processor run in a child
// process), or an animation's frames, path, files, remapping and motion.
FramePlan frame_plan(SimRequest &r, const FrameScene &fs, StagedOutputs &outputs, CameraPathPtr &path)
{
    FramePlan plan;
    if (r.animated()) {
        path = camera_path(r, fs.scene);
        plan.frames = r.frame_count;
        plan.path = path.get();
        for (size_t k = 0; k < r.frame_files.size(); k++)
            plan.files.push_back(outputs.set.path(outputs.first_frame + k));
        plan.policy = r.remap;
        plan.adaptive = r.adaptive;
        plan.motion = fs.motion.get();
        plan.moving_grid = fs.motion ? fs.grid : nullptr;
        plan.report_frames = !r.stats.empty() || !r.frames_csv.empty();
        // Each frame goes to its temporary as it completes; commit() renames them all at the end.
        const rt_camera *cam = rt_scene_camera(fs.scene);
        unsigned w = cam->width, h = cam->height;
        plan.frame_done = [&outputs, w, h](size_t k, const std::vector<uint8_t> &rgb8) {
            write_png_file(outputs.set.staged(outputs.first_frame + k), outputs.set.path(outputs.first_frame + k), w, h,
                           rgb8);
        };
        return plan;
    }
    plan.t1_s = r.config.t1_s;
    plan.t1_source = "passed with --t1";
    if (plan.t1_s < 0 && r.config.processor_count() > 1) {
        plan.t1_s = one_processor_time(r.config, fs.scene, fs.grid);
        plan.t1_source = "one-processor run";
    }
    return plan;
}

// Writes the image (an animation's frames are staged as they complete), the statistics and the
// frame table, and commits them with the mapping outputs already staged.
void write_outputs(const SimRequest &r, const rt_scene *scene, StagedOutputs &outputs, const RunOutcome &out)
{
    const rt_camera *cam = rt_scene_camera(scene);
    if (!r.animated())
        write_png_file(outputs.set.staged(*outputs.png), r.image, cam->width, cam->height, out.images.front());
    write_stats(outputs, r, out.report);
    if (outputs.frames_csv)
        write_text_file(outputs.set.staged(*outputs.frames_csv), r.frames_csv, frames_csv(out.frames));
    if (outputs.series) write_text_file(outputs.set.staged(*outputs.series), r.stats_series, out.series_csv);
    outputs.set.commit();
}

}  // namespace

std::string save_file_path(const std::string &vcd)
{
    const std::string ext = ".vcd";
    bool has_ext = vcd.size() > ext.size() && vcd.compare(vcd.size() - ext.size(), ext.size(), ext) == 0;
    return (has_ext ? vcd.substr(0, vcd.size() - ext.size()) : vcd) + ".gtkw";
}

int simulate(SimRequest &r, double wall_start_s)
{
    SimConfig &config = r.config;
    StagedOutputs outputs;
    stage_outputs(r, outputs);
    // What the mapping reads (a map file) is checked before the scene is.
    if (const auto check = mapping_of(config).check_inputs) check(config);
    set_run_stage("loading the scene and building its cell lists");
    LoadedScene loaded;
    FrameScene fs = load_frame_scene(r, loaded);
    rt_scene *scene = fs.scene;
    check_shade_tree(config.scene_path, scene, config.step, config.memory, PacketPool::bytes_per_packet());
    nlohmann::json mapping_facts = prepare_mapping(config, scene, fs.grid);
    if (config.replicated() && r.remap != RemapPolicy::static_map)
        throw UserError("--map-file: a table with replicated cells is not remapped (--remap)", 2);
    if (config.replicated() && fs.motion)
        throw UserError("--motion: not with replicated cells (--replicate, or a map file with several owners for a "
                        "cell): a moved object's transfers are counted for one owner per cell",
                        2);
    // An animation's mapping outputs show frame 0's table, written before its camera moves.
    if (r.animated()) write_mapping_outputs(config, scene, fs.grid, outputs.set, outputs.write_map, outputs.load_map);
    CameraPathPtr path;
    FramePlan plan = frame_plan(r, fs, outputs, path);
    RunOutcome out = run_frames(config, scene, fs.grid, plan, wall_start_s);
    out.report.mapping = mapping_facts;
    if (r.animated()) {
        out.report.camera_source = r.camera_source;
        out.report.output_pattern = r.image;
    }
    if (fs.motion) {
        out.report.motion = fs.motion->json();
        out.report.motion.update(motion_totals_json(out.frames));
    }
    if (out.deadlock) {  // the JSON alone (status "deadlock"), no image
        write_stats(outputs, r, out.report);
        outputs.set.commit("--stats");
        report_deadlock(config, out.sim_time_s, out.deadlock_details);
        return 3;
    }
    set_run_stage("writing the outputs");
    if (!r.animated()) write_mapping_outputs(config, scene, fs.grid, outputs.set, outputs.write_map, outputs.load_map);
    write_outputs(r, scene, outputs, out);
    if (!config.quiet) {
        print_summary_stdout(out.report);
        print_written(r, r.animated() ? std::to_string(out.frames.size()) + " frames " + r.image : r.image);
    }
    return 0;
}

}  // namespace torusrt
