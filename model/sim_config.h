// sim_config.h - the settings of a model run in two parts: the machine (what is simulated:
// topology, mapping, capacities, timing, cluster, policies) and the run options (the scene, its
// image size, the outputs, tracing, limits). The hardware modules see only the machine.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "named_values.h"
#include "routing.h"
#include "preprocess_count.h"
#include "rt_budget.h"
#include "rt_memory.h"
#include "rt_replicas.h"
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
constexpr int kMaxCluster = 256;
constexpr unsigned kMaxQueue = 100000000;   // packets per queue
constexpr unsigned kMaxRecordBytes = 4096;  // --cell-header-bytes, --list-entry-bytes, --object-record-bytes

enum class TimingStyle { at, lt };
enum class DataMode { replicated, shared };
enum class FlowControl { none, classes };               // see flow_control.h
enum class ReplicaRule { nearest, hash };               // see replica_choice.h
enum class QueueOrder { primaries_first, rays_first };  // see packet_queue.h

// The names the options take and the reports print (the topology, the arbiter and dispatch
// policies and the mappings are named by their registries, rt_topology.h, bus_arbiter.h,
// cluster_dispatch.h and run/mapping/mapping.h).
constexpr NamedValue<RouteTies> kRouteTiesNames[] = {{RouteTies::split, "split"}, {RouteTies::plus, "plus"}};
constexpr NamedValue<TimingStyle> kStyleNames[] = {{TimingStyle::at, "at"}, {TimingStyle::lt, "lt"}};
constexpr NamedValue<DataMode> kDataModeNames[] = {{DataMode::replicated, "replicated"}, {DataMode::shared, "shared"}};
constexpr NamedValue<FlowControl> kFlowNames[] = {{FlowControl::classes, "classes"}, {FlowControl::none, "none"}};
constexpr NamedValue<ReplicaRule> kReplicaRuleNames[] = {{ReplicaRule::nearest, "nearest"},
                                                         {ReplicaRule::hash, "hash"}};
constexpr NamedValue<QueueOrder> kQueueOrderNames[] = {{QueueOrder::primaries_first, "primaries-first"},
                                                       {QueueOrder::rays_first, "rays-first"}};

// The default profile's timing table (rt_timing_default_profile()).
inline rt_timing default_timing()
{
    rt_timing timing;
    rt_timing_profile(rt_timing_default_profile(), &timing, nullptr, 0);
    return timing;
}

// The machine: everything that decides the image time. machine_options.h writes it back as
// the options that rebuild it (--dump-config, the JSON report's config.options). Each field's
// initialiser is its option's default, written nowhere else: the option table's help and docs
// show what a default-constructed machine holds (machine_option_table).
struct MachineConfig {
    std::array<int, 3> ips{1, 1, 1};                             // nodes per axis of the mapping's grid
    std::string topology = "torus";                              // the network, by its registered name
    RouteTies route_ties = kDefaultRouteTies;                    // the way round an even ring on a tie
    std::array<int, 3> cells{24, 24, 24};                        // grid cells per axis (the object space's division)
    rt_preprocess_count preprocess_count = RT_COUNT_SEQUENTIAL;  // how preprocessing units are counted
    std::string mapping = "cyclic";                              // cell-to-node mapping, by its registered name
    int block = 1;                                               // block size of block-cyclic, K of cost:K
    std::string map_file;                                        // --map-file: explicit cell -> node table
    std::array<unsigned, 2> pilot_size{0, 0};                    // --pilot-size for --map cost (0 = the image's)
    double replicate = 0;                                  // --replicate: extra memory per node for replicas (fraction)
    ReplicaRule replica_choice = ReplicaRule::nearest;     // which owner of a replicated cell a packet goes to
    unsigned queue_capacity = 0;                           // packets per buffer (per class), 0 = unbounded
    FlowControl flow = FlowControl::classes;               // deadlock-free class split, or one class (none)
    QueueOrder queue_order = QueueOrder::primaries_first;  // which waiting packet an IP takes up next
    rt_timing timing = default_timing();                   // operation and transfer times
    std::string timing_profile = rt_timing_default_profile();  // label: the profile, with " + FILE" for a file
    std::string timing_base = rt_timing_default_profile();     // the built-in profile the table started from
    std::string timing_file;                                   // the timing file applied on top ("" = none)
    bool timing_values = false;                                // --timing-values set the whole table
    rt_step_params step = rt_step_params_default();            // shade-tree limits
    TimingStyle style = TimingStyle::at;                       // approximately- or loosely-timed
    double quantum_us = 0;                                     // loosely-timed global quantum
    int cluster = 1;                                           // processors per node (1 = flat torus)
    DataMode data = DataMode::replicated;                      // object data in a cluster
    std::string arbiter = "round-robin";   // cluster bus arbiter, by its registered name (bus_arbiter.h)
    std::string dispatch = "round-robin";  // cluster packet dispatch, by name (cluster_dispatch.h)
    rt_memory_layout memory_layout = rt_memory_layout_default();  // what the memory report charges

