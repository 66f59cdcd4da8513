// sim_config.h - every setting of a model run in one struct: defaults, then the timing
// file, then command-line overrides, checked by one validator.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "rt_budget.h"
#include "rt_mapping.h"
#include "rt_step.h"
#include "rt_timing.h"

namespace torusrt {

// A run stops with an error when simulated time passes this (SystemC's time is a 64-bit count
// of picoseconds, about 1.8e7 s).
constexpr double kMaxSimTimeS = 1e7;
// The most nodes (and processors) that elaborate: each has its own SystemC threads and stacks;
// 8192 processors exceed Linux's default 65530 memory maps per process and abort.
constexpr int kMaxNodes = 4096;
constexpr int kMaxProcessors = 4096;

enum class Topology { torus, mesh };
enum class TimingStyle { at, lt };
enum class DataMode { replicated, shared };
enum class ArbiterPolicy { round_robin, fixed_priority };
enum class DispatchPolicy { round_robin, shortest_queue };
enum class FlowControl { none, classes }; // see flow_control.h

struct SimConfig {
    std::string scene_path;                 // NFF scene
    std::array<int, 3> cells{24, 24, 24};   // grid cells per axis
    unsigned width = 0, height = 0;         // image size override (0 = the scene's)
    std::array<int, 3> ips{1, 1, 1};        // torus nodes per axis
    rt_map_kind mapping = RT_MAP_CYCLIC;    // cell-to-node mapping
    int block = 1;                          // block size for block-cyclic
    Topology topology = Topology::torus;    // rings in every dimension, or a mesh
    unsigned queue_capacity = 0;            // packets per buffer (per class), 0 = unbounded
    FlowControl flow = FlowControl::classes; // deadlock-free class split, or one class (none)
    rt_timing timing{};                     // operation and transfer times
    std::string timing_profile;             // which profile (and file) the timing came from
    rt_step_params step{};                  // shade-tree limits
    TimingStyle style = TimingStyle::at;    // approximately- or loosely-timed
    double quantum_us = 0;                  // loosely-timed global quantum
    int cluster = 1;                        // processors per node (1 = flat torus)
    DataMode data = DataMode::replicated;   // object data in a cluster
    ArbiterPolicy arbiter = ArbiterPolicy::round_robin;
    DispatchPolicy dispatch = DispatchPolicy::round_robin;
    std::string vcd_path;                   // VCD trace file ("" = no tracing)
    std::string vcd_write_path;             // where it is written now (a temporary or vcd_path)
    std::string gtkw_path, gtkw_write_path; // GTKWave save file beside it ("" = none)
    double trace_from_us = 0;               // trace window start
    double trace_to_us = -1;                // trace window end (< 0: the end of the run)
    std::vector<int> trace_ips;             // nodes to trace (empty = all)
    double t1_s = -1;                       // T(1) passed in (< 0: compute)
    rt_budget memory{};                     // what is left of --memory-budget for packets
    double time_limit_s = kMaxSimTimeS;     // stop with an error past this simulated time
    // Mapping inputs and the table a run uses (filled by prepare_mapping before the run).
    std::string map_file;                   // --map-file: explicit cell -> node table
    std::string write_map;                  // --write-map: where to write the table used
    std::array<unsigned, 2> pilot_size{0, 0}; // --pilot-size for --map cost (0 = the image's)
    std::vector<int32_t> owner_table;       // node of every cell (empty: rt_mapping_fill)
    bool quiet = false;

    int node_count() const { return ips[0] * ips[1] * ips[2]; }
    int processor_count() const { return node_count() * cluster; }
};

// Throws UserError (exit 2) naming the first bad setting.
void validate(const SimConfig &config);

const char *mapping_name(rt_map_kind kind);
const char *topology_name(Topology t);
const char *style_name(TimingStyle s);
const char *data_mode_name(DataMode d);
const char *arbiter_name(ArbiterPolicy a);
const char *dispatch_name(DispatchPolicy d);
const char *flow_name(FlowControl f);

}  // namespace torusrt
