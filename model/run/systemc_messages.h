// systemc_messages.h - SystemC's own report messages go to stderr (stdout holds the summary
// only); with --quiet its infos and warnings are dropped, errors still show.
#pragma once

namespace torusrt {

void route_systemc_messages(bool quiet);
// Whether SystemC failed to set up a process's stack (E518, not displayed): the system refused
// the memory.
bool systemc_stack_failed();
// Whether a process ended on std::bad_alloc (E549 "uncaught exception", not displayed): the
// system refused the memory while simulating.
bool systemc_out_of_memory();

}  // namespace torusrt
