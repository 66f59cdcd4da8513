// time_keeper.cpp - waits (AT) or quantum-keeper offsets (LT).
#include "time_keeper.h"

namespace torusrt {

TimeKeeper::TimeKeeper(bool loosely_timed) : m_lt(loosely_timed) { m_qk.reset(); }

sc_core::sc_time TimeKeeper::now() const
{
    return m_lt ? m_qk.get_current_time() : sc_core::sc_time_stamp();
}

void TimeKeeper::advance(const sc_core::sc_time &d)
{
    if (!m_lt) {
        sc_core::wait(d);
        return;
    }
    m_qk.inc(d);
    if (m_qk.need_sync()) sync();
}

void TimeKeeper::advance_to(const sc_core::sc_time &t)
{
    sc_core::sc_time n = now();
    if (t > n) advance(t - n);
}

void TimeKeeper::sync()
{
    // A zero offset needs no wait: skipping it keeps quantum 0 identical to AT.
    if (m_lt && m_qk.get_local_time() > sc_core::SC_ZERO_TIME) m_qk.sync();
    else if (m_lt) m_qk.reset();
}

void TimeKeeper::settle(const sc_core::sc_time &before)
{
    if (!m_lt) return;
    sc_core::sc_time now = sc_core::sc_time_stamp();
    m_qk.set(before > now ? before - now : sc_core::SC_ZERO_TIME);
}

}  // namespace torusrt
