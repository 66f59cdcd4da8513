// torus_system.cpp - elaboration of the whole machine.
#include "torus_system.h"

#include <string>

#include "cluster_dispatch.h"
#include "cluster_node.h"

namespace torusrt {

TorusSystem::TorusSystem(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene,
                         const rt_grid *grid, const int32_t *cell_owner, PacketLedger &ledger, rt_framebuffer *fb,
                         HandOverTiming hand_over, const rt_replicas *replicas)
    : sc_module(name), m_routing(config.network(), config.route_ties)
{
    if (replicas)
        m_replica_choice = std::make_unique<ReplicaChoice>(cell_owner, *replicas, m_routing, config.replica_choice);
    const ReplicaChoice *choice = m_replica_choice.get();
    int nodes = config.node_count();
    sc_core::sc_time lookahead =
        config.style == TimingStyle::lt ? sc_core::sc_time(config.quantum_us, sc_core::SC_US) : sc_core::SC_ZERO_TIME;
    // A flat approximately-timed machine with a positive link time: the units due at one time do
    // not affect each other within the delta, so the order of simultaneous processes does not
    // change the times. Elsewhere it can.
    bool order_free =
        config.cluster == 1 && lookahead == sc_core::SC_ZERO_TIME && rt_timing_link_packet_us(&config.timing) > 0;
    // Elsewhere the calendar would change the outcome (wake_calendar.h): those machines keep
    // their per-unit timed events.
    if (order_free) m_calendar = std::make_unique<WakeCalendar>("wake_calendar");
    // With unbounded buffers too, a processor's packets for other nodes are routed as they are
    // handed over, a waiting processor is woken in the delta its packet arrives, and a processor
    // runs as soon as its own node's deliveries of the delta are done: nodes then meet only
    // through links, whose packets arrive later, so the order of what is routed and taken up at
    // each time is the same as one delta later, so are the times.
    bool at_once = hand_over == HandOverTiming::at_once && order_free && config.queue_capacity == 0;
    if (config.cluster == 1) m_activations = std::make_unique<ActivationQueue>("activations");
    m_fb = std::make_unique<FrameBuffer>("fb", fb);
    m_host = std::make_unique<Host>("host", config, scene, grid, cell_owner, ledger, choice);
    m_host->fb_socket.bind(m_fb->socket);
    for (int n = 0; n < nodes; n++) {
        // Built node by node: the calendar's order of simultaneous wakes.
        CommUnit::Setup setup{config.flow, lookahead, &m_pool, m_calendar.get(), at_once, choice};
        m_comm.push_back(
            std::make_unique<CommUnit>(("cu_" + std::to_string(n)).c_str(), n, m_routing, grid, cell_owner, setup));
        if (config.cluster == 1) {
            // Built after its node's comm unit: the calendar's order.
            ProcessorSetup ip_setup{m_calendar.get(), m_activations.get(),  at_once ? m_comm[n].get() : nullptr,
                                    &m_pool,          &m_host->primaries(), choice ? choice->table() : nullptr};
            auto ip = std::make_unique<IntersectionProcessor>(("ip_" + std::to_string(n)).c_str(), config, scene, grid,
                                                              cell_owner, n, n, ledger, ip_setup);
            ip->out.bind(m_comm[n]->in);
            ip->fb_socket.bind(m_fb->socket);
            m_comm[n]->local.bind(ip->in);
            m_ips.push_back(std::move(ip));
        } else {
            auto cl = std::make_unique<ClusterNode>(("cluster_" + std::to_string(n)).c_str(), config, scene, grid,
                                                    cell_owner, n, ledger, &m_pool, &m_host->primaries(), choice);
            cl->to_comm_unit.bind(m_comm[n]->in);
            for (auto *p : cl->processors()) p->fb_socket.bind(m_fb->socket);
            m_comm[n]->local.bind(cl->from_comm_unit);
            m_clusters.push_back(std::move(cl));
        }
    }
    for (int n = 0; n < nodes; n++) {
        for (int dir = 0; dir < m_routing.ports(); dir++) {
            int to = m_routing.neighbour(n, dir);
            if (to < 0) continue;
            // Named by its ends, so a trace says where every link goes.
            std::string lname =
                "link_" + std::to_string(n) + "_to_" + std::to_string(to) + "_" + m_routing.port_name(dir);
            auto link = std::make_unique<ToroidalLink>(lname.c_str(), config, n, to, dir, &m_transactions);
            m_comm[n]->connect_link(dir, link->in, link->socket, *m_comm[to]);
            m_links.push_back(std::move(link));
        }
    }
    for (const auto &ip : m_ips) ip->register_queues(m_queues);
    for (const auto &cl : m_clusters) cl->register_queues(m_queues);
    for (const auto &l : m_links) l->register_queues(m_queues);
}

TorusSystem::~TorusSystem() = default;

void TorusSystem::start_frame(rt_framebuffer *fb, const int32_t *cell_owner, const sc_core::sc_time &offset)
{
    m_fb->retarget(fb);
    m_host->start_frame(cell_owner, offset);
    for (const auto &ip : m_ips) ip->queue().wake();
    for (const auto &cl : m_clusters) cl->dispatcher().inbox().wake();
}

void TorusSystem::place_objects(const rt_grid *grid, const int32_t *cell_owner)
{
    for (const auto &cl : m_clusters) cl->place_objects(grid, cell_owner);
}

std::vector<IntersectionProcessor *> TorusSystem::processors() const
{
    std::vector<IntersectionProcessor *> out;
    for (const auto &ip : m_ips) out.push_back(ip.get());
    for (const auto &cl : m_clusters)
        for (auto *p : cl->processors()) out.push_back(p);
    return out;
}

}  // namespace torusrt
