// cluster_node.h - a torus node of the hierarchical system: m processors on one shared bus with a
// dedicated arbiter, each with a 2-port memory, and the node's communication unit writing
// arriving packets into the processors' queues and taking their outgoing packets over the bus.
//
//   comm unit --local--> from_comm_unit --> dispatcher (queue, policy) --bus--> ip_k.in
//   ip_k.out --> port_k --bus--> to_comm_unit --> comm unit (routes to links or back here)
//   ip_k.fetch --> port_k --bus (read)--> mem_h.bus_side        (shared data only)
//
// Requesters on the bus: port_k is k (0..m-1), the dispatcher is m. Children: ip_K (K = the
// global processor index node * m + k; owner id = node, so every processor of a node works on
// all the node's cells), mem_k, port_k, dispatcher, bus, arbiter. Built only for m > 1.
#pragma once

#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "bus_arbiter.h"
#include "cluster_bus.h"
#include "replica_choice.h"
#include "cluster_dispatch.h"
#include "intersection_processor.h"
#include "packet_ledger.h"
#include "packet_sink_if.h"
#include "processor_bus_port.h"
#include "queue_registry.h"
#include "sim_config.h"
#include "two_port_memory.h"

namespace torusrt {

class ClusterNode : public sc_core::sc_module, public PacketSinkIf {
  public:
    sc_core::sc_export<PacketSinkIf> from_comm_unit;  // packets for this node's cells
    sc_core::sc_port<PacketSinkIf> to_comm_unit;      // the processors' outgoing packets

    // `pool`: the machine's packet pool, for the dispatcher's and the processors' input queues
    // (null: their own); `primaries`: the host's primaries entering at this node, which the
    // dispatcher takes (null: none).
    ClusterNode(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene, const rt_grid *grid,
                const int32_t *cell_owner, int node, PacketLedger &ledger, PacketPool *pool = nullptr,
                PrimarySource *primaries = nullptr, const ReplicaChoice *replicas = nullptr);
    ~ClusterNode() override;

    void accept(const TimedPacket &p) override;
    void accept_pooled(PacketPool &pool, uint32_t handle) override;
    bool can_accept(const TimedPacket &p) const override;
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override;
    BufferSpace *room_for(const TimedPacket &p) override;
    std::vector<IntersectionProcessor *> processors() const;
    void register_queues(QueueRegistry &reg);  // the processors' and the dispatcher's

    int node() const { return m_node; }
    int size() const { return static_cast<int>(m_processors.size()); }
    ClusterBus &bus() { return *m_bus; }
    ClusterDispatcher &dispatcher() { return *m_dispatcher; }
    TwoPortMemory &memory(int k) { return *m_memories[k]; }
    ProcessorBusPort &port(int k) { return *m_ports[k]; }
    const std::vector<uint32_t> &node_objects() const { return m_node_objects; }
    // Places again the objects the node's cells list (a moving scene's lists change between
    // frames); the memories and ports see the new placement.
    void place_objects(const rt_grid *grid, const int32_t *cell_owner);

  private:
    int m_node;
    const rt_replicas *m_replicas;         // replicated cells (null: none)
    std::vector<uint32_t> m_node_objects;  // objects the node's cells list, ascending
    std::vector<std::unique_ptr<IntersectionProcessor>> m_processors;
    std::vector<std::unique_ptr<TwoPortMemory>> m_memories;
    std::vector<std::unique_ptr<ProcessorBusPort>> m_ports;
    std::unique_ptr<BusArbiter> m_arbiter;
    std::unique_ptr<ClusterBus> m_bus;
    std::unique_ptr<ClusterDispatcher> m_dispatcher;
};

}  // namespace torusrt
