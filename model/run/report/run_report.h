// run_report.h - what a run reports, as one plain struct: collect() reads every module's
// statistics once after sc_start (and the queue registry), to_json() writes the JSON report
// from it, print_summary() the human summary and deadlock_text() the stall's description.
#pragma once

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cluster_memory.h"
#include "frame_report.h"
#include "module_stats.h"
#include "packet_ledger.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

class TorusSystem;

struct RunFacts {
    double t1_s = 0;        // T(1): the same model with one processor
    std::string t1_source;  // "passed with --t1", "one-processor run", "this run" or, for an animation, "sum of the
                            // frames' pilots"
    double wall_s = 0;      // wall-clock seconds of the whole run
    // Wall-clock seconds of elaboration (building and binding the modules, SystemC's end of
    // elaboration and start of simulation) and of the simulation after it (sc_start).
    double elaboration_wall_s = 0, sim_wall_s = 0;
    uint64_t delta_cycles = 0;
};

// Replicated cells: how many, the extra copies (owners beyond one per cell), and the data bytes
// those copies add over all nodes.
struct ReplicationReport {
    size_t cells = 0, copies = 0;
    uint64_t bytes = 0;
};

// Data memory, computed once per run (flat: per node; clusters: per processor and data mode).
struct MemoryReport {
    ReplicationReport replication;
    uint64_t max_per_ip_bytes = 0, total_bytes = 0, pixel_partitioned_bytes = 0, whole_scene_bytes = 0;
    bool clustered = false;
    ClusterMemoryFigures cluster;  // clustered only
};

struct ClusterNodeReport {
    int node = 0;
    std::string bus_name;
    uint64_t objects = 0;  // objects the node's cells list
    DispatcherStats dispatcher;
    BusStats bus;
    std::vector<BusPortStats> ports;        // per processor of the node
    std::vector<MemoryPortStats> memories;  // per processor of the node
};

// Sums over the modules, kept beside the per-module figures.
struct RunTotals {
    uint64_t steps = 0, hops = 0, events = 0;
    double busy_s = 0, link_bytes = 0;
    rt_op_counts ops{};
};

struct DeadlockReport {
    double time_s = 0;                                   // simulated time of the stall
    std::vector<QueueStats> full;                        // queues with no room left
    std::vector<std::pair<std::string, int>> bus_waits;  // buses with requesters waiting
    uint64_t held = 0;                                   // packets held in communication units
};

struct RunReport {
    std::string status = "ok";  // "ok" or "deadlock"
    SimConfig config;
    unsigned width = 0, height = 0;
    uint64_t objects = 0, lights = 0;
    double sim_time_s = 0;  // image time; for a deadlock, the time of the stall
    RunFacts facts;
    std::vector<IpStats> ips;  // node-major, index = processor id
    std::vector<LinkStats> links;
    std::vector<CommUnitStats> comm_units;
    HostStats host;
    std::vector<ClusterNodeReport> clusters;  // --cluster > 1
    std::vector<QueueStats> queues;           // the queue registry's order
    double any_stalled_s = 0;                 // time during which some writer of some queue waited
    rt_packet_totals packets{};
    bool conserved = false;
    RunTotals totals;
    MemoryReport memory;
    uint64_t units_serial = 0, units_parallel = 0;
    nlohmann::json units_parallel_by_p;  // preprocess_json's table
    nlohmann::json mapping;              // the mapping set-up's facts (null: none given)
    DeadlockReport deadlock;             // status "deadlock" only
    nlohmann::json flow;                 // flow control: capacities, packet memory, classes (flow_report.h)
    // An animation (no frames: a single image).
    std::vector<FrameRecord> frames;
    RemapSettings remap;
    std::string camera_source, output_pattern;
    nlohmann::json motion;   // a moving scene: the motion file and the updates' totals (null: none)
    nlohmann::json latency;  // packet and pixel latencies (time_report.cpp)
};

// Reads the system after the run. `deadlock`: the network stalled (fills report.deadlock).
RunReport collect(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger, const rt_scene *scene,
                  const rt_grid *grid, const int32_t *cell_owner, const RunFacts &facts, bool deadlock);
nlohmann::json to_json(const RunReport &report);
void print_summary(const RunReport &report, std::FILE *out);
// Where the time goes (time_report.cpp): the JSON's `time` and `latency`, and the summary's
// efficiency factors, time split, latency and busiest links lines.
nlohmann::json time_breakdown_json(const RunReport &report);
nlohmann::json latency_json(const PacketLatency &latency);
void print_efficiency_factors(const RunReport &report, std::FILE *out);
void print_time_split(const RunReport &report, std::FILE *out);
void print_latency(const RunReport &report, std::FILE *out);
void print_busiest_links(const RunReport &report, std::FILE *out);
// Lines naming the full queues (occupancy/capacity, writers waiting) and waiting bus requesters.
std::string deadlock_text(const RunReport &report);

// Parts of collect() and to_json() for clustered runs (cluster_report.cpp).
MemoryReport cluster_memory(const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
                            const int32_t *cell_owner, uint64_t pixel_partitioned);
void collect_clusters(TorusSystem &top, RunReport &report);
void clusters_to_json(const RunReport &report, nlohmann::json &j);

}  // namespace torusrt
