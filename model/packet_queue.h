// packet_queue.h - the input queue of an IP or a cluster dispatcher: packets in arrival order,
// with a bounded buffer per packet class (ClassBuffers; one class under --flow none). Every
// packet in the queue counts against its class's capacity. A queue at a primary ray's entry
// node is also fed by the host's PrimarySource: primaries wait in the host, not here, and the
// next one is offered when its injection time is no later than the oldest queued packet's stamp
// (ties to the primary), so with host_inject = 0 a node works through all its primaries, in
// pixel order, before the network packets, as if all had been injected at time 0.
//
// Storage: the queue holds 32-bit handles into a packet pool (packet_pool.h), the machine's one
// (PacketQueueSetup::pool) or, for a queue alone, its own. A packet delivered from the network by handle
// (push_pooled, from the same pool) stays in its slot: a push copies nothing and allocates
// nothing; a packet pushed by value (push_blocking) is copied into a slot once. The slot is
// freed when a reader takes the packet.
//
// try_take() offers the packets to the reader in that order (the primary first when due, then
// the queued packets oldest first, then a primary not yet due) and removes the first it accepts;
// a reader that accepts every packet sees a plain FIFO (try_take_first). That is the order
// primaries-first (--queue-order); under rays-first (PacketQueueSetup::rays_first) the offer is: the queued
// ray packets newest first, then the next primary when due (its injection time no later than
// the newest shadow packet's stamp, or no shadow packet waits), then the shadow packets newest
// first, then a primary not yet due. A ray packet leads to more work (a hit makes shadow
// packets) and the newest finishes its walk soonest, so the work behind it starts sooner.
// Under the class scheme the reader accepts a packet only once the buffers its outputs go to
// have room, so it never waits while holding a packet (flow_control.h). The reader looks at each candidate in its pool
// slot; only the packet taken is copied out. A process that must not wait (an SC_METHOD) calls
// the try_ forms and, when nothing was taken, wait_reader() and then waits on not_empty_event()
// (and, unless empty(), on its own retry event); a thread calls the blocking take_first(). A
// reader given in PacketQueueSetup::reader is called instead, in the pushing delta.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <systemc>

#include "class_buffers.h"
#include "packet_pool.h"
#include "pooled_fifo.h"
#include "primary_source.h"
#include "timed_packet.h"

namespace torusrt {

// A reader told at once, in the writer's delta, instead of through not_empty_event() one delta
// on: it must itself run only after the processes runnable now (a flat processor).
class PacketQueueReader {
  public:
    virtual void queue_ready() = 0;

  protected:
    ~PacketQueueReader() = default;
};

// The machine's choices for a queue, fixed at elaboration; a queue alone takes the defaults.
struct PacketQueueSetup {
    PacketPool *pool = nullptr;          // where the packets are kept: the machine's pool (null: the queue's own)
    PrimarySource *primaries = nullptr;  // the host's primaries that feed the queue (null: none)
    int entry_node = 0;                  // the node whose primaries those are
    bool rays_first = false;             // the rays-first order above (false: primaries-first)
    // Packets kept in stamp order rather than arrival order (loosely timed with a quantum, where
    // a packet can arrive after one stamped later; approximately timed the two are the same), for
    // a reader that takes the first packet only (try_take_first*); not under rays-first.
    bool stamp_order = false;
    PacketQueueReader *reader = nullptr;  // told of a push at once (null: not_empty_event() only)
};

class PacketQueue {
  public:
    // capacity 0 = unbounded.
    PacketQueue(std::string name, unsigned capacity, const PacketQueueSetup &setup = PacketQueueSetup());
    PacketQueue(const PacketQueue &) = delete;
    PacketQueue &operator=(const PacketQueue &) = delete;

    // The buffer `p` takes a slot in.
    BufferSpace &space_for(const TimedPacket &p) { return m_spaces.at(p.cls); }
    // Whether `p` fits now (its slot may already be reserved).
    bool has_room(const TimedPacket &p) const
    {
        const BufferSpace *s = m_spaces.find(p.cls);  // not made yet: empty
        return p.reserved || !s || s->available();
    }
    // Appends, waiting (in the calling thread) while its class is full; a reserved packet
    // already holds its slot.
    void push_blocking(const TimedPacket &p);
    // The same for packet `handle` of `pool`: from this queue's pool it stays in its slot, which
    // the queue now owns; from another it is copied in and released there.
    void push_pooled(PacketPool &pool, uint32_t handle);
    // Removes the first packet (in the order above) that `accept` (a callable taking a
    // const TimedPacket &) takes, copying it to `*taken` unless null; false: none taken (nothing
    // removed). When it refuses, `accept` registers its retry event with whatever it waits for.
    template <class Accept> bool try_take(Accept &&accept, TimedPacket *taken);
    // The same for a reader that takes every packet (it never refuses).
    bool try_take_first(TimedPacket &taken);
    // The same, the packet left in its pool slot: `handle` is the reader's now (it releases it,
    // or hands it on by handle). A primary is put into a slot first.
    bool try_take_first_pooled(uint32_t &handle);
    PacketPool &pool() { return m_items.pool(); }
    // Blocking form of try_take: waits (in the calling thread) while there is none, on the queue
    // and, once one was refused, on `retry`.
    template <class Accept> TimedPacket take_first(Accept &&accept, sc_core::sc_event &retry);
    // After a try that took nothing: a push (or wake()) notifies not_empty_event() (or, for a
    // push, tells the reader set below) until the reader's next try.
    void wait_reader() { m_reader_waiting = true; }
    sc_core::sc_event &not_empty_event() { return m_not_empty; }
    using Reader = PacketQueueReader;
    // Wakes a reader waiting on an empty queue, so it looks again at the primary source
    // (a new frame's primaries appeared between two sc_start calls).
    void wake()
    {
        if (m_reader_waiting) m_not_empty.notify(sc_core::SC_ZERO_TIME);
    }
    bool empty() const { return m_items.empty() && !(m_source && m_source->pending(m_node)); }
    bool full() const { return m_spaces.full(); }
    size_t size() const { return m_items.size(); }  // packets waiting (every class)
    // Most packets waiting at once, every class together.
    size_t high_water() const { return m_high_water; }
    // Most packets of one class waiting at once (bounded by the capacity).
    size_t class_high_water() const { return m_spaces.high_water(); }
    unsigned capacity() const { return m_spaces.capacity(); }
    const std::string &name() const { return m_name; }
    // Writers waiting for room (for the deadlock report).
    unsigned blocked_writers() const { return m_spaces.blocked_writers(); }
    // The class-0 buffer (the only one under --flow none).
    BufferSpace &space() { return m_spaces.at(0); }
    ClassBuffers &spaces() { return m_spaces; }
    // Traced queue depth (a plain int that sc_trace can watch).
    int &depth_trace() { return m_depth; }

