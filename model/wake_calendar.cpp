// wake_calendar.cpp - a binary min-heap of wake keys with lazy deletion, and the method that
// wakes the clients due.
#include "wake_calendar.h"

#include <algorithm>

#include "sim_now.h"

namespace torusrt {

WakeCalendar::WakeCalendar(sc_core::sc_module_name name) : sc_module(name)
{
    SC_HAS_PROCESS(WakeCalendar);
    SC_METHOD(run);
    sensitive << m_due;
    dont_initialize();
}

int WakeCalendar::add(Client &client)
{
    if (m_slots.size() >= (size_t{1} << (64 - kSeqBits))) SC_REPORT_FATAL(name(), "too many clients");
    m_slots.push_back(Slot{&client, kNone, kNone});
    return static_cast<int>(m_slots.size() - 1);
}

void WakeCalendar::wake_at(int id, const sc_core::sc_time &when)
{
    Slot &s = m_slots[static_cast<size_t>(id)];
    uint64_t t = when.value();
    if (t >= s.when) return; // an earlier (or the same) wake is live
    s.when = t;
    s.order = static_cast<uint64_t>(id) << kSeqBits | m_seq++;
    m_heap.push_back(Key{t, s.order});
    std::push_heap(m_heap.begin(), m_heap.end(), later);
    if (t < m_notified) { // an earlier notification replaces a pending later one
        m_notified = t;
        m_due.notify(sc_core::sc_time::from_value(t) - sim_now());
    }
}

bool WakeCalendar::due_time(int id, sc_core::sc_time &when) const
{
    const Slot &s = m_slots[static_cast<size_t>(id)];
    if (s.when == kNone) return false;
    when = sc_core::sc_time::from_value(s.when);
    return true;
}

WakeCalendar::Key WakeCalendar::pop()
{
    std::pop_heap(m_heap.begin(), m_heap.end(), later);
    Key k = m_heap.back();
    m_heap.pop_back();
    return k;
}

void WakeCalendar::run()
{
    uint64_t now = sim_now().value();
    m_notified = kNone;
    // Wakes asked for by the clients woken here are later than now: they wait for the next run.
    while (!m_heap.empty() && m_heap.front().when <= now) {
        Key k = pop();
        if (stale(k)) continue;
        Slot &s = m_slots[k.order >> kSeqBits];
        s.when = s.order = kNone;
        // The next client due is cold (a node's unit): fetch it while this one runs.
        if (!m_heap.empty() && m_heap.front().when <= now)
            __builtin_prefetch(m_slots[m_heap.front().order >> kSeqBits].client);
        s.client->wake_due();
    }
    arm(now);
}

void WakeCalendar::arm(uint64_t now)
{
    while (!m_heap.empty() && stale(m_heap.front())) pop();
    if (m_heap.empty() || m_heap.front().when >= m_notified) return;
    m_notified = m_heap.front().when;
    m_due.notify(sc_core::sc_time::from_value(m_notified - now));
}

}  // namespace torusrt
