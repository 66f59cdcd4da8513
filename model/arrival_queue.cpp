// arrival_queue.cpp - a binary min-heap of arrival keys.
#include "arrival_queue.h"

#include <algorithm>

namespace torusrt {

void ArrivalQueue::push(const sc_core::sc_time &when, int source, uint32_t packet)
{
    sc_dt::uint64 delta = sc_core::sc_delta_count();
    if (delta != m_push_delta) {
        m_push_delta = delta;
        m_delta_first_seq = m_seq;
    }
    uint64_t order = static_cast<uint64_t>(source) << kSeqBits | m_seq++;
    m_heap.push_back(Key{when.value(), order, packet});
    std::push_heap(m_heap.begin(), m_heap.end(), later);
}

ArrivalQueue::Arrival ArrivalQueue::pop()
{
    std::pop_heap(m_heap.begin(), m_heap.end(), later);
    const Key &k = m_heap.back();
    Arrival a{k.packet, static_cast<int>(k.order >> kSeqBits)};
    m_heap.pop_back();
    return a;
}

}  // namespace torusrt
