// cluster_report.cpp - the clustered run's part of the report: the memory figures, the buses,
// dispatchers, bus ports and 2-port memories (collect), and the `cluster.` and `bus.` sections.
#include <algorithm>

#include "cluster_node.h"
#include "run_report.h"
#include "torus_system.h"

namespace torusrt {

namespace {

double to_us(uint64_t ticks) { return sc_core::sc_time::from_value(ticks).to_seconds() * 1e6; }

nlohmann::json wait_json(const GrantWait &g)
{
    double mean = g.grants ? to_us(g.wait_sum) / static_cast<double>(g.grants) : 0.0;
    return {{"mean", mean}, {"max", to_us(g.wait_max)}};
}

double bus_utilisation(const BusStats &b, double T) { return T > 0 ? std::min(1.0, b.busy_s / T) : 0.0; }

nlohmann::json bus_json(const RunReport &r, const ClusterNodeReport &c)
{
    int m = r.config.cluster;
    const BusStats &bus = c.bus;
    nlohmann::json requesters = nlohmann::json::array();
    for (size_t k = 0; k < bus.per_requester.size(); k++) {
        int q = static_cast<int>(k);
        requesters.push_back({{"requester", q},
                              {"master", q < m ? "processor" : "comm_unit"},
                              {"processor", q < m ? nlohmann::json(c.node * m + q) : nlohmann::json()},
                              {"grants", bus.per_requester[k].grants},
                              {"grant_wait_us", wait_json(bus.per_requester[k])}});
    }
    return {{"node", c.node},
            {"busy_s", bus.busy_s},
            {"utilisation", bus_utilisation(bus, r.sim_time_s)},
            {"transfers", bus.packet_transfers + bus.object_reads},
            {"packet_transfers", bus.packet_transfers},
            {"object_reads", bus.object_reads},
            {"bytes", bus.packet_bytes + bus.object_bytes},
            {"packet_bytes", bus.packet_bytes},
            {"object_bytes", bus.object_bytes},
            {"grants", bus.all.grants},
            {"grant_wait_us", wait_json(bus.all)},
            {"per_requester", requesters}};
}

nlohmann::json node_json(const RunReport &r, const ClusterNodeReport &c)
{
    nlohmann::json procs = nlohmann::json::array();
    for (size_t k = 0; k < c.ports.size(); k++)
        procs.push_back({{"id", c.node * r.config.cluster + static_cast<int>(k)},
                         {"dispatched", c.dispatcher.dispatched[k]},
                         {"objects_held", c.memories[k].objects_held},
                         {"remote_reads", c.ports[k].remote_reads},
                         {"local_reads", c.ports[k].local_reads},
                         {"reads_served", c.memories[k].reads_served}});
    return {{"node", c.node},
            {"objects", c.objects},
            {"dispatch_queue_high_water", c.dispatcher.inbox_high_water},
            {"processors", procs}};
}

nlohmann::json buses_json(const RunReport &r)
{
    nlohmann::json per_bus = nlohmann::json::array();
    std::vector<double> util;
    GrantWait all;
    double busy = 0, packet_bytes = 0, object_bytes = 0;
    uint64_t packet_transfers = 0, object_reads = 0;
    for (const auto &c : r.clusters) {
        const BusStats &b = c.bus;
        util.push_back(bus_utilisation(b, r.sim_time_s));
        busy += b.busy_s;
        packet_bytes += b.packet_bytes;
        object_bytes += b.object_bytes;
        packet_transfers += b.packet_transfers;
        object_reads += b.object_reads;
        all.grants += b.all.grants;
        all.wait_sum += b.all.wait_sum;
        all.wait_max = std::max(all.wait_max, b.all.wait_max);
        per_bus.push_back(bus_json(r, c));
    }
    double umin = util.empty() ? 0 : *std::min_element(util.begin(), util.end());
    double umax = util.empty() ? 0 : *std::max_element(util.begin(), util.end());
    double umean = 0;
    for (double u : util) umean += u;
    if (!util.empty()) umean /= static_cast<double>(util.size());
    return {{"count", r.clusters.size()},
            {"utilisation", {{"min", umin}, {"mean", umean}, {"max", umax}}},
            {"busy_s", busy},
            {"grants", all.grants},
            {"grant_wait_us", wait_json(all)},
            {"transfers", packet_transfers + object_reads},
            {"packet_transfers", packet_transfers},
            {"object_reads", object_reads},
            {"bytes", packet_bytes + object_bytes},
            {"packet_bytes", packet_bytes},
            {"object_bytes", object_bytes},
            {"per_bus", per_bus}};
}

}  // namespace

MemoryReport cluster_memory(const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
                            const int32_t *cell_owner, uint64_t pixel_partitioned)
{
    MemoryReport m;
    m.clustered = true;
    rt_replicas replicas = config.replica_table();
    m.cluster = cluster_memory_figures(scene, grid, cell_owner, config.node_count(), config.cluster,
                                       &config.memory_layout, config.replicated() ? &replicas : nullptr);
    m.max_per_ip_bytes =
        config.data == DataMode::replicated ? m.cluster.replicated_per_processor : m.cluster.shared_per_processor;
    m.total_bytes = m.max_per_ip_bytes * static_cast<uint64_t>(config.processor_count());
    m.pixel_partitioned_bytes = pixel_partitioned;
    return m;
}

void collect_clusters(TorusSystem &top, RunReport &r)
{
    for (const auto &cl : top.clusters()) {
        ClusterNodeReport c;
        c.node = cl->node();
        c.bus_name = cl->bus().name();
        c.objects = cl->node_objects().size();
        c.dispatcher = cl->dispatcher().stats();
        c.bus = cl->bus().stats();
        for (int k = 0; k < cl->size(); k++) {
            c.ports.push_back(cl->port(k).stats());
            c.memories.push_back(cl->memory(k).stats());
        }
        r.clusters.push_back(std::move(c));
    }
}

void clusters_to_json(const RunReport &r, nlohmann::json &j)
{
    const SimConfig &config = r.config;
    nlohmann::json per_node = nlohmann::json::array();
    for (const auto &c : r.clusters) per_node.push_back(node_json(r, c));
    j["cluster"] = {{"m", config.cluster},
                    {"processors_per_node", config.cluster},
                    {"nodes", config.node_count()},
                    {"data", data_mode_name(config.data)},
                    {"dispatch", config.dispatch},
                    {"arbiter", config.arbiter},
                    {"arbiter_priority", config.arbiter == "fixed-priority"
                                             ? "comm unit first, then processors by index (0 highest)"
                                             : "rotating"},
                    {"placement", "shared: the j-th object (ascending index) listed by a node's cells is held "
                                  "by its processor j mod m"},
                    {"per_node", per_node}};
    j["bus"] = buses_json(r);
    // Per processor: object reads it made over the bus (shared data).
    auto &per_ip = j["per_ip"];
    for (const auto &c : r.clusters)
        for (size_t k = 0; k < c.ports.size(); k++) {
            size_t id = static_cast<size_t>(c.node * config.cluster) + k;
            if (id < per_ip.size()) per_ip[id]["bus_object_reads"] = c.ports[k].remote_reads;
        }
}

}  // namespace torusrt
