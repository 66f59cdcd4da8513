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
#include <utility>
#include <vector>

#include "animation_options.h"
#include "cli_main.h"
#include "common_options.h"
#include "frame_pattern.h"
#include "huge_pages.h"
#include "idle_options.h"
#include "input_file_check.h"
#include "machine_file_reader.h"
#include "machine_options.h"
#include "model_run.h"
#include "motion_options.h"
#include "option_docs.h"
#include "option_parsing.h"
#include "output_files.h"
#include "packet_pool.h"
#include "scene_motion.h"
#include "scene_setup.h"
#include "sim_config.h"
#include "mapping.h"
#include "mapping_setup.h"
#include "option_registration.h"
#include "option_spec.h"
#include "remap_policy.h"
#include "run_options.h"
#include "signal_cleanup.h"
#include "simulation.h"
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
    std::string config_file;  // the --config file read, if any (no output may replace it)
    bool dump_config = false, with_timing = false;

    bool has(const std::string &name) const { return given.count(name) > 0; }
    std::string text(const std::string &name) const
    {
        auto it = given.find(name);
        return it == given.end() ? "" : it->second;
    }
};

// The run's parts of the configuration that the options both executables have set.
void run_from(const CommandLine &cl, const CommonSettings &common, RunOptions &r)
{
    r.scene_path = cl.common.scene;
    r.quiet = cl.common.quiet;
    r.width = common.size[0];
    r.height = common.size[1];
    r.memory = rt_budget_make(common.memory_bytes);
}

// The machine options' keys a machine file may hold with their tables, and those whose bare
// number would be seconds.
std::vector<std::pair<std::string, std::string>> machine_keys()
{
    std::vector<std::pair<std::string, std::string>> keys;
    for (const MachineOption &o : machine_option_table()) keys.emplace_back(o.spec.key, o.table);
    return keys;
}

std::vector<std::string> timed_machine_keys()
{
    std::vector<std::string> keys;
    for (const MachineOption &o : machine_option_table())
        if (o.spec.kind == ValueKind::time && o.spec.unit == "s") keys.push_back(o.spec.key);
    return keys;
}

// "[network], [timing], ...": the machine file's tables for the help.
std::string machine_file_table_names()
{
    std::string s;
    for (const std::string &t : machine_file_tables()) s += (s.empty() ? "[" : ", [") + t + "]";
    return s;
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
    const std::string output_help =
        "PNG image to write; with --frames/--camera-path/--motion a pattern like out_%04d.png";
    add_common_options(app, output_help, {"scene", "--size"});
    app.set_config("--config", "",
                   wrapped("read the machine from this TOML file (as --dump-config writes it), its keys in the "
                           "tables " +
                               machine_file_table_names() +
                               " or at the top; options on the command line take precedence",
                           kHelpColumns - 31))
        ->type_name("FILE")
        ->group(group_title(OptionGroup::machine))
        ->check(input_file_check(kMachineFileMaxBytes));      // before CLI11's own blocking read
    app.allow_config_extras(CLI::config_extras_mode::error);  // an unknown key is an error
    app.config_formatter(reader);
    add_spec_option(app, {"--dump-config", "", ValueKind::flag, "", 0, 0, "",
                          "print the machine as TOML and exit without running", OptionGroup::machine, ""});
    add_spec_option(app, {"--with-timing", "", ValueKind::flag, "", 0, 0, "",
                          "with --dump-config: write every timing value (timing-values), so that the file needs "
                          "no timing file",
                          OptionGroup::machine, ""});
    // Not in the help: docs/cli.md's generated tables (scripts/write_option_docs.py writes them there).
    app.add_flag("--option-tables")->group("")->configurable(false);
    for (const MachineOption &o : machine_option_table()) add_spec_option(app, o.spec);
    add_common_options(app, output_help, {"--output", "--stats"});
    for (const RunOption &o : run_option_table())
        if (o.spec.group == OptionGroup::outputs || o.spec.group == OptionGroup::tracing) add_spec_option(app, o.spec);
    for (const OptionSpec &spec : animation_option_specs()) add_spec_option(app, spec);
    add_spec_option(app, motion_option_spec());
    for (const RunOption &o : run_option_table())
        if (o.spec.group == OptionGroup::animation || o.spec.group == OptionGroup::run) add_spec_option(app, o.spec);
    add_common_options(app, output_help, {"--memory-budget", "--quiet"});
    // The machine options are what a --config file holds (torusrt-render shares some, without files).
    retitle_group(app, group_title(OptionGroup::machine), "Machine (a --config file may hold these)");
    set_help_layout(app, kUsage, kRules, kExamples);
}

