// intersection_processor.cpp - the IP's state machine (one kernel packet step per packet taken
// up); processor_driver.cpp runs it.
#include "intersection_processor.h"

#include <algorithm>
#include <stdexcept>

#include "flow_control.h"

namespace torusrt {

IntersectionProcessor::IntersectionProcessor(sc_core::sc_module_name name, const MachineConfig &config,
                                             const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                                             int owner_id, int index, PacketLedger &ledger, const ProcessorSetup &setup)
    : sc_module(name), in("in"), out("out"), fetch("fetch"), fb_socket("fb_socket"),
      m_reserving(config.flow != FlowControl::none && config.queue_capacity != 0), m_threaded(config.cluster > 1),
      m_config(config), m_scene(scene), m_grid(grid), m_owner(cell_owner), m_owner_id(owner_id), m_index(index),
      m_ledger(ledger), m_params(config.step), m_time(config.style == TimingStyle::lt),
      m_driver(*this, m_queue, m_room, m_out_room, setup.calendar, setup.activations, setup.order_after),
      m_queue(std::string(basename()) + ".queue", config.queue_capacity,
              {setup.pool, setup.primaries, owner_id, config.queue_order == QueueOrder::rays_first,
               config.style == TimingStyle::lt && config.quantum_us > 0 && !m_reserving,
               setup.order_after ? &m_driver : nullptr})
{
    in.bind(*this);
    m_params.replicas = setup.replicas;
    if (rt_step_result_init(&m_result, scene) != RT_OK) throw std::bad_alloc();
    SC_HAS_PROCESS(IntersectionProcessor);
    if (m_threaded) {
        SC_THREAD(run_thread);
        return;
    }
    SC_METHOD(on_wake);  // also runs once at the start
    sensitive << m_driver.timer_event() << m_queue.not_empty_event() << m_out_room;
    SC_METHOD(on_room);
    sensitive << m_room;
    dont_initialize();
    SC_METHOD(run_method);
    sensitive << m_driver.act_event();
    dont_initialize();
}

void IntersectionProcessor::end_of_elaboration()
{
    if (fetch.size() > 0) {
        m_params.on_test = &IntersectionProcessor::on_test;
        m_params.on_test_ctx = this;
        if (!m_threaded) SC_REPORT_FATAL(name(), "shared-data fetches wait on the bus: the processor needs its thread");
    }
}

IntersectionProcessor::~IntersectionProcessor() { rt_step_result_release(&m_result); }

void IntersectionProcessor::on_test(void *ctx, uint32_t object)
{
    static_cast<IntersectionProcessor *>(ctx)->m_tested.push_back(object);
}

bool IntersectionProcessor::prepare(TimedPacket &tp)
{
    if (m_params.on_test) m_tested.clear();  // shared data only: else the list's line stays cold
    rt_status st = rt_step(m_scene, m_grid, m_owner, m_owner_id, &m_params, &tp.packet, &m_result);
    if (st != RT_OK) SC_REPORT_FATAL(name(), rt_status_name(st));
    m_outputs.clear();
    uint32_t cls = output_class(m_config.flow, tp.cls);
    m_out_cls = cls;
    for (size_t i = 0; i < m_result.created_count; i++) m_outputs.push_back(TimedPacket{m_result.created[i], {}});
    // Stepped in its pool slot, a forwarded packet leaves by its handle (hand_over()).
    m_forward_pooled = m_result.fate == RT_FATE_FORWARDED && m_handle != kNoHandle;
    if (m_result.fate == RT_FATE_FORWARDED && !m_forward_pooled) m_outputs.push_back(TimedPacket{tp.packet, {}});
    for (TimedPacket &o : m_outputs) o.cls = cls;
    // Unbounded buffers always have room: nothing to reserve (the timing is the same either way).
    return !m_reserving || reserve_outputs();
}

bool IntersectionProcessor::reserve_outputs()
{
    // Outputs that would share a first buffer go one class up each (see flow_control.h), so
    // every output needs one slot of its own and a step fits buffers of capacity 1.
    std::vector<BufferSpace *> base(m_outputs.size()), first(m_outputs.size());
    for (size_t i = 0; i < m_outputs.size(); i++) {
        first[i] = base[i] = m_out->room_for(m_outputs[i]);
        uint32_t rank = 0;
        for (size_t j = 0; j < i; j++) rank += base[j] == base[i];
        if (!rank) continue;
        m_outputs[i].cls += rank;
        first[i] = m_out->room_for(m_outputs[i]);
    }
    for (size_t i = 0; i < m_outputs.size(); i++)
        if (first[i] && !first[i]->available()) {
            first[i]->on_release(m_room);
            return false;
        }
    for (size_t i = 0; i < m_outputs.size(); i++) {
        if (first[i]) first[i]->take();
        m_outputs[i].reserved = true;
    }
    return true;
}

bool IntersectionProcessor::try_take_up()
{
    // Unbounded buffers or --flow none: the oldest packet, stepped once taken, in its pool slot.
    if (!m_reserving) {
        if (!m_queue.try_take_first_pooled(m_handle)) return false;
        m_cur = &m_queue.pool().at(m_handle);
        return prepare(*m_cur);
    }
    // Else each candidate is stepped (on a copy: a refused one stays as it is in the queue).
    m_cur = &m_current;
    return m_queue.try_take(
        [this](const TimedPacket &c) {
            m_current = c;
            return prepare(m_current);
        },
        nullptr);
}

bool IntersectionProcessor::owe(const TimeWait &w)
{
    m_driver.owe(w.delay);
    return w.due;
}

IntersectionProcessor::Wake IntersectionProcessor::act()
{
    if (m_driver.waited_for() == Wake::timer) m_time.resumed();
    for (;;) switch (m_stage) {
        case Stage::top:
            m_stage = Stage::take_up_first;
            // Loosely timed, a processor whose queue ran empty synchronises before it waits: one
            // that waited ahead would take up later packets before earlier ones still to come
            // (docs/model.md, Timing styles).
            if (m_queue.empty() && owe(m_time.sync_nb())) return Wake::timer;
            break;
        case Stage::take_up_first:
            m_before = m_time.now();
            m_stage = Stage::take_up;
            break;
        case Stage::take_up:
            if (!try_take_up()) {
                if (!m_room_wait && !m_queue.empty()) {  // a packet waits for room for its outputs
                    m_room_wait = true;
                    m_room_from = m_time.now();
                }
                m_queue.wait_reader();
                return m_queue.empty() ? Wake::queue : Wake::queue_or_room;
            }
            m_time.settle(m_before);  // it may have waited for room
            if (m_room_wait) {
                m_blocked += m_time.now() - m_room_from;
                m_room_wait = false;
            }
            m_stage = Stage::begin;
            if (owe(m_time.advance_to_nb(m_cur->stamp))) return Wake::timer;  // never start before it arrived
            break;
        case Stage::begin:
            begin_step();
            m_stage = Stage::end;
            if (owe(m_time.advance_nb(
                    sc_core::sc_time(rt_timing_step_us(&m_config.timing, &m_result.ops), sc_core::SC_US))))
                return Wake::timer;
            break;
        case Stage::end:
            end_step();
            m_next_out = 0;
            m_stage = Stage::hand_over;
            break;
        case Stage::hand_over:
            if (!hand_over()) return Wake::out_room;
            m_stage = Stage::top;
            break;
        }
}

void IntersectionProcessor::begin_step()
{
    m_packets_in++;
    m_busy_flag = true;
    rt_ops_add(&m_ops, &m_result.ops);
    m_start = m_time.now();
    // A primary's first step: nothing worked on it yet, no link crossed.
    const rt_packet &in = m_cur->packet;
    if (in.depth == 0 && in.kind == RT_PACKET_RAY && m_cur->hops == 0 && m_cur->worked_ns == 0) {
        m_cur->born = m_start;  // its wait in the host's memory, in no buffer, is not its latency
        m_ledger.latency().primary_started(in.x, in.y, m_start);
    }
    if (m_params.on_test)
        for (uint32_t obj : m_tested) fetch->fetch(m_index, obj, m_time);  // a thread: it may wait
}

void IntersectionProcessor::end_step()
{
    sc_core::sc_time done = m_time.now();
    m_busy += done - m_start;
    if (m_series) m_series->ip_busy(m_start, done);
    m_busy_flag = false;
    if (m_result.contrib_count) {
        sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
        m_fb_trans.set_command(tlm::TLM_WRITE_COMMAND);
        m_fb_trans.set_data_ptr(reinterpret_cast<unsigned char *>(m_result.contrib));
        m_fb_trans.set_data_length(static_cast<unsigned>(m_result.contrib_count * sizeof(rt_contribution)));
        m_fb_trans.set_streaming_width(m_fb_trans.get_data_length());
        m_fb_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        m_fb->b_transport(m_fb_trans, delay);
    }
    // New packets are counted before the input is consumed, so the ledger never sees
    // zero outstanding while work remains.
    m_handed_at = m_time.now();
    for (size_t i = 0; i < m_result.contrib_count; i++)
        m_ledger.latency().contributed(m_result.contrib[i].x, m_result.contrib[i].y, m_handed_at);
    for (size_t i = 0; i < m_result.created_count; i++) m_ledger.created(m_result.created[i].kind);
    sc_core::sc_time step = m_handed_at - m_start;
    if (m_result.fate == RT_FATE_FORWARDED) {
        m_ledger.forwarded();
        // It goes on, in its slot or as the last output; its steps' time (time values are
        // picoseconds, module_stats.h) saturates.
        uint64_t ns = m_cur->worked_ns + step.value() / 1000;
        m_cur->worked_ns = static_cast<uint32_t>(std::min<uint64_t>(ns, UINT32_MAX));
        if (!m_forward_pooled) {
            TimedPacket &copy = m_outputs.back();
            copy.born = m_cur->born;
            copy.worked_ns = m_cur->worked_ns;
            copy.hops = m_cur->hops;
        }
    } else {
        const rt_packet &in = m_cur->packet;
        int kind = in.kind == RT_PACKET_SHADOW ? PacketLatency::shadow
                   : in.depth == 0             ? PacketLatency::primary
                                               : PacketLatency::ray;
        m_ledger.latency().consumed(kind, m_cur->born, m_cur->worked_ns * UINT64_C(1000), step, m_cur->hops,
                                    m_handed_at);
        m_ledger.consumed(m_cur->packet.kind, m_handed_at);
    }
    for (size_t i = 0; i < m_result.created_count; i++) m_outputs[i].born = m_handed_at;
    if (m_handle != kNoHandle && !m_forward_pooled) {  // consumed: its slot is free
        m_queue.pool().release(m_handle);
        m_handle = kNoHandle;
    }
}

bool IntersectionProcessor::hand_over()
{
    size_t total = m_outputs.size() + m_forward_pooled;
    for (; m_next_out < total; m_next_out++) {
        bool pooled = m_next_out == m_outputs.size();  // the forwarded packet, in its slot
        TimedPacket &o = pooled ? *m_cur : m_outputs[m_next_out];
        if (pooled) {  // as a new packet of the step's: only the kernel's packet carries over
            o.cls = m_out_cls;
            o.vc = 0;
            o.last_dir = -1;
            o.reserved = o.from_host = false;
        }
        o.stamp = m_handed_at;
        if (!m_out->can_accept(o)) {  // a packet of ours is held (--flow none)
            m_out->on_space(o, m_out_room);
            m_hand_over_waited = true;
            return false;
        }
        // A cluster's bus port waits here for the bus (a thread).
        if (pooled) m_out->accept_pooled(m_queue.pool(), m_handle);
        else m_out->accept(o);
        m_time.settle(m_handed_at);
    }
    if (m_forward_pooled) m_handle = kNoHandle;  // the receiver owns it now
    m_packets_out += total;
    // Waiting for room or (a thread) the bus to hand over.
    if (m_threaded || m_hand_over_waited) m_blocked += m_time.now() - m_handed_at;
    m_hand_over_waited = false;
    return true;
}

}  // namespace torusrt
