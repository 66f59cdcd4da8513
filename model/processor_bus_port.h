// processor_bus_port.h - a cluster processor's bus interface (requester k on the cluster bus).
// It takes the processor's outgoing packets (new and forwarded), moves each over the bus with
// the processor as master and then hands it to the node's communication unit; with shared
// object data it also serves the processor's object fetches, reading an object held in another
// processor's 2-port memory over the bus (rt_scene_object_bytes of it, plus the memory's access
// latency). Both run in the processor's own thread, so a processor has at most one transfer on
// the bus at a time.
//
// Time: approximately-timed, the processor waits for the grant and the transfer. Loosely-timed,
// a fetch advances the processor's TimeKeeper to the end of the read; an outgoing packet leaves
// with its stamp advanced to the end of its transfer, but the processor itself is not charged for
// it (the PacketSinkIf call carries no TimeKeeper): a few microseconds per packet against
// milliseconds of packet work.
#pragma once

#include <cstdint>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "module_stats.h"
#include "object_fetch_if.h"
#include "packet_sink_if.h"
#include "rt_scene.h"

namespace torusrt {

class ProcessorBusPort : public sc_core::sc_module, public PacketSinkIf, public ObjectFetchIf {
  public:
    sc_core::sc_export<PacketSinkIf> in;                              // the processor's outgoing packets
    sc_core::sc_export<ObjectFetchIf> objects;                        // the processor's object fetches
    sc_core::sc_port<PacketSinkIf> to_comm_unit;                      // packets after crossing the bus
    tlm_utils::simple_initiator_socket<ProcessorBusPort> bus_socket;  // transfers as requester k

    // `local` = k, the processor's index in its node; `node_objects` (ascending, outliving this
    // port) and `m` give the holder of each object under the placement rule.
    ProcessorBusPort(sc_core::sc_module_name name, const rt_scene *scene, int local,
                     const std::vector<uint32_t> &node_objects, int m);

    void accept(const TimedPacket &p) override;
    BufferSpace *room_for(const TimedPacket &p) override { return to_comm_unit->room_for(p); }
    void fetch(int reader, uint32_t object, TimeKeeper &time) override;

    uint64_t remote_reads() const { return m_remote_reads; }
    uint64_t local_reads() const { return m_local_reads; }
    BusPortStats stats() const { return {m_remote_reads, m_local_reads}; }

  private:
    const rt_scene *m_scene;
    int m_local, m_m;
    const std::vector<uint32_t> &m_node_objects;
    tlm::tlm_generic_payload m_trans;
    std::vector<unsigned char> m_buffer;  // read data (timing only: never inspected)
    uint64_t m_remote_reads = 0, m_local_reads = 0;
};

}  // namespace torusrt
