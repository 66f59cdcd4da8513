// host.cpp - primary-ray injection in pixel order.
#include "host.h"

#include "rt_packet.h"
#include "rt_step.h"

namespace torusrt {

Host::Host(sc_core::sc_module_name name, const SimConfig &config, const rt_scene *scene, const rt_grid *grid,
           const int32_t *cell_owner, PacketLedger &ledger)
    : sc_module(name), inject("inject"), fb_socket("fb_socket"), m_config(config), m_scene(scene), m_grid(grid),
      m_owner(cell_owner), m_ledger(ledger), m_time(config.style == TimingStyle::lt)
{
    SC_HAS_PROCESS(Host);
    SC_THREAD(run);
}

void Host::run()
{
    const rt_camera *cam = rt_scene_camera(m_scene);
    sc_core::sc_time inject_cost(m_config.timing.host_inject_us, sc_core::SC_US);
    rt_vec3 background = rt_scene_background(m_scene);
    tlm::tlm_generic_payload trans;
    for (uint32_t y = 0; y < cam->height; y++) {
        for (uint32_t x = 0; x < cam->width; x++) {
            rt_packet p;
            int enters = 0;
            rt_primary_packet(m_scene, m_grid, x, y, &p, &enters);
            if (inject_cost > sc_core::SC_ZERO_TIME) m_time.advance(inject_cost);
            if (!enters) {
                rt_contribution c{x, y, background};
                sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
                trans.set_command(tlm::TLM_WRITE_COMMAND);
                trans.set_data_ptr(reinterpret_cast<unsigned char *>(&c));
                trans.set_data_length(sizeof c);
                trans.set_streaming_width(sizeof c);
                fb_socket->b_transport(trans, delay);
                m_ledger.primary_missed(m_time.now());
                continue;
            }
            m_ledger.created(RT_PACKET_RAY);
            m_injected++;
            sc_core::sc_time now = m_time.now();
            inject[m_owner[rt_packet_cell(m_grid, &p)]]->accept(TimedPacket{p, now, true});
            m_time.settle(now); // a full input queue may have held the host
        }
    }
    m_time.sync();
    m_done = true;
}

}  // namespace torusrt
