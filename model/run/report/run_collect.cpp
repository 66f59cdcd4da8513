// run_collect.cpp - collect(): every module's statistics read once after the run into a
// RunReport, with the data-memory figures and the preprocessing units.
#include <algorithm>

#include "cluster_node.h"
#include "rt_memory.h"
#include "flow_report.h"
#include "run_report.h"
#include "stats_json.h"
#include "torus_system.h"
#include "user_error.h"

namespace torusrt {

namespace {

// Flat torus: what each node must hold for its cells, against every processor holding all.
MemoryReport flat_memory(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                         uint64_t pixel_partitioned)
{
    std::vector<rt_memory_use> use(static_cast<size_t>(config.node_count()));
    rt_replicas replicas = config.replica_table();
    rt_status st = rt_memory_per_owner_replicas(scene, grid, cell_owner, config.replicated() ? &replicas : nullptr,
                                                config.node_count(), &config.memory_layout, use.data());
    if (st == RT_ERR_NOMEM) throw UserError("out of memory while computing the data memory per node");
    if (st != RT_OK) throw UserError("cannot compute the data memory per node (an inconsistent cell table)");
    MemoryReport m;
    for (const auto &u : use) m.max_per_ip_bytes = std::max(m.max_per_ip_bytes, rt_memory_total(&u));
    m.total_bytes = m.max_per_ip_bytes * static_cast<uint64_t>(config.processor_count());
    m.pixel_partitioned_bytes = pixel_partitioned;
    return m;
}

// Per node data summed with and without the extra owners' copies: what replication costs.
ReplicationReport replication(const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
                              const int32_t *cell_owner)
{
    ReplicationReport rep;
    if (!config.replicated()) return rep;
    rt_replicas replicas = config.replica_table();
    rt_replicas_count(&replicas, rt_grid_cell_count(grid), &rep.cells, &rep.copies);
    std::vector<rt_memory_use> with(static_cast<size_t>(config.node_count())), without(with.size());
    if (rt_memory_per_owner_replicas(scene, grid, cell_owner, &replicas, config.node_count(), &config.memory_layout,
                                     with.data()) != RT_OK ||
        rt_memory_per_owner_layout(scene, grid, cell_owner, config.node_count(), &config.memory_layout,
                                   without.data()) != RT_OK)
        throw UserError("cannot compute the data memory of the replicated cells (out of memory)");
    for (size_t i = 0; i < with.size(); i++) rep.bytes += rt_memory_total(&with[i]) - rt_memory_total(&without[i]);
    return rep;
}

QueueStats queue_stats(const QueueRef &q)
{
    const ClassBuffers &b = *q.buffers;
    uint64_t used = 0;
    for (uint32_t i = 0; i < b.count(); i++) used += b.find(i) != nullptr;
    return {q.name,
            queue_kind_name(q.kind),
            q.node,
            used,
            b.capacity(),
            b.used(),
            b.high_water(),
            b.blocked_writers(),
            b.stalled_time().to_seconds()};
}

void collect_modules(TorusSystem &top, RunReport &r)
{
    for (IntersectionProcessor *p : top.processors()) {
        r.ips.push_back(p->stats());
        const IpStats &s = r.ips.back();
        r.totals.busy_s += s.busy_s;
        r.totals.steps += s.packets_in;
        rt_ops_add(&r.totals.ops, &s.ops);
    }
    for (const auto &l : top.links()) {
        r.links.push_back(l->stats());
        r.totals.hops += r.links.back().packets;
        r.totals.link_bytes += r.links.back().bytes;
    }
    for (const auto &cu : top.comm_units()) r.comm_units.push_back(cu->stats());
    r.host = top.host().stats();
    for (const QueueRef &q : top.queues().all()) r.queues.push_back(queue_stats(q));
    r.any_stalled_s = top.queues().any_stalled_time().to_seconds();
    if (!top.clusters().empty()) collect_clusters(top, r);
    r.totals.events = r.totals.steps + r.totals.hops + r.host.injected;
    for (const auto &c : r.clusters) r.totals.events += c.bus.packet_transfers + c.bus.object_reads;
}

void collect_deadlock(RunReport &r)
{
    r.status = "deadlock";
    r.deadlock.time_s = r.sim_time_s;
    for (const QueueStats &q : r.queues)
        if (q.capacity && q.occupancy >= q.capacity) r.deadlock.full.push_back(q);
    for (const auto &c : r.clusters)
        if (c.bus.waiting) r.deadlock.bus_waits.push_back({c.bus_name, c.bus.waiting});
    for (const auto &cu : r.comm_units) r.deadlock.held += cu.held;
}

}  // namespace

RunReport collect(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger, const rt_scene *scene,
                  const rt_grid *grid, const int32_t *cell_owner, const RunFacts &facts, bool deadlock)
{
    RunReport r;
    r.config = config;
    const rt_camera *cam = rt_scene_camera(scene);
    r.width = cam->width;
    r.height = cam->height;
    r.objects = rt_scene_object_count(scene);
    r.lights = rt_scene_light_count(scene);
    r.sim_time_s = deadlock ? sc_core::sc_time_stamp().to_seconds() : ledger.image_time().to_seconds();
    r.facts = facts;
    collect_modules(top, r);
    r.flow = flow_report_json(config, top, scene);
    r.packets = ledger.totals();
    r.conserved = ledger.conserved();
    r.latency = latency_json(ledger.latency());

    int n = config.processor_count();
    rt_memory_use whole = rt_memory_whole_scene_layout(scene, grid, &config.memory_layout);
    uint64_t pixel_partitioned = rt_memory_total(&whole) * static_cast<uint64_t>(n);
    r.memory = config.cluster == 1 ? flat_memory(config, scene, grid, cell_owner, pixel_partitioned)
                                   : cluster_memory(config, scene, grid, cell_owner, pixel_partitioned);
    r.memory.whole_scene_bytes = rt_memory_total(&whole);
    r.memory.replication = replication(config, scene, grid, cell_owner);
    r.units_serial = rt_grid_units_serial(grid);
    r.units_parallel = rt_grid_units_parallel(grid, n);
    r.units_parallel_by_p = preprocess_json(grid, n)["units_parallel_by_p"];
    if (deadlock) collect_deadlock(r);
    return r;
}

}  // namespace torusrt
