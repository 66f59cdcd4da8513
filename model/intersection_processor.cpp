// intersection_processor.cpp - the IP's process: one kernel packet step per packet taken up.
#include "intersection_processor.h"

#include <stdexcept>

namespace torusrt {

IntersectionProcessor::IntersectionProcessor(sc_core::sc_module_name name, const MachineConfig &config,
                                             const rt_scene *scene, const rt_grid *grid,
                                             const int32_t *cell_owner, int owner_id, int index,
                                             PacketLedger &ledger)
    : sc_module(name), in("in"), out("out"), fetch("fetch"), fb_socket("fb_socket"), m_config(config),
      m_scene(scene), m_grid(grid), m_owner(cell_owner), m_owner_id(owner_id), m_index(index),
      m_ledger(ledger), m_queue(std::string(basename()) + ".queue", config.queue_capacity),
      m_time(config.style == TimingStyle::lt), m_params(config.step)
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

void IntersectionProcessor::run()
{
    bool fetching = fetch.size() > 0;
    if (fetching) {
        m_params.on_test = &IntersectionProcessor::on_test;
        m_params.on_test_ctx = this;
    }
    for (;;) {
        if (m_queue.empty()) m_time.sync();
        TimedPacket tp = m_queue.pop_blocking();
        m_time.advance_to(tp.stamp); // never start a packet before it arrived
        m_packets_in++;
        m_busy_flag = true;
        m_tested.clear();
        rt_status st = rt_step(m_scene, m_grid, m_owner, m_owner_id, &m_params, &tp.packet, &m_result);
        if (st != RT_OK) SC_REPORT_FATAL(name(), rt_status_name(st));
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
        for (size_t i = 0; i < m_result.created_count; i++) {
            out->accept(TimedPacket{m_result.created[i], now});
            m_time.settle(now); // a full queue may have held us
        }
        m_packets_out += m_result.created_count;
        if (m_result.fate == RT_FATE_FORWARDED) {
            out->accept(TimedPacket{tp.packet, now});
            m_time.settle(now);
            m_packets_out++;
        }
    }
}

}  // namespace torusrt
