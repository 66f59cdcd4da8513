// torusrt_sim.cpp - the main simulator: the object-space-parallel ray-tracing machine as a
// SystemC/TLM-2.0 model, on one scene, with one configuration.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <systemc>
#include <tuple>

#include "animation_options.h"
#include "animation_run.h"
#include "cli_main.h"
#include "common_options.h"
#include "frame_pattern.h"
#include "huge_pages.h"
#include "machine_file_reader.h"
#include "machine_options.h"
#include "model_run.h"
#include "option_parsing.h"
#include "output_files.h"
#include "scene_setup.h"
#include "sim_config.h"
#include "mapping_setup.h"
#include "systemc_messages.h"
#include "user_error.h"
#include "wall_clock.h"

using namespace torusrt;

namespace {

struct CommandLine {
    CommonOptions common;  // scene, -o, --stats, cells, size, step limits, memory, timing, -q
    // The machine: --config reads these, --dump-config writes them (machine_options.cpp).
    std::string ips = "1", map = "cyclic", topology = "torus", style = "at", quantum = "0", data = "replicated";
    std::string arbiter = "round-robin", dispatch = "round-robin", link_us, packet_bytes, link_bytes_per_us;
    std::string flow = "classes";
    long long queue = 0;
    long long cell_header_bytes = 4, list_entry_bytes = 4, object_record_bytes = 0;  // memory accounting
    int cluster = 1;
    MappingOptions mapping;
    bool map_given = false; // --map was on the command line or in the --config file
    // The run: the command line only.
    std::string vcd, trace_ips, trace_from, trace_to, t1, time_limit;
    bool dump_config = false;
    // Animation (run options too: the frames are the workload).
    AnimationOptions anim;
    std::string remap, remap_pilot, remap_window, remap_margin, frames_csv;
    std::string config_file;  // the --config file read, if any (no output may replace it)
};

rt_map_kind parse_mapping(const std::string &text, int &block)
{
    if (text == "block") return RT_MAP_BLOCK;
    if (text == "cyclic") return RT_MAP_CYCLIC;
    if (text == "cost") return RT_MAP_COST;
    if (text.compare(0, 5, "cost:") == 0) {
        block = parse_dims_1_to_3("--map cost:K", text.substr(5), 1, 64)[0];
        return RT_MAP_COST;
    }
    const std::string prefix = "block-cyclic:";
    if (text.compare(0, prefix.size(), prefix) == 0) {
        block = parse_dims_1_to_3("--map block-cyclic:B", text.substr(prefix.size()), 1, 1 << 20)[0];
        return RT_MAP_BLOCK_CYCLIC;
    }
    throw UserError("--map '" + text + "': expected block, cyclic, block-cyclic:B, cost or cost:K", 2);
}

std::vector<int> parse_list(const std::string &option, const std::string &text)
{
    std::vector<int> out;
    size_t pos = 0;
    while (pos <= text.size()) {
        size_t comma = text.find(',', pos);
        std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        out.push_back(parse_dims_1_to_3(option, item, 0, 1 << 20)[0]);
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    return out;
}

// X.vcd -> X.gtkw; any other name gets ".gtkw" appended.
std::string save_file_path(const std::string &vcd)
{
    const std::string ext = ".vcd";
    bool has_ext = vcd.size() > ext.size() && vcd.compare(vcd.size() - ext.size(), ext.size(), ext) == 0;
    return (has_ext ? vcd.substr(0, vcd.size() - ext.size()) : vcd) + ".gtkw";
}

// --link-us, --packet-bytes, --link-bytes-per-us on top of the profile and the timing file.
void apply_timing_overrides(const CommandLine &cl, rt_timing &timing)
{
    char msg[RT_MSG_LEN] = "";
    auto set = [&](const char *key, const std::string &opt, const std::string &text, bool is_time) {
        if (text.empty()) return;
        double v = is_time ? parse_time_us(opt, text) : parse_non_negative(opt, text);
        if (rt_timing_set(&timing, key, v, msg, sizeof msg) != RT_OK) throw UserError(opt + ": " + msg, 2);
    };
    set("link", "--link-us", cl.link_us, true);
    set("packet_bytes", "--packet-bytes", cl.packet_bytes, false);
    set("link_bytes_per_us", "--link-bytes-per-us", cl.link_bytes_per_us, false);
}

// The machine the options describe; values that do not parse are errors here, ranges are the
// validator's.
MachineConfig machine_from(const CommandLine &cl, const CommonSettings &common)
{
    MachineConfig m;
    m.cells = common.cells;
    m.preprocess_count = common.preprocess_count;
    m.step = common.step;
    m.timing = common.timing;
    m.timing_profile = common.timing_label;
    m.timing_base = common.timing_base;
    m.timing_file = cl.common.timing_file;
    apply_timing_overrides(cl, m.timing);
    m.ips = parse_dims_1_to_3("--ips", cl.ips, 1, kMaxNodes);
    m.mapping = parse_mapping(cl.map, m.block);
    m.topology = value_named("--topology", cl.topology, kTopologyNames);
    m.flow = value_named("--flow", cl.flow, kFlowNames);
    if (cl.queue < 0 || cl.queue > kMaxQueue)
        throw UserError("--queue: must be 0 (unbounded) to " + std::to_string(kMaxQueue), 2);
    m.queue_capacity = static_cast<unsigned>(cl.queue);
    m.style = value_named("--style", cl.style, kStyleNames);
    m.quantum_us = parse_time_us("--quantum", cl.quantum);
    m.cluster = cl.cluster;
    m.data = value_named("--data", cl.data, kDataModeNames);
    m.arbiter = value_named("--arbiter", cl.arbiter, kArbiterNames);
    m.dispatch = value_named("--dispatch", cl.dispatch, kDispatchNames);
    for (const auto &[name, value, field] :
         {std::tuple<const char *, long long, uint32_t *>{"--cell-header-bytes", cl.cell_header_bytes,
                                                          &m.memory_layout.cell_header_bytes},
          {"--list-entry-bytes", cl.list_entry_bytes, &m.memory_layout.list_entry_bytes},
          {"--object-record-bytes", cl.object_record_bytes, &m.memory_layout.object_record_bytes}}) {
        if (value < 0 || value > kMaxRecordBytes)
            throw UserError(std::string(name) + ": must be 0 to " + std::to_string(kMaxRecordBytes), 2);
        *field = static_cast<uint32_t>(value);
    }
    return m;
}

RunOptions run_from(const CommandLine &cl, const CommonSettings &common)
{
    RunOptions r;
    r.scene_path = cl.common.scene;
    r.quiet = cl.common.quiet;
    r.width = common.size[0];
    r.height = common.size[1];
    r.memory = rt_budget_make(common.memory_bytes);
    r.vcd_path = cl.vcd;
    if (!cl.trace_ips.empty()) r.trace_ips = parse_list("--trace-ips", cl.trace_ips);
    if (!cl.t1.empty()) r.t1_s = parse_non_negative("--t1", cl.t1);
    if (!cl.time_limit.empty()) r.time_limit_s = parse_time_us("--time-limit", cl.time_limit) * 1e-6;
    if (!cl.trace_from.empty()) r.trace_from_us = parse_time_us("--trace-from", cl.trace_from);
    if (!cl.trace_to.empty()) r.trace_to_us = parse_time_us("--trace-to", cl.trace_to);
    return r;
}

// The machine's options: configurable, so that --config reads them (a new machine option goes
// here, in MachineConfig, machine_from, machine_options.cpp and the validator).
void declare_machine_options(CLI::App &app, CommandLine &cl)
{
    app.add_option("--ips", cl.ips, "torus nodes: P, PXxPY or PXxPYxPZ (default 1, at most 4096)")->type_name("DIMS");
    app.add_option("--map", cl.map, "cell mapping: block, cyclic (default), block-cyclic:B, cost or cost:K")->type_name("KIND");
    app.add_option("--topology", cl.topology, "torus (default, rings) or mesh (no wrap-around)")->type_name("KIND");
    app.add_option("--queue", cl.queue, "capacity of every packet buffer (of each class), 0 = unbounded (default)")
        ->type_name("N");
    app.add_option("--flow", cl.flow, "flow control: classes (default, deadlock-free class-split buffers) or none\n"
                                     "(one class; finite buffers may deadlock, exit 3)")->type_name("SCHEME");
    app.add_option("--link-us", cl.link_us, "time per packet on a link: microseconds, or with a unit ns, us, ms, s\n"
                                         "(default 50)")->type_name("TIME");
    app.add_option("--packet-bytes", cl.packet_bytes, "packet size on the wire in bytes (default 28)")->type_name("BYTES");
    app.add_option("--link-bytes-per-us", cl.link_bytes_per_us,
                   "link bandwidth; when > 0 a packet takes packet-bytes / this (default 0: use --link-us)")
        ->type_name("RATE");
    app.add_option("--style", cl.style, "timing style: at (approximately timed, default) or lt (loosely timed)")
        ->type_name("at|lt");
    app.add_option("--quantum", cl.quantum, "loosely-timed global quantum, same syntax as --link-us, e.g. 500us, 10ms")
        ->type_name("TIME");
    app.add_option("--cluster", cl.cluster, "processors per torus node on a shared bus (default 1)")->type_name("N");
    app.add_option("--data", cl.data, "object data in a cluster: replicated (default) or shared")->type_name("KIND");
    app.add_option("--arbiter", cl.arbiter, "cluster bus arbiter: round-robin (default) or fixed-priority")->type_name("KIND");
    app.add_option("--dispatch", cl.dispatch, "cluster packet dispatch: round-robin (default) or shortest-queue")
        ->type_name("KIND");
    app.add_option("--cell-header-bytes", cl.cell_header_bytes, "memory accounting: bytes per cell list (default 4)")
        ->type_name("BYTES");
    app.add_option("--list-entry-bytes", cl.list_entry_bytes, "memory accounting: bytes per object in a cell list (default 4)")
        ->type_name("BYTES");
    app.add_option("--object-record-bytes", cl.object_record_bytes,
                   "memory accounting: bytes per object record (default 0: each kind's own size)")->type_name("BYTES");
    add_mapping_options(app, cl.mapping); // --map-file, --pilot-size; the run's --write-map, --load-map
}

// The run's options: the command line only (a machine file names no files and no limits).
void declare_run_options(CLI::App &app, CommandLine &cl)
{
    app.add_option("--vcd", cl.vcd, "write a VCD trace (IP busy, queue depths, link and bus activity) and a GTKWave\n"
                               "save file beside it (X.gtkw for X.vcd)")->type_name("FILE");
    app.add_option("--trace-from", cl.trace_from, "trace only from this simulated time (default 0)")->type_name("TIME");
    app.add_option("--trace-to", cl.trace_to, "trace only up to this simulated time (default: the end)")->type_name("TIME");
    app.add_option("--trace-ips", cl.trace_ips, "trace only these nodes, e.g. 0,1,5 (default all)")->type_name("N,N,...");
    app.add_option("--t1", cl.t1, "T(1) in seconds for the efficiency T(1)/(n T(n)) (default: run the model with one processor)")
        ->type_name("SECONDS");
    app.add_option("--time-limit", cl.time_limit, "stop with an error (exit 1) when simulated time passes this\n"
                   "(default and maximum 1e7 s, SystemC's 64-bit picosecond time holds 1.8e7 s)")->type_name("TIME");
    add_animation_options(app, cl.anim);
    app.add_option("--remap", cl.remap, "mapping across the frames: static (default: the first frame's), every-frame,\n"
                   "adaptive or oracle")->type_name("POLICY");
    app.add_option("--remap-pilot", cl.remap_pilot, "adaptive's host preview of each frame: this fraction of the pixels\n"
                   "(default 0: no preview, guesses of the load from earlier frames)")->type_name("FRACTION");
    app.add_option("--remap-window", cl.remap_window, "adaptive without a preview: judge its guesses over this many past\n"
                   "frames (default " + std::to_string(default_remap_window) + ")")->type_name("N");
    char margin_default[32];
    std::snprintf(margin_default, sizeof margin_default, "%g", default_remap_margin);
    app.add_option("--remap-margin", cl.remap_margin, std::string("adaptive without a preview: keep the previous frame's load as the\n"
                   "guess unless another's back-test is better by more than this fraction (default ") +
                   margin_default + ")")->type_name("FRACTION");
    app.add_option("--frames-csv", cl.frames_csv, "write one CSV row per frame of an animation")->type_name("FILE");
    for (const char *name : {"--vcd", "--trace-from", "--trace-to", "--trace-ips", "--t1", "--time-limit", "--remap",
                             "--remap-pilot", "--remap-window", "--remap-margin", "--frames-csv"})
        app.get_option(name)->configurable(false);
}

// The animation options checked before any file is read (exit 2).
void check_animation(CommandLine &cl)
{
    check_animation_options(cl.anim);
    if (!cl.anim.animated()) {
        for (const auto &[name, value] : {std::pair<const char *, const std::string &>{"--remap-pilot", cl.remap_pilot},
                                          {"--remap-window", cl.remap_window},
                                          {"--remap-margin", cl.remap_margin}})
            if (!value.empty()) throw UserError(std::string(name) + ": only for an animation with --remap adaptive", 2);
        if (!cl.remap.empty() || !cl.frames_csv.empty())
            throw UserError(std::string(cl.remap.empty() ? "--frames-csv" : "--remap") +
                                ": only for an animation (--frames N with --orbit DEG, or --camera-path FILE)", 2);
        return;
    }
    if (!cl.remap.empty()) parse_remap_policy(cl.remap);
    if (!cl.remap_pilot.empty()) {
        parse_remap_pilot(cl.remap_pilot);
        if (cl.remap != "adaptive") throw UserError("--remap-pilot: only with --remap adaptive", 2);
    }
    // --remap-window and --remap-margin tune how adaptive judges its guesses, which a preview replaces.
    auto guess_option = [&cl](const std::string &name) {
        if (cl.remap != "adaptive") throw UserError(name + ": only with --remap adaptive", 2);
        if (!cl.remap_pilot.empty() && parse_remap_pilot(cl.remap_pilot) > 0)
            throw UserError(name + ": only without a preview (--remap-pilot 0); the preview judges the tables", 2);
    };
    if (!cl.remap_window.empty()) {
        parse_remap_window(cl.remap_window);
        guess_option("--remap-window");
    }
    if (!cl.remap_margin.empty()) {
        parse_remap_margin(cl.remap_margin);
        guess_option("--remap-margin");
    }
    if (!cl.t1.empty()) throw UserError("--t1: not used by an animation (each frame's T(1) is its pilot's work)", 2);
    if (!cl.common.output.empty()) check_frame_pattern("-o", cl.common.output);
}

void declare_options(CLI::App &app, CommandLine &cl)
{
    add_common_options(app, cl.common, "PNG image to write");
    declare_machine_options(app, cl);
    declare_run_options(app, cl);
    app.allow_config_extras(CLI::config_extras_mode::error);  // an unknown key is an error
    app.config_formatter(std::make_shared<MachineFileReader>());  // '#' in a quoted path, no repeated key
    app.set_config("--config", "", "read the machine from this TOML file (as --dump-config writes it);\n"
                                   "options on the command line take precedence")->type_name("FILE");
    app.add_flag("--dump-config", cl.dump_config, "print the machine as TOML and exit without running")
        ->configurable(false);
    for (CLI::Option *opt : app.get_options())  // --help shows which options make the machine
        if (!opt->get_positional() && opt != app.get_help_ptr() && opt != app.get_config_ptr() &&
            opt->get_name() != "--dump-config")
            opt->group(opt->get_configurable() ? "Machine (a --config file may hold these)" : "Run");
}

bool on_command_line(int argc, char **argv, const std::string &name)
{
    for (int i = 1; i < argc; i++)
        if (argv[i] == name || std::string(argv[i]).rfind(name + "=", 0) == 0) return true;
    return false;
}

// A bad setting (exit 2) whose option came from the --config file, not the command line: the
// message names the file too (the validator names only the option).
UserError naming_config_file(const CLI::App &app, const UserError &e, int argc, char **argv)
{
    std::string what = e.what();
    size_t end = what.find_first_of(" :");
    std::string name = what.substr(0, end);
    const CLI::Option *config = app.get_config_ptr();
    const CLI::Option *opt = name.rfind("--", 0) == 0 ? app.get_option_no_throw(name) : nullptr;
    if (e.exit_code() != 2 || config == nullptr || config->count() == 0 || opt == nullptr ||
        !opt->get_configurable() || opt->count() == 0 || on_command_line(argc, argv, name))
        return e;
    return UserError(config->as<std::string>() + ": " + what, 2);
}

// A relative --timing or --map-file path read from a --config file names a file beside the
// machine file, so that a machine file and its timing file travel together.
void resolve_config_relative_paths(const CLI::App &app, CommandLine &cl, int argc, char **argv)
{
    if (cl.config_file.empty()) return;
    size_t slash = cl.config_file.find_last_of('/');
    if (slash == std::string::npos) return;  // the machine file is in the working folder
    std::string dir = cl.config_file.substr(0, slash + 1);
    for (const auto &[name, path] : {std::pair<const char *, std::string *>{"--timing", &cl.common.timing_file},
                                     {"--map-file", &cl.mapping.map_file}})
        if (app.count(name) > 0 && !on_command_line(argc, argv, name) && !path->empty() && (*path)[0] != '/')
            *path = dir + *path;
}

// --map and --map-file exclude each other; one on the command line replaces the other from a
// --config file (both in one place is an error, reported by apply_mapping_options).
void resolve_mapping_sources(const CLI::App &app, CommandLine &cl, int argc, char **argv)
{
    bool map_here = on_command_line(argc, argv, "--map"), file_here = on_command_line(argc, argv, "--map-file");
    cl.map_given = app.count("--map") > 0;
    if (map_here && !file_here) cl.mapping.map_file.clear();
    if (file_here && !map_here) cl.map_given = false;
}

// The options turned into a checked configuration (UserError on a bad value).
SimConfig checked_config(const CommandLine &cl)
{
    CommonSettings common = parse_common_options(cl.common);
    SimConfig config;
    static_cast<MachineConfig &>(config) = machine_from(cl, common);
    static_cast<RunOptions &>(config) = run_from(cl, common);
    apply_mapping_options(config, cl.mapping, cl.map_given);
    validate(config);
    return config;
}

// Every option a machine file may hold must be written by --dump-config, or the file would
// not give the same machine.
void check_dump_covers_options(const CLI::App &app, const OptionList &written)
{
    std::set<std::string> keys;
    for (const auto &kv : written) keys.insert(kv.first);
    keys.insert("map");  // left out with --map-file
    for (const CLI::Option *opt : app.get_options()) {
        if (!opt->get_configurable() || opt == app.get_config_ptr() || opt == app.get_help_ptr() ||
            opt == app.get_option_no_throw("--version"))
            continue;
        if (!keys.count(opt->get_single_name()))
            throw std::logic_error("--" + opt->get_single_name() +
                                   " can come from a machine file but machine_options() does not write it");
    }
}

// --dump-config: the machine of the command line and --config, checked as a run would check
// it, as TOML on stdout.
int dump_config(const CLI::App &app, const CommandLine &cl)
{
    route_systemc_messages(cl.common.quiet);
    SimConfig config = checked_config(cl);
    std::vector<int32_t> owner;  // the table a run would read, checked as the run checks it
    if (config.mapping == RT_MAP_FILE) read_map_file(config, config.cells.data(), owner);
    check_dump_covers_options(app, machine_options(config));
    for (const auto &kv : machine_options(config))  // a key="value" line cannot hold a line break
        if (kv.second.find_first_of("\r\n") != std::string::npos)
            throw UserError("--" + kv.first + ": a value with a line break cannot be written to a machine file", 2);
    std::fputs(machine_options_toml(config).c_str(), stdout);
    return 0;
}

// Every output's temporary, named before anything runs.
struct StagedOutputs {
    OutputSet set;
    std::string png, stats, write_map, load_map;
};

void stage_outputs(const CommandLine &cl, SimConfig &config, StagedOutputs &out)
{
    const std::string &scene = cl.common.scene;
    if (!cl.anim.animated()) out.png = out.set.add("-o", cl.common.output, scene);  // frames: animate()
    if (!cl.common.stats.empty()) out.stats = out.set.add("--stats", cl.common.stats, scene);
    if (!cl.vcd.empty()) {
        config.vcd_write_path = out.set.add("--vcd", cl.vcd, scene);
        if (!is_special_file(cl.vcd)) {  // no save file beside /dev/null
            config.gtkw_path = save_file_path(cl.vcd);
            config.gtkw_write_path = out.set.add("--vcd (save file)", config.gtkw_path, scene);
        }
    }
    if (!cl.mapping.write_map.empty()) out.write_map = out.set.add("--write-map", cl.mapping.write_map, scene);
    if (!cl.mapping.load_map.empty()) out.load_map = out.set.add("--load-map", cl.mapping.load_map, scene);
    out.set.check_not_input("--config", cl.config_file);
    out.set.check_not_input("--timing", config.timing_file);
    out.set.check_not_input("--map-file", config.map_file);
}

void print_written(const CommandLine &cl, const SimConfig &config)
{
    std::printf("  wrote        %s", cl.common.output.c_str());
    if (!cl.common.stats.empty()) std::printf(", %s", cl.common.stats.c_str());
    if (!cl.vcd.empty()) std::printf(", %s", cl.vcd.c_str());
    if (!config.gtkw_path.empty()) std::printf(" (gtkwave %s)", config.gtkw_path.c_str());
    std::printf("\n");
}

void report_deadlock(const SimConfig &config, double sim_time_s, const std::string &details)
{
    std::fprintf(stderr,
                 "torusrt-sim: deadlock: the network stalled at %.6f s simulated with packets still "
                 "outstanding (queue capacity %u)\n%s",
                 sim_time_s, config.queue_capacity, details.c_str());
}

void write_stats(const StagedOutputs &outputs, const CommandLine &cl, const RunReport &report)
{
    if (outputs.stats.empty()) return;
    std::string text = to_json(report).dump(2);  // the tree is freed before the file is written
    text += '\n';
    write_text_file(outputs.stats, cl.common.stats, text);
}

// An animation: every frame's PNG, the statistics and the CSV commit together.
int animate(const CommandLine &cl, SimConfig &config, LoadedScene &loaded, const nlohmann::json &mapping_facts,
            StagedOutputs &outputs, double wall_start)
{
    rt_scene *scene = loaded.scene.get();
    CameraPathPtr path = make_camera_path(cl.anim, scene);
    size_t n = rt_camera_path_count(path.get());
    std::vector<std::string> files, staged;
    for (size_t k = 0; k < n; k++) {
        files.push_back(frame_file_name(cl.common.output, k));
        staged.push_back(outputs.set.add("-o", files.back(), cl.common.scene));
    }
    std::string csv = cl.frames_csv.empty() ? "" : outputs.set.add("--frames-csv", cl.frames_csv, cl.common.scene);
    RemapPolicy policy = cl.remap.empty() ? RemapPolicy::static_map : parse_remap_policy(cl.remap);
    AdaptiveSettings adaptive;
    if (!cl.remap_pilot.empty()) adaptive.pilot_fraction = parse_remap_pilot(cl.remap_pilot);
    if (!cl.remap_window.empty()) adaptive.window = parse_remap_window(cl.remap_window);
    if (!cl.remap_margin.empty()) adaptive.margin = parse_remap_margin(cl.remap_margin);
    AnimationOutcome out =
        run_animation(config, scene, loaded.grid.get(), path.get(), files, policy, adaptive, wall_start);
    out.report.mapping = mapping_facts;
    out.report.camera_source = cl.anim.orbit.empty() ? "camera-path" : "orbit";
    out.report.output_pattern = cl.common.output;
    if (out.deadlock) {  // the JSON alone (status "deadlock"), no image
        write_stats(outputs, cl, out.report);
        outputs.set.commit("--stats");
        report_deadlock(config, out.sim_time_s, out.deadlock_details);
        return 3;
    }
    const rt_camera *cam = rt_scene_camera(scene);
    for (size_t k = 0; k < n; k++) write_png_file(staged[k], files[k], cam->width, cam->height, out.images[k]);
    write_stats(outputs, cl, out.report);
    if (!csv.empty()) write_text_file(csv, cl.frames_csv, frames_csv(out.frames));
    outputs.set.commit();
    if (!config.quiet) {
        print_summary_stdout(out.report);
        std::printf("  wrote        %zu frames %s", n, cl.common.output.c_str());
        if (!cl.common.stats.empty()) std::printf(", %s", cl.common.stats.c_str());
        if (!cl.frames_csv.empty()) std::printf(", %s", cl.frames_csv.c_str());
        if (!cl.vcd.empty()) std::printf(", %s", cl.vcd.c_str());
        std::printf("\n");
    }
    return 0;
}

int run(CommandLine &cl, double wall_start)
{
    require_scene_and_output(cl.common);
    route_systemc_messages(cl.common.quiet);
    check_animation(cl);
    SimConfig config = checked_config(cl);
    warn_about_settings("torusrt-sim", config.step, config.quiet);
    StagedOutputs outputs;
    stage_outputs(cl, config, outputs);
    LoadedScene loaded = load_scene(config.scene_path, config.width, config.height, config.cells, config.quiet,
                                    &config.memory, config.preprocess_count);
    nlohmann::json mapping_facts = prepare_mapping(config, loaded.scene.get(), loaded.grid.get());
    if (cl.anim.animated()) {
        write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), outputs.write_map, outputs.load_map);
        return animate(cl, config, loaded, mapping_facts, outputs, wall_start);
    }
    double t1 = config.t1_s;
    std::string t1_source = "passed with --t1";
    if (t1 < 0 && config.processor_count() > 1) {
        t1 = one_processor_time(config, loaded.scene.get(), loaded.grid.get());
        t1_source = "one-processor run";
    }
    ModelOutcome out = run_model(config, loaded.scene.get(), loaded.grid.get(), t1, t1_source, wall_start);
    out.report.mapping = mapping_facts;
    if (out.deadlock) {  // the JSON alone (status "deadlock"), no image
        write_stats(outputs, cl, out.report);
        outputs.set.commit("--stats");
        report_deadlock(config, out.sim_time_s, out.deadlock_details);
        return 3;
    }
    const rt_camera *cam = rt_scene_camera(loaded.scene.get());
    write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), outputs.write_map, outputs.load_map);
    write_png_file(outputs.png, cl.common.output, cam->width, cam->height, out.rgb8);
    write_stats(outputs, cl, out.report);
    outputs.set.commit();
    if (!config.quiet) {
        print_summary_stdout(out.report);
        print_written(cl, config);
    }
    return 0;
}

}  // namespace

