// comm_unit.h - a node's communication unit: takes packets from its IP (or cluster) and from
// incoming links (TLM-2.0 b_transport), and routes each to the local processor side or to the
// outgoing link of the first hop toward the owner of the packet's cell. The host's primaries
// never pass through it: the processor side's input queue takes them from the primary source.
//
// Timing path: packets from the links and from the processor side enter the arrival queue (a
// payload event queue) at their annotated time; one SC_METHOD delivers every arrival due, in the
// arrival queue's fixed order (time, source, sequence), but never one pushed in the same delta
// cycle: that one waits for the next delta, so whether its sender ran before or after the
// delivery method does not matter. Sources: incoming links 0..L-1, numbered in the order their
// sockets were bound (next_link_in), then the processor side (L). With route_at_once (flat, approximately timed,
// positive link time, unbounded buffers) a packet from the processor side for another node is
// routed as it is handed over when no arrival is due: the processor runs after the delta's
// deliveries, so this is the order of one delta later.
//
// Timed wake-up (TimedWake, timed_wake.h): in a machine that has one (Setup::calendar), the unit
// asks the machine's wake calendar to wake it at its earliest arrival time, and the calendar calls
// deliver() then, units due at one time in node order; alone, the unit notifies its own timed
// event. Either way an arrival due now (or pushed in this delta) waits for m_run, one delta on.
// A processor that runs after its own node's deliveries (ProcessorSetup::order_after)
// asks the unit whether an arrival is still due and, during a delivery round, to be run when
// the round is over.
//
// Loosely timed (temporal decoupling with quantum Q > 0): an arrival stamped no more than Q ahead
// of simulation time is routed in the call that brings it, with no event (the next link books it
// and hands it on in the same call); one stamped further ahead waits in the arrival queue until
// it is Q ahead. Packets are routed in the order they are handed over, which is where the
// style's timing error comes from (docs/model.md, Timing styles). Q = 0 is the
// approximately-timed path exactly.
//
// Room: a packet whose next buffer is full is held here, in a FIFO per source and buffer it
// came from (class and virtual channel of the incoming link; one per source under --flow none),
// and later packets from that buffer queue behind it; the next buffer's release wakes the retry
// method. A held packet keeps its link slot (credit) until it moves on. The processor side
// waits at its next hand-over while one of its packets is held (a thread in accept(), a method
// through can_accept() and on_space()); under the class
// scheme its packets come with their next slot reserved and are never held. A packet going on
// to a link gets its virtual channel there by the dateline rule (flow_control.h).
#pragma once

#include <array>
#include <deque>
#include <systemc>
#include <tlm>
#include <vector>

#include "activation_queue.h"
#include "arrival_queue.h"
#include "delivery_round_if.h"
#include "hop_path.h"
#include "module_stats.h"
#include "packet_pool.h"
#include "packet_sink_if.h"
#include "rt_grid.h"
#include "routing.h"
#include "sim_now.h"
#include "sim_config.h"
#include "timed_wake.h"
#include "wake_calendar.h"

