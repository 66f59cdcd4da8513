// class_buffers.h - one bounded buffer split by packet class (and, on a link, by virtual
// channel): a BufferSpace of the same capacity per index, made when first used, so a run pays
// only for the classes its packets reach; unbounded (capacity 0), one BufferSpace for all. Index = class for queues, 2 x class + channel for
// links (see flow_control.h). With --flow none every packet has index 0 and this is one buffer.
// The aggregate accessors let reports, traces and the queue registry treat the group as one
// queue.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "buffer_space.h"

namespace torusrt {

class ClassBuffers {
  public:
    explicit ClassBuffers(unsigned capacity) : m_capacity(capacity) {}

    BufferSpace &at(uint32_t index)
    {
        if (index > m_top) m_top = index;
        index = slot(index);
        if (index >= m_spaces.size()) m_spaces.resize(index + 1);
        auto &s = m_spaces[index];
        if (!s) {
            s = std::make_unique<BufferSpace>(m_capacity);
            s->count_in(&m_depth, &m_stall);
        }
        return *s;
    }
    // Buffers made so far (indexes below this may be unused).
    size_t count() const { return m_spaces.size(); }
    const BufferSpace *find(uint32_t index) const
    {
        index = slot(index);
        return index < m_spaces.size() ? m_spaces[index].get() : nullptr;
    }
    // The highest index a packet asked for (the classes the run reached), split or not.
    uint32_t top_index() const { return m_top; }

    // Every buffer together.
    size_t size() const { return static_cast<size_t>(m_depth); }
    size_t used() const { return size(); }
    unsigned capacity() const { return m_capacity; }
    // Highest occupancy of any one buffer (what the capacity bounds).
    size_t high_water() const
    {
        size_t h = 0;
        for (const auto &s : m_spaces)
            if (s && s->high_water() > h) h = s->high_water();
        return h;
    }
    // Whether some buffer is full (a packet of its index would wait).
    bool full() const
    {
        for (const auto &s : m_spaces)
            if (s && s->full()) return true;
        return false;
    }
    unsigned blocked_writers() const
    {
        unsigned n = 0;
        for (const auto &s : m_spaces)
            if (s) n += s->blocked_writers();
        return n;
    }
    int &depth_trace() { return m_depth; }
    // Simulated time during which some class had a writer waiting for room (overlaps once).
    sc_core::sc_time stalled_time() const { return m_stall.time(); }

  private:
    // An unbounded buffer keeps every index in one BufferSpace: nothing ever waits for room, so
    // a split would change no time and only cost memory (hundreds of classes per buffer).
    uint32_t slot(uint32_t index) const { return m_capacity ? index : 0; }

    unsigned m_capacity;
    uint32_t m_top = 0;
    std::vector<std::unique_ptr<BufferSpace>> m_spaces;
    int m_depth = 0;
    StallClock m_stall;
};

}  // namespace torusrt
