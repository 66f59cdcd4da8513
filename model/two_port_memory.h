// two_port_memory.h - one processor's 2-port memory in a cluster. The processor reads it through
// its local port at no bus cost (that is inside the processor's operation times); the bus side
// serves other processors' reads of the objects held here, each adding memory_access to the
// bus occupancy of the transfer. It also says what it holds, for the data-memory figures:
// with shared data its share of the node's objects (placement rule in cluster_memory.h), with
// replicated data all of them.
//
// Bus-side transaction: READ, address = object index, data length = bytes read. A read of an
// object not held here is an address error (a placement bug).
#pragma once

#include <cstdint>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "module_stats.h"
#include "rt_timing.h"

namespace torusrt {

class TwoPortMemory : public sc_core::sc_module {
  public:
    tlm_utils::simple_target_socket<TwoPortMemory> bus_side;  // object reads from the cluster bus

    // Holds node_objects[j] for every j with j mod shares == share (replicated: share 0 of 1).
    // `node_objects` (ascending) must outlive the memory.
    TwoPortMemory(sc_core::sc_module_name name, const rt_timing &timing, const std::vector<uint32_t> &node_objects,
                  int share, int shares);

    bool holds(uint32_t object) const;
    size_t object_count() const;
    uint64_t reads_served() const { return m_reads; }
    MemoryPortStats stats() const { return {object_count(), m_reads}; }

  private:
    void b_transport(tlm::tlm_generic_payload &trans, sc_core::sc_time &delay);

    sc_core::sc_time m_access;  // bus-side access latency
    const std::vector<uint32_t> &m_node_objects;
    int m_share, m_shares;
    uint64_t m_reads = 0;
};

}  // namespace torusrt
