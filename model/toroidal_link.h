// toroidal_link.h - one direction of one link between neighbouring nodes, without a process of
// its own. A packet handed to the link starts crossing when both it and the link are ready
// (busy-until) and takes the serialisation time; the link forwards it at once to the receiving
// communication unit as a TLM-2.0 b_transport whose delay is annotated with the queueing and the
// serialisation, and the receiver delivers it at that time from its arrival queue. The packet
// crosses by its handle in a packet pool (PacketExtension); one handed over by value (accept)
// enters a pool of the link's own first.
//
// Room: with --queue N the link holds at most N packets of each class and virtual channel
// (one buffer under --flow none), counted from the moment the sender hands one over until the
// receiver has taken it on (waiting, on the wire, or held at the receiver for room further on).
// The transaction carries the slot (the credit); the receiver releases it.
#pragma once

#include <deque>
#include <memory>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <utility>

#include "class_buffers.h"
#include "link_bookings.h"
#include "module_stats.h"
#include "packet_pool.h"
#include "packet_sink_if.h"
#include "queue_registry.h"
#include "sim_config.h"
#include "time_series.h"
#include "transaction_pool.h"

namespace torusrt {

class ToroidalLink : public sc_core::sc_module, public PacketSinkIf {
  public:
    tlm_utils::simple_initiator_socket<ToroidalLink> socket;  // packets to the receiving comm unit
    sc_core::sc_export<PacketSinkIf> in;                      // packets from the sending comm unit

    // `transactions`: the machine's, shared by its links (null: the link's own).
    ToroidalLink(sc_core::sc_module_name name, const MachineConfig &config, int from, int to, int dir,
                 TransactionPool *transactions = nullptr);

    // Waits (in a thread) for room, then sends. A method caller checks can_accept() first.
    void accept(const TimedPacket &p) override;
    // The same for packet `handle` of `pool`, which crosses by handle (the receiver takes it on).
    void accept_pooled(PacketPool &pool, uint32_t handle) override;
    bool can_accept(const TimedPacket &p) const override
    {
        if (m_spaces.unbounded() || p.reserved) return true;
        const BufferSpace *s = m_spaces.find(index_of(p));
        return !s || s->available();
    }
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override { space_for(p).on_release(e); }
    BufferSpace *room_for(const TimedPacket &p) override { return &space_for(p); }

    int from() const { return m_from; }
    int to() const { return m_to; }
    int dir() const { return m_dir; }
    uint64_t packets() const { return m_packets; }
    double bytes() const { return m_bytes; }
    // Every crossing takes one packet time: the product is the sum, exactly (integer ticks).
    sc_core::sc_time busy_time() const { return sc_core::sc_time::from_value(m_packet_time.value() * m_packets); }
    // The link's buffers, every class and channel.
    ClassBuffers &queue() { return m_spaces; }
    LinkStats stats() const
    {
        return {m_from, m_to, m_dir, m_packets, m_bytes, busy_time().to_seconds(), m_spaces.high_water()};
    }
    void register_queues(QueueRegistry &reg)
    {
        reg.add(name(), QueueKind::link, m_from, m_spaces, m_spaces.depth_trace());
    }
    // The series told of every crossing as link `index` (null: none).
    void record_into(TimeSeries *series, size_t index)
    {
        m_series = series;
        m_series_index = index;
        m_recording = series != nullptr;
    }
    // Traced use: the percentage of the last window of kUseWindow packet times the link was
    // busy, set at each window's end; asking for it (before sc_start) makes the process that
    // drives it.
    int &use_trace();
    int use_peak() const { return m_use_peak; }  // the highest traced use
    static constexpr uint64_t kUseWindow = 100;

  private:
    static uint32_t index_of(const TimedPacket &p) { return 2 * p.cls + p.vc; }
    BufferSpace &space_for(const TimedPacket &p) { return m_spaces.at(index_of(p)); }
    // Sends packet `handle` of `pool` (its slot taken) now or, behind earlier crossings, later.
    void send(PacketPool &pool, uint32_t handle);
    // Loosely timed with a quantum: the start of the earliest gap at or after `ready` (booked);
    // out of line, so the approximately-timed send stays as small as without it.
    [[gnu::noinline]] sc_core::sc_time gap_start(const sc_core::sc_time &ready, const sc_core::sc_time &now);
    void drive_use_trace();
    void record_use(const sc_core::sc_time &start, const sc_core::sc_time &end);
    void before_end_of_elaboration() override;
    void start_of_simulation() override { m_fw = socket.operator->(); }

    sc_core::sc_time m_free_at = sc_core::SC_ZERO_TIME;  // busy until (the latest crossing's end)
    sc_core::sc_time m_packet_time;                      // serialisation time of one packet
    TransactionPool *m_transactions = &m_own_transactions;
    // The socket's bound target interface (what socket-> returns), kept after elaboration so a
    // crossing does not read the port for it.
    tlm::tlm_fw_transport_if<> *m_fw = nullptr;
    int m_to;  // the receiving node: each crossing is addressed to it
    int8_t m_dir;
    bool m_tracing = false, m_recording = false;  // the use traced; the crossings told to a series
    uint64_t m_packets = 0;
    double m_bytes = 0;
    double m_packet_bytes;
    ClassBuffers m_spaces;
    int m_from;
    TransactionPool m_own_transactions;
    PacketPool m_own_pool;  // packets handed over by value (accept), until they cross
    // Use trace (only when traced): the busy picoseconds of each window not yet shown (window
    // index, busy), in time order, and the event at the next window's end while there are any.
    struct UseTrace {
        uint64_t window = 0;  // picoseconds
        std::deque<std::pair<uint64_t, uint64_t>> windows;
        sc_core::sc_event tick{"trace_tick"};
        bool ticking = false;
    };
    std::unique_ptr<UseTrace> m_trace;
    int m_use = 0, m_use_peak = 0;   // the traced use and its highest value
    TimeSeries *m_series = nullptr;  // --stats-interval's (null: none), this link's index in it
    size_t m_series_index = 0;
    // Loosely timed with a quantum: the crossings booked ahead (null otherwise; off the lines a
    // crossing touches).
    std::unique_ptr<LinkBookings> m_bookings;
};

}  // namespace torusrt