namespace torusrt {

class ReplicaChoice;

// The machine's choices for this unit, fixed at elaboration; a unit alone takes the defaults.
struct CommUnitSetup {
    FlowControl flow = FlowControl::none;                // the flow-control scheme (virtual channels)
    sc_core::sc_time lookahead = sc_core::SC_ZERO_TIME;  // the quantum when loosely timed
    // The machine's packet pool, shared by every unit so that a packet crosses by handle
    // (null: the unit's own).
    PacketPool *pool = nullptr;
    // The machine's wake calendar, which then wakes the unit for its timed deliveries, units
    // due at one time in the order they were built (null: an event of the unit's own).
    WakeCalendar *calendar = nullptr;
    // Packets from the processor side are routed as they are handed over, not one delta later:
    // for a flat approximately-timed machine with a positive link time and unbounded buffers,
    // where the processor hands over after the deliveries of its time, so the order is the same.
    bool route_at_once = false;
    // Which owner of a replicated cell a packet goes to (null: no cell is replicated).
    const ReplicaChoice *replicas = nullptr;
};

class CommUnit final : public sc_core::sc_module,
                       public PacketSinkIf,
                       public DeliveryRoundIf,
                       public WakeCalendar::Client {
  public:
    // Packets from incoming links: one socket per neighbour (none when the node has none).
    using LinkInSocket = tlm::tlm_target_socket<32, tlm::tlm_base_protocol_types, 1, sc_core::SC_ZERO_OR_MORE_BOUND>;
    sc_core::sc_vector<LinkInSocket> link_in;
    sc_core::sc_export<PacketSinkIf> in;   // packets from the IP side
    sc_core::sc_port<PacketSinkIf> local;  // packets for this node's cells
    sc_core::sc_port<PacketSinkIf, kMaxPorts, sc_core::SC_ZERO_OR_MORE_BOUND> link_out;  // outgoing links

    using Setup = CommUnitSetup;
    CommUnit(sc_core::sc_module_name name, int node, const Routing &routing, const rt_grid *grid,
             const int32_t *cell_owner, const Setup &setup = Setup());

    // The next incoming-link socket not yet handed out, for a link to bind to (elaboration). A
    // link's crossings are numbered by its socket, so sources are numbered in this order.
    LinkInSocket &next_link_in();
    // Where a crossing into the socket next_link_in() handed out last lands first: the input
    // that socket is bound to, and the unit's own state a crossing reads first (its members
    // from m_pool on: the pool, the wake, the arrival queue). Addresses for a sender's
    // prefetch (hop_path.h), never read through; elaboration.
    struct Landing {
        const void *input;
        const void *arrivals;
    };
    Landing last_link_landing() const { return {&m_inputs[m_processor_source - 1], &m_pool}; }

    void accept(const TimedPacket &p) override;
    // From the processor side by handle in the machine's pool (a packet its processor stepped in
    // its slot): as accept(), without a copy.
    void accept_pooled(PacketPool &pool, uint32_t handle) override;
    // The processor side may hand over now unless one of its packets is held; else on_space()'s
    // event is notified once none is (a processor that must not wait in accept() waits for it).
    bool can_accept(const TimedPacket &) const override { return !processor_held(); }
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override;
    BufferSpace *room_for(const TimedPacket &p) override;
    // Binds link_out to `sink`, the way out in direction `dir` (elaboration; a link's own
    // connection is connect_link).
    template <typename Sink> void bind_link_out(int dir, Sink &sink)
    {
        m_port_of_dir[dir] = m_links_bound++;
        link_out.bind(sink);
    }
    // Binds a link as the way out in direction `dir`: link_out to the link's `in`, and the link's
    // `socket` to `receiver`'s next incoming-link socket (elaboration; nothing of either is kept).
    void connect_link(int dir, sc_core::sc_export<PacketSinkIf> &in, tlm::tlm_initiator_socket<> &socket,
                      CommUnit &receiver);

    bool arrival_due() const override { return !m_arrivals.empty() && m_arrivals.next_value() <= sim_now().value(); }
    bool run_after_delivery(ActivationQueue::Client &client) override
    {
        if (!m_delivering) return false;
        m_after_delivery = &client;
        return true;
    }

    // Packets held for room further on (for the deadlock report).
    size_t held() const;
    CommUnitStats stats() const { return {m_local, m_transit, held()}; }

  private:
    // What an incoming link's socket is bound to: it passes the link's number on with each
    // crossing. A unit holds its own, so a crossing reaches b_transport in two direct calls.
    class LinkInput final : public tlm::tlm_fw_transport_if<> {
      public:
        void b_transport(tlm::tlm_generic_payload &trans, sc_core::sc_time &delay) override
        {
            m_unit->b_transport(m_source, trans, delay);
        }
        // Links only use b_transport.
        tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload &trans, tlm::tlm_phase &,
                                           sc_core::sc_time &) override
        {
            trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
            return tlm::TLM_COMPLETED;
        }
        bool get_direct_mem_ptr(tlm::tlm_generic_payload &, tlm::tlm_dmi &) override { return false; }
        unsigned int transport_dbg(tlm::tlm_generic_payload &) override { return 0; }

        CommUnit *m_unit = nullptr;
        int m_source = 0;
    };
    struct Hop {
        PacketSinkIf *sink;
        bool local;  // the processor side; else the way out in direction `dir`
        int dir;
    };
    // The node owning the cell `p` is in.
    int owner_of(const TimedPacket &p) const;
    // The next hop of `p` toward node `owner`, setting its channel when that is a link.
    Hop next_hop(TimedPacket &p, int owner);
    bool processor_held() const;
    // Whether packets from `buffer` of `source` are held.
    bool holds(int source, uint32_t buffer) const;
    struct HeldFifo;
    const HeldFifo *held_fifo(int source, uint32_t buffer) const;
    // Holds `packet` at the back of its source and buffer's FIFO.
    void hold(int source, uint32_t buffer, uint32_t packet);
    // Moves pool packet `packet` on if its next buffer has room.
    bool forward(uint32_t packet);
    void b_transport(int source, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay);
    void enqueue(uint32_t packet, const sc_core::sc_time &stamp, int source, BufferSpace *credit);
    // Loosely timed, an arrival within the quantum: routed in this call, with no event (behind
    // packets held from its buffer it is held too). Out of line: the approximately-timed
    // enqueue stays as small as without it.
    [[gnu::noinline]] void route_in_quantum(uint32_t packet, int source);
    // Routes pool packet `packet`, just handed over by the processor side.
    void from_processor(uint32_t packet);
    void wake_at(const sc_core::sc_time &when);
    // A delivery round, then the processor that asked to run after it.
    void deliver();
    // The round: every arrival due now, in the arrival queue's order.
    void deliver_due();
    void wake_due() override { deliver(); }
    void retry();
    int processor_source() const { return m_processor_source; }
    void end_of_elaboration() override;
    void start_of_simulation() override;

