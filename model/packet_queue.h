// packet_queue.h - the input queue of an IP or a cluster dispatcher: packets in arrival order,
// with a bounded buffer per packet class (ClassBuffers; one class under --flow none). Every
// packet in the queue counts against its class's capacity. A queue at a primary ray's entry
// node is also fed by the host's PrimarySource: primaries wait in the host, not here, and the
// next one is offered when its injection time is no later than the oldest queued packet's stamp
// (ties to the primary), so with host_inject = 0 a node works through all its primaries, in
// pixel order, before the network packets, as if all had been injected at time 0.
//
// take_first() offers the packets to the reader in that order (the primary first when due, then
// the queued packets oldest first, then a primary not yet due) and removes the first it accepts;
// a reader that accepts every packet sees a plain FIFO. Under the class scheme the reader
// accepts a packet only once the buffers its outputs go to have room, so it never waits while
// holding a packet (flow_control.h).
#pragma once

#include <deque>
#include <functional>
#include <string>
#include <systemc>

#include "class_buffers.h"
#include "primary_source.h"
#include "timed_packet.h"

namespace torusrt {

class PacketQueue {
  public:
    // capacity 0 = unbounded.
    PacketQueue(std::string name, unsigned capacity);

    // The buffer `p` takes a slot in.
    BufferSpace &space_for(const TimedPacket &p) { return m_spaces.at(p.cls); }
    // Whether `p` fits now (its slot may already be reserved).
    bool has_room(const TimedPacket &p) const
    {
        const BufferSpace *s = m_spaces.find(p.cls); // not made yet: empty
        return p.reserved || !s || s->available();
    }
    // Appends, waiting (in the calling thread) while its class is full; a reserved packet
    // already holds its slot.
    void push_blocking(const TimedPacket &p);
    // Removes the oldest packet, waiting while the queue is empty.
    TimedPacket pop_blocking();
    // Removes and returns the first packet (in the order above) that `accept` takes, waiting
    // while there is none: `accept` gets a copy it may change (the returned packet is that
    // copy) and, when it refuses, registers `retry` with whatever it waits for.
    TimedPacket take_first(const std::function<bool(TimedPacket &)> &accept, sc_core::sc_event &retry);
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
    bool full() const { return m_spaces.full(); }
    size_t size() const { return m_items.size(); } // packets waiting (every class)
    // Most packets waiting at once, every class together.
    size_t high_water() const { return m_high_water; }
    // Most packets of one class waiting at once (bounded by the capacity).
    size_t class_high_water() const { return m_spaces.high_water(); }
    unsigned capacity() const { return m_spaces.capacity(); }
    const std::string &name() const { return m_name; }
    // Writers waiting for room (for the deadlock report).
    unsigned blocked_writers() const { return m_spaces.blocked_writers(); }
    // The class-0 buffer (the only one under --flow none).
    BufferSpace &space() { return m_spaces.at(0); }
    ClassBuffers &spaces() { return m_spaces; }
    // Traced queue depth (a plain int that sc_trace can watch).
    int &depth_trace() { return m_depth; }

  private:
    void remove(size_t index);
    void wait_for(sc_core::sc_event *retry);

    std::string m_name;
    ClassBuffers m_spaces;
    std::deque<TimedPacket> m_items;
    sc_core::sc_event m_not_empty;
    size_t m_high_water = 0;
    int m_depth = 0;
    bool m_reader_waiting = false;
    PrimarySource *m_source = nullptr;
    int m_node = -1;
};

}  // namespace torusrt
