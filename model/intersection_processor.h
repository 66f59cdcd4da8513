// intersection_processor.h - an intersection processor (IP): takes packets from its input queue,
// runs the kernel's packet step over the cells its node owns, spends the time the step's
// operation counts cost, writes contributions to the frame buffer and hands new and forwarded
// packets to its communication unit. Under the class scheme (flow_control.h) it takes up a
// packet only once it has reserved a slot for each of the packet's outputs in the buffer the
// output goes to first, trying its waiting packets in queue order; so it never waits with a
// packet in hand. Under --flow none it takes the oldest packet and waits at each hand-over.
//
// Process: one state machine (act(): take up, wait for the arrival, fetch, step, hand over) that
// runs until it must wait and says what for. Its driver (processor_driver.h) runs it again when
// that comes, and decides its order within a delta cycle: SC_METHODs on a flat torus, an
// SC_THREAD in a cluster, because crossing the cluster bus (packets out, shared-data fetches)
// waits in b_transport. Without reservations it steps a packet in its pool slot and forwards it
// by the same handle.
#pragma once

#include <string>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "delivery_round_if.h"
#include "module_stats.h"
#include "object_fetch_if.h"
#include "packet_ledger.h"
#include "packet_queue.h"
#include "packet_sink_if.h"
#include "processor_driver.h"
#include "queue_registry.h"
#include "rt_grid.h"
#include "rt_ops.h"
#include "rt_scene.h"
#include "rt_step.h"
#include "activation_queue.h"
#include "sim_config.h"
#include "time_keeper.h"
#include "time_series.h"
#include "timed_wake.h"
#include "wake_calendar.h"

namespace torusrt {

// The machine's choices for a processor, fixed at elaboration; a processor alone takes the
// defaults (its own timer, activation event and queue pool, no primaries).
struct ProcessorSetup {
    // The machine's wake calendar, which then ends the method driver's timed waits (without it,
    // and for a zero wait, the processor notifies its own timer). Processors and units due at one
    // time wake in the order they were built.
    WakeCalendar *calendar = nullptr;
    // The machine's activation queue, which then runs this processor's state machine when it is
    // woken (null: an event of its own).
    ActivationQueue *activations = nullptr;
    // Where nodes do not affect each other within a delta cycle (a flat, approximately-timed
    // machine with a positive link time and unbounded buffers), what must come before the state
    // machine in a delta is only the deliveries of its own node's unit: it then runs at once
    // when none is due, or right after the unit's delivery round, not from the activation queue,
    // and its queue tells it of a packet in the pushing delta (null: not so).
    DeliveryRoundIf *order_after = nullptr;
    // The machine's packet pool, for the input queue (null: the queue's own).
    PacketPool *pool = nullptr;
    // The host's primaries that enter at this processor's node (null: none, as in a cluster,
    // whose dispatcher takes them).
    PrimarySource *primaries = nullptr;
    // Extra owners of replicated cells, for the step (null: none).
    const rt_replicas *replicas = nullptr;
};

class IntersectionProcessor : public sc_core::sc_module, public PacketSinkIf {
  public:
    sc_core::sc_export<PacketSinkIf> in;                                       // packets to process
    sc_core::sc_port<PacketSinkIf> out;                                        // new and forwarded packets
    sc_core::sc_port<ObjectFetchIf, 1, sc_core::SC_ZERO_OR_MORE_BOUND> fetch;  // shared-data reads
    tlm_utils::simple_initiator_socket<IntersectionProcessor> fb_socket;       // frame-buffer writes

    // `owner_id` is the id the cell-owner table uses for this IP's node.
    IntersectionProcessor(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene,
                          const rt_grid *grid, const int32_t *cell_owner, int owner_id, int index, PacketLedger &ledger,
                          const ProcessorSetup &setup = ProcessorSetup());
    ~IntersectionProcessor() override;

    void accept(const TimedPacket &p) override { m_queue.push_blocking(p); }
    void accept_pooled(PacketPool &pool, uint32_t handle) override { m_queue.push_pooled(pool, handle); }
    bool can_accept(const TimedPacket &p) const override { return m_queue.has_room(p); }
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override { m_queue.space_for(p).on_release(e); }
    BufferSpace *room_for(const TimedPacket &p) override { return &m_queue.space_for(p); }

