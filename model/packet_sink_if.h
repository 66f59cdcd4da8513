// packet_sink_if.h - where a module hands a packet on: an IP's input queue, a link, a
// communication unit. accept() may wait (in the caller's thread) while the receiver is full; a
// caller that must not wait (an SC_METHOD) asks can_accept() first and, if there is no room,
// registers an event with on_space() to be notified when room is released. accept_pooled()
// hands over a packet of a packet pool by handle (packet_pool.h): a receiver that keeps its
// packets in that pool (an input queue) takes the handle on and the packet stays in its slot;
// any other copies it out and releases the slot.
#pragma once

#include <cstdint>
#include <systemc>

#include "buffer_space.h"
#include "packet_pool.h"
#include "timed_packet.h"

namespace torusrt {

class PacketSinkIf : public virtual sc_core::sc_interface {
  public:
    virtual void accept(const TimedPacket &p) = 0;
    // The same for packet `handle` of `pool`, which the receiver now owns (it releases it).
    virtual void accept_pooled(PacketPool &pool, uint32_t handle)
    {
        accept(pool.at(handle));
        pool.release(handle);
    }
    virtual bool can_accept(const TimedPacket &) const { return true; }
    virtual void on_space(const TimedPacket &, sc_core::sc_event &) {}
    // The buffer `p` would take a slot in if handed over now (null: none, no bound). A
    // processor reserves its outputs' slots there before it takes up a packet (flow_control.h).
    virtual BufferSpace *room_for(const TimedPacket &) { return nullptr; }
};

}  // namespace torusrt
