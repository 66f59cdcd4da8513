// comm_unit.cpp - routing by the owner of the packet's current cell.
#include "comm_unit.h"

#include "rt_step.h"
#include "timed_packet.h"

namespace torusrt {

CommUnit::CommUnit(sc_core::sc_module_name name, int node, const Routing &routing, const rt_grid *grid,
                   const int32_t *cell_owner)
    : sc_module(name), link_in("link_in"), in("in"), local("local"), link_out("link_out"), m_node(node),
      m_routing(routing), m_grid(grid), m_owner(cell_owner)
{
    m_port_of_dir.fill(-1);
    in.bind(*this);
    link_in.register_b_transport(this, &CommUnit::b_transport);
}

void CommUnit::route(const TimedPacket &p)
{
    int owner = m_owner[rt_packet_cell(m_grid, &p.packet)];
    if (owner == m_node) {
        m_local++;
        local->accept(p);
        return;
    }
    int dir = m_routing.next_direction(m_node, owner);
    int port = dir >= 0 ? m_port_of_dir[dir] : -1;
    if (port < 0) SC_REPORT_FATAL(name(), "no link toward the packet's owner");
    m_transit++;
    link_out[port]->accept(p);
}

void CommUnit::b_transport(int, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay)
{
    auto *ext = trans.get_extension<PacketExtension>();
    if (!ext) {
        trans.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
        return;
    }
    TimedPacket p = ext->item;
    p.stamp = sc_core::sc_time_stamp() + delay; // arrival in the sender's local time
    route(p);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace torusrt
