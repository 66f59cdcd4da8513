// cluster_dispatch.h - the processor side of a cluster's communication unit. Packets the
// communication unit routes to this node wait in the dispatcher's input queue; for each, a
// dispatch policy picks a processor, the packet crosses the cluster bus (the communication unit
// is the master: requester m) and is written into that processor's input queue (waiting while
// that queue is full). Policies register by name, like the bus arbiters:
//   round-robin    - processors 0, 1, ..., m-1, 0, ... in turn;
//   shortest-queue - the processor with the fewest packets waiting or in service (its input
//                    queue plus the one it is working on), ties to the lowest index.
// Under the class scheme (flow_control.h) the dispatcher takes up a packet only when the chosen
// processor's queue has room for its class, reserving the slot before the bus transfer; it tries
// its waiting packets in queue order, so it never waits with a packet in hand. Under --flow none
// it takes the oldest packet and waits while the processor's queue is full.
#pragma once

#include <memory>
#include <string>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "intersection_processor.h"
#include "module_stats.h"
#include "packet_queue.h"
#include "packet_sink_if.h"
#include "queue_registry.h"
#include "sim_config.h"
#include "time_keeper.h"

namespace torusrt {

class DispatchPolicyIf {
  public:
    virtual ~DispatchPolicyIf() = default;
    // The processor (index into `processors`) to receive the next packet.
    int choose(const std::vector<IntersectionProcessor *> &processors)
    {
        int k = candidate(processors);
        chosen(k);
        return k;
    }
    // The processor choose() would pick now, without picking it.
    virtual int candidate(const std::vector<IntersectionProcessor *> &processors) const = 0;
    // Records that processor `k` received the packet.
    virtual void chosen(int) {}
};

// Builds a dispatch policy by name ("round-robin", "shortest-queue"); throws std::invalid_argument
// for an unknown name.
std::unique_ptr<DispatchPolicyIf> make_dispatch_policy(const std::string &name);
// The policy names make_dispatch_policy knows, in the help's order.
std::vector<std::string> dispatch_policy_names();

class ClusterDispatcher : public sc_core::sc_module, public PacketSinkIf {
  public:
    sc_core::sc_export<PacketSinkIf> in;                               // packets for this node's cells
    tlm_utils::simple_initiator_socket<ClusterDispatcher> bus_socket;  // packet writes over the bus

    // `inbox`: the machine's choices for its input queue (pool, primaries).
    ClusterDispatcher(sc_core::sc_module_name name, const MachineConfig &config,
                      std::vector<IntersectionProcessor *> processors,
                      const PacketQueueSetup &inbox = PacketQueueSetup());

    void accept(const TimedPacket &p) override { m_inbox.push_blocking(p); }
    void accept_pooled(PacketPool &pool, uint32_t handle) override { m_inbox.push_pooled(pool, handle); }
    bool can_accept(const TimedPacket &p) const override { return m_inbox.has_room(p); }
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override { m_inbox.space_for(p).on_release(e); }
    BufferSpace *room_for(const TimedPacket &p) override { return &m_inbox.space_for(p); }

    PacketQueue &inbox() { return m_inbox; }
    uint64_t dispatched(int k) const { return m_dispatched[k]; }
    DispatcherStats stats() const { return {m_dispatched, m_inbox.high_water()}; }
    void register_queues(QueueRegistry &reg, int node)
    {
        reg.add(std::string(name()) + ".input", QueueKind::dispatcher, node, m_inbox.spaces(), m_inbox.depth_trace(),
                std::string(name()) + ".queue_depth");
    }
    bool &busy_trace() { return m_busy_flag; }

  private:
    void run();
    // Picks the processor for `tp`; under the class scheme reserves its slot there (m_target >=
    // 0) or returns false (waiting for room).
    bool place(const TimedPacket &tp);

    std::vector<IntersectionProcessor *> m_processors;
    std::unique_ptr<DispatchPolicyIf> m_policy;
    PacketQueue m_inbox;
    TimeKeeper m_time;
    FlowControl m_flow;
    int m_target = 0;          // the processor place() picked
    sc_core::sc_event m_room;  // a processor queue released a slot
    std::vector<uint64_t> m_dispatched;
    bool m_busy_flag = false;
    tlm::tlm_generic_payload m_trans;
};

}  // namespace torusrt
