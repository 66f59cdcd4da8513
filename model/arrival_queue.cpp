// arrival_queue.cpp - a binary min-heap of arrival keys over a pool of packet slots.
#include "arrival_queue.h"

#include <algorithm>

namespace torusrt {

bool ArrivalQueue::later(const Key &a, const Key &b)
{
    if (a.when != b.when) return a.when > b.when;
    if (a.source != b.source) return a.source > b.source;
    return a.seq > b.seq;
}

uint32_t ArrivalQueue::push(const sc_core::sc_time &when, int source, const TimedPacket &item,
                        const sc_core::sc_time &stamp, BufferSpace *credit)
{
    uint32_t slot;
    if (m_free.empty()) {
        slot = static_cast<uint32_t>(m_slots.size());
        m_slots.emplace_back();
    } else {
        slot = m_free.back();
        m_free.pop_back();
    }
    Arrival &a = m_slots[slot];
    a.item = item;
    a.item.stamp = stamp;
    a.source = source;
    a.credit = credit;
    m_heap.push_back(Key{when, source, slot, m_seq++, sc_core::sc_delta_count()});
    std::push_heap(m_heap.begin(), m_heap.end(), later);
    return slot;
}

uint32_t ArrivalQueue::pop()
{
    std::pop_heap(m_heap.begin(), m_heap.end(), later);
    uint32_t slot = m_heap.back().slot;
    m_heap.pop_back();
    return slot;
}

}  // namespace torusrt
