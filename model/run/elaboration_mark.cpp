// elaboration_mark.cpp - the wall-clock time at the start of the simulation.
#include "elaboration_mark.h"

#include "wall_clock.h"

namespace torusrt {

void ElaborationMark::start_of_simulation() { m_ended_at = wall_clock_s(); }

ElaborationMark &elaboration_mark()
{
    // Never destroyed: SystemC keeps a pointer to every module until the process ends.
    static auto *mark = new ElaborationMark("elaboration_mark");
    return *mark;
}

}  // namespace torusrt
