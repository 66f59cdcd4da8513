// buffer_space.h - the room in one bounded buffer, counted in packets: the "space available"
// notion of flow control. A writer takes a slot before it hands a packet over and the reader
// gives it back once the packet has left the buffer (a credit returned). A thread that finds no
// room waits for the next release; an SC_METHOD registers an event with on_release() and is notified
// once, at the next release. Capacity 0 = unbounded (room always available).
// Stall time: the simulated time during which at least one writer waits for room, from the
// moment the first writer starts waiting until the next release (a writer that still finds no
// room starts a new interval). A group of buffers (ClassBuffers: one queue split by packet class)
// shares an occupancy count and a StallClock, so a queue reports its stall time once however
// many of its classes wait at the same time.
#pragma once

#include <cstddef>
#include <memory>
#include <systemc>
#include <vector>

#include "sim_now.h"

namespace torusrt {

// The simulated time during which at least one of its members is stalled (intervals that
// overlap count once). A clock may feed a parent (the machine's: any writer of any buffer).
class StallClock {
  public:
    void begin()
    {
        if (m_active++ == 0) {
            m_since = sim_now();
            if (m_parent) m_parent->begin();
        }
    }
    void end()
    {
        if (m_active && --m_active == 0) {
            m_total += sim_now() - m_since;
            if (m_parent) m_parent->end();
        }
    }
    void feed(StallClock *parent) { m_parent = parent; }
    // An interval still open counts up to now.
    sc_core::sc_time time() const { return m_active ? m_total + (sim_now() - m_since) : m_total; }

  private:
    unsigned m_active = 0;
    sc_core::sc_time m_since = sc_core::SC_ZERO_TIME, m_total = sc_core::SC_ZERO_TIME;
    StallClock *m_parent = nullptr;
};

class BufferSpace {
  public:
    explicit BufferSpace(unsigned capacity) : m_capacity(capacity) {}

    bool available() const { return !m_capacity || m_used < m_capacity; }
    bool full() const { return !available(); }
    // Whether `n` more packets fit now.
    bool room(size_t n) const { return !m_capacity || m_used + n <= m_capacity; }
    void take()
    {
        m_used++;
        if (m_total) ++*m_total;
        m_depth = static_cast<int>(m_used);
        if (m_used > m_high_water) m_high_water = m_used;
    }
    void release()
    {
        m_used--;
        m_depth = static_cast<int>(m_used);
        if (m_total) --*m_total;
        if (!m_capacity) return;
        end_stall();
        if (m_released) m_released->notify(sc_core::SC_ZERO_TIME);
        for (sc_core::sc_event *e : m_waiters) e->notify(sc_core::SC_ZERO_TIME);
        m_waiters.clear();
    }
    // Takes a slot, waiting (in the calling thread) while there is none.
    void take_blocking()
    {
        while (!available()) {
            m_blocked_writers++;
            begin_stall();
            if (!m_released) m_released = std::make_unique<sc_core::sc_event>();
            sc_core::wait(*m_released);
            m_blocked_writers--;
        }
        take();
    }
    // `e` is notified at the next release (an SC_METHOD writer retries then).
    void on_release(sc_core::sc_event &e)
    {
        begin_stall();
        for (sc_core::sc_event *w : m_waiters)
            if (w == &e) return;
        m_waiters.push_back(&e);
    }

    size_t used() const { return m_used; }
    size_t size() const { return m_used; }
    // Traced occupancy (a plain int that sc_trace can watch).
    int &depth_trace() { return m_depth; }
    size_t high_water() const { return m_high_water; }
    unsigned capacity() const { return m_capacity; }
    // Writers (threads and methods) waiting for room, for the deadlock report.
    unsigned blocked_writers() const { return m_blocked_writers + static_cast<unsigned>(m_waiters.size()); }
    // Simulated time writers have waited for room so far (an interval still open counts up to now).
    sc_core::sc_time stalled_time() const { return m_stall.time(); }
    // Also counts takes and releases in `*total` and stalls in `*group` (a group of buffers).
    void count_in(int *total, StallClock *group = nullptr)
    {
        m_total = total;
        m_group = group;
    }

  private:
    void begin_stall()
    {
        if (m_stalling) return;
        m_stalling = true;
        m_stall.begin();
        if (m_group) m_group->begin();
    }
    void end_stall()
    {
        if (!m_stalling) return;
        m_stalling = false;
        m_stall.end();
        if (m_group) m_group->end();
    }

    // take() and release() touch the first 48 bytes only.
    unsigned m_capacity;
    int m_depth = 0;
    size_t m_used = 0, m_high_water = 0;
    int *m_total = nullptr;
    StallClock *m_group = nullptr;
    unsigned m_blocked_writers = 0;
    bool m_stalling = false;  // a writer waits for room
    StallClock m_stall;
    // Made when a thread first waits for room: a run makes thousands of buffers (one per class
    // and channel in use) and most never fill.
    std::unique_ptr<sc_core::sc_event> m_released;
    std::vector<sc_core::sc_event *> m_waiters;
};

}  // namespace torusrt