int sc_main(int argc, char **argv)
{
    double wall_start = wall_clock_s();
    sc_core::sc_report_handler::set_actions(sc_core::SC_FATAL, sc_core::SC_DISPLAY | sc_core::SC_THROW);
    sc_core::sc_report_handler::set_actions(sc_core::SC_ERROR, sc_core::SC_DISPLAY | sc_core::SC_THROW);
    CommandLine cl;
    CLI::App app{"torusrt-sim: a SystemC/TLM-2.0 model of the object-space-parallel ray-tracing\n"
                 "multiprocessor (Kubota et al.): intersection processors on a torus exchange ray packets."};
    declare_options(app, cl);
    return run_cli("torusrt-sim", app, argc, argv,
                   [&] {
                       resolve_mapping_sources(app, cl, argc, argv);
                       if (app.get_config_ptr()->count() > 0) cl.config_file = app.get_config_ptr()->as<std::string>();
                       resolve_config_relative_paths(app, cl, argc, argv);
                       try {
                           return cl.dump_config ? dump_config(app, cl) : run(cl, wall_start);
                       } catch (const UserError &e) {
                           throw naming_config_file(app, e, argc, argv);
                       }
                   },
                   "  3 deadlock: the network stalled with packets outstanding\n");
}

// Our own entry point: the SystemC banner is printed before sc_main runs, so it is switched off
// here; and the allocator's huge pages are asked for before anything is allocated.
int main(int argc, char **argv)
{
    torusrt::reexec_with_huge_pages(argv);
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "DISABLE", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}
