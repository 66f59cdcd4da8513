// arrival_queue.h - the payload event queue of a communication unit: packets that have crossed a
// link (or left the local processor side) wait here, by handle, until their annotated arrival
// time. Simultaneous arrivals leave in a fixed order: time, then source (the receiving port),
// then sequence (the order the source sent them in), whatever order the SystemC kernel ran the
// senders in. The packet bodies (and the credits they hold) stay in the machine's packet pool;
// the heap holds 24-byte keys compared as two 64-bit words (time; source and sequence packed)
// and the packet's pool handle, nothing else.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

namespace torusrt {

class ArrivalQueue {
  public:
    struct Arrival {
        uint32_t packet;  // handle in the packet pool
        int source;
    };

    // Holds pool packet `packet` from `source` until `when` (>= simulation time).
    void push(const sc_core::sc_time &when, int source, uint32_t packet);
    bool empty() const { return m_heap.empty(); }
    sc_core::sc_time next_time() const { return sc_core::sc_time::from_value(m_heap.front().when); }
    // The same as a time value (picoseconds): compared as such on the unit's path, where building
    // an sc_time (a library call) for each comparison cost 0.8 % of a run's instructions.
    sc_dt::uint64 next_value() const { return m_heap.front().when; }
    // Whether the earliest arrival was pushed in the current delta cycle (sequence numbers grow
    // with every push: this delta's pushes are those from the first one it made).
    bool next_is_new() const
    {
        return m_push_delta == sc_core::sc_delta_count() && (m_heap.front().order & kSeqMask) >= m_delta_first_seq;
    }
    // Takes the earliest arrival (in the order above) off the heap.
    Arrival pop();
    size_t size() const { return m_heap.size(); }

  private:
    // Sources below 64 (32 link ports and the processor side); 58 bits of sequence.
    static constexpr int kSeqBits = 58;
    static constexpr uint64_t kSeqMask = (uint64_t{1} << kSeqBits) - 1;
    struct Key {
        sc_dt::uint64 when;  // sc_time value
        uint64_t order;      // source << kSeqBits | sequence
        uint32_t packet;
    };
    static bool later(const Key &a, const Key &b) { return a.when != b.when ? a.when > b.when : a.order > b.order; }

    std::vector<Key> m_heap;
    uint64_t m_seq = 0;
    uint64_t m_delta_first_seq = 0;  // sequence of the first push in delta m_push_delta
    sc_dt::uint64 m_push_delta = ~sc_dt::uint64{0};
};

}  // namespace torusrt
