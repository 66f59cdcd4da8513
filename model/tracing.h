// tracing.h - the optional VCD trace: IP busy and queue depth, link activity and queue depth,
// bus owner and request lines. Created only when --vcd is given; written to a temporary file
// and renamed when the run succeeds.
#pragma once

#include <string>
#include <systemc>

#include "sim_config.h"
#include "torus_system.h"

namespace torusrt {

class Tracer {
  public:
    Tracer(const std::string &path, const SimConfig &config, TorusSystem &top);
    ~Tracer();  // closes and removes the temporary file unless commit() was called
    // Closes the trace and moves it to its final path.
    void commit();

  private:
    std::string m_path, m_tmp_base;
    sc_core::sc_trace_file *m_file = nullptr;
    bool m_committed = false;
};

}  // namespace torusrt
