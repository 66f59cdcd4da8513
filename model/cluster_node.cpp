// cluster_node.cpp - elaboration of one cluster: processors, memories, bus ports, dispatcher,
// bus and arbiter, and their bindings.
#include "cluster_node.h"

#include <string>

#include "cluster_memory.h"

namespace torusrt {

ClusterNode::ClusterNode(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene,
                         const rt_grid *grid, const int32_t *cell_owner, int node, PacketLedger &ledger,
                         PacketPool *pool, PrimarySource *primaries, const ReplicaChoice *replicas)
    : sc_module(name), from_comm_unit("from_comm_unit"), to_comm_unit("to_comm_unit"), m_node(node),
      m_replicas(replicas ? replicas->table() : nullptr),
      m_node_objects(cluster_node_objects(grid, cell_owner, node, m_replicas))
{
    from_comm_unit.bind(*this);
    int m = config.cluster;
    bool shared = config.data == DataMode::shared;
    bool lt = config.style == TimingStyle::lt;

    // The communication unit (requester m) ranks first under fixed priority: see bus_arbiter.h.
    m_arbiter = make_arbiter(config.arbiter, "arbiter", m + 1, m);
    m_bus = std::make_unique<ClusterBus>("bus", config.timing, lt, m + 1);
    m_bus->arbiter.bind(*m_arbiter);

    std::vector<IntersectionProcessor *> procs;
    for (int k = 0; k < m; k++) {
        int global = node * m + k;
        ProcessorSetup setup;
        setup.pool = pool;
        setup.replicas = replicas ? replicas->table() : nullptr;
        auto ip = std::make_unique<IntersectionProcessor>(("ip_" + std::to_string(global)).c_str(), config, scene, grid,
                                                          cell_owner, node, global, ledger, setup);
        auto mem = std::make_unique<TwoPortMemory>(("mem_" + std::to_string(k)).c_str(), config.timing, m_node_objects,
                                                   shared ? k : 0, shared ? m : 1);
        auto port =
            std::make_unique<ProcessorBusPort>(("port_" + std::to_string(k)).c_str(), scene, k, m_node_objects, m);
        ip->out.bind(port->in);
        if (shared) ip->fetch.bind(port->objects);
        port->to_comm_unit.bind(to_comm_unit);
        port->bus_socket.bind(m_bus->target);  // requester k
        m_bus->memory.bind(mem->bus_side);     // memory port k
        procs.push_back(ip.get());
        m_processors.push_back(std::move(ip));
        m_memories.push_back(std::move(mem));
        m_ports.push_back(std::move(port));
    }
    PacketQueueSetup inbox;
    inbox.pool = pool;
    inbox.primaries = primaries;
    inbox.entry_node = node;
    m_dispatcher = std::make_unique<ClusterDispatcher>("dispatcher", config, procs, inbox);
    m_dispatcher->bus_socket.bind(m_bus->target);  // requester m, bound last
}

ClusterNode::~ClusterNode() = default;

void ClusterNode::place_objects(const rt_grid *grid, const int32_t *cell_owner)
{
    m_node_objects = cluster_node_objects(grid, cell_owner, m_node, m_replicas);  // in place: held by reference
}

void ClusterNode::accept(const TimedPacket &p) { m_dispatcher->accept(p); }
void ClusterNode::accept_pooled(PacketPool &pool, uint32_t handle) { m_dispatcher->accept_pooled(pool, handle); }
bool ClusterNode::can_accept(const TimedPacket &p) const { return m_dispatcher->can_accept(p); }
void ClusterNode::on_space(const TimedPacket &p, sc_core::sc_event &e) { m_dispatcher->on_space(p, e); }
BufferSpace *ClusterNode::room_for(const TimedPacket &p) { return m_dispatcher->room_for(p); }

void ClusterNode::register_queues(QueueRegistry &reg)
{
    for (auto &p : m_processors) p->register_queues(reg);
    m_dispatcher->register_queues(reg, m_node);
}

std::vector<IntersectionProcessor *> ClusterNode::processors() const
{
    std::vector<IntersectionProcessor *> out;
    for (const auto &p : m_processors) out.push_back(p.get());
    return out;
}

}  // namespace torusrt
