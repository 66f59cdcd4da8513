// arrival_queue.h - the payload event queue of a communication unit: packets that have crossed a
// link (or left the local processor side) wait here, by handle, until their annotated arrival
// time. Simultaneous arrivals leave in a fixed order: time, then source (the receiving port),
// then sequence (the order the source sent them in), whatever order the SystemC kernel ran the
// senders in. The packet bodies stay in the machine's packet pool; an arrival is a 24-byte slot
// (pool handle, source, credit, delta cycle) and the heap moves 24-byte keys compared as two
// 64-bit words (time; source and sequence packed).
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "buffer_space.h"

namespace torusrt {

class ArrivalQueue {
  public:
    struct Arrival {
        uint32_t packet;     // handle in the packet pool
        int source;
        BufferSpace *credit; // returned once the packet is taken on (null: nothing to return)
        sc_dt::uint64 delta; // delta cycle of the push
    };

    // Holds pool packet `packet` until `when` (>= simulation time); returns the arrival's handle.
    uint32_t push(const sc_core::sc_time &when, int source, uint32_t packet, BufferSpace *credit);
    bool empty() const { return m_heap.empty(); }
    sc_core::sc_time next_time() const { return sc_core::sc_time::from_value(m_heap.front().when); }
    // Whether the earliest arrival was pushed in the current delta cycle.
    bool next_is_new() const { return m_slots[m_heap.front().slot].delta == sc_core::sc_delta_count(); }
    // Takes the earliest arrival (in the order above) off the heap; returns its handle, which
    // stays valid until release().
    uint32_t pop();
    Arrival &at(uint32_t handle) { return m_slots[handle]; }
    void release(uint32_t handle) { m_free.push_back(handle); }
    size_t size() const { return m_heap.size(); }

  private:
    // Sources below 64 (32 link ports and the processor side); 58 bits of sequence.
    static constexpr int kSeqBits = 58;
    struct Key {
        sc_dt::uint64 when;  // sc_time value
        uint64_t order;      // source << kSeqBits | sequence
        uint32_t slot;
    };
    static bool later(const Key &a, const Key &b)
    {
        return a.when != b.when ? a.when > b.when : a.order > b.order;
    }

    std::vector<Key> m_heap;
    std::vector<Arrival> m_slots;
    std::vector<uint32_t> m_free;
    uint64_t m_seq = 0;
};

}  // namespace torusrt
