// class_buffers.h - one bounded buffer split by packet class (and, on a link, by virtual
// channel): a BufferSpace of the same capacity per index, made when first used, so a run pays
// only for the classes its packets reach; unbounded (capacity 0), one BufferSpace for all. Index = class for queues, 2
// x class + channel for links (see flow_control.h). With --flow none every packet has index 0 and this is one buffer.
// The aggregate accessors let reports, traces and the queue registry treat the group as one
// queue.
// Storage: index 0 (every packet of an unbounded buffer or of --flow none) lives inside the
// group, so the hop path finds it in the same cache lines as its owner; higher indexes live
// side by side in a deque. Credits and waiting writers keep BufferSpace pointers: a buffer never
// moves once made, and the group itself never moves (members point at its totals).
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "buffer_space.h"

namespace torusrt {

class ClassBuffers {
  public:
    explicit ClassBuffers(unsigned capacity) : m_capacity(capacity), m_first(capacity) {}
    ClassBuffers(const ClassBuffers &) = delete;
    ClassBuffers &operator=(const ClassBuffers &) = delete;

    // Inlined: the hop path calls it several times a hop and nearly always takes the first test.
    [[gnu::always_inline]] BufferSpace &at(uint32_t index)
    {
        if (index > m_top) m_top = index;
        if (m_first_made && !slot(index)) return m_first;  // the hop path's case: no look-up
        return made(slot(index));
    }
    // Unbounded: every packet finds room, nothing to check.
    bool unbounded() const { return !m_capacity; }
    // Buffers made so far (indexes below this may be unused).
    size_t count() const { return m_count; }
    const BufferSpace *find(uint32_t index) const
    {
        index = slot(index);
        if (!index) return m_first_made ? &m_first : nullptr;
        if (index >= m_made.size() || !m_made[index]) return nullptr;
        return index ? &(*m_rest)[index - 1] : &m_first;
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
        for (uint32_t i = 0; i < count(); i++)
            if (const BufferSpace *s = find(i); s && s->high_water() > h) h = s->high_water();
        return h;
    }
    // Whether some buffer is full (a packet of its index would wait).
    bool full() const
    {
        for (uint32_t i = 0; i < count(); i++)
            if (const BufferSpace *s = find(i); s && s->full()) return true;
        return false;
    }
    unsigned blocked_writers() const
    {
        unsigned n = 0;
        for (uint32_t i = 0; i < count(); i++)
            if (const BufferSpace *s = find(i)) n += s->blocked_writers();
        return n;
    }
    int &depth_trace() { return m_depth; }
    // Simulated time during which some class had a writer waiting for room (overlaps once).
    sc_core::sc_time stalled_time() const { return m_stall.time(); }
    // Feeds this buffer's stall time into `machine` too (the time any writer waited).
    void feed_stalls(StallClock &machine) { m_stall.feed(&machine); }

  private:
    // An unbounded buffer keeps every index in one BufferSpace: nothing ever waits for room, so
    // a split would change no time and only cost memory (hundreds of classes per buffer).
    uint32_t slot(uint32_t index) const { return m_capacity ? index : 0; }
    // The buffer at slot `index`, made and counted in on first use (out of line: rare).
    [[gnu::noinline]] BufferSpace &made(uint32_t index)
    {
        if (index >= m_count) m_count = index + 1;
        if (index >= m_made.size()) m_made.resize(index + 1, 0);
        BufferSpace &s = space(index);
        if (!m_made[index]) {
            m_made[index] = 1;
            m_first_made = m_first_made || !index;
            s.count_in(&m_depth, &m_stall);
        }
        return s;
    }
    // The buffer at `index`, making the storage up to it (deque growth keeps addresses).
    BufferSpace &space(uint32_t index)
    {
        if (!index) return m_first;
        if (!m_rest) m_rest = std::make_unique<std::deque<BufferSpace>>();
        while (m_rest->size() < index) m_rest->emplace_back(m_capacity);
        return (*m_rest)[index - 1];
    }

    unsigned m_capacity;
    uint32_t m_top = 0;
    int m_depth = 0;
    uint32_t m_count = 0;       // = count()
    bool m_first_made = false;  // index 0 made
    BufferSpace m_first;
    std::vector<uint8_t> m_made;                      // per index: whether a packet asked for it
    std::unique_ptr<std::deque<BufferSpace>> m_rest;  // indexes 1.. (bounded, split runs only)
    StallClock m_stall;
};

}  // namespace torusrt