  private:
    // Appends pool packet `handle`, its buffer slot taken.
    void append(uint32_t handle);
    // Removes the packet at `index`, freeing its buffer slot and (unless `keep_slot`) its pool
    // slot.
    void remove(size_t index, bool keep_slot = false);
    void wait_for(sc_core::sc_event *retry);
    bool primary_first() const
    {
        return m_source->pending(m_node) && (m_items.empty() || m_source->next_time(m_node) <= m_items.at(0).stamp);
    }
    static constexpr size_t kNone = SIZE_MAX;
    // Rays-first: the position of the newest packet of `kind` older than position `before`, or kNone.
    size_t newest_before(size_t before, uint8_t kind) const
    {
        if (kind == RT_PACKET_RAY && m_rays == 0) return kNone;
        while (before-- > 0)
            if (m_items.at(before).packet.kind == kind) return before;
        return kNone;
    }
    // Rays-first: whether the next primary comes before the shadow packet at `shadow` (kNone: none).
    bool primary_before(size_t shadow) const
    {
        return m_source && m_source->pending(m_node) &&
               (shadow == kNone || m_source->next_time(m_node) <= m_items.at(shadow).stamp);
    }
    // Rays-first: the position try_take_first_pooled takes, kNone for the next primary.
    size_t rays_first_pick() const;

    // What a push and a take touch first, then the buffers, then the rest (a reader told at
    // once never touches the event).
    PooledFifo m_items;  // the packets, oldest first
    size_t m_high_water = 0;
    size_t m_rays = 0;  // ray packets among the queued (rays-first looks for them)
    bool m_rays_first = false;
    bool m_stamp_order = false;
    int m_depth = 0;
    bool m_reader_waiting = false;
    Reader *m_ready_reader = nullptr;
    PrimarySource *m_source = nullptr;
    int m_node = -1;
    ClassBuffers m_spaces;
    sc_core::sc_event m_not_empty;
    PacketPool m_own_pool;  // a queue alone (tests); the machine's queues share its pool
    std::string m_name;
};

template <class Accept> bool PacketQueue::try_take(Accept &&accept, TimedPacket *taken)
{
    m_reader_waiting = false;
    if (m_rays_first) {
        auto offer = [&](size_t i) {
            const TimedPacket &c = m_items.at(i);
            if (!accept(c)) return false;
            if (taken) *taken = c;
            remove(i);
            return true;
        };
        auto offer_primary = [&]() {
            TimedPacket c = m_source->peek(m_node);
            if (!accept(static_cast<const TimedPacket &>(c))) return false;
            m_source->drop(m_node);
            if (taken) *taken = c;
            return true;
        };
        for (size_t i = newest_before(m_items.size(), RT_PACKET_RAY); i != kNone; i = newest_before(i, RT_PACKET_RAY))
            if (offer(i)) return true;
        size_t shadow = newest_before(m_items.size(), RT_PACKET_SHADOW);
        bool due = primary_before(shadow);
        if (due && offer_primary()) return true;
        for (size_t i = shadow; i != kNone; i = newest_before(i, RT_PACKET_SHADOW))
            if (offer(i)) return true;
        return !due && m_source && m_source->pending(m_node) && offer_primary();
    }
    bool primary = m_source && m_source->pending(m_node);
    bool first = primary && primary_first();
    if (first) {
        TimedPacket c = m_source->peek(m_node);  // made on demand: a copy either way
        if (accept(static_cast<const TimedPacket &>(c))) {
            m_source->drop(m_node);
            if (taken) *taken = c;
            return true;
        }
    }
    for (size_t i = 0; i < m_items.size(); i++) {
        const TimedPacket &c = m_items.at(i);
        if (!accept(c)) continue;
        if (taken) *taken = c;
        remove(i);
        return true;
    }
    if (primary && !first) {
        TimedPacket c = m_source->peek(m_node);
        if (accept(static_cast<const TimedPacket &>(c))) {
            m_source->drop(m_node);
            if (taken) *taken = c;
            return true;
        }
    }
    return false;
}

template <class Accept> TimedPacket PacketQueue::take_first(Accept &&accept, sc_core::sc_event &retry)
{
    TimedPacket tp;
    while (!try_take(accept, &tp)) wait_for(empty() ? nullptr : &retry);
    return tp;
}

}  // namespace torusrt
