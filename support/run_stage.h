// run_stage.h - what the run is doing now, in words, for the message when memory runs out.
//
// Usage:
//   set_run_stage("building the machine (" + std::to_string(nodes) + " nodes)");
//   ...                       // a std::bad_alloc from here on is reported
//   run_stage();              // "building the machine (4096 nodes)"
// The words are kept in a fixed buffer (no allocation, cut at 127 bytes), so that reading them
// after an allocation failed cannot fail again.
#pragma once

#include <string>

namespace torusrt {

void set_run_stage(const std::string &what);
// The last stage set; "" before the first.
const char *run_stage();

}  // namespace torusrt
