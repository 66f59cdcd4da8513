// host.h - the host: knows for each pixel's primary ray the node owning the cell where it enters
// the object space, and hands the primaries out on demand (PrimarySource): each node's input
// queue takes up its next primary when it runs dry of earlier packets. The host writes the
// background for rays that miss the space. Completion is detected by the packet ledger (no
// packet outstanding); every primary counts as created from the start.
#pragma once

#include <memory>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "module_stats.h"
#include "packet_ledger.h"
#include "primary_source.h"
#include "replica_choice.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

class Host : public sc_core::sc_module {
  public:
    tlm_utils::simple_initiator_socket<Host> fb_socket;  // background of missed rays

    Host(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene, const rt_grid *grid,
         const int32_t *cell_owner, PacketLedger &ledger, const ReplicaChoice *replicas = nullptr);

    PrimarySource &primaries() { return m_primaries; }
    // Between frames of an animation (no packet outstanding): plans the next frame's primaries
    // with the scene's current camera and `cell_owner` as it is now, stamped from `offset`,
    // counts them in the ledger and writes the background of the rays that miss.
    void start_frame(const int32_t *cell_owner, const sc_core::sc_time &offset);
    bool done_injecting() const { return m_done; }
    uint64_t injected() const { return m_injected; }  // primaries entering the space, every frame
    HostStats stats() const { return {injected()}; }

  private:
    void write_background();

    void count_primaries();

    const rt_scene *m_scene;
    PacketLedger &m_ledger;
    PrimarySource m_primaries;
    bool m_done = false;
    uint64_t m_injected = 0;
};

}  // namespace torusrt