    int node_count() const { return ips[0] * ips[1] * ips[2]; }
    // The network of the nodes (the validator has checked that `topology` takes `ips`).
    rt_topology network() const { return make_topology(ips, topology); }
    int processor_count() const { return node_count() * cluster; }
};

// The run: what is rendered and what is written, watched and allowed. None of it changes the
// simulated time (the image size is the workload's, like the scene).
struct RunOptions {
    std::string scene_path;                  // NFF scene
    unsigned width = 0, height = 0;          // image size override (0 = the scene's)
    std::string vcd_path;                    // VCD trace file ("" = no tracing)
    std::string vcd_write_path;              // where it is written now (a temporary or vcd_path)
    std::string gtkw_path, gtkw_write_path;  // GTKWave save file beside it ("" = none)
    double trace_from_us = 0;                // trace window start
    double trace_to_us = -1;                 // trace window end (< 0: the end of the run)
    std::vector<int> trace_ips;              // nodes to trace (empty = all)
    double t1_s = -1;                        // T(1) passed in (< 0: compute)
    rt_budget memory{};                      // what is left of --memory-budget for packets
    double time_limit_s = kMaxSimTimeS;      // stop with an error past this simulated time
    std::string write_map;                   // --write-map: where to write the table used
    bool quiet = false;
    double stats_interval_s = 0;    // --stats-interval: the time series' interval (0: no series)
    double progress_every_s = 10;   // seconds between progress lines in a batch log (0: none)
    bool stderr_is_output = false;  // an output goes to standard error: no progress shown
};

// A run of a machine, with the cell -> node table prepared for it (prepare_mapping).
struct SimConfig : MachineConfig, RunOptions {
    std::vector<int32_t> owner_table;  // node of every cell (empty: the mapping fills it)
    // Extra owners of replicated cells (rt_replicas.h; both empty: none): per cell, cells + 1
    // offsets into replica_extra.
    std::vector<uint32_t> replica_first;
    std::vector<int32_t> replica_extra;
    bool replicated() const { return !replica_extra.empty(); }
    // The table as the kernel reads it (replicated() only).
    rt_replicas replica_table() const { return {replica_first.data(), replica_extra.data()}; }
};

// The one validator (config_validation.cpp): every range and every combination of settings,
// before the scene is loaded. Throws UserError (exit 2) naming the option of the first bad one.
void validate_machine(const MachineConfig &machine);
void validate_run(const RunOptions &run, const MachineConfig &machine);
void validate(const SimConfig &config);

inline const char *route_ties_name(RouteTies r) { return name_in(kRouteTiesNames, r); }
inline const char *style_name(TimingStyle s) { return name_in(kStyleNames, s); }
inline const char *data_mode_name(DataMode d) { return name_in(kDataModeNames, d); }
inline const char *flow_name(FlowControl f) { return name_in(kFlowNames, f); }
inline const char *replica_rule_name(ReplicaRule r) { return name_in(kReplicaRuleNames, r); }
inline const char *queue_order_name(QueueOrder o) { return name_in(kQueueOrderNames, o); }

}  // namespace torusrt
