// processor_bus_port.cpp - outgoing packets and remote object reads over the cluster bus.
#include "processor_bus_port.h"

#include <string>

#include "cluster_memory.h"
#include "sim_now.h"

namespace torusrt {

namespace {

// Offset of a local time from simulation time (zero if it does not lie ahead).
sc_core::sc_time offset_of(const sc_core::sc_time &local)
{
    sc_core::sc_time now = sim_now();
    return local > now ? local - now : sc_core::SC_ZERO_TIME;
}

}  // namespace

ProcessorBusPort::ProcessorBusPort(sc_core::sc_module_name name, const rt_scene *scene, int local,
                                   const std::vector<uint32_t> &node_objects, int m)
    : sc_module(name), in("in"), objects("objects"), to_comm_unit("to_comm_unit"), bus_socket("bus_socket"),
      m_scene(scene), m_local(local), m_m(m), m_node_objects(node_objects)
{
    in.bind(*this);
    objects.bind(*this);
}

void ProcessorBusPort::accept(const TimedPacket &p)
{
    TimedPacket out = p;
    sc_core::sc_time delay = offset_of(p.stamp);
    m_trans.set_command(tlm::TLM_WRITE_COMMAND);
    m_trans.set_address(static_cast<uint64_t>(m_m));  // to the communication unit
    m_trans.set_data_ptr(reinterpret_cast<unsigned char *>(&out.packet));
    m_trans.set_data_length(sizeof(rt_packet));
    m_trans.set_streaming_width(sizeof(rt_packet));
    m_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    bus_socket->b_transport(m_trans, delay);
    if (m_trans.is_response_error()) SC_REPORT_FATAL(name(), "packet transfer over the cluster bus failed");
    out.stamp = sim_now() + delay;
    to_comm_unit->accept(out);
}

void ProcessorBusPort::fetch(int, uint32_t object, TimeKeeper &time)
{
    int holder = shared_holder(m_node_objects, object, m_m);
    if (holder < 0)
        SC_REPORT_FATAL(name(), ("object " + std::to_string(object) + " is not placed in this node").c_str());
    if (holder == m_local) {
        m_local_reads++;
        return;  // in this processor's own memory: read through the local port
    }
    m_remote_reads++;
    unsigned bytes = rt_scene_object_bytes(m_scene, object);
    if (m_buffer.size() < bytes) m_buffer.resize(bytes);
    sc_core::sc_time delay = offset_of(time.now());
    m_trans.set_command(tlm::TLM_READ_COMMAND);
    m_trans.set_address((static_cast<uint64_t>(holder) << 32) | object);
    m_trans.set_data_ptr(m_buffer.data());
    m_trans.set_data_length(bytes);
    m_trans.set_streaming_width(bytes);
    m_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    bus_socket->b_transport(m_trans, delay);
    if (m_trans.is_response_error()) SC_REPORT_FATAL(name(), "object read over the cluster bus failed");
    time.advance_to(sim_now() + delay);
}

}  // namespace torusrt
