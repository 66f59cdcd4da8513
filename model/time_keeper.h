// time_keeper.h - one process's view of time. Approximately-timed: every delay is a wait().
// Loosely-timed: delays accumulate in a tlm_quantumkeeper and the process synchronises only
// when its local time runs a quantum ahead (TLM-2.0 temporal decoupling).
#pragma once

#include <systemc>
#include <tlm_utils/tlm_quantumkeeper.h>

namespace torusrt {

class TimeKeeper {
  public:
    explicit TimeKeeper(bool loosely_timed);
    // The process's local time (simulation time plus its offset).
    sc_core::sc_time now() const;
    // Spends `d` of simulated time.
    void advance(const sc_core::sc_time &d);
    // Moves local time forward to `t` if it lies ahead (a packet's arrival).
    void advance_to(const sc_core::sc_time &t);
    // Synchronises with simulation time before waiting on an event.
    void sync();
    // After a call that may have waited on an event (a full queue), local time becomes the later
    // of `before` (the local time when the call began) and simulation time, rather than keeping
    // an offset that predates the wait. No effect when approximately timed.
    void settle(const sc_core::sc_time &before);

  private:
    bool m_lt;
    tlm_utils::tlm_quantumkeeper m_qk;
};

}  // namespace torusrt
