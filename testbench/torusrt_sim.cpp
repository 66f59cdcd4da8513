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
#include "timing_choice.h"
#include "mapping_setup.h"
#include "user_error.h"

using namespace torusrt;

namespace {

struct CommandLine {
    std::string output, stats, timing_file, ips = "1", map = "cyclic", topology = "torus", cells = "24", size;
    std::string min_weight = "1/512", style = "at", quantum = "0", data = "replicated", arbiter = "round-robin";
    std::string dispatch = "round-robin", trace_ips, link_us, packet_bytes, link_bytes_per_us, t1;
    long long queue = 0;
    int max_depth = 8;
    // Timing profiles and mappings (their own block).
    std::string timing_profile;
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
    c.ips = parse_dims_1_to_3("--ips", cl.ips, 1, 4096);
    c.mapping = parse_mapping(cl.map, c.block);
    c.topology = parse_choice("--topology", cl.topology, "torus", Topology::torus, "mesh", Topology::mesh);
    if (cl.queue < 0 || cl.queue > 100000000) throw UserError("--queue: must be 0 (unbounded) to 100000000", 2);
    c.queue_capacity = static_cast<unsigned>(cl.queue);
    c.timing_profile = choose_timing(cl.timing_profile, cl.timing_file, &c.timing);
    char msg[RT_MSG_LEN] = "";
    auto set = [&](const char *key, const std::string &opt, const std::string &text) {
        if (text.empty()) return;
        double v = parse_non_negative(opt, text);
        if (rt_timing_set(&c.timing, key, v, msg, sizeof msg) != RT_OK) throw UserError(opt + ": " + msg, 2);
    };
    set("link", "--link-us", cl.link_us);
    set("packet_bytes", "--packet-bytes", cl.packet_bytes);
    set("link_bytes_per_us", "--link-bytes-per-us", cl.link_bytes_per_us);
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
        if (!(c.t1_s > 0)) throw UserError("--t1: must be a positive number of seconds", 2);
    }
    return c;
}

}  // namespace

int sc_main(int argc, char **argv)
{
    double wall_start = seconds_now();
    sc_core::sc_report_handler::set_actions(sc_core::SC_FATAL, sc_core::SC_DISPLAY | sc_core::SC_THROW);
    sc_core::sc_report_handler::set_actions(sc_core::SC_ERROR, sc_core::SC_DISPLAY | sc_core::SC_THROW);

    CommandLine cl;
    MappingOptions mapping_options;
    std::string scene, vcd;
    int cluster = 1;
    bool quiet = false;
    CLI::App app{"torusrt-sim: a SystemC/TLM-2.0 model of the object-space-parallel ray-tracing\n"
                 "multiprocessor (Kubota et al.): intersection processors on a torus exchange ray packets."};
    app.add_option("scene", scene, "scene file (NFF)")->required();
    app.add_option("-o,--output", cl.output, "PNG image to write")->required();
    app.add_option("--stats", cl.stats, "write the statistics as JSON to this file");
    app.add_option("--vcd", vcd, "write a VCD trace (IP busy, queue depths, link and bus activity)");
    app.add_option("--trace-ips", cl.trace_ips, "trace only these nodes, e.g. 0,1,5 (default all)");
    app.add_option("--ips", cl.ips, "torus nodes: P, PXxPY or PXxPYxPZ (default 1)");
    app.add_option("--map", cl.map, "cell mapping: block, cyclic (default) or block-cyclic:B");
    app.add_option("--topology", cl.topology, "torus (default, rings) or mesh (no wrap-around)");
    app.add_option("--cells", cl.cells, "grid cells: N or NXxNYxNZ (default 24)");
    app.add_option("--size", cl.size, "image size WxH, overriding the scene's resolution");
    app.add_option("--queue", cl.queue, "capacity of every packet queue, 0 = unbounded (default)");
    app.add_option("--timing", cl.timing_file, "timing file overriding the paper's table");
    app.add_option("--link-us", cl.link_us, "microseconds per packet on a link (default 50)");
    app.add_option("--packet-bytes", cl.packet_bytes, "packet size on the wire in bytes (default 28)");
    app.add_option("--link-bytes-per-us", cl.link_bytes_per_us,
                   "link bandwidth; when > 0 a packet takes packet-bytes / this (default 0: use --link-us)");
    app.add_option("--max-depth", cl.max_depth, "deepest shade-tree depth of a ray (default 8)");
    app.add_option("--min-weight", cl.min_weight, "smallest ray weight, e.g. 1/512 (default)");
    app.add_option("--style", cl.style, "timing style: at (approximately timed, default) or lt (loosely timed)");
    app.add_option("--quantum", cl.quantum, "loosely-timed global quantum with a unit, e.g. 500us, 10ms");
    app.add_option("--cluster", cluster, "processors per torus node on a shared bus (default 1)");
    app.add_option("--data", cl.data, "object data in a cluster: replicated (default) or shared");
    app.add_option("--arbiter", cl.arbiter, "cluster bus arbiter: round-robin (default) or fixed-priority");
    app.add_option("--dispatch", cl.dispatch, "cluster packet dispatch: round-robin (default) or shortest-queue");
    app.add_option("--t1", cl.t1, "T(1) in seconds for efficiency_t1 (default: run the model with one processor)");
    app.add_flag("-q,--quiet", quiet, "print nothing but errors; no progress");
    add_mapping_options(app, cl.timing_profile, mapping_options); // profiles and mappings
    return run_cli("torusrt-sim", app, argc, argv, [&]() -> int {
        SimConfig config = make_config(scene, cl, quiet);
        config.cluster = cluster;
        config.vcd_path = vcd;
        apply_mapping_options(config, mapping_options, app.count("--map") > 0);
        validate(config);
        check_output_folder("-o", cl.output);
        if (!cl.stats.empty()) check_output_folder("--stats", cl.stats);
        if (!vcd.empty()) check_output_folder("--vcd", vcd);
        LoadedScene loaded = load_scene(scene, config.width, config.height, config.cells, quiet);
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
        write_png_file(cl.output, cam->width, cam->height, out.rgb8);
        try {
            write_mapping_outputs(config, loaded.scene.get(), loaded.grid.get(), mapping_options);
            if (!cl.stats.empty()) write_text_file(cl.stats, out.report.dump(2) + "\n");
        } catch (...) {
            remove_file(cl.output);
            remove_mapping_outputs(mapping_options);
            if (!vcd.empty()) remove_file(vcd);
            throw;
        }
        if (!quiet) print_summary_stdout(out.report);
        return 0;
    });
}

// Our own entry point: the SystemC banner is printed before sc_main runs, so it is switched off here.
int main(int argc, char **argv)
{
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "DISABLE", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}
