// arrival_queue.cpp - a binary min-heap of arrival keys over a pool of arrival slots.
#include "arrival_queue.h"

#include <algorithm>

namespace torusrt {

uint32_t ArrivalQueue::push(const sc_core::sc_time &when, int source, uint32_t packet, BufferSpace *credit)
{
    uint32_t slot;
    if (m_free.empty()) {
        slot = static_cast<uint32_t>(m_slots.size());
        m_slots.emplace_back();
    } else {
        slot = m_free.back();
        m_free.pop_back();
    }
    m_slots[slot] = Arrival{packet, source, credit, sc_core::sc_delta_count()};
    uint64_t order = static_cast<uint64_t>(source) << kSeqBits | m_seq++;
    m_heap.push_back(Key{when.value(), order, slot});
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
