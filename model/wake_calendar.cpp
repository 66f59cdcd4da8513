// wake_calendar.cpp - the tournament tree of wake times and the method that wakes the clients
// due.
#include "wake_calendar.h"

#include "sim_now.h"

namespace torusrt {

WakeCalendar::WakeCalendar(sc_core::sc_module_name name) : sc_module(name), m_when(1, kNone), m_win(2, 0)
{
    SC_HAS_PROCESS(WakeCalendar);
    SC_METHOD(run);
    sensitive << m_due;
    dont_initialize();
}

int WakeCalendar::add(Client &client)
{
    if (m_clients.size() >= (size_t{1} << 30)) SC_REPORT_FATAL(name(), "too many clients");
    if (m_asked) SC_REPORT_FATAL(name(), "clients are added before any wake");
    m_clients.push_back(&client);
    if (m_clients.size() > m_leaves) {  // twice the leaves; every wake is still kNone
        m_leaves *= 2;
        m_when.assign(m_leaves, kNone);
        m_win.assign(2 * m_leaves, 0);
        for (size_t j = 0; j < m_leaves; j++) m_win[m_leaves + j] = static_cast<int32_t>(j);
        for (size_t p = m_leaves - 1; p >= 1; p--) m_win[p] = m_win[2 * p];  // all kNone: the lower index
    }
    return static_cast<int>(m_clients.size() - 1);
}

void WakeCalendar::wake_at(int id, const sc_core::sc_time &when)
{
    m_asked = true;
    uint64_t t = when.value();
    if (t >= m_when[id]) return;  // an earlier (or the same) wake is pending
    m_when[id] = t;
    // Up from the leaf while it is, or now beats, what each node holds; above a node it does not
    // beat, nothing changes.
    for (size_t p = (m_leaves + id) >> 1; p >= 1; p >>= 1) {
        int32_t w = m_win[p];
        if (w != id && !before(id, w)) break;
        m_win[p] = id;
    }
    if (t < m_notified) {  // an earlier notification replaces a pending later one
        m_notified = t;
        m_due.notify(sc_core::sc_time::from_value(t) - sim_now());
    }
}

bool WakeCalendar::due_time(int id, sc_core::sc_time &when) const
{
    if (m_when[id] == kNone) return false;
    when = sc_core::sc_time::from_value(m_when[id]);
    return true;
}

size_t WakeCalendar::pending() const
{
    size_t n = 0;
    for (uint64_t w : m_when) n += w != kNone;
    return n;
}

void WakeCalendar::clear_earliest(int32_t id)
{
    m_when[id] = kNone;
    // It was the earliest at every node of its path: each now holds the earlier of what comes up
    // the path (carried here) and what its other child holds. The other children are not on the
    // path and do not change, so their loads do not wait for the stores above them.
    int32_t w = id;
    uint64_t wt = kNone;
    for (size_t node = m_leaves + id; node > 1; node >>= 1) {
        int32_t s = m_win[node ^ 1];
        uint64_t st = m_when[s];
        // Selected by masks, not branches: which side wins is a coin toss to a branch predictor.
        uint64_t other = uint64_t{0} - ((st < wt) | ((st == wt) & (s < w)));
        w = static_cast<int32_t>((static_cast<uint64_t>(s) & other) | (static_cast<uint64_t>(w) & ~other));
        wt = (st & other) | (wt & ~other);
        m_win[node >> 1] = w;
    }
}

void WakeCalendar::run()
{
    uint64_t now = sim_now().value();
    // Wakes asked for by the clients woken here are later than now: they wait for the next run,
    // and arm() notifies the event once for the earliest of them.
    m_notified = 0;
    for (int32_t id = earliest(); m_when[id] <= now; id = earliest()) {
        clear_earliest(id);
        // The next client due is cold (a node's unit): fetch it while this one runs.
        int32_t next = earliest();
        if (m_when[next] <= now) __builtin_prefetch(m_clients[next]);
        m_clients[id]->wake_due();
    }
    m_notified = kNone;
    arm(now);
}

void WakeCalendar::arm(uint64_t now)
{
    uint64_t t = m_when[earliest()];
    if (t >= m_notified) return;  // nothing pending (kNone), or notified for it already
    m_notified = t;
    m_due.notify(sc_core::sc_time::from_value(t - now));
}

}  // namespace torusrt
