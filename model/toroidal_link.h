// toroidal_link.h - one direction of one link between neighbouring nodes. Packets wait in its
// output queue and cross one at a time (serialisation time per packet); the receiving
// communication unit gets each as a TLM-2.0 b_transport.
#pragma once

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "packet_queue.h"
#include "packet_sink_if.h"
#include "sim_config.h"
#include "time_keeper.h"

namespace torusrt {

class ToroidalLink : public sc_core::sc_module, public PacketSinkIf {
  public:
    tlm_utils::simple_initiator_socket<ToroidalLink> socket; // packets to the receiving comm unit
    sc_core::sc_export<PacketSinkIf> in;                     // packets from the sending comm unit

    ToroidalLink(sc_core::sc_module_name name, const SimConfig &config, int from, int to, int dir);

    void accept(const TimedPacket &p) override { m_queue.push_blocking(p); }

    int from() const { return m_from; }
    int to() const { return m_to; }
    int dir() const { return m_dir; }
    uint64_t packets() const { return m_packets; }
    double bytes() const { return m_bytes; }
    const sc_core::sc_time &busy_time() const { return m_busy; }
    PacketQueue &queue() { return m_queue; }
    bool &busy_trace() { return m_busy_flag; }

  private:
    void run();

    sc_core::sc_time m_packet_time; // serialisation time of one packet
    double m_packet_bytes;
    int m_from, m_to, m_dir;
    PacketQueue m_queue;
    TimeKeeper m_time;
    uint64_t m_packets = 0;
    double m_bytes = 0;
    sc_core::sc_time m_busy = sc_core::SC_ZERO_TIME;
    bool m_busy_flag = false;
    tlm::tlm_generic_payload m_trans;
    PacketExtension *m_ext; // owned by m_trans
};

}  // namespace torusrt
