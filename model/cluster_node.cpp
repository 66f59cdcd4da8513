// cluster_node.cpp - placeholder until the cluster bus exists: rejected by validation.
#include "cluster_node.h"

namespace torusrt {

ClusterNode::ClusterNode(sc_core::sc_module_name name, const SimConfig &, const rt_scene *, const rt_grid *,
                         const int32_t *, int, PacketLedger &)
    : sc_module(name), from_comm_unit("from_comm_unit"), to_comm_unit("to_comm_unit")
{
    from_comm_unit.bind(*this);
    SC_REPORT_FATAL(this->name(), "clusters are not available in this build");
}

ClusterNode::~ClusterNode() = default;

void ClusterNode::accept(const TimedPacket &) {}

std::vector<IntersectionProcessor *> ClusterNode::processors() const
{
    std::vector<IntersectionProcessor *> out;
    for (const auto &p : m_processors) out.push_back(p.get());
    return out;
}

nlohmann::json cluster_memory_json(const SimConfig &, TorusSystem &, const rt_scene *, const rt_grid *,
                                   const int32_t *, uint64_t pixel_partitioned)
{
    return {{"max_per_ip_bytes", 0}, {"total_bytes", 0}, {"pixel_partitioned_bytes", pixel_partitioned}};
}

void add_cluster_report(nlohmann::json &, const SimConfig &, TorusSystem &) {}

void trace_cluster(sc_core::sc_trace_file *, ClusterNode &) {}

std::string cluster_deadlock_lines(ClusterNode &) { return ""; }

}  // namespace torusrt
