// time_keeper.cpp - waits (AT) or quantum-keeper offsets (LT).
#include "time_keeper.h"

#include "sim_now.h"

namespace torusrt {

TimeKeeper::TimeKeeper(bool loosely_timed) : m_lt(loosely_timed) { m_qk.reset(); }

TimeWait TimeKeeper::advance_nb(const sc_core::sc_time &d)
{
    if (!m_lt) return {true, d};
    m_qk.inc(d);
    return m_qk.need_sync() ? sync_nb() : TimeWait{};
}

TimeWait TimeKeeper::advance_to_nb(const sc_core::sc_time &t)
{
    sc_core::sc_time n = now();
    return t > n ? advance_nb(t - n) : TimeWait{};
}

TimeWait TimeKeeper::sync_nb()
{
    if (!m_lt) return {};
    // A zero offset needs no wait: skipping it keeps quantum 0 identical to AT.
    if (m_qk.get_local_time() > sc_core::SC_ZERO_TIME) return {true, m_qk.get_local_time()};
    m_qk.reset();
    return {};
}

void TimeKeeper::resumed()
{
    if (m_lt) m_qk.reset();
}

void TimeKeeper::settle(const sc_core::sc_time &before)
{
    if (!m_lt) return;
    sc_core::sc_time now = sim_now();
    m_qk.set(before > now ? before - now : sc_core::SC_ZERO_TIME);
}

}  // namespace torusrt
