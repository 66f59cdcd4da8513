// torusrt_sim.cpp - the main simulator: the object-space-parallel ray-tracing machine as a
// SystemC/TLM-2.0 model, on one scene, with one configuration.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <systemc>

#include "animation_options.h"
#include "animation_run.h"
#include "cli_main.h"
#include "common_options.h"
#include "frame_pattern.h"
#include "huge_pages.h"
#include "input_file_check.h"
#include "machine_file_reader.h"
#include "machine_options.h"
#include "model_run.h"
#include "option_parsing.h"
#include "output_files.h"
#include "packet_pool.h"
#include "scene_setup.h"
#include "sim_config.h"
#include "mapping_setup.h"
#include "option_registration.h"
#include "option_spec.h"
#include "remap_policy.h"
#include "systemc_messages.h"
#include "user_error.h"
#include "wall_clock.h"

using namespace torusrt;

namespace {

// The command line, parsed once: the options given (by long name, as typed) and the run's
// settings that are no part of SimConfig.
struct CommandLine {
    std::map<std::string, std::string> given;
    CommonOptions common;  // scene, -o, --stats, size, memory, -q
    AnimationOptions anim;
    RemapPolicy remap = RemapPolicy::static_map;
    AdaptiveSettings adaptive;
    std::string config_file;  // the --config file read, if any (no output may replace it)
    bool dump_config = false, with_timing = false;

