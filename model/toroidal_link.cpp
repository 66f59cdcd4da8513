// toroidal_link.cpp - serialises packets over one link direction.
#include "toroidal_link.h"

namespace torusrt {

ToroidalLink::ToroidalLink(sc_core::sc_module_name name, const SimConfig &config, int from, int to, int dir)
    : sc_module(name), socket("socket"), in("in"),
      m_packet_time(rt_timing_link_packet_us(&config.timing), sc_core::SC_US),
      m_packet_bytes(config.timing.packet_bytes), m_from(from), m_to(to), m_dir(dir),
      m_queue(std::string(basename()) + ".queue", config.queue_capacity),
      m_time(config.style == TimingStyle::lt)
{
    in.bind(*this);
    m_ext = new PacketExtension;
    m_trans.set_extension(m_ext);
    SC_HAS_PROCESS(ToroidalLink);
    SC_THREAD(run);
}

void ToroidalLink::run()
{
    for (;;) {
        if (m_queue.empty()) m_time.sync();
        m_ext->item = m_queue.pop_blocking();
        m_time.advance_to(m_ext->item.stamp); // cannot start before the packet was sent
        m_busy_flag = true;
        m_time.advance(m_packet_time);
        m_busy_flag = false;
        m_busy += m_packet_time;
        m_packets++;
        m_bytes += m_packet_bytes;
        // The delay argument carries this process's local-time offset (loosely timed).
        sc_core::sc_time delay = m_time.now() - sc_core::sc_time_stamp();
        m_ext->item.stamp = m_time.now();
        m_trans.set_command(tlm::TLM_WRITE_COMMAND);
        m_trans.set_address(static_cast<uint64_t>(m_to));
        // Data = the packet as held in memory; its size on the wire is a timing parameter.
        m_trans.set_data_ptr(reinterpret_cast<unsigned char *>(&m_ext->item.packet));
        m_trans.set_data_length(sizeof(rt_packet));
        m_trans.set_streaming_width(sizeof(rt_packet));
        m_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_core::sc_time sent = m_time.now();
        socket->b_transport(m_trans, delay);
        m_time.settle(sent); // the receiver may have held the packet while its queue was full
    }
}

}  // namespace torusrt
