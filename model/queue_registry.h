// queue_registry.h - the list of the system's bounded buffers, filled at elaboration by the
// modules that own them (one add() per buffer, in register_queues()). The run's statistics, the
// flow report, the deadlock report and the VCD queue-depth traces all walk this one list. A
// buffer is a ClassBuffers group: one BufferSpace per packet class (and, on a link, per virtual
// channel); under --flow none, one.
#pragma once

#include <string>
#include <vector>

#include "class_buffers.h"

namespace torusrt {

enum class QueueKind { ip, dispatcher, link };

struct QueueRef {
    std::string name;       // hierarchical, e.g. top.ip_3.input, top.link_3_to_7_xp
    QueueKind kind;         // whose buffer: a processor's input, a dispatcher's input, a link
    int node;               // the torus node whose memory holds the buffer
    ClassBuffers *buffers;  // its room: capacity, occupancy, high water, waiting writers, stall time
    int *depth;             // the traced occupancy, every class (a plain int for sc_trace)
    std::string trace;      // the VCD signal name of `depth`
};

inline const char *queue_kind_name(QueueKind k)
{
    return k == QueueKind::ip ? "ip" : k == QueueKind::dispatcher ? "dispatcher" : "link";
}

class QueueRegistry {
  public:
    // Registers a buffer; `trace` defaults to NAME.queue_depth.
    void add(const std::string &name, QueueKind kind, int node, ClassBuffers &buffers, int &depth,
             const std::string &trace = "")
    {
        m_queues.push_back({name, kind, node, &buffers, &depth, trace.empty() ? name + ".queue_depth" : trace});
        buffers.feed_stalls(m_any_stall);
    }
    const std::vector<QueueRef> &all() const { return m_queues; }
    // Simulated time during which some writer of some registered buffer waited for room.
    sc_core::sc_time any_stalled_time() const { return m_any_stall.time(); }

  private:
    std::vector<QueueRef> m_queues;
    StallClock m_any_stall;
};

}  // namespace torusrt