    bool has(const std::string &name) const { return given.count(name) > 0; }
    std::string text(const std::string &name) const
    {
        auto it = given.find(name);
        return it == given.end() ? "" : it->second;
    }
};

// The run's options (the command line only: a machine file names no files and no limits).
std::vector<OptionSpec> run_option_specs()
{
    using G = OptionGroup;
    using K = ValueKind;
    const double max_s = kMaxSimTimeS;
    return {
        {"--write-map", "FILE", K::file, "", 0, 0, "", "write the cell -> node table this run used", G::outputs, ""},
        {"--load-map", "FILE", K::file, "", 0, 0, "", "write the cells' work and owners as a PNG", G::outputs, ""},
        {"--frames-csv", "FILE", K::file, "", 0, 0, "", "write one CSV row per frame of an animation", G::outputs, ""},
        {"--t1", "TIME", K::time, "", 0, max_s, "s",
         "T(1) for the efficiency T(1)/(n T(n)) (default: run the model with one processor)", G::outputs, ""},
        {"--vcd", "FILE", K::file, "", 0, 0, "",
         "write a VCD trace (IP busy, queue depths, link and bus activity) and a GTKWave save file beside "
         "it (X.gtkw for X.vcd)", G::tracing, ""},
        {"--trace-from", "TIME", K::time, "0", 0, max_s, "s", "trace only from this simulated time", G::tracing, ""},
        {"--trace-to", "TIME", K::time, "", 0, max_s, "s", "trace only up to this simulated time (default: the end)",
         G::tracing, ""},
        {"--trace-ips", "N,N,...", K::text, "", 0, kMaxNodes - 1, "", "trace only these nodes, e.g. 0,1,5 (default all)",
         G::tracing, ""},
        {"--remap", "POLICY", K::text, "static", 0, 0, "",
         "mapping across the frames: static (the first frame's), every-frame, adaptive or oracle", G::animation, ""},
        {"--remap-pilot", "FRACTION", K::real, "0", 0, 1, "",
         "adaptive's host preview of each frame: this fraction of the pixels (0: no preview, guesses of the load "
         "from earlier frames)", G::animation, ""},
        {"--remap-window", "N", K::integer, std::to_string(default_remap_window), 1, double(max_remap_window), "",
         "adaptive without a preview: judge its guesses over this many past frames", G::animation, ""},
        {"--remap-margin", "FRACTION", K::real, number_text(default_remap_margin), 0, 1, "",
         "adaptive without a preview: keep the previous frame's load as the guess unless another's back-test "
         "is better by more than this fraction", G::animation, ""},
        {"--time-limit", "TIME", K::time, "1e7s", 0, max_s, "s",
         "stop with an error (exit 1) when simulated time passes this (at most 1e7 s: SystemC's 64-bit "
         "picosecond time holds 1.8e7 s)", G::run, ""},
    };
}

const OptionSpec &run_spec(const std::string &name)
{
    static const std::vector<OptionSpec> specs = run_option_specs();
    for (const OptionSpec &s : specs)
        if (s.long_name() == name) return s;
    throw std::logic_error("no run option " + name);
}

// A time option of the run in microseconds (a bare number is seconds).
double run_time_us(const CommandLine &cl, const std::string &name)
{
    return parse_time(name, cl.text(name), 0, -6);
}

RunOptions run_from(const CommandLine &cl, const CommonSettings &common)
{
    RunOptions r;
    r.scene_path = cl.common.scene;
    r.quiet = cl.common.quiet;
    r.width = common.size[0];
    r.height = common.size[1];
    r.memory = rt_budget_make(common.memory_bytes);
    r.vcd_path = cl.text("--vcd");
    if (cl.has("--trace-ips")) r.trace_ips = parse_integer_list("--trace-ips", cl.text("--trace-ips"), 0, kMaxNodes - 1);
    if (cl.has("--t1")) r.t1_s = parse_time("--t1", cl.text("--t1"), 0, 0);
    if (cl.has("--time-limit")) r.time_limit_s = parse_time("--time-limit", cl.text("--time-limit"), 0, 0);
    if (cl.has("--trace-from")) r.trace_from_us = run_time_us(cl, "--trace-from");
    if (cl.has("--trace-to")) r.trace_to_us = run_time_us(cl, "--trace-to");
    r.write_map = cl.text("--write-map");
    if (!r.write_map.empty()) check_output_folder("--write-map", r.write_map);
    if (cl.has("--load-map")) check_output_folder("--load-map", cl.text("--load-map"));
    return r;
}

// The names of the machine options' keys a machine file may hold, and those whose bare number
// would be seconds.
std::vector<std::string> machine_keys(bool timed_only)
{
    std::vector<std::string> keys;
    for (const MachineOption &o : machine_option_table())
        if (!timed_only || (o.spec.kind == ValueKind::time && o.spec.unit == "s")) keys.push_back(o.spec.key);
    return keys;
}

const char *const kUsage = "Usage: torusrt-sim SCENE -o FILE [OPTIONS]\n"
                           "       torusrt-sim --dump-config [--with-timing] [MACHINE OPTIONS]";
const char *const kRules = "Numbers are decimal (010 and 0x10 are refused). A time takes a unit ns, us, ms or s; a\n"
                           "bare number is seconds, except for an option whose name carries its unit (--link-us).";
const char *const kExamples =
    "  torusrt-sim scenes/paper-image1.nff -o sim.png --ips 4x2x2 --stats sim.json\n"
    "  torusrt-sim scenes/paper-image2.nff -o sim.png --ips 4x4 --map block --link-us 500 --queue 64\n"
    "  torusrt-sim scenes/paper-image1.nff -o 'f_%02d.png' --ips 2x2 --frames 12 --orbit 360\n";

void declare_options(CLI::App &app, std::shared_ptr<MachineFileReader> reader)
{
    const std::string output_help = "PNG image to write; with --frames/--camera-path a pattern like out_%04d.png";
    add_common_options(app, output_help, {"scene", "--size"});
    app.set_config("--config", "", wrapped("read the machine from this TOML file (as --dump-config writes it); "
                                           "options on the command line take precedence", kHelpColumns - 31))
        ->type_name("FILE")
        ->group(group_title(OptionGroup::machine))
        ->check(input_file_check(kMachineFileMaxBytes));  // before CLI11's own blocking read
    app.allow_config_extras(CLI::config_extras_mode::error);  // an unknown key is an error
    app.config_formatter(reader);
    add_spec_option(app, {"--dump-config", "", ValueKind::flag, "", 0, 0, "",
                          "print the machine as TOML and exit without running", OptionGroup::machine, ""});
    add_spec_option(app, {"--with-timing", "", ValueKind::flag, "", 0, 0, "",
                          "with --dump-config: write every timing value (timing-values), so that the file needs "
                          "no timing file", OptionGroup::machine, ""});
    for (const MachineOption &o : machine_option_table()) add_spec_option(app, o.spec);
    add_common_options(app, output_help, {"--output", "--stats"});
    for (const OptionSpec &spec : run_option_specs())
        if (spec.group == OptionGroup::outputs || spec.group == OptionGroup::tracing) add_spec_option(app, spec);
    for (const OptionSpec &spec : animation_option_specs()) add_spec_option(app, spec);
    for (const OptionSpec &spec : run_option_specs())
        if (spec.group == OptionGroup::animation || spec.group == OptionGroup::run) add_spec_option(app, spec);
    add_common_options(app, output_help, {"--memory-budget", "--quiet"});
    set_help_layout(app, kUsage, kRules, kExamples);
}

// The animation's run options parsed once, checked before any file is read (exit 2).
void check_animation(CommandLine &cl)
{
    check_animation_options(cl.anim);
    if (!cl.anim.animated()) {
        for (const char *name : {"--remap-pilot", "--remap-window", "--remap-margin"})
            if (cl.has(name)) throw UserError(std::string(name) + ": only for an animation with --remap adaptive", 2);
        if (cl.has("--remap") || cl.has("--frames-csv"))
            throw UserError(std::string(cl.has("--remap") ? "--remap" : "--frames-csv") +
                                ": only for an animation (--frames N with --orbit DEG, or --camera-path FILE)", 2);
        return;
    }
    if (cl.has("--remap")) cl.remap = parse_remap_policy(cl.text("--remap"));
    auto real = [&cl](const char *name) {
        const OptionSpec &s = run_spec(name);
        return parse_real(name, cl.text(name), s.min, s.max);
    };
    if (cl.has("--remap-pilot")) {
        cl.adaptive.pilot_fraction = real("--remap-pilot");
        if (cl.remap != RemapPolicy::adaptive) throw UserError("--remap-pilot: only with --remap adaptive", 2);
    }
    // --remap-window and --remap-margin tune how adaptive judges its guesses, which a preview replaces.
    auto guess_option = [&cl](const std::string &name) {
        if (cl.remap != RemapPolicy::adaptive) throw UserError(name + ": only with --remap adaptive", 2);
        if (cl.adaptive.pilot_fraction > 0)
            throw UserError(name + ": only without a preview (--remap-pilot 0); the preview judges the tables", 2);
    };
    if (cl.has("--remap-window")) {
        const OptionSpec &s = run_spec("--remap-window");
        cl.adaptive.window = static_cast<size_t>(
            parse_integer("--remap-window", cl.text("--remap-window"), static_cast<long long>(s.min),
                          static_cast<long long>(s.max)));
        guess_option("--remap-window");
    }
    if (cl.has("--remap-margin")) {
        cl.adaptive.margin = real("--remap-margin");
        guess_option("--remap-margin");
    }
    if (cl.has("--t1")) throw UserError("--t1: not used by an animation (each frame's T(1) is its pilot's work)", 2);
    if (!cl.common.output.empty()) check_frame_pattern("-o", cl.common.output);
}

bool on_command_line(int argc, char **argv, const std::string &name)
{
    for (int i = 1; i < argc; i++)
        if (argv[i] == name || std::string(argv[i]).rfind(name + "=", 0) == 0) return true;
    return false;
}

// A bad setting (exit 2) whose option came from the --config file, not the command line: the
// message names the file and its line too (the option's parser names only the option).
UserError naming_config_file(const CommandLine &cl, const MachineFileReader &reader, const UserError &e, int argc,
                             char **argv)
{
    std::string what = e.what();
    std::string name = what.substr(0, what.find_first_of(" :"));
    int line = name.rfind("--", 0) == 0 ? reader.line_of(name.substr(2)) : 0;
    if (e.exit_code() != 2 || cl.config_file.empty() || line == 0 || on_command_line(argc, argv, name)) return e;
    return UserError(shown_text(cl.config_file) + ":" + std::to_string(line) + ": " + what, 2);
}

// A relative --timing or --map-file path read from a --config file names a file beside the
// machine file, so that a machine file and its timing file travel together.
void resolve_config_relative_paths(CommandLine &cl, int argc, char **argv)
{
    if (cl.config_file.empty()) return;
    size_t slash = cl.config_file.find_last_of('/');
    if (slash == std::string::npos) return;  // the machine file is in the working folder
    std::string dir = cl.config_file.substr(0, slash + 1);
    for (const char *name : {"--timing", "--map-file"}) {
        auto it = cl.given.find(name);
        if (it != cl.given.end() && !on_command_line(argc, argv, name) && !it->second.empty() && it->second[0] != '/')
            it->second = dir + it->second;
    }
}

// --map and --map-file exclude each other; one on the command line replaces the other from a
// --config file (both in one place is an error, reported by machine_from_texts).
void resolve_mapping_sources(CommandLine &cl, int argc, char **argv)
{
    bool map_here = on_command_line(argc, argv, "--map"), file_here = on_command_line(argc, argv, "--map-file");
    if (map_here && !file_here) cl.given.erase("--map-file");
    if (file_here && !map_here) cl.given.erase("--map");
}

// The options turned into a checked configuration (UserError on a bad value).
SimConfig checked_config(const CommandLine &cl)
{
    CommonSettings common = parse_common_options(cl.common);
    SimConfig config;
    static_cast<MachineConfig &>(config) = machine_from_texts(cl.given);
    static_cast<RunOptions &>(config) = run_from(cl, common);
    validate(config);
    return config;
}

// --dump-config: the machine of the command line and --config, checked as a run would check
// it, as TOML on stdout.
int dump_config(const CommandLine &cl)
{
    route_systemc_messages(cl.common.quiet);
    SimConfig config = checked_config(cl);
    std::vector<int32_t> owner;  // the table a run would read, checked as the run checks it
    if (config.mapping == RT_MAP_FILE) read_map_file(config, config.cells.data(), owner);
    std::fputs(machine_options_toml(config, cl.with_timing).c_str(), stdout);
    return 0;
}

// X.vcd -> X.gtkw; any other name gets ".gtkw" appended.
std::string save_file_path(const std::string &vcd)
{
    const std::string ext = ".vcd";
    bool has_ext = vcd.size() > ext.size() && vcd.compare(vcd.size() - ext.size(), ext.size(), ext) == 0;
    return (has_ext ? vcd.substr(0, vcd.size() - ext.size()) : vcd) + ".gtkw";
}

// Every output of the run (every frame's included), registered and checked against the inputs
// and each other before the scene is read.
struct StagedOutputs {
    OutputSet set;
    std::optional<OutputSet::Id> png, stats, write_map, load_map, frames_csv;
    OutputSet::Id first_frame = 0;  // frame k is first_frame + k
};

void stage_outputs(const CommandLine &cl, SimConfig &config, size_t frames, StagedOutputs &out)
{
    const std::string &pattern = cl.common.output;
    if (!cl.anim.animated()) out.png = out.set.add("-o", pattern);
    for (size_t k = 0; k < frames; k++) {
        OutputSet::Id id = out.set.add("-o", frame_file_name(pattern, k));
        if (k == 0) out.first_frame = id;
    }
    if (!cl.common.stats.empty()) out.stats = out.set.add("--stats", cl.common.stats);
    std::optional<OutputSet::Id> vcd, gtkw;
    if (cl.has("--vcd")) {
        vcd = out.set.add("--vcd", cl.text("--vcd"));
        if (!out.set.special(*vcd)) {  // no save file beside /dev/null
            config.gtkw_path = save_file_path(cl.text("--vcd"));
            gtkw = out.set.add("--vcd (save file)", config.gtkw_path);
        }
    }
    if (cl.has("--write-map")) out.write_map = out.set.add("--write-map", cl.text("--write-map"));
    if (cl.has("--load-map")) out.load_map = out.set.add("--load-map", cl.text("--load-map"));
    if (cl.has("--frames-csv")) out.frames_csv = out.set.add("--frames-csv", cl.text("--frames-csv"));
    out.set.add_input("scene", cl.common.scene);
    out.set.add_input("--config", cl.config_file);
    out.set.add_input("--timing", config.timing_file);
    out.set.add_input("--map-file", config.map_file);
    out.set.add_input("--camera-path", cl.anim.camera_path);
    out.set.check();
    if (vcd) config.vcd_write_path = out.set.staged(*vcd);
    if (gtkw) config.gtkw_write_path = out.set.staged(*gtkw);
}

// The summary's last line: every output written, FIRST (the image or the frames) first.
void print_written(const CommandLine &cl, const SimConfig &config, const std::string &first)
{
    std::printf("  wrote        %s", first.c_str());
    if (!cl.common.stats.empty()) std::printf(", %s", cl.common.stats.c_str());
    for (const char *name : {"--frames-csv", "--write-map", "--load-map", "--vcd"})
        if (cl.has(name) && !cl.text(name).empty()) std::printf(", %s", cl.text(name).c_str());
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

void write_stats(StagedOutputs &outputs, const CommandLine &cl, const RunReport &report)
{
    if (!outputs.stats) return;
    std::string text = to_json(report).dump(2);  // the tree is freed before the file is written
    text += '\n';
    write_text_file(outputs.set.staged(*outputs.stats), cl.common.stats, text);
}

// An animation: every frame's PNG, the statistics and the CSV commit together.
int animate(const CommandLine &cl, SimConfig &config, LoadedScene &loaded, const nlohmann::json &mapping_facts,
            StagedOutputs &outputs, CameraPathPtr file, double wall_start)
{
    rt_scene *scene = loaded.scene.get();
    CameraPathPtr path = make_camera_path(cl.anim, scene, std::move(file));
    size_t n = rt_camera_path_count(path.get());
    std::vector<std::string> files;
    for (size_t k = 0; k < n; k++) files.push_back(outputs.set.path(outputs.first_frame + k));
    AnimationOutcome out =
        run_animation(config, scene, loaded.grid.get(), path.get(), files, cl.remap, cl.adaptive, wall_start);
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
    for (size_t k = 0; k < n; k++)
        write_png_file(outputs.set.staged(outputs.first_frame + k), files[k], cam->width, cam->height, out.images[k]);
    write_stats(outputs, cl, out.report);
    if (outputs.frames_csv)
        write_text_file(outputs.set.staged(*outputs.frames_csv), cl.text("--frames-csv"), frames_csv(out.frames));
    outputs.set.commit();
    if (!config.quiet) {
        print_summary_stdout(out.report);
        print_written(cl, config, std::to_string(n) + " frames " + cl.common.output);
    }
    return 0;
}

int run(CommandLine &cl, double wall_start)
{
    require_scene_and_output(cl.common);
    route_systemc_messages(cl.common.quiet);
    check_animation(cl);
    SimConfig config = checked_config(cl);
    if (config.replicate > 0 && cl.remap != RemapPolicy::static_map)
        throw UserError("--replicate: not with --remap (a remapped table keeps one owner per cell)", 2);
    warn_about_settings("torusrt-sim", config.step, config.quiet);
    if (config.style == TimingStyle::lt && config.quantum_us == 0 && !config.quiet)
        std::fprintf(stderr, "torusrt-sim: warning: --style lt without --quantum: a quantum of 0 synchronises at "
                             "every transfer, as --style at does (give --quantum, e.g. 1ms)\n");
    CameraPathPtr file = read_camera_path_file(cl.anim);
    StagedOutputs outputs;
    stage_outputs(cl, config, cl.anim.animated() ? animation_frame_count(cl.anim, file.get()) : 0, outputs);
    LoadedScene loaded = load_scene(config.scene_path, config.width, config.height, config.cells, config.quiet,
                                    &config.memory, config.preprocess_count);
    check_shade_tree(config.scene_path, loaded.scene.get(), config.step, config.memory, PacketPool::bytes_per_packet());
    nlohmann::json mapping_facts = prepare_mapping(config, loaded.scene.get(), loaded.grid.get());
    if (config.replicated() && cl.remap != RemapPolicy::static_map)
        throw UserError("--map-file: a table with replicated cells is not remapped (--remap)", 2);
    if (cl.anim.animated()) {
        write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), outputs.set, outputs.write_map,
                              outputs.load_map);
        return animate(cl, config, loaded, mapping_facts, outputs, std::move(file), wall_start);
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
    write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), outputs.set, outputs.write_map,
                          outputs.load_map);
    write_png_file(outputs.set.staged(*outputs.png), cl.common.output, cam->width, cam->height, out.rgb8);
    write_stats(outputs, cl, out.report);
    outputs.set.commit();
    if (!config.quiet) {
        print_summary_stdout(out.report);
        print_written(cl, config, cl.common.output);
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
    auto reader = std::make_shared<MachineFileReader>(machine_keys(false), machine_keys(true));
    declare_options(app, reader);
    return run_cli("torusrt-sim", app, argc, argv,
                   [&] {
                       cl.given = given_options(app);
                       resolve_mapping_sources(cl, argc, argv);
                       if (app.get_config_ptr()->count() > 0) cl.config_file = app.get_config_ptr()->as<std::string>();
                       resolve_config_relative_paths(cl, argc, argv);
                       cl.common = common_options_given(cl.given);
                       cl.anim = animation_options_given(cl.given);
                       cl.dump_config = cl.has("--dump-config");
                       cl.with_timing = cl.has("--with-timing");
                       try {
                           if (cl.with_timing && !cl.dump_config)
                               throw UserError("--with-timing: only with --dump-config", 2);
                           return cl.dump_config ? dump_config(cl) : run(cl, wall_start);
                       } catch (const UserError &e) {
                           throw naming_config_file(cl, *reader, e, argc, argv);
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
