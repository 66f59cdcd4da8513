// timed_wake.h - how a module asks to run again at a later time: through the machine's wake
// calendar where the machine has one (wake_calendar.h: one SystemC event for the machine, wakes
// at one time in a fixed order), else by notifying a timed event of the module's own.
//
// Usage: built at elaboration with the calendar (or null), the module as the calendar's client
// and the module's own event; at(when, after) then wakes the module at `when`, `after` from now.
#pragma once

#include <systemc>

#include "wake_calendar.h"

namespace torusrt {

class TimedWake {
  public:
    TimedWake(WakeCalendar *calendar, WakeCalendar::Client &client, sc_core::sc_event &own)
        : m_calendar(calendar), m_id(calendar ? calendar->add(client) : -1), m_own(&own)
    {
    }
    // Wakes the module at `when` (= now + `after`, later than now). The calendar keeps an earlier
    // wake already asked for; so does a timed event.
    void at(const sc_core::sc_time &when, const sc_core::sc_time &after)
    {
        if (m_calendar) m_calendar->wake_at(m_id, when);
        else m_own->notify(after);
    }

  private:
    WakeCalendar *m_calendar;
    int m_id;
    sc_core::sc_event *m_own;
};

}  // namespace torusrt
