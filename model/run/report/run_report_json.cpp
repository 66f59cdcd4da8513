// run_report_json.cpp - the JSON report, written from a RunReport (keys in docs/report.md).
#include <algorithm>
#include <cstdlib>
#include <utility>

#include "routing.h"
#include "machine_options.h"
#include "run_report.h"
#include "stats_json.h"

namespace torusrt {

namespace {

nlohmann::json min_mean_max(const std::vector<double> &v)
{
    if (v.empty()) return {{"min", 0.0}, {"mean", 0.0}, {"max", 0.0}};
    double sum = 0;
    for (double x : v) sum += x;
    return {{"min", *std::min_element(v.begin(), v.end())},
            {"mean", sum / v.size()},
            {"max", *std::max_element(v.begin(), v.end())}};
}

// The machine's keys from its option table, then the machine as --dump-config writes it.
nlohmann::json config_json(const SimConfig &config)
{
    nlohmann::json j = machine_config_json(config);
    j["options"] = machine_options_json(config);
    j["option_order"] = machine_option_order_json(config);
    j["option_tables"] = machine_option_tables_json(config);  // the machine file's table of each key
    return j;
}

nlohmann::json per_ip_json(const RunReport &r, std::vector<double> &busy)
{
    double T = r.sim_time_s;
    nlohmann::json per_ip = nlohmann::json::array();
    for (size_t i = 0; i < r.ips.size(); i++) {
        const IpStats &p = r.ips[i];
        busy.push_back(p.busy_s);
        per_ip.push_back({{"id", i},
                          {"node", static_cast<int>(i) / r.config.cluster},
                          {"busy_s", p.busy_s},
                          {"idle_s", std::max(0.0, T - p.busy_s)},
                          {"utilisation", T > 0 ? p.busy_s / T : 0.0},
                          {"packets_in", p.packets_in},
                          {"packets_out", p.packets_out},
                          {"tests", p.ops.tests_hit + p.ops.tests_missed},
                          {"queue_high_water", p.queue_high_water},
                          {"ops", ops_json(p.ops)}});
    }
    return per_ip;
}

nlohmann::json links_json(const RunReport &r)
{
    double T = r.sim_time_s;
    const rt_topology topo = r.config.network();
    nlohmann::json per_link = nlohmann::json::array();
    std::vector<double> util;
    for (const LinkStats &l : r.links) {
        double u = T > 0 ? l.busy_s / T : 0.0;
        util.push_back(u);
        per_link.push_back({{"from", l.from},
                            {"to", l.to},
                            {"dir", rt_topology_port_name(&topo, l.dir)},
                            {"packets", l.packets},
                            {"busy_s", l.busy_s},
                            {"utilisation", u},
                            {"queue_high_water", l.queue_high_water}});
    }
    nlohmann::json j = {{"count", r.links.size()},
                        {"packets", r.totals.hops},
                        {"bytes", r.totals.link_bytes},
                        {"utilisation", min_mean_max(util)}};
    j["per_link"] = std::move(per_link);  // an initializer list would copy it
    return j;
}

nlohmann::json memory_json(const RunReport &r)
{
    const MemoryReport &m = r.memory;
    nlohmann::json j;
    if (m.clustered)
        j = cluster_memory_report(m.cluster, r.config.data, r.config.processor_count(), m.pixel_partitioned_bytes);
    else
        j = {{"max_per_ip_bytes", m.max_per_ip_bytes},
             {"total_bytes", m.total_bytes},
             {"pixel_partitioned_bytes", m.pixel_partitioned_bytes}};
    j["whole_scene_bytes"] = m.whole_scene_bytes;
    j["ratio_to_pixel_partitioned"] =
        m.pixel_partitioned_bytes ? static_cast<double>(m.total_bytes) / static_cast<double>(m.pixel_partitioned_bytes)
                                  : 0.0;
    return j;
}

nlohmann::json queue_json(const QueueStats &q)
{
    return {{"name", q.name},
            {"kind", q.kind},
            {"node", q.node},
            {"buffers_used", q.buffers_used},
            {"capacity", q.capacity},
            {"occupancy", q.occupancy},
            {"high_water", q.high_water},
            {"waiting_writers", q.waiting_writers},
            {"stalled_s", q.stalled_s}};
}

nlohmann::json deadlock_json(const DeadlockReport &d)
{
    nlohmann::json full = nlohmann::json::array(), buses = nlohmann::json::array();
    for (const QueueStats &q : d.full) full.push_back(queue_json(q));
    for (const auto &b : d.bus_waits) buses.push_back({{"bus", b.first}, {"waiting", b.second}});
    return {{"time_s", d.time_s}, {"full_queues", full}, {"bus_waits", buses}, {"held_packets", d.held}};
}

}  // namespace

nlohmann::json to_json(const RunReport &r)
{
    double T = r.sim_time_s;
    int n = r.config.processor_count();
    const RunFacts &f = r.facts;
    std::vector<double> busy;
    nlohmann::json per_ip = per_ip_json(r, busy);
    nlohmann::json queues = nlohmann::json::array();
    for (const QueueStats &q : r.queues) queues.push_back(queue_json(q));
    nlohmann::json j = {{"status", r.status},
                        {"scene", r.config.scene_path},
                        {"width", r.width},
                        {"height", r.height},
                        {"cells", r.config.cells},
                        {"objects", r.objects},
                        {"lights", r.lights},
                        {"config", config_json(r.config)},
                        {"sim_time_s", T},
                        {"t1_s", f.t1_s},
                        {"t1_source", f.t1_source},
                        {"ips", n},
                        // The headline: ideal time over actual time, T(1) / (n T(n)). Busy time over n T(n)
                        // only says how evenly the work was spread (hand-over costs count as busy).
                        {"efficiency", T > 0 ? f.t1_s / (n * T) : 0.0},
                        {"efficiency_t1", T > 0 ? f.t1_s / (n * T) : 0.0},
                        {"load_balance", T > 0 ? r.totals.busy_s / (n * T) : 0.0},
                        {"efficiency_busy", T > 0 ? r.totals.busy_s / (n * T) : 0.0},
                        {"load", {{"busy_s", min_mean_max(busy)}}},
                        {"packets", packets_json(r.packets)},
                        {"memory", memory_json(r)},
                        {"preprocess",
                         {{"units_serial", r.units_serial},
                          {"units_parallel", r.units_parallel},
                          {"units_parallel_by_p", r.units_parallel_by_p}}},
                        {"ops", ops_json(r.totals.ops)},
                        {"packet_bytes_wire", r.config.timing.packet_bytes},
                        {"packet_bytes_in_memory", sizeof(rt_packet)},
                        {"wall_s", f.wall_s},
                        {"elaboration_wall_s", f.elaboration_wall_s},
                        {"sim_wall_s", f.sim_wall_s},
                        // What the allocator was told (huge pages; huge_pages.h): it moves the wall times above.
                        {"allocator_tunables", std::getenv("GLIBC_TUNABLES") ? std::getenv("GLIBC_TUNABLES") : ""},
                        {"events", r.totals.events},
                        {"events_per_s", f.sim_wall_s > 0 ? r.totals.events / f.sim_wall_s : 0.0},
                        {"packet_hops", r.totals.hops},
                        {"packet_hops_per_s", f.sim_wall_s > 0 ? r.totals.hops / f.sim_wall_s : 0.0},
                        {"delta_cycles", f.delta_cycles}};
    // The long arrays are moved in: an initializer list copies what it holds (keys are sorted).
    j["links"] = links_json(r);
    j["queues"] = std::move(queues);
    j["per_ip"] = std::move(per_ip);
    j["packets"]["conserved"] = r.conserved;
    if (!r.mapping.is_null()) j["mapping"] = r.mapping;
    const ReplicationReport &rep = r.memory.replication;
    j["replication"] = {{"cells", rep.cells},
                        {"copies", rep.copies},
                        {"bytes", rep.bytes},
                        {"budget", r.config.replicate},
                        {"choice", replica_rule_name(r.config.replica_choice)}};
    if (!r.frames.empty()) {
        j["animation"] = animation_json(r.frames, r.remap);
        j["frames"] = nlohmann::json::array();
        for (const FrameRecord &frame : r.frames) j["frames"].push_back(frame_json(frame));
        j["camera_source"] = r.camera_source;
        j["output_pattern"] = r.output_pattern;
    }
    if (!r.motion.is_null()) j["motion"] = r.motion;
    j["flow"] = r.flow;
    j["time"] = time_breakdown_json(r);
    if (r.latency.is_object()) j["latency"] = r.latency;
    if (r.status == "deadlock") {  // no image was finished: the stall's time is no T(n)
        j["deadlock"] = deadlock_json(r.deadlock);
        j["efficiency"] = j["efficiency_t1"] = nullptr;
    }
    if (!r.clusters.empty()) clusters_to_json(r, j);
    return j;
}

}  // namespace torusrt
