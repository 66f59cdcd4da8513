// packet_injector.h - a test module that hands a list of packets to a PacketSinkIf at start-up.
#pragma once

#include <systemc>
#include <vector>

#include "packet_sink_if.h"
#include "timed_packet.h"

namespace model_test {

struct Injector : sc_core::sc_module {
    sc_core::sc_port<torusrt::PacketSinkIf> out;  // where the packets go
    std::vector<torusrt::TimedPacket> packets;    // handed over in order at time 0
    explicit Injector(sc_core::sc_module_name n) : sc_module(n), out("out")
    {
        SC_HAS_PROCESS(Injector);
        SC_THREAD(run);
    }
    void run()
    {
        for (const torusrt::TimedPacket &p : packets) out->accept(p);
    }
};

}  // namespace model_test
