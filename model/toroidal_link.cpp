// toroidal_link.cpp - busy-until serialisation of one link direction.
#include "toroidal_link.h"

#include <algorithm>
#include <cmath>

#include "sim_now.h"

namespace torusrt {

ToroidalLink::ToroidalLink(sc_core::sc_module_name name, const MachineConfig &config, int from, int to, int dir,
                           TransactionPool *transactions)
    : sc_module(name), socket("socket"), in("in"),
      m_packet_time(rt_timing_link_packet_us(&config.timing), sc_core::SC_US), m_to(to),
      m_dir(static_cast<int8_t>(dir)), m_packet_bytes(config.timing.packet_bytes), m_spaces(config.queue_capacity),
      m_from(from)
{
    if (transactions) m_transactions = transactions;
    if (config.style == TimingStyle::lt && config.quantum_us > 0) m_bookings = std::make_unique<LinkBookings>();
    in.bind(*this);
}

void ToroidalLink::before_end_of_elaboration()
{
    // Only a traced link has the process, its event and its list of windows: an untraced
    // machine of n nodes saves 6n of each (5 MB at 512 nodes) and their creation. Tracing is
    // asked for before sc_start.
    if (!m_tracing || m_packet_time == sc_core::SC_ZERO_TIME) return;  // an instant link stays at 0
    m_trace = std::make_unique<UseTrace>();
    m_trace->window = m_packet_time.value() * kUseWindow;
    SC_HAS_PROCESS(ToroidalLink);
    SC_METHOD(drive_use_trace);
    sensitive << m_trace->tick;
    dont_initialize();
}

void ToroidalLink::accept(const TimedPacket &p) { accept_pooled(m_own_pool, m_own_pool.add(p, -1)); }

void ToroidalLink::accept_pooled(PacketPool &pool, uint32_t handle)
{
    if (!pool.at(handle).reserved) space_for(pool.at(handle)).take_blocking();  // a method checked room: no wait
    pool.at(handle).reserved = false;
    send(pool, handle);
}

void ToroidalLink::send(PacketPool &pool, uint32_t handle)
{
    // A packet that waited for room is sent no earlier than now; a crossing cannot start before
    // the packet was sent, nor before the previous crossing ends.
    const sc_core::sc_time now = sim_now();
    TimedPacket &p = pool.at(handle);
    if (p.stamp < now) p.stamp = now;
    sc_core::sc_time start = p.stamp > m_free_at ? p.stamp : m_free_at;
    if (m_bookings) start = gap_start(p.stamp, now);
    const sc_core::sc_time end = start + m_packet_time;
    if (end > m_free_at) m_free_at = end;
    m_packets++;
    m_bytes += m_packet_bytes;
    if (m_recording) m_series->link_busy(m_series_index, start, end);
    if (m_tracing && m_trace) record_use(start, end);  // m_trace: a link that takes time
    p.stamp = end;
    p.last_dir = m_dir;
    p.hops++;
    // A write to the receiving node, data = the packet as held in memory (its size on the wire is
    // a timing parameter); the packet itself goes by handle, with the slot it holds here.
    TransactionPool::Crossing c = m_transactions->take();
    c.ext->pool = &pool;
    c.ext->handle = handle;
    c.ext->credit = &space_for(p);
    tlm::tlm_generic_payload &trans = *c.trans;
    trans.set_address(static_cast<uint64_t>(m_to));
    trans.set_data_ptr(reinterpret_cast<unsigned char *>(&p.packet));
    trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    // Annotated delay: queueing behind earlier packets plus serialisation.
    sc_core::sc_time delay = end - now;
    trans.acquire();
    m_fw->b_transport(trans, delay);
    bool refused = trans.is_response_error();
    trans.release();  // back to the pool
    if (refused) SC_REPORT_FATAL(name(), "the receiving communication unit refused a packet");
}

sc_core::sc_time ToroidalLink::gap_start(const sc_core::sc_time &ready, const sc_core::sc_time &now)
{
    if (m_packet_time == sc_core::SC_ZERO_TIME) return ready;
    return sc_core::sc_time::from_value(m_bookings->book(ready.value(), now.value(), m_packet_time.value()));
}

int &ToroidalLink::use_trace()
{
    // The process that drives the value is made at the end of elaboration.
    if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)
        SC_REPORT_FATAL(name(), "a link's use trace must be asked for before sc_start");
    m_tracing = true;
    return m_use;
}

void ToroidalLink::record_use(const sc_core::sc_time &start, const sc_core::sc_time &end)
{
    UseTrace &t = *m_trace;
    // Crossings come in time order, so each piece lands in the last window listed or a later one.
    for (uint64_t a = start.value(), b = end.value(); a < b;) {
        uint64_t k = a / t.window, stop = std::min(b, (k + 1) * t.window);
        if (t.windows.empty() || t.windows.back().first != k) t.windows.emplace_back(k, 0);
        t.windows.back().second += stop - a;
        a = stop;
    }
    if (t.ticking) return;
    t.ticking = true;
    uint64_t now = sc_core::sc_time_stamp().value();
    t.tick.notify(sc_core::sc_time::from_value((now / t.window + 1) * t.window - now));
}

void ToroidalLink::drive_use_trace()
{
    UseTrace &t = *m_trace;
    uint64_t ended = sc_core::sc_time_stamp().value() / t.window;  // window ended-1 just ended
    while (!t.windows.empty() && t.windows.front().first + 1 < ended) t.windows.pop_front();
    uint64_t busy = 0;
    if (!t.windows.empty() && t.windows.front().first + 1 == ended) {
        busy = t.windows.front().second;
        t.windows.pop_front();
    }
    m_use = static_cast<int>(std::lround(100.0 * static_cast<double>(busy) / static_cast<double>(t.window)));
    if (m_use > m_use_peak) m_use_peak = m_use;
    t.ticking = !t.windows.empty() || m_use != 0;  // one more window shows the return to 0
    if (t.ticking) t.tick.notify(sc_core::sc_time::from_value(t.window));
}

}  // namespace torusrt
