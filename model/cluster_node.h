// cluster_node.h - a torus node of the hierarchical system: m processors on one shared bus.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <systemc>
#include <vector>

#include "intersection_processor.h"
#include "packet_ledger.h"
#include "packet_sink_if.h"
#include "sim_config.h"

namespace torusrt {

class ClusterNode : public sc_core::sc_module, public PacketSinkIf {
  public:
    sc_core::sc_export<PacketSinkIf> from_comm_unit; // packets for this node's cells
    sc_core::sc_port<PacketSinkIf> to_comm_unit;     // the processors' outgoing packets

    ClusterNode(sc_core::sc_module_name name, const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
                const int32_t *cell_owner, int node, PacketLedger &ledger);
    ~ClusterNode() override;

    void accept(const TimedPacket &p) override;
    std::vector<IntersectionProcessor *> processors() const;

  private:
    std::vector<std::unique_ptr<IntersectionProcessor>> m_processors;
};

class TorusSystem;

// Data memory of a clustered system (keys as the flat system's, plus per-mode detail).
nlohmann::json cluster_memory_json(const SimConfig &config, TorusSystem &top, const rt_scene *scene,
                                   const rt_grid *grid, const int32_t *cell_owner, uint64_t pixel_partitioned);
// Adds the `cluster.` and `bus.` sections to a report.
void add_cluster_report(nlohmann::json &report, const SimConfig &config, TorusSystem &top);
// Adds the cluster's bus owner and request lines to a VCD trace.
void trace_cluster(sc_core::sc_trace_file *file, ClusterNode &cluster);
// Lines naming the cluster's full queues and waiting requesters.
std::string cluster_deadlock_lines(ClusterNode &cluster);

}  // namespace torusrt
