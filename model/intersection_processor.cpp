// intersection_processor.cpp - the IP's process: one kernel packet step per packet taken up.
#include "intersection_processor.h"

#include <stdexcept>

#include "flow_control.h"

namespace torusrt {

IntersectionProcessor::IntersectionProcessor(sc_core::sc_module_name name, const MachineConfig &config,
                                             const rt_scene *scene, const rt_grid *grid,
                                             const int32_t *cell_owner, int owner_id, int index,
                                             PacketLedger &ledger)
    : sc_module(name), in("in"), out("out"), fetch("fetch"), fb_socket("fb_socket"), m_config(config),
      m_scene(scene), m_grid(grid), m_owner(cell_owner), m_owner_id(owner_id), m_index(index),
      m_ledger(ledger), m_queue(std::string(basename()) + ".queue", config.queue_capacity),
      m_time(config.style == TimingStyle::lt), m_params(config.step),
      m_reserving(config.flow != FlowControl::none && config.queue_capacity != 0)
{
    in.bind(*this);
    if (rt_step_result_init(&m_result, scene) != RT_OK) throw std::bad_alloc();
    SC_HAS_PROCESS(IntersectionProcessor);
    SC_THREAD(run);
}

IntersectionProcessor::~IntersectionProcessor() { rt_step_result_release(&m_result); }

void IntersectionProcessor::on_test(void *ctx, uint32_t object)
{
    static_cast<IntersectionProcessor *>(ctx)->m_tested.push_back(object);
}

bool IntersectionProcessor::prepare(TimedPacket &tp)
{
    m_tested.clear();
    rt_status st = rt_step(m_scene, m_grid, m_owner, m_owner_id, &m_params, &tp.packet, &m_result);
    if (st != RT_OK) SC_REPORT_FATAL(name(), rt_status_name(st));
    m_outputs.clear();
    uint32_t cls = output_class(m_config.flow, tp.cls);
    for (size_t i = 0; i < m_result.created_count; i++) m_outputs.push_back(TimedPacket{m_result.created[i], {}});
    if (m_result.fate == RT_FATE_FORWARDED) m_outputs.push_back(TimedPacket{tp.packet, {}});
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
        first[i] = base[i] = out->room_for(m_outputs[i]);
        uint32_t rank = 0;
        for (size_t j = 0; j < i; j++) rank += base[j] == base[i];
        if (!rank) continue;
        m_outputs[i].cls += rank;
        first[i] = out->room_for(m_outputs[i]);
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
    // Unbounded buffers or --flow none: the oldest packet, stepped once taken.
    if (!m_reserving) return m_queue.try_take_first(m_current) && prepare(m_current);
    // Else each candidate is stepped (on a copy: a refused one stays as it is in the queue).
    return m_queue.try_take(
        [this](const TimedPacket &c) {
            m_current = c;
            return prepare(m_current);
        },
        nullptr);
}

void IntersectionProcessor::run()
{
    bool fetching = fetch.size() > 0;
    if (fetching) {
        m_params.on_test = &IntersectionProcessor::on_test;
        m_params.on_test_ctx = this;
    }
    for (;;) {
        if (m_queue.empty()) m_time.sync();
        sc_core::sc_time before = m_time.now();
        while (!try_take_up()) {
            m_queue.wait_reader();
            if (m_queue.empty()) sc_core::wait(m_queue.not_empty_event());
            else sc_core::wait(m_queue.not_empty_event() | m_room);
        }
        TimedPacket &tp = m_current;
        m_time.settle(before); // it may have waited for room
        m_time.advance_to(tp.stamp); // never start a packet before it arrived
        m_packets_in++;
        m_busy_flag = true;
        rt_ops_add(&m_ops, &m_result.ops);
        sc_core::sc_time start = m_time.now();
        for (uint32_t obj : m_tested) fetch->fetch(m_index, obj, m_time);
        m_time.advance(sc_core::sc_time(rt_timing_step_us(&m_config.timing, &m_result.ops), sc_core::SC_US));
        m_busy += m_time.now() - start;
        m_busy_flag = false;

        if (m_result.contrib_count) {
            sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
            m_fb_trans.set_command(tlm::TLM_WRITE_COMMAND);
            m_fb_trans.set_data_ptr(reinterpret_cast<unsigned char *>(m_result.contrib));
            m_fb_trans.set_data_length(static_cast<unsigned>(m_result.contrib_count * sizeof(rt_contribution)));
            m_fb_trans.set_streaming_width(m_fb_trans.get_data_length());
            m_fb_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
            fb_socket->b_transport(m_fb_trans, delay);
        }
        // New packets are counted before the input is consumed, so the ledger never sees
        // zero outstanding while work remains.
        sc_core::sc_time now = m_time.now();
        for (size_t i = 0; i < m_result.created_count; i++) m_ledger.created(m_result.created[i].kind);
        if (m_result.fate == RT_FATE_FORWARDED) m_ledger.forwarded();
        else m_ledger.consumed(tp.packet.kind, now);
        for (TimedPacket &o : m_outputs) {
            o.stamp = now;
            out->accept(o);
            m_time.settle(now); // a full queue may have held us (--flow none)
        }
        m_packets_out += m_outputs.size();
    }
}

}  // namespace torusrt
