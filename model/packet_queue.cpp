// packet_queue.cpp - FIFO with blocking push/pop on SystemC events.
#include "packet_queue.h"

namespace torusrt {

PacketQueue::PacketQueue(std::string name, unsigned capacity)
    : m_name(std::move(name)), m_capacity(capacity) {}

void PacketQueue::push_blocking(const TimedPacket &p)
{
    while (!p.from_host && full()) {
        m_blocked_writers++;
        sc_core::wait(m_not_full);
        m_blocked_writers--;
    }
    m_items.push_back(p);
    if (!p.from_host) m_network++;
    m_depth = static_cast<int>(m_items.size());
    if (m_items.size() > m_high_water) m_high_water = m_items.size();
    m_not_empty.notify(sc_core::SC_ZERO_TIME);
}

TimedPacket PacketQueue::pop_blocking()
{
    while (m_items.empty()) sc_core::wait(m_not_empty);
    TimedPacket p = m_items.front();
    m_items.pop_front();
    m_depth = static_cast<int>(m_items.size());
    if (!p.from_host) {
        m_network--;
        if (m_capacity) m_not_full.notify(sc_core::SC_ZERO_TIME);
    }
    return p;
}

}  // namespace torusrt
