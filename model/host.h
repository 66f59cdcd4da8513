// host.h - the host: makes one primary ray packet per pixel and injects it at the node owning the
// cell where the ray enters the object space; writes the background for rays that miss it.
// Completion is detected by the packet ledger (no packet outstanding once injection is over).
#pragma once

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "packet_ledger.h"
#include "packet_sink_if.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"
#include "time_keeper.h"

namespace torusrt {

class Host : public sc_core::sc_module {
  public:
    sc_core::sc_port<PacketSinkIf, 0> inject;                   // one per node, in node order
    tlm_utils::simple_initiator_socket<Host> fb_socket;         // background of missed rays

    Host(sc_core::sc_module_name name, const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
         const int32_t *cell_owner, PacketLedger &ledger);

    bool done_injecting() const { return m_done; }
    uint64_t injected() const { return m_injected; }

  private:
    void run();

    const SimConfig &m_config;
    const rt_scene *m_scene;
    const rt_grid *m_grid;
    const int32_t *m_owner;
    PacketLedger &m_ledger;
    TimeKeeper m_time;
    bool m_done = false;
    uint64_t m_injected = 0;
};

}  // namespace torusrt
