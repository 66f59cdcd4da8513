// packet_queue.cpp - FIFO of pool handles with blocking push/pop on SystemC events, and the
// ordered offer of packets to a reader that may refuse them.
#include "packet_queue.h"

namespace torusrt {

PacketQueue::PacketQueue(std::string name, unsigned capacity, const PacketQueueSetup &setup)
    : m_items(setup.pool ? setup.pool : &m_own_pool), m_rays_first(setup.rays_first), m_stamp_order(setup.stamp_order),
      m_ready_reader(setup.reader), m_source(setup.primaries), m_node(setup.primaries ? setup.entry_node : -1),
      m_spaces(capacity), m_name(std::move(name))
{
    if (m_stamp_order && !m_rays_first) m_items.order_by_stamp();
}

void PacketQueue::push_blocking(const TimedPacket &p) { push_pooled(pool(), pool().add(p, -1)); }

void PacketQueue::push_pooled(PacketPool &pool, uint32_t handle)
{
    if (&pool != &m_items.pool()) {
        push_blocking(pool.at(handle));
        pool.release(handle);
        return;
    }
    const TimedPacket &p = pool.at(handle);
    if (!p.reserved) space_for(p).take_blocking();
    append(handle);
}

void PacketQueue::append(uint32_t handle)
{
    TimedPacket &p = pool().at(handle);
    p.reserved = false;
    p.from_host = false;  // it is in this queue now, holding a slot
    m_items.push_back(handle);
    m_rays += p.packet.kind == RT_PACKET_RAY;
    m_depth = static_cast<int>(m_items.size());
    if (m_items.size() > m_high_water) m_high_water = m_items.size();
    if (!m_reader_waiting) return;
    if (m_ready_reader) m_ready_reader->queue_ready();
    else m_not_empty.notify(sc_core::SC_ZERO_TIME);
}

void PacketQueue::remove(size_t index, bool keep_slot)
{
    BufferSpace &space = space_for(m_items.at(index));
    m_rays -= m_items.at(index).packet.kind == RT_PACKET_RAY;
    uint32_t handle = m_items.take(index);
    m_depth = static_cast<int>(m_items.size());
    if (!keep_slot) pool().release(handle);
    space.release();
}

void PacketQueue::wait_for(sc_core::sc_event *retry)
{
    m_reader_waiting = true;
    if (retry) sc_core::wait(m_not_empty | *retry);
    else sc_core::wait(m_not_empty);
    m_reader_waiting = false;
}

bool PacketQueue::try_take_first(TimedPacket &taken)
{
    uint32_t handle;
    if (!try_take_first_pooled(handle)) return false;
    taken = pool().at(handle);
    pool().release(handle);
    return true;
}

size_t PacketQueue::rays_first_pick() const
{
    size_t ray = newest_before(m_items.size(), RT_PACKET_RAY);
    if (ray != kNone) return ray;
    size_t shadow = newest_before(m_items.size(), RT_PACKET_SHADOW);
    return primary_before(shadow) ? kNone : shadow;
}

bool PacketQueue::try_take_first_pooled(uint32_t &handle)
{
    m_reader_waiting = false;
    if (m_rays_first) {
        size_t i = rays_first_pick();
        if (i != kNone) {
            handle = m_items.handle(i);
            remove(i, true);
            return true;
        }
        if (!m_source || !m_source->pending(m_node)) return false;
        handle = pool().add(m_source->take(m_node), -1);
        return true;
    }
    if (m_source && m_source->pending(m_node) && primary_first()) {
        handle = pool().add(m_source->take(m_node), -1);
        return true;
    }
    if (!m_items.empty()) {
        handle = m_items.handle(0);
        remove(0, true);
        m_items.prefetch_front();
        return true;
    }
    if (m_source && m_source->pending(m_node)) {  // a primary not yet due
        handle = pool().add(m_source->take(m_node), -1);
        return true;
    }
    return false;
}

}  // namespace torusrt