    PacketPool *m_pool;            // the machine's packet pool, or m_own_pool
    TimedWake m_wake;              // the machine's wake calendar, or m_due
    int m_processor_source = 0;    // = the number of incoming links bound
    sc_core::sc_time m_lookahead;  // the quantum when loosely timed, else 0
    size_t m_held_total = 0;       // packets held (checked first: usually none)
    bool m_route_at_once = false;
    bool m_delivering = false;
    ActivationQueue::Client *m_after_delivery = nullptr;
    uint64_t m_local = 0, m_transit = 0;
    int m_node;
    FlowControl m_flow = FlowControl::none;
    ArrivalQueue m_arrivals;
    const Routing &m_routing;
    const rt_grid *m_grid;
    const int32_t *m_owner;
    PacketSinkIf *m_local_sink = nullptr;  // what `local` is bound to (from the start of simulation)
    // Per incoming-link socket, what it is bound to (a crossing's target).
    std::array<LinkInput, kMaxPorts> m_inputs;
    HopPath m_ways;  // per direction, what link_out is bound to there (from the start of simulation)
    // Per source, per incoming buffer (2 x class + channel), pool handles.
    // Sorted by buffer; retry() visits them in that order.
    struct HeldFifo {
        uint32_t buffer;
        std::deque<uint32_t> packets;
    };
    std::vector<std::vector<HeldFifo>> m_held;
    // Per source, packets in m_held (so a check does not walk every class's FIFO).
    std::vector<size_t> m_held_count;
    sc_core::sc_event m_due, m_run, m_retry, m_processor_room;
    std::vector<sc_core::sc_event *> m_processor_waiters;  // on_space(): notified with m_processor_room
    std::array<int, kMaxPorts> m_port_of_dir;              // link_out's index per direction (-1: none)
    int m_links_bound = 0;                                 // link_out's bindings so far
    const ReplicaChoice *m_replicas;                       // the owners of replicated cells, or null
    PacketPool m_own_pool;
};

}  // namespace torusrt
