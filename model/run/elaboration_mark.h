// elaboration_mark.h - when SystemC's elaboration ended, in wall-clock seconds, so that a run can
// report its elaboration and its simulation apart. IEEE 1666 runs every end_of_elaboration
// callback before any start_of_simulation callback, both inside the first sc_start; a module
// built after the machine notes the time in its start_of_simulation.
#ifndef TORUSRT_ELABORATION_MARK_H
#define TORUSRT_ELABORATION_MARK_H

#include <systemc>

namespace torusrt {

class ElaborationMark : public sc_core::sc_module {
  public:
    explicit ElaborationMark(sc_core::sc_module_name name) : sc_module(name) {}
    // The wall-clock time of start_of_simulation, or `before` if sc_start has not run yet.
    double ended_at(double before) const { return m_ended_at >= 0 ? m_ended_at : before; }

  private:
    void start_of_simulation() override;
    double m_ended_at = -1;
};

// The one mark of this process, built at the first call (after the machine) and kept to the end.
ElaborationMark &elaboration_mark();

}  // namespace torusrt

#endif