    // Statistics, read after the run.
    const sc_core::sc_time &busy_time() const { return m_busy; }
    uint64_t packets_in() const { return m_packets_in; }
    uint64_t packets_out() const { return m_packets_out; }
    PacketQueue &queue() { return m_queue; }
    IpStats stats() const
    {
        // Starved: the rest of the time before the last hand-over (busy and blocked are counted).
        sc_core::sc_time counted = m_busy + m_blocked;
        sc_core::sc_time starved = m_before > counted ? m_before - counted : sc_core::SC_ZERO_TIME;
        return {m_busy.to_seconds(), starved.to_seconds(), m_blocked.to_seconds(), m_before.to_seconds(),
                m_packets_in,        m_packets_out,        m_queue.high_water(),   m_ops};
    }
    void register_queues(QueueRegistry &reg)
    {
        reg.add(std::string(name()) + ".input", QueueKind::ip, m_owner_id, m_queue.spaces(), m_queue.depth_trace(),
                std::string(name()) + ".queue_depth");
    }
    int index() const { return m_index; }
    // The series told of every busy span (null: none).
    void record_into(TimeSeries *series) { m_series = series; }
    bool &busy_trace() { return m_busy_flag; }  // the VCD's busy row
    bool busy() const { return m_busy_flag; }   // working on a packet now

  private:
    friend class ProcessorDriver;  // runs act()
    using Wake = ProcessorWake;
    enum class Stage : uint8_t { top, take_up_first, take_up, begin, end, hand_over };
    // Runs the machine from m_stage until it must wait; returns what for.
    Wake act();
    bool owe(const TimeWait &w);
    void begin_step();
    void end_step();
    bool hand_over();  // false: waiting for the processor side (m_out_room)
    // The processes, each its driver's.
    void run_thread() { m_driver.run_thread(); }
    void on_wake() { m_driver.woken(); }
    void on_room() { m_driver.room_released(); }
    void run_method() { m_driver.run(); }
    void end_of_elaboration() override;
    void start_of_simulation() override
    {
        m_out = out.operator->();
        m_fb = fb_socket.operator->();
    }
    // Runs the step of `tp` (updated in place) and lists its outputs; under the class scheme
    // reserves their slots and returns false (nothing reserved) if one has no room.
    bool prepare(TimedPacket &tp);
    bool reserve_outputs();
    // Takes up the next packet into m_current (stepped, its outputs listed and reserved); false:
    // none can be taken now.
    bool try_take_up();
    static void on_test(void *ctx, uint32_t object);

    // What a step reads and writes first, in the order a step touches it; what only a cluster,
    // the class scheme or a copied packet uses after the queue.
    Stage m_stage = Stage::top;
    bool m_reserving;                 // outputs reserve their slots before a packet is taken up
    bool m_threaded;                  // a thread (cluster): a hand-over may wait for the bus
    bool m_forward_pooled = false;    // the step forwards the packet taken up by its handle
    bool m_room_wait = false;         // a wait for room for a queued packet's outputs is on
    bool m_hand_over_waited = false;  // a method: the hand-over waited for the processor side
    static constexpr uint32_t kNoHandle = ~uint32_t{0};
    uint32_t m_handle = kNoHandle;
    uint32_t m_out_cls = 0;  // the class of the step's outputs
    // The packet taken up: m_current, or its pool slot (m_handle) where it was stepped in place.
    TimedPacket *m_cur = &m_current;
    // The interfaces bound to `out` and `fb_socket`, kept after elaboration so a step does not
    // read the ports for them.
    PacketSinkIf *m_out = nullptr;
    tlm::tlm_fw_transport_if<> *m_fb = nullptr;
    const MachineConfig &m_config;
    const rt_scene *m_scene;
    const rt_grid *m_grid;
    const int32_t *m_owner;
    int m_owner_id, m_index;
    PacketLedger &m_ledger;
    rt_step_params m_params;
    TimeKeeper m_time;
    sc_core::sc_time m_before, m_start, m_handed_at;
    sc_core::sc_time m_busy = sc_core::SC_ZERO_TIME;
    TimeSeries *m_series = nullptr;  // --stats-interval's series (null: none), asked at each step's end
    size_t m_next_out = 0;           // the next output to hand over
    uint64_t m_packets_in = 0, m_packets_out = 0;
    bool m_busy_flag = false;
    rt_op_counts m_ops{};
    rt_step_result m_result;
    // The current step's created packets, then the forwarded one (by copy).
    std::vector<TimedPacket> m_outputs;
    sc_core::sc_event m_room;      // an output's buffer released a slot
    sc_core::sc_event m_out_room;  // the processor side may hand over again
    ProcessorDriver m_driver;      // runs act() when what it waits for comes (the queue's reader)
    PacketQueue m_queue;
    TimedPacket m_current;  // the packet taken up (after its step), when taken up by copy
    // Idle time waiting for room or to hand over; a wait for room for the outputs of a packet in
    // the queue began at m_room_from.
    sc_core::sc_time m_blocked, m_room_from;
    std::vector<uint32_t> m_tested;       // objects tested in the current step (shared data only)
    tlm::tlm_generic_payload m_fb_trans;  // a member, not a thread local: freed with the module
};

}  // namespace torusrt
