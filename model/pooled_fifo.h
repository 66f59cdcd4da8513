// pooled_fifo.h - the storage of an input queue: packets in arrival order, as handles into a
// packet pool (packet_pool.h), the machine's or the queue's own.
//
// Usage: push_back a handle of pool(); at(i) is the i-th oldest packet in its slot; take(i)
// removes it (the slot stays the caller's). No SystemC, no buffers: PacketQueue adds those.
//
// The trick: after a reader takes the oldest packet, prefetch_front() asks for the next one's
// slot (the one it takes next, cold after its wait in the queue) while it works on this one;
// forced inline, as GCC drops a called function whose only effect is a prefetch. Measured gain,
// with HopPath's prefetch (the two were not measured apart): 0.490 s against 0.561 s at 512 IPs
// (docs/model.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>

#include "packet_pool.h"

namespace torusrt {

class PooledFifo {
  public:
    explicit PooledFifo(PacketPool *pool) : m_pool(pool) {}

    // Keeps the packets in `pool` (while empty).
    PacketPool &pool() const { return *m_pool; }
    bool empty() const { return m_by_stamp ? m_sorted.empty() : m_items.empty(); }
    size_t size() const { return m_by_stamp ? m_sorted.size() : m_items.size(); }
    uint32_t handle(size_t i) const { return m_by_stamp ? m_sorted.front().handle : m_items[i]; }
    TimedPacket &at(size_t i) const { return m_pool->at(handle(i)); }
    // Keeps the packets in stamp order from now on (while empty): the earliest stamp first, ties
    // in arrival order. Then only the first packet can be looked at or taken (at(0), take(0)).
    // Packets mostly come in stamp order: one is appended, or put in place by a binary search
    // on the stamps kept beside the handles (no packet is read).
    void order_by_stamp() { m_by_stamp = true; }
    bool ordered_by_stamp() const { return m_by_stamp; }
    void push_back(uint32_t handle)
    {
        if (!m_by_stamp) {
            m_items.push_back(handle);
            return;
        }
        const Stamped item{m_pool->at(handle).stamp.value(), handle};
        if (m_sorted.empty() || m_sorted.back().stamp <= item.stamp) {
            m_sorted.push_back(item);
            return;
        }
        m_sorted.insert(std::upper_bound(m_sorted.begin(), m_sorted.end(), item,
                                         [](const Stamped &a, const Stamped &b) { return a.stamp < b.stamp; }),
                        item);
    }
    // Removes the i-th oldest and returns its handle.
    uint32_t take(size_t i)
    {
        if (m_by_stamp) {
            uint32_t handle = m_sorted.front().handle;
            m_sorted.pop_front();
            return handle;
        }
        uint32_t handle = m_items[i];
        if (i == 0) m_items.pop_front();
        else m_items.erase(m_items.begin() + static_cast<std::ptrdiff_t>(i));
        return handle;
    }
    // Asks for the oldest packet's slot (after a take of the one before it).
    [[gnu::always_inline]] void prefetch_front() const
    {
        if (empty()) return;
        const char *p = reinterpret_cast<const char *>(&at(0));
        for (size_t b = 0; b < sizeof(TimedPacket); b += 64) __builtin_prefetch(p + b);
        __builtin_prefetch(p + sizeof(TimedPacket) - 1);  // the slot need not start a line
    }

  private:
    PacketPool *m_pool;
    std::deque<uint32_t> m_items;  // oldest first
    struct Stamped {
        uint64_t stamp;
        uint32_t handle;
    };
    std::deque<Stamped> m_sorted;  // order_by_stamp(): the packets, earliest stamp first
    bool m_by_stamp = false;
};

}  // namespace torusrt
