// cluster_bus.cpp - request, arbitration, grant and occupancy of the cluster bus.
#include "cluster_bus.h"

#include <string>

#include "sim_now.h"

namespace torusrt {

ClusterBus::ClusterBus(sc_core::sc_module_name name, const rt_timing &timing, bool loosely_timed, int requesters)
    : sc_module(name), target("target"), memory("memory"), arbiter("arbiter"), m_timing(timing), m_lt(loosely_timed),
      m_requesters(requesters), m_request_line(new bool[requesters]()), m_requesting(requesters, false),
      m_per(requesters)
{
    for (int i = 0; i < requesters; i++)
        m_granted.push_back(std::make_unique<sc_core::sc_event>(("granted_" + std::to_string(i)).c_str()));
    target.register_b_transport(this, &ClusterBus::b_transport);
    SC_HAS_PROCESS(ClusterBus);
    SC_METHOD(arbitrate);
    sensitive << m_arbitrate;
    dont_initialize();
}

void ClusterBus::end_of_elaboration()
{
    if (static_cast<int>(target.size()) != m_requesters)
        SC_REPORT_FATAL(name(), ("expected " + std::to_string(m_requesters) + " masters, " +
                                 std::to_string(target.size()) + " bound")
                                    .c_str());
}

sc_core::sc_time ClusterBus::transfer_time(double bytes) const
{
    return sc_core::sc_time(m_timing.bus_arbitration_us + rt_timing_bus_transfer_us(&m_timing, bytes), sc_core::SC_US);
}

int ClusterBus::waiting() const
{
    int n = 0;
    for (bool r : m_requesting) n += r;
    return n;
}

namespace {

GrantWait grant_wait(const ClusterBus::GrantStats &g) { return {g.grants, g.wait_sum.value(), g.wait_max.value()}; }

}  // namespace

BusStats ClusterBus::stats() const
{
    BusStats s;
    s.busy_s = m_busy.to_seconds();
    s.packet_transfers = m_packet_transfers;
    s.object_reads = m_object_reads;
    s.packet_bytes = m_packet_bytes;
    s.object_bytes = m_object_bytes;
    s.all = grant_wait(m_all);
    for (const auto &g : m_per) s.per_requester.push_back(grant_wait(g));
    s.waiting = waiting();
    return s;
}

double ClusterBus::carry(tlm::tlm_generic_payload &trans, sc_core::sc_time &memory_delay)
{
    memory_delay = sc_core::SC_ZERO_TIME;
    if (trans.is_write()) {
        trans.set_response_status(tlm::TLM_OK_RESPONSE);
        return m_timing.packet_bytes;
    }
    int holder = static_cast<int>(trans.get_address() >> 32);
    if (holder < 0 || holder >= static_cast<int>(memory.size())) {
        trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return 0;
    }
    uint64_t address = trans.get_address();
    trans.set_address(address & 0xffffffffu);  // the memory sees its local address
    memory[holder]->b_transport(trans, memory_delay);
    trans.set_address(address);
    return trans.get_data_length();
}

void ClusterBus::record(int id, const tlm::tlm_generic_payload &trans, double bytes, const sc_core::sc_time &requested,
                        const sc_core::sc_time &start, const sc_core::sc_time &occupancy)
{
    sc_core::sc_time wait = start - requested;
    m_all.add(wait);
    m_per[id].add(wait);
    m_busy += occupancy;
    if (trans.is_write()) {
        m_packet_transfers++;
        m_packet_bytes += bytes;
    } else if (trans.is_response_ok()) {  // a failed read occupies the bus but moves nothing
        m_object_reads++;
        m_object_bytes += bytes;
    }
    if (m_observer) m_observer->granted(Grant{id, requested, start, start + occupancy});
}

void ClusterBus::b_transport(int id, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay)
{
    if (id < 0 || id >= m_requesters) {
        trans.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
        return;
    }
    if (m_lt) {
        sc_core::sc_time requested = sim_now() + delay;
        sc_core::sc_time memory_delay;
        double bytes = carry(trans, memory_delay);
        sc_core::sc_time occupancy = transfer_time(bytes) + memory_delay;
        sc_core::sc_time start = reserve(requested, occupancy);
        record(id, trans, bytes, requested, start, occupancy);
        delay = start + occupancy - sim_now();
        return;
    }
    // Approximately timed: the master's annotated delay is spent first, then it requests.
    if (delay > sc_core::SC_ZERO_TIME) {
        sc_core::wait(delay);
        delay = sc_core::SC_ZERO_TIME;
    }
    if (m_requesting[id] || m_owner == id)
        SC_REPORT_FATAL(
            name(), ("requester " + std::to_string(id) + " issued a second transfer before its first ended").c_str());
    sc_core::sc_time requested = sim_now();
    m_requesting[id] = true;
    m_request_line[id] = true;
    if (m_owner < 0) m_arbitrate.notify(sc_core::SC_ZERO_TIME);
    while (m_owner != id) sc_core::wait(*m_granted[id]);
    sc_core::sc_time start = sim_now();
    sc_core::sc_time memory_delay;
    double bytes = carry(trans, memory_delay);
    sc_core::sc_time occupancy = transfer_time(bytes) + memory_delay;
    sc_core::wait(occupancy);
    record(id, trans, bytes, requested, start, occupancy);
    m_owner = -1;
    for (bool r : m_requesting)
        if (r) {
            m_arbitrate.notify(sc_core::SC_ZERO_TIME);
            break;
        }
}

sc_core::sc_time ClusterBus::reserve(const sc_core::sc_time &requested, const sc_core::sc_time &occupancy)
{
    // Every requester's local time is at or after simulation time: older slots can go.
    while (!m_reserved.empty() && m_reserved.begin()->second <= sim_now()) m_reserved.erase(m_reserved.begin());
    sc_core::sc_time start = requested;
    if (occupancy == sc_core::SC_ZERO_TIME) return start;
    auto it = m_reserved.upper_bound(start);
    if (it != m_reserved.begin() && std::prev(it)->second > start) start = std::prev(it)->second;
    for (; it != m_reserved.end() && it->first < start + occupancy; ++it)
        if (it->second > start) start = it->second;
    m_reserved.emplace(start, start + occupancy);
    return start;
}

void ClusterBus::arbitrate()
{
    if (m_owner >= 0) return;
    int pick = arbiter->pick(m_requesting);
    if (pick < 0) return;
    if (pick >= m_requesters || !m_requesting[pick])
        SC_REPORT_FATAL(name(),
                        ("arbiter granted requester " + std::to_string(pick) + ", which is not requesting").c_str());
    m_owner = pick;
    m_requesting[pick] = false;
    m_request_line[pick] = false;
    m_granted[pick]->notify();
}

}  // namespace torusrt
