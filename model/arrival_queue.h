// arrival_queue.h - the payload event queue of a communication unit: packets that have crossed a
// link (or left the local processor side) wait here, by handle, until their annotated arrival
// time. Simultaneous arrivals leave in a fixed order: time, then source (the receiving port),
// then sequence (the order the source sent them in), whatever order the SystemC kernel ran the
// senders in. The packet bodies stay in a slot pool; the heap moves only 24-byte keys.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "buffer_space.h"
#include "timed_packet.h"

namespace torusrt {

class ArrivalQueue {
  public:
    struct Arrival {
        TimedPacket item;
        int source;
        BufferSpace *credit; // returned once the packet is taken on (null: nothing to return)
    };

    // Holds `item` (stamped `stamp`) until `when` (>= simulation time); returns its handle.
    uint32_t push(const sc_core::sc_time &when, int source, const TimedPacket &item, const sc_core::sc_time &stamp,
              BufferSpace *credit);
    bool empty() const { return m_heap.empty(); }
    const sc_core::sc_time &next_time() const { return m_heap.front().when; }
    // Whether the earliest arrival was pushed in the current delta cycle.
    bool next_is_new() const { return m_heap.front().delta == sc_core::sc_delta_count(); }
    // Takes the earliest arrival (in the order above) off the heap; returns its handle, which
    // stays valid until release().
    uint32_t pop();
    Arrival &at(uint32_t handle) { return m_slots[handle]; }
    void release(uint32_t handle) { m_free.push_back(handle); }
    size_t size() const { return m_heap.size(); }

  private:
    struct Key {
        sc_core::sc_time when;
        int source;
        uint32_t slot;
        uint64_t seq;
        sc_dt::uint64 delta; // delta cycle of the push
    };
    static bool later(const Key &a, const Key &b);

    std::vector<Key> m_heap;
    std::vector<Arrival> m_slots;
    std::vector<uint32_t> m_free;
    uint64_t m_seq = 0;
};

}  // namespace torusrt
