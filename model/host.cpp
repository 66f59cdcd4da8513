// host.cpp - primary rays on demand and the background of the rays that miss.
#include "host.h"

#include "rt_step.h"

namespace torusrt {

Host::Host(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene, const rt_grid *grid,
           const int32_t *cell_owner, PacketLedger &ledger, const ReplicaChoice *replicas)
    : sc_module(name), fb_socket("fb_socket"), m_scene(scene), m_ledger(ledger),
      m_primaries(scene, grid, cell_owner, config.node_count(),
                  sc_core::sc_time(config.timing.host_inject_us, sc_core::SC_US), replicas)
{
    count_primaries();
    SC_HAS_PROCESS(Host);
    SC_METHOD(write_background);
}

void Host::count_primaries()
{
    for (uint64_t i = 0; i < m_primaries.entering(); i++) m_ledger.created(RT_PACKET_RAY);
    m_injected += m_primaries.entering();
    for (uint32_t pixel : m_primaries.missed()) m_ledger.primary_missed(m_primaries.inject_time(pixel));
}

void Host::start_frame(const int32_t *cell_owner, const sc_core::sc_time &offset)
{
    m_done = false;
    m_primaries.restart(cell_owner, offset);
    count_primaries();
    write_background();  // a plain call: the frame buffer's b_transport never waits
}

void Host::write_background()
{
    // The frame buffer sums order-independently: the background may be written at the start.
    rt_vec3 background = rt_scene_background(m_scene);
    tlm::tlm_generic_payload trans;
    for (uint32_t pixel : m_primaries.missed()) {
        rt_contribution c{pixel % m_primaries.width(), pixel / m_primaries.width(), background};
        sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
        trans.set_command(tlm::TLM_WRITE_COMMAND);
        trans.set_data_ptr(reinterpret_cast<unsigned char *>(&c));
        trans.set_data_length(sizeof c);
        trans.set_streaming_width(sizeof c);
        fb_socket->b_transport(trans, delay);
    }
    m_done = true;
}

}  // namespace torusrt
