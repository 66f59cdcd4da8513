// toroidal_link.cpp - busy-until serialisation of one link direction.
#include "toroidal_link.h"

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
    in.bind(*this);
}

void ToroidalLink::before_end_of_elaboration()
{
    // Only a traced link has the process, its event and its list of crossings: an untraced
    // machine of n nodes saves 6n of each (5 MB at 512 nodes) and their creation. Tracing is
    // asked for before sc_start.
    if (!m_tracing) return;
    m_trace = std::make_unique<BusyTrace>();
    SC_HAS_PROCESS(ToroidalLink);
    SC_METHOD(drive_busy_trace);
    sensitive << m_trace->changed;
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
    m_free_at = start + m_packet_time;
    m_packets++;
    m_bytes += m_packet_bytes;
    if (m_tracing) {  // m_trace exists whenever it is set
        m_trace->crossings.emplace_back(start, m_free_at);
        m_trace->changed.notify(sc_core::SC_ZERO_TIME);
    }
    p.stamp = m_free_at;
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
    sc_core::sc_time delay = m_free_at - now;
    trans.acquire();
    m_fw->b_transport(trans, delay);
    bool refused = trans.is_response_error();
    trans.release();  // back to the pool
    if (refused) SC_REPORT_FATAL(name(), "the receiving communication unit refused a packet");
}

bool &ToroidalLink::busy_trace()
{
    // The process that drives the line is made at the end of elaboration.
    if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)
        SC_REPORT_FATAL(name(), "a link's busy trace must be asked for before sc_start");
    m_tracing = true;
    return m_busy_flag;
}

void ToroidalLink::drive_busy_trace()
{
    sc_core::sc_time now = sim_now();
    auto &crossings = m_trace->crossings;
    while (!crossings.empty() && crossings.front().second <= now) crossings.pop_front();
    // Crossings are back to back or separated by idle time; the flag follows the front one.
    m_busy_flag = !crossings.empty() && crossings.front().first <= now;
    if (crossings.empty()) return;
    const sc_core::sc_time &next = m_busy_flag ? crossings.front().second : crossings.front().first;
    m_trace->changed.notify(next - now);
}

}  // namespace torusrt
