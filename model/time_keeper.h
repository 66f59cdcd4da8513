// time_keeper.h - one process's view of time. Approximately-timed: every delay is a wait().
// Loosely-timed: delays accumulate in a tlm_quantumkeeper and the process synchronises only
// when its local time runs a quantum ahead (TLM-2.0 temporal decoupling).
//
// Threads call the blocking forms. A process that must not wait (an SC_METHOD) calls the _nb
// forms: each returns the wait it owes (none, or a delay, zero meaning one delta cycle), which
// it spends by being triggered that much later and then calling resumed(). Both forms give the
// same times: a blocking call is its _nb form followed by that wait and resumed().
#pragma once

#include <systemc>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "sim_now.h"

namespace torusrt {

// A wait owed: `due` false = none; else `delay` (SC_ZERO_TIME: one delta cycle).
struct TimeWait {
    bool due = false;
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
};

class TimeKeeper {
  public:
    explicit TimeKeeper(bool loosely_timed);
    // The process's local time (simulation time plus its offset; the keeper's own
    // get_current_time() reads the time through the library call, sim_now.h).
    sc_core::sc_time now() const { return m_lt ? sim_now() + m_qk.get_local_time() : sim_now(); }
    // Spends `d` of simulated time.
    void advance(const sc_core::sc_time &d) { spend(advance_nb(d)); }
    TimeWait advance_nb(const sc_core::sc_time &d);
    // Moves local time forward to `t` if it lies ahead (a packet's arrival).
    void advance_to(const sc_core::sc_time &t) { spend(advance_to_nb(t)); }
    TimeWait advance_to_nb(const sc_core::sc_time &t);
    // Synchronises with simulation time before waiting on an event.
    void sync() { spend(sync_nb()); }
    TimeWait sync_nb();
    // After an owed wait has been spent (LT: the quantum starts again from simulation time, as
    // tlm_quantumkeeper::sync does after its wait).
    void resumed();
    // After a call that may have waited on an event (a full queue), local time becomes the later
    // of `before` (the local time when the call began) and simulation time, rather than keeping
    // an offset that predates the wait. No effect when approximately timed.
    void settle(const sc_core::sc_time &before);

  private:
    void spend(const TimeWait &w)
    {
        if (!w.due) return;
        sc_core::wait(w.delay);
        resumed();
    }

    bool m_lt;
    tlm_utils::tlm_quantumkeeper m_qk;
};

}  // namespace torusrt
