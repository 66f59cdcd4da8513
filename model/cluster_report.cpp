// cluster_report.cpp - the cluster's statistics (`cluster.` and `bus.` report sections), its
// memory figures, its VCD lines and its deadlock lines.
#include <algorithm>
#include <sstream>

#include "cluster_memory.h"
#include "cluster_node.h"
#include "torus_system.h"

namespace torusrt {

namespace {

nlohmann::json wait_json(const ClusterBus::GrantStats &g)
{
    double mean = g.grants ? g.wait_sum.to_seconds() * 1e6 / static_cast<double>(g.grants) : 0.0;
    return {{"mean", mean}, {"max", g.wait_max.to_seconds() * 1e6}};
}

}  // namespace

nlohmann::json cluster_memory_json(const SimConfig &config, TorusSystem &, const rt_scene *scene, const rt_grid *grid,
                                   const int32_t *cell_owner, uint64_t pixel_partitioned)
{
    ClusterMemoryFigures f = cluster_memory_figures(scene, grid, cell_owner, config.node_count(), config.cluster);
    return cluster_memory_report(f, config.data, config.processor_count(), pixel_partitioned);
}

void add_cluster_report(nlohmann::json &report, const SimConfig &config, TorusSystem &top)
{
    double T = report["sim_time_s"].get<double>();
    int m = config.cluster;
    nlohmann::json per_node = nlohmann::json::array(), per_bus = nlohmann::json::array();
    std::vector<double> util;
    ClusterBus::GrantStats all;
    double busy = 0, packet_bytes = 0, object_bytes = 0;
    uint64_t packet_transfers = 0, object_reads = 0;
    for (const auto &cl : top.clusters()) {
        ClusterBus &bus = cl->bus();
        double b = bus.busy_time().to_seconds();
        double u = T > 0 ? std::min(1.0, b / T) : 0.0;
        util.push_back(u);
        busy += b;
        packet_bytes += bus.packet_bytes();
        object_bytes += bus.object_bytes();
        packet_transfers += bus.packet_transfers();
        object_reads += bus.object_reads();
        const auto &g = bus.grant_stats();
        all.grants += g.grants;
        all.wait_sum += g.wait_sum;
        if (g.wait_max > all.wait_max) all.wait_max = g.wait_max;

        nlohmann::json requesters = nlohmann::json::array();
        for (int r = 0; r < bus.requesters(); r++) {
            const auto &rg = bus.grant_stats(r);
            requesters.push_back({{"requester", r},
                                  {"master", r < m ? "processor" : "comm_unit"},
                                  {"processor", r < m ? nlohmann::json(cl->node() * m + r) : nlohmann::json()},
                                  {"grants", rg.grants},
                                  {"grant_wait_us", wait_json(rg)}});
        }
        per_bus.push_back({{"node", cl->node()},
                           {"busy_s", b},
                           {"utilisation", u},
                           {"transfers", bus.transfers()},
                           {"packet_transfers", bus.packet_transfers()},
                           {"object_reads", bus.object_reads()},
                           {"bytes", bus.packet_bytes() + bus.object_bytes()},
                           {"packet_bytes", bus.packet_bytes()},
                           {"object_bytes", bus.object_bytes()},
                           {"grants", g.grants},
                           {"grant_wait_us", wait_json(g)},
                           {"per_requester", requesters}});

        nlohmann::json procs = nlohmann::json::array();
        for (int k = 0; k < cl->size(); k++) {
            procs.push_back({{"id", cl->node() * m + k},
                             {"dispatched", cl->dispatcher().dispatched(k)},
                             {"objects_held", cl->memory(k).object_count()},
                             {"remote_reads", cl->port(k).remote_reads()},
                             {"local_reads", cl->port(k).local_reads()},
                             {"reads_served", cl->memory(k).reads_served()}});
        }
        per_node.push_back({{"node", cl->node()},
                            {"objects", cl->node_objects().size()},
                            {"dispatch_queue_high_water", cl->dispatcher().inbox().high_water()},
                            {"processors", procs}});
    }
    double umin = util.empty() ? 0 : *std::min_element(util.begin(), util.end());
    double umax = util.empty() ? 0 : *std::max_element(util.begin(), util.end());
    double umean = 0;
    for (double u : util) umean += u;
    if (!util.empty()) umean /= static_cast<double>(util.size());

    report["cluster"] = {{"m", m},
                         {"processors_per_node", m},
                         {"nodes", config.node_count()},
                         {"data", data_mode_name(config.data)},
                         {"dispatch", dispatch_name(config.dispatch)},
                         {"arbiter", arbiter_name(config.arbiter)},
                         {"arbiter_priority", config.arbiter == ArbiterPolicy::fixed_priority
                                                  ? "comm unit first, then processors by index (0 highest)"
                                                  : "rotating"},
                         {"placement", "shared: the j-th object (ascending index) listed by a node's cells is held "
                                       "by its processor j mod m"},
                         {"per_node", per_node}};
    report["bus"] = {{"count", top.clusters().size()},
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
    // Per processor: object reads it made over the bus (shared data).
    auto &per_ip = report["per_ip"];
    for (const auto &cl : top.clusters())
        for (int k = 0; k < cl->size(); k++) {
            size_t id = static_cast<size_t>(cl->node() * m + k);
            if (id < per_ip.size()) per_ip[id]["bus_object_reads"] = cl->port(k).remote_reads();
        }
}

std::string cluster_deadlock_lines(ClusterNode &cluster)
{
    // Full processor queues are listed by deadlock_report with every other processor's.
    std::ostringstream s;
    PacketQueue &q = cluster.dispatcher().inbox();
    if (q.full())
        s << "  full: " << cluster.dispatcher().name() << " input queue (" << q.size() << "/" << q.capacity() << "), "
          << q.blocked_writers() << " writer(s) waiting\n";
    if (int w = cluster.bus().waiting()) s << "  waiting: " << w << " requester(s) on " << cluster.bus().name() << "\n";
    return s.str();
}

}  // namespace torusrt
