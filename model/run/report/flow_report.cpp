// flow_report.cpp - buffer capacities, packet memory and per-class high water of a run, from
// the queue registry.
#include "flow_report.h"

#include <algorithm>
#include <vector>

#include "flow_control.h"
#include "torus_system.h"

namespace torusrt {

namespace {

// Folds one queue's class buffers into the per-class maxima, and the classes it reached into
// `used` (unbounded buffers are not split: one maximum for every class).
void add_classes(std::vector<size_t> &per_class, size_t &used, const QueueRef &q)
{
    const ClassBuffers &b = *q.buffers;
    used = std::max<size_t>(used, (q.kind == QueueKind::link ? b.top_index() / 2 : b.top_index()) + 1);
    for (uint32_t i = 0; i < b.count(); i++) {
        const BufferSpace *s = b.find(i);
        if (!s) continue;
        uint32_t cls = q.kind == QueueKind::link ? i / 2 : i;  // link buffers: 2 x class + channel
        if (per_class.size() <= cls) per_class.resize(cls + 1, 0);
        per_class[cls] = std::max(per_class[cls], s->high_water());
    }
}

}  // namespace

nlohmann::json flow_report_json(const SimConfig &config, TorusSystem &top, const rt_scene *scene)
{
    std::vector<size_t> per_class;
    size_t used = 1;
    for (const QueueRef &q : top.queues().all()) add_classes(per_class, used, q);
    if (config.flow == FlowControl::none) used = 1;

    // Buffers of one class per node: input queues, and a buffer per channel of each outgoing link.
    const rt_topology topo = config.network();
    bool channels = config.flow == FlowControl::classes && rt_topology_channels(&topo) > 1;
    double links_per_node = static_cast<double>(top.links().size()) / config.node_count();
    double node_buffers = (config.cluster > 1 ? config.cluster + 1 : 1) + links_per_node * (channels ? 2 : 1);
    double per_ip = node_buffers / config.cluster;
    double class_bytes = per_ip * sizeof(rt_packet) * config.queue_capacity;
    uint64_t bound = class_bound(config, static_cast<uint32_t>(rt_scene_light_count(scene)));
    size_t high = 0;
    for (size_t h : per_class) high = std::max(high, h);
    return {{"scheme", flow_name(config.flow)},
            {"capacity_packets", config.queue_capacity},
            {"classes_bound", bound},
            {"classes_used", used},
            {"channels_per_link", channels ? 2 : 1},
            {"buffers_per_ip_per_class", per_ip},
            {"packet_struct_bytes", sizeof(rt_packet)},
            {"bytes_per_ip_per_class", class_bytes},
            {"bytes_per_ip_used", class_bytes * static_cast<double>(used)},
            {"bytes_per_ip_bound", class_bytes * static_cast<double>(bound)},
            {"high_water", high},
            {"class_high_water", per_class}};
}

}  // namespace torusrt
