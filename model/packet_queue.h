// packet_queue.h - a FIFO of packets with an optional capacity, the events to wait on, and its
// high-water mark. Used for IP input queues and link output queues. The capacity bounds network
// packets; primary packets injected by the host are held in the host's memory and never block.
#pragma once

#include <deque>
#include <string>
#include <systemc>

#include "timed_packet.h"

namespace torusrt {

class PacketQueue {
  public:
    // capacity 0 = unbounded.
    PacketQueue(std::string name, unsigned capacity);

    // Appends, waiting (in the calling thread) while the queue is full (host packets never wait).
    void push_blocking(const TimedPacket &p);
    // Removes the oldest packet, waiting while the queue is empty.
    TimedPacket pop_blocking();
    bool empty() const { return m_items.empty(); }
    bool full() const { return m_capacity && m_network >= m_capacity; }
    size_t size() const { return m_items.size(); }
    size_t high_water() const { return m_high_water; }
    unsigned capacity() const { return m_capacity; }
    const std::string &name() const { return m_name; }
    // Number of threads waiting for room (for the deadlock report).
    unsigned blocked_writers() const { return m_blocked_writers; }
    // Traced queue depth (a plain int that sc_trace can watch).
    int &depth_trace() { return m_depth; }

  private:
    std::string m_name;
    unsigned m_capacity;
    std::deque<TimedPacket> m_items;
    sc_core::sc_event m_not_empty, m_not_full;
    size_t m_network = 0; // items that count against the capacity
    size_t m_high_water = 0;
    unsigned m_blocked_writers = 0;
    int m_depth = 0;
};

}  // namespace torusrt
