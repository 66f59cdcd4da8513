// packet_sink_if.h - where a module hands a packet on: an IP's input queue, a link, a
// communication unit. accept() may wait (in the caller's thread) while the receiver is full.
#pragma once

#include <systemc>

#include "timed_packet.h"

namespace torusrt {

class PacketSinkIf : public virtual sc_core::sc_interface {
  public:
    virtual void accept(const TimedPacket &p) = 0;
};

}  // namespace torusrt
