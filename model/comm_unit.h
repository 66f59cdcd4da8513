// comm_unit.h - a node's communication unit: takes packets from its IP (or cluster), from the
// host and from incoming links (TLM-2.0 b_transport), and routes each to the local processor
// side or to the outgoing link of the first hop toward the owner of the packet's cell.
#pragma once

#include <array>
#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "packet_sink_if.h"
#include "rt_grid.h"
#include "routing.h"

namespace torusrt {

class CommUnit : public sc_core::sc_module, public PacketSinkIf {
  public:
    // Packets from incoming links (none when the node has no neighbours).
    tlm_utils::multi_passthrough_target_socket<CommUnit, 32, tlm::tlm_base_protocol_types, 0,
                                               sc_core::SC_ZERO_OR_MORE_BOUND>
        link_in;
    sc_core::sc_export<PacketSinkIf> in;                          // packets from the IP side and the host
    sc_core::sc_port<PacketSinkIf> local;                         // packets for this node's cells
    sc_core::sc_port<PacketSinkIf, kDirections, sc_core::SC_ZERO_OR_MORE_BOUND> link_out; // outgoing links

    CommUnit(sc_core::sc_module_name name, int node, const Routing &routing, const rt_grid *grid,
             const int32_t *cell_owner);

    void accept(const TimedPacket &p) override { route(p); }
    // Records which link_out port index serves direction `dir` (call at elaboration).
    void set_link_port(int dir, int port_index) { m_port_of_dir[dir] = port_index; }

    uint64_t routed_local() const { return m_local; }
    uint64_t routed_transit() const { return m_transit; }

  private:
    void route(const TimedPacket &p);
    void b_transport(int id, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay);

    int m_node;
    const Routing &m_routing;
    const rt_grid *m_grid;
    const int32_t *m_owner;
    std::array<int, kDirections> m_port_of_dir;
    uint64_t m_local = 0, m_transit = 0;
};

}  // namespace torusrt
