// tracing.h - the optional VCD trace: IP busy, link use, bus owner and request lines, the
// depth of every queue of the queue registry, and a GTKWave save file: the processors' busy rows
// first, then a group per node.
// Created only when --vcd is given; the trace goes through a VcdStream (every write checked,
// optional time window) into the path the run's OutputSet handed out.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "sim_config.h"
#include "torus_system.h"
#include "vcd_stream.h"

namespace torusrt {

class Tracer {
  public:
    Tracer(const SimConfig &config, TorusSystem &top);
    ~Tracer();  // closes the trace; the OutputSet removes what was not committed
    // Closes the trace, waits for every byte to reach the file and writes the save file.
    // Throws UserError on any write error.
    void finish();

  private:
    enum class Shown { flag, count, level };  // a binary row, a decimal row, an analog step
    struct Signal {
        std::string name;   // as GTKWave names it: SystemC.top.ip_3.busy
        std::string alias;  // the row's name: ip 3 busy
        Shown shown;
        const ToroidalLink *link = nullptr;  // a link's use: its peak is added to the name
    };
    struct Group {
        std::string name;
        std::vector<Signal> signals;
    };
    void add(Group &g, bool &value, const std::string &name);
    void add(Group &g, int &value, const std::string &name, Shown shown = Shown::count);
    void trace_cluster(Group &g, ClusterNode &cluster);
    std::string save_file_text(uint64_t end_ps) const;  // end_ps: the end of the run

    const SimConfig &m_config;
    std::unique_ptr<VcdStream> m_stream;
    sc_core::sc_trace_file *m_file = nullptr;
    std::vector<Group> m_groups;
};

}  // namespace torusrt
