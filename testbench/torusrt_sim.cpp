// torusrt_sim.cpp - the main simulator: the object-space-parallel ray-tracing machine as a
// SystemC/TLM-2.0 model, on one scene, with one configuration.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <systemc>

#include "cli_main.h"
#include "model_run.h"
#include "option_parsing.h"
#include "output_files.h"
#include "scene_setup.h"
#include "sim_config.h"
#include "mapping_setup.h"
#include "systemc_messages.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

using namespace torusrt;

namespace {

struct CommandLine {
    std::string output, stats, timing_file, ips = "1", map = "cyclic", topology = "torus", cells = "24", size;
    std::string min_weight = "1/512", style = "at", quantum = "0", data = "replicated", arbiter = "round-robin";
    std::string dispatch = "round-robin", trace_ips, link_us, packet_bytes, link_bytes_per_us, t1;
    std::string memory_budget = "4G";
    std::string flow = "classes";
    std::string trace_from, trace_to, time_limit, scene, vcd;
    int cluster = 1;
    bool quiet = false;
    long long queue = 0;
    int max_depth = 8;
    // Timing profiles and mappings (their own block).
    std::string timing_profile;
    MappingOptions mapping;
    bool map_given = false; // --map was on the command line or in the --config file
    bool dump_config = false;
};

double seconds_now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

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

template <typename E>
E parse_choice(const std::string &option, const std::string &text, const char *a, E ea, const char *b, E eb)
{
    if (text == a) return ea;
    if (text == b) return eb;
    throw UserError(option + " '" + text + "': expected " + a + " or " + b, 2);
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

SimConfig make_config(const std::string &scene, const CommandLine &cl, bool quiet)
{
    SimConfig c;
    c.scene_path = scene;
    c.quiet = quiet;
    c.cells = parse_triple("--cells", cl.cells, 1, RT_GRID_MAX_CELLS_PER_AXIS);
    if (!cl.size.empty()) {
        auto s = parse_size("--size", cl.size);
        c.width = s[0];
        c.height = s[1];
    }
    c.ips = parse_dims_1_to_3("--ips", cl.ips, 1, kMaxNodes);
    c.mapping = parse_mapping(cl.map, c.block);
    c.topology = parse_choice("--topology", cl.topology, "torus", Topology::torus, "mesh", Topology::mesh);
    if (cl.queue < 0 || cl.queue > 100000000) throw UserError("--queue: must be 0 (unbounded) to 100000000", 2);
    c.queue_capacity = static_cast<unsigned>(cl.queue);
    c.flow = parse_choice("--flow", cl.flow, "classes", FlowControl::classes, "none", FlowControl::none);
    c.timing_profile = choose_timing(cl.timing_profile, cl.timing_file, &c.timing);
    char msg[RT_MSG_LEN] = "";
    std::string problem = timing_limit_problem(c.timing);
    if (!problem.empty()) throw UserError((cl.timing_file.empty() ? c.timing_profile : cl.timing_file) + ": " + problem);
    auto set = [&](const char *key, const std::string &opt, const std::string &text, bool is_time) {
        if (text.empty()) return;
        double v = is_time ? parse_time_us(opt, text) : parse_non_negative(opt, text);
        if (rt_timing_set(&c.timing, key, v, msg, sizeof msg) != RT_OK) throw UserError(opt + ": " + msg, 2);
        std::string why = timing_limit_problem(c.timing);
        if (!why.empty()) throw UserError(opt + " '" + text + "': " + why, 2);
    };
    set("link", "--link-us", cl.link_us, true);
    set("packet_bytes", "--packet-bytes", cl.packet_bytes, false);
    set("link_bytes_per_us", "--link-bytes-per-us", cl.link_bytes_per_us, false);
    c.step = rt_step_params_default();
    c.step.max_depth = cl.max_depth;
    c.step.min_weight = parse_fraction("--min-weight", cl.min_weight);
    c.style = parse_choice("--style", cl.style, "at", TimingStyle::at, "lt", TimingStyle::lt);
    c.quantum_us = parse_time_us("--quantum", cl.quantum);
    c.data = parse_choice("--data", cl.data, "replicated", DataMode::replicated, "shared", DataMode::shared);
    c.arbiter = parse_choice("--arbiter", cl.arbiter, "round-robin", ArbiterPolicy::round_robin, "fixed-priority",
                             ArbiterPolicy::fixed_priority);
    c.dispatch = parse_choice("--dispatch", cl.dispatch, "round-robin", DispatchPolicy::round_robin,
                              "shortest-queue", DispatchPolicy::shortest_queue);
    if (!cl.trace_ips.empty()) c.trace_ips = parse_list("--trace-ips", cl.trace_ips);
    if (!cl.t1.empty()) {
        c.t1_s = parse_non_negative("--t1", cl.t1);
        if (!(c.t1_s > 0) || c.t1_s > kMaxSimTimeS)
            throw UserError("--t1 '" + cl.t1 + "': must be a positive number of seconds, at most " +
                                std::to_string(static_cast<long>(kMaxSimTimeS)), 2);
    }
    if (!cl.time_limit.empty()) c.time_limit_s = parse_time_us("--time-limit", cl.time_limit) * 1e-6;
    if (!cl.trace_from.empty()) c.trace_from_us = parse_time_us("--trace-from", cl.trace_from);
    if (!cl.trace_to.empty()) c.trace_to_us = parse_time_us("--trace-to", cl.trace_to);
    return c;
}

void declare_options(CLI::App &app, CommandLine &cl)
{
    // The scene and the outputs are not configurable: a machine file names no files to write.
    // scene and -o are checked in run(), so that --dump-config can go without them.
    app.add_option("scene", cl.scene, "scene file (NFF)")->type_name("FILE")->configurable(false);
    app.add_option("-o,--output", cl.output, "PNG image to write")->type_name("FILE")->configurable(false);
    app.add_option("--stats", cl.stats, "write the statistics as JSON to this file")->type_name("FILE")
        ->configurable(false);
    app.add_option("--vcd", cl.vcd, "write a VCD trace (IP busy, queue depths, link and bus activity) and a GTKWave\n"
                               "save file beside it (X.gtkw for X.vcd)")->type_name("FILE")->configurable(false);
    app.allow_config_extras(CLI::config_extras_mode::error);  // an unknown key is an error
    app.set_config("--config", "", "read options from this TOML/INI file (as --dump-config writes it);\n"
                                   "options on the command line take precedence")->type_name("FILE");
    app.add_flag("--dump-config", cl.dump_config, "print the effective options as TOML and exit without running")
        ->configurable(false);
    app.add_option("--trace-from", cl.trace_from, "trace only from this simulated time (default 0)")->type_name("TIME");
    app.add_option("--trace-to", cl.trace_to, "trace only up to this simulated time (default: the end)")->type_name("TIME");
    app.add_option("--trace-ips", cl.trace_ips, "trace only these nodes, e.g. 0,1,5 (default all)")->type_name("N,N,...");
    app.add_option("--ips", cl.ips, "torus nodes: P, PXxPY or PXxPYxPZ (default 1, at most 4096)")->type_name("DIMS");
    app.add_option("--map", cl.map, "cell mapping: block, cyclic (default), block-cyclic:B, cost or cost:K")->type_name("KIND");
    app.add_option("--topology", cl.topology, "torus (default, rings) or mesh (no wrap-around)")->type_name("KIND");
    app.add_option("--cells", cl.cells, "grid cells: N or NXxNYxNZ (default 24)")->type_name("DIMS");
    app.add_option("--size", cl.size, "image size WxH, overriding the scene's resolution")->type_name("WxH");
    app.add_option("--queue", cl.queue, "capacity of every packet buffer (of each class), 0 = unbounded (default)")
        ->type_name("N");
    app.add_option("--flow", cl.flow, "flow control: classes (default, deadlock-free class-split buffers) or none\n"
                                     "(one class; finite buffers may deadlock, exit 3)")->type_name("SCHEME");
    app.add_option("--timing", cl.timing_file, "timing file overriding the paper's table")->type_name("FILE");
    app.add_option("--link-us", cl.link_us, "time per packet on a link: microseconds, or with a unit ns, us, ms, s\n"
                                         "(default 50)")->type_name("TIME");
    app.add_option("--packet-bytes", cl.packet_bytes, "packet size on the wire in bytes (default 28)")->type_name("BYTES");
    app.add_option("--link-bytes-per-us", cl.link_bytes_per_us,
                   "link bandwidth; when > 0 a packet takes packet-bytes / this (default 0: use --link-us)")
        ->type_name("RATE");
    app.add_option("--max-depth", cl.max_depth, "deepest shade-tree depth of a ray (default 8)")->type_name("N");
    app.add_option("--min-weight", cl.min_weight, "smallest ray weight, e.g. 1/512 (default)")->type_name("W");
    app.add_option("--style", cl.style, "timing style: at (approximately timed, default) or lt (loosely timed)")
        ->type_name("at|lt");
    app.add_option("--quantum", cl.quantum, "loosely-timed global quantum, same syntax as --link-us, e.g. 500us, 10ms")
        ->type_name("TIME");
    app.add_option("--cluster", cl.cluster, "processors per torus node on a shared bus (default 1)")->type_name("N");
    app.add_option("--data", cl.data, "object data in a cluster: replicated (default) or shared")->type_name("KIND");
    app.add_option("--arbiter", cl.arbiter, "cluster bus arbiter: round-robin (default) or fixed-priority")->type_name("KIND");
    app.add_option("--dispatch", cl.dispatch, "cluster packet dispatch: round-robin (default) or shortest-queue")
        ->type_name("KIND");
    app.add_option("--t1", cl.t1, "T(1) in seconds for the efficiency T(1)/(n T(n)) (default: run the model with one processor)")
        ->type_name("SECONDS");
    app.add_option("--time-limit", cl.time_limit, "stop with an error (exit 1) when simulated time passes this\n"
                   "(default and maximum 1e7 s, SystemC's 64-bit picosecond time holds 1.8e7 s)")->type_name("TIME");
    app.add_option("--memory-budget", cl.memory_budget, "memory the run may use for cell lists, frame buffer and\n"
                   "packets, e.g. 512M or 4G; 0 = no limit (default 4G)")->type_name("SIZE");
    app.add_flag("-q,--quiet", cl.quiet, "print nothing but errors; no progress");
    add_mapping_options(app, cl.timing_profile, cl.mapping); // profiles and mappings
}

// The options turned into a checked configuration (UserError on a bad value).
SimConfig checked_config(const CommandLine &cl)
{
    SimConfig config = make_config(cl.scene, cl, cl.quiet);
    config.cluster = cl.cluster;
    config.vcd_path = cl.vcd;
    apply_mapping_options(config, cl.mapping, cl.map_given);
    validate(config);
    return config;
}

// --dump-config: the options from the command line and --config, and the defaults of the rest,
// checked as a run would check them, as TOML on stdout.
int dump_config(CLI::App &app, const CommandLine &cl)
{
    route_systemc_messages(cl.quiet);
    checked_config(cl);
    // --map-file replaces --map: its default must not come back as a conflicting --map.
    if (!cl.mapping.map_file.empty() && !cl.map_given) app.get_option("--map")->configurable(false);
    for (CLI::Option *opt : app.get_options())  // an option not given still holds its default
        if (opt->count() == 0) opt->capture_default_str();
    std::fputs(app.config_to_str(true, false).c_str(), stdout);
    return 0;
}

int run(const CommandLine &cl, double wall_start)
{
    if (cl.scene.empty()) throw UserError("scene is required", 2);
    if (cl.output.empty()) throw UserError("--output is required", 2);
    route_systemc_messages(cl.quiet);
    SimConfig config = checked_config(cl);
    if (config.step.min_weight > 1 && !cl.quiet)
        std::fprintf(stderr, "torusrt-sim: warning: --min-weight %g is above 1: every secondary ray is dropped\n",
                     config.step.min_weight);
    OutputSet outputs;
    std::string png = outputs.add("-o", cl.output, cl.scene);
    std::string stats = cl.stats.empty() ? "" : outputs.add("--stats", cl.stats, cl.scene);
    if (!cl.vcd.empty()) {
        config.vcd_write_path = outputs.add("--vcd", cl.vcd, cl.scene);
        if (!is_special_file(cl.vcd)) {  // no save file beside /dev/null
            config.gtkw_path = save_file_path(cl.vcd);
            config.gtkw_write_path = outputs.add("--vcd (save file)", config.gtkw_path, cl.scene);
        }
    }
    std::string map_out = cl.mapping.write_map.empty() ? "" : outputs.add("--write-map", cl.mapping.write_map, cl.scene);
    std::string load_map = cl.mapping.load_map.empty() ? "" : outputs.add("--load-map", cl.mapping.load_map, cl.scene);

    config.memory = rt_budget_make(parse_memory_size("--memory-budget", cl.memory_budget));
    LoadedScene loaded = load_scene(cl.scene, config.width, config.height, config.cells, cl.quiet, &config.memory);
    nlohmann::json mapping_facts = prepare_mapping(config, loaded.scene.get(), loaded.grid.get());
    double t1 = config.t1_s;
    std::string t1_source = "passed with --t1";
    if (t1 < 0 && config.processor_count() > 1) {
        t1 = one_processor_time(config, loaded.scene.get(), loaded.grid.get());
        t1_source = "one-processor run";
    }
    ModelOutcome out = run_model(config, loaded.scene.get(), loaded.grid.get(), t1, t1_source, wall_start);
    if (out.deadlock) {
        std::fprintf(stderr,
                     "torusrt-sim: deadlock: the network stalled at %.6f s simulated with packets still "
                     "outstanding (queue capacity %u)\n%s",
                     out.sim_time_s, config.queue_capacity, out.deadlock_details.c_str());
        return 3;
    }
    const rt_camera *cam = rt_scene_camera(loaded.scene.get());
    out.report["mapping"] = mapping_facts;
    write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), map_out, load_map);
    write_png_file(png, cl.output, cam->width, cam->height, out.rgb8);
    if (!stats.empty()) write_text_file(stats, cl.stats, out.report.dump(2) + "\n");
    outputs.commit();
    if (!cl.quiet) {
        print_summary_stdout(out.report);
        std::printf("  wrote        %s", cl.output.c_str());
        if (!cl.stats.empty()) std::printf(", %s", cl.stats.c_str());
        if (!cl.vcd.empty()) std::printf(", %s", cl.vcd.c_str());
        if (!config.gtkw_path.empty()) std::printf(" (gtkwave %s)", config.gtkw_path.c_str());
        std::printf("\n");
    }
    return 0;
}

}  // namespace

int sc_main(int argc, char **argv)
{
    double wall_start = seconds_now();
    sc_core::sc_report_handler::set_actions(sc_core::SC_FATAL, sc_core::SC_DISPLAY | sc_core::SC_THROW);
    sc_core::sc_report_handler::set_actions(sc_core::SC_ERROR, sc_core::SC_DISPLAY | sc_core::SC_THROW);
    CommandLine cl;
    CLI::App app{"torusrt-sim: a SystemC/TLM-2.0 model of the object-space-parallel ray-tracing\n"
                 "multiprocessor (Kubota et al.): intersection processors on a torus exchange ray packets."};
    declare_options(app, cl);
    return run_cli("torusrt-sim", app, argc, argv,
                   [&] {
                       cl.map_given = app.count("--map") > 0;
                       return cl.dump_config ? dump_config(app, cl) : run(cl, wall_start);
                   },
                   "  3 deadlock: the network stalled with packets outstanding\n");
}

// Our own entry point: the SystemC banner is printed before sc_main runs, so it is switched off here.
int main(int argc, char **argv)
{
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "DISABLE", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}
