// two_port_memory.cpp - bus-side reads of a processor's 2-port memory.
#include "two_port_memory.h"

#include "cluster_memory.h"

namespace torusrt {

TwoPortMemory::TwoPortMemory(sc_core::sc_module_name name, const rt_timing &timing,
                             const std::vector<uint32_t> &node_objects, int share, int shares)
    : sc_module(name), bus_side("bus_side"), m_access(timing.memory_access_us, sc_core::SC_US),
      m_node_objects(node_objects), m_share(share), m_shares(shares)
{
    bus_side.register_b_transport(this, &TwoPortMemory::b_transport);
}

bool TwoPortMemory::holds(uint32_t object) const { return shared_holder(m_node_objects, object, m_shares) == m_share; }

size_t TwoPortMemory::object_count() const
{
    size_t n = m_node_objects.size();
    return n / m_shares + (static_cast<size_t>(m_share) < n % m_shares ? 1 : 0);
}

void TwoPortMemory::b_transport(tlm::tlm_generic_payload &trans, sc_core::sc_time &delay)
{
    uint64_t address = trans.get_address();
    if (!trans.is_read() || address > 0xffffffffu || !holds(static_cast<uint32_t>(address))) {
        trans.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
        return;
    }
    // The object's contents live in the kernel's scene; the read is timing only.
    delay += m_access;
    m_reads++;
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace torusrt
