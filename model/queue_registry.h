// queue_registry.h - the list of the system's bounded buffers, filled at elaboration by the
// modules that own them (one add() per buffer, in register_queues()). The run's statistics, the
// deadlock report and the VCD queue-depth traces all walk this one list.
#pragma once

#include <string>
#include <vector>

#include "buffer_space.h"

namespace torusrt {

struct QueueRef {
    std::string name;    // hierarchical, e.g. top.ip_3.input, top.link_3_to_7_xp
    int node;            // the torus node whose memory holds the buffer
    BufferSpace *space;  // its room: capacity, occupancy, high water, waiting writers, stall time
    int *depth;          // the traced occupancy (a plain int for sc_trace)
    std::string trace;   // the VCD signal name of `depth`
};

class QueueRegistry {
  public:
    // Registers a buffer; `trace` defaults to NAME.queue_depth.
    void add(const std::string &name, int node, BufferSpace &space, int &depth, const std::string &trace = "")
    {
        m_queues.push_back({name, node, &space, &depth, trace.empty() ? name + ".queue_depth" : trace});
    }
    const std::vector<QueueRef> &all() const { return m_queues; }

  private:
    std::vector<QueueRef> m_queues;
};

}  // namespace torusrt
