// packet_queue.h - a FIFO of packets with an optional capacity, the events to wait on, and its
// high-water mark. Used for IP and dispatcher input queues. The capacity bounds network packets
// (its BufferSpace). A queue at a primary ray's entry node is also fed by the host's
// PrimarySource: the next primary is taken up when its injection time is no later than the
// oldest network packet's stamp (ties to the primary), so with host_inject = 0 a node works
// through all its primaries, in pixel order, before the network packets, as if all had been
// injected at time 0. Primaries live in the host's memory: they never count against capacity.
#pragma once

#include <deque>
#include <string>
#include <systemc>

#include "buffer_space.h"
#include "primary_source.h"
#include "timed_packet.h"

namespace torusrt {

class PacketQueue {
  public:
    // capacity 0 = unbounded.
    PacketQueue(std::string name, unsigned capacity);

    // Whether `p` fits now (host packets always do).
    bool has_room(const TimedPacket &p) const { return p.from_host || m_space.available(); }
    // Appends, waiting (in the calling thread) while the queue is full (host packets never wait).
    void push_blocking(const TimedPacket &p);
    // Removes the oldest packet, waiting while the queue is empty.
    TimedPacket pop_blocking();
    // Feeds this queue with `source`'s primaries for entry node `node`.
    void attach(PrimarySource *source, int node)
    {
        m_source = source;
        m_node = node;
    }
    // Wakes a reader waiting on an empty queue, so it looks again at the primary source
    // (a new frame's primaries appeared between two sc_start calls).
    void wake()
    {
        if (m_reader_waiting) m_not_empty.notify(sc_core::SC_ZERO_TIME);
    }
    bool empty() const { return m_items.empty() && !(m_source && m_source->pending(m_node)); }
    bool full() const { return m_space.full(); }
    size_t size() const { return m_items.size(); } // network packets waiting
    size_t high_water() const { return m_high_water; }
    unsigned capacity() const { return m_space.capacity(); }
    const std::string &name() const { return m_name; }
    // Writers waiting for room (for the deadlock report).
    unsigned blocked_writers() const { return m_space.blocked_writers(); }
    BufferSpace &space() { return m_space; }
    // Traced queue depth (a plain int that sc_trace can watch).
    int &depth_trace() { return m_depth; }

  private:
    std::string m_name;
    BufferSpace m_space;
    std::deque<TimedPacket> m_items;
    sc_core::sc_event m_not_empty;
    size_t m_high_water = 0;
    int m_depth = 0;
    bool m_reader_waiting = false;
    PrimarySource *m_source = nullptr;
    int m_node = -1;
};

}  // namespace torusrt
