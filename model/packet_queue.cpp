// packet_queue.cpp - FIFO with blocking push/pop on SystemC events, and the ordered offer of
// packets to a reader that may refuse them.
#include "packet_queue.h"

namespace torusrt {

PacketQueue::PacketQueue(std::string name, unsigned capacity) : m_name(std::move(name)), m_spaces(capacity) {}

void PacketQueue::push_blocking(const TimedPacket &p)
{
    if (!p.reserved) space_for(p).take_blocking();
    m_items.push_back(p);
    m_items.back().reserved = false;
    m_items.back().from_host = false; // it is in this queue now, holding a slot
    m_depth = static_cast<int>(m_items.size());
    if (m_items.size() > m_high_water) m_high_water = m_items.size();
    if (m_reader_waiting) m_not_empty.notify(sc_core::SC_ZERO_TIME);
}

void PacketQueue::remove(size_t index)
{
    BufferSpace &space = space_for(m_items[index]);
    if (index == 0) m_items.pop_front();
    else m_items.erase(m_items.begin() + static_cast<std::ptrdiff_t>(index));
    m_depth = static_cast<int>(m_items.size());
    space.release();
}

void PacketQueue::wait_for(sc_core::sc_event *retry)
{
    m_reader_waiting = true;
    if (retry) sc_core::wait(m_not_empty | *retry);
    else sc_core::wait(m_not_empty);
    m_reader_waiting = false;
}

TimedPacket PacketQueue::pop_blocking()
{
    sc_core::sc_event never; // a reader that takes every packet never waits for room
    return take_first([](TimedPacket &) { return true; }, never);
}

TimedPacket PacketQueue::take_first(const std::function<bool(TimedPacket &)> &accept, sc_core::sc_event &retry)
{
    for (;;) {
        bool primary = m_source && m_source->pending(m_node);
        bool primary_first = primary && (m_items.empty() || m_source->next_time(m_node) <= m_items.front().stamp);
        if (primary_first) {
            TimedPacket c = m_source->peek(m_node);
            if (accept(c)) {
                m_source->take(m_node);
                return c;
            }
        }
        for (size_t i = 0; i < m_items.size(); i++) {
            TimedPacket c = m_items[i];
            if (accept(c)) {
                remove(i);
                return c;
            }
        }
        if (primary && !primary_first) {
            TimedPacket c = m_source->peek(m_node);
            if (accept(c)) {
                m_source->take(m_node);
                return c;
            }
        }
        wait_for(m_items.empty() && !primary ? nullptr : &retry);
    }
}

}  // namespace torusrt
