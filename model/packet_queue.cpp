// packet_queue.cpp - FIFO with blocking push/pop on SystemC events.
#include "packet_queue.h"

namespace torusrt {

PacketQueue::PacketQueue(std::string name, unsigned capacity) : m_name(std::move(name)), m_space(capacity) {}

void PacketQueue::push_blocking(const TimedPacket &p)
{
    if (!p.from_host) m_space.take_blocking();
    m_items.push_back(p);
    m_depth = static_cast<int>(m_items.size());
    if (m_items.size() > m_high_water) m_high_water = m_items.size();
    if (m_reader_waiting) m_not_empty.notify(sc_core::SC_ZERO_TIME);
}

TimedPacket PacketQueue::pop_blocking()
{
    for (;;) {
        bool primary = m_source && m_source->pending(m_node);
        if (primary && (m_items.empty() || m_source->next_time(m_node) <= m_items.front().stamp))
            return m_source->take(m_node);
        if (!m_items.empty()) break;
        m_reader_waiting = true;
        sc_core::wait(m_not_empty);
        m_reader_waiting = false;
    }
    TimedPacket p = m_items.front();
    m_items.pop_front();
    m_depth = static_cast<int>(m_items.size());
    if (!p.from_host) m_space.release();
    return p;
}

}  // namespace torusrt
