// systemc_messages.h - SystemC's own report messages go to stderr (stdout holds the summary
// only); with --quiet its infos and warnings are dropped, errors still show.
#pragma once

namespace torusrt {

void route_systemc_messages(bool quiet);

}  // namespace torusrt