// The frames, their remapping and the motion file (read here, exit 2 with FILE:LINE when bad),
// checked before any other file is read (exit 2).
void check_animation(CommandLine &cl, SimRequest &request)
{
    request.motion = read_motion_file(cl.anim.motion);
    take_motion_frame_count(cl.anim, request.motion.get());
    check_animation_options(cl.anim);
    read_animation_run_options(cl.given, cl.anim.animated(), request);
    if (cl.anim.animated() && !cl.common.output.empty()) check_frame_pattern("-o", cl.common.output);
}

bool on_command_line(int argc, char **argv, const std::string &name)
{
    for (int i = 1; i < argc; i++)
        if (argv[i] == name || std::string(argv[i]).rfind(name + "=", 0) == 0) return true;
    return false;
}

// A bad setting (exit 2) whose option came from the --config file, not the command line: the
// message names the file, its line and column too (the option's parser names only the option).
UserError naming_config_file(const CommandLine &cl, const MachineFileReader &reader, const UserError &e, int argc,
                             char **argv)
{
    std::string what = e.what();
    std::string name = what.substr(0, what.find_first_of(" :"));
    std::string at = name.rfind("--", 0) == 0 ? reader.position_of(name.substr(2)) : "";
    if (e.exit_code() != 2 || cl.config_file.empty() || at.empty() || on_command_line(argc, argv, name)) return e;
    return UserError(shown_text(cl.config_file) + ":" + at + ": " + what, 2);
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

// The options turned into the request's checked configuration (UserError on a bad value).
void check_config(const CommandLine &cl, SimRequest &request)
{
    CommonSettings common = parse_common_options(cl.common);
    SimConfig &config = request.config;
    static_cast<MachineConfig &>(config) = machine_from_texts(cl.given);
    run_from(cl, common, config);
    read_run_options(cl.given, request);
    validate(config);
}

// The files a run reads, each with the option that names it.
std::vector<std::pair<std::string, std::string>> run_inputs(const CommandLine &cl, const SimConfig &config)
{
    return {{"scene", cl.common.scene},      {"--config", cl.config_file},           {"--timing", config.timing_file},
            {"--map-file", config.map_file}, {"--camera-path", cl.anim.camera_path}, {"--motion", cl.anim.motion}};
}

// Refuses standard output or error redirected to one of the inputs (exit 2) before any warning
// is printed; standard error that is an input is diverted first, so nothing is written into it.
void check_streams(const CommandLine &cl, const SimConfig &config)
{
    OutputSet streams;
    for (const auto &input : run_inputs(cl, config)) streams.add_input(input.first, input.second);
    streams.check();
}

// --dump-config: the machine of the command line and --config, checked as a run would check
// it, as TOML on stdout.
int dump_config(const CommandLine &cl)
{
    route_systemc_messages(cl.common.quiet);
    SimRequest request;
    check_streams(cl, request.config);  // `--dump-config --config m.toml >> m.toml`: never into an input
    check_config(cl, request);
    check_streams(cl, request.config);  // nor into a file the machine file names
    const SimConfig &config = request.config;
    // The table a run would read, checked as the run checks it.
    if (const auto check = mapping_of(config).check_inputs) check(config);
    std::fputs(machine_options_toml(config, cl.with_timing).c_str(), stdout);
    return 0;
}

// The rest of the request the command line describes: the frames and the files to write.
void fill_request(CommandLine &cl, SimRequest &r)
{
    r.camera_file = read_camera_path_file(cl.anim);
    if (r.motion) check_motion_frames(cl.anim, r.motion.get(), r.camera_file.get());
    r.motion_path = cl.anim.motion;
    if (cl.anim.animated()) {
        r.frame_count = animation_frame_count(cl.anim, r.camera_file.get());
        r.orbit_degrees = cl.anim.orbit_degrees;
        r.camera_source = !cl.anim.orbit.empty() ? "orbit" : !cl.anim.camera_path.empty() ? "camera-path" : "scene";
        for (size_t k = 0; k < r.frame_count; k++) r.frame_files.push_back(frame_file_name(cl.common.output, k));
    }
    r.image = cl.common.output;
    r.stats = cl.common.stats;
    r.inputs = run_inputs(cl, r.config);
}

// --ips N (one number, 3 or more) builds a ring (a line on a mesh), which is easy to take for a
// square machine: a note on standard error says so.
void note_ring(const CommandLine &cl, const SimConfig &config)
{
    const std::string ips = cl.text("--ips");
    if (config.quiet || ips.empty() || ips.find('x') != std::string::npos || config.node_count() < 3) return;
    const rt_topology topo = config.network();
    const char *one_axis = rt_topology_one_axis_name(&topo);
    if (!one_axis) return;
    std::fprintf(stderr,
                 "torusrt-sim: note: --ips %s builds a %dx1x1 %s: a %s of %d (PXxPY or PXxPYxPZ, e.g. 4x4, spreads "
                 "the nodes over two or three dimensions)\n",
                 ips.c_str(), config.node_count(), config.topology.c_str(), one_axis, config.node_count());
}

int run(CommandLine &cl, double wall_start, int argc, char **argv)
{
    require_scene_and_output(cl.common);
    route_systemc_messages(cl.common.quiet);
    SimRequest request;
    check_streams(cl, request.config);  // the inputs named on the command line
    check_animation(cl, request);
    check_config(cl, request);
    check_streams(cl, request.config);  // and those the machine file names
    const SimConfig &config = request.config;
    if (config.replicate > 0 && request.remap != RemapPolicy::static_map)
        throw UserError("--replicate: not with --remap (a remapped table keeps one owner per cell)", 2);
    if (mapping_of(config).no_remap && request.remap != RemapPolicy::static_map)
        throw UserError("--map " + config.mapping + ": not with --remap (" + mapping_of(config).no_remap + ")", 2);
    if (config.replicate > 0 && request.motion)
        throw UserError("--replicate: not with --motion (a moved object's transfers are counted for one owner "
                        "per cell)",
                        2);
    warn_about_settings("torusrt-sim", config.step, config.quiet);
    note_ring(cl, config);
    if (!config.quiet)
        for (const std::string &line :
             idle_option_warnings(config, [&](const std::string &name) { return on_command_line(argc, argv, name); }))
            std::fprintf(stderr, "torusrt-sim: warning: %s\n", line.c_str());
    if (config.style == TimingStyle::lt && config.quantum_us == 0 && !config.quiet)
        std::fprintf(stderr, "torusrt-sim: warning: --style lt with a quantum of 0 (the default) synchronises at "
                             "every transfer, as --style at does (give --quantum, e.g. 1ms)\n");
    fill_request(cl, request);
    return simulate(request, wall_start);
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
    auto reader = std::make_shared<MachineFileReader>(machine_keys(), timed_machine_keys());
    declare_options(app, reader);
    return run_cli(
        "torusrt-sim", app, argc, argv,
        [&] {
            cl.given = given_options(app);
            resolve_mapping_sources(cl, argc, argv);
            if (app.get_config_ptr()->count() > 0) cl.config_file = app.get_config_ptr()->as<std::string>();
            resolve_config_relative_paths(cl, argc, argv);
            cl.common = common_options_given(cl.given);
            cl.anim = animation_options_given(cl.given);
            cl.dump_config = cl.has("--dump-config");
            cl.with_timing = cl.has("--with-timing");
            if (cl.has("--option-tables")) return std::fputs(option_tables_markdown().c_str(), stdout) < 0 ? 1 : 0;
            try {
                if (cl.with_timing && !cl.dump_config) throw UserError("--with-timing: only with --dump-config", 2);
                return cl.dump_config ? dump_config(cl) : run(cl, wall_start, argc, argv);
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
    torusrt::stop_on_signals("torusrt-sim");  // before the re-exec and SystemC's start-up
    torusrt::reexec_with_huge_pages(argv);
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "DISABLE", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}
