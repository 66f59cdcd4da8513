// timed_packet.h - a packet with the simulated time it was sent (its arrival time once delivered),
// and the TLM-2.0 extension that carries it in a generic payload.
#pragma once

#include <systemc>
#include <tlm>

#include "buffer_space.h"
#include "rt_packet.h"

namespace torusrt {

class PacketPool;

// The fields a hop reads and writes come first, the kernel's packet (read only by processors)
// last, so a packet crossing the network touches its first cache line only (packet_pool.h).
struct TimedPacket {
    TimedPacket() = default;
    TimedPacket(const rt_packet &p, const sc_core::sc_time &sent = sc_core::SC_ZERO_TIME) : stamp(sent), packet(p) {}

    sc_core::sc_time stamp;  // send time; after a link, arrival time (loosely-timed runs use it)
    // Flow control (flow_control.h): the packet's class, its virtual channel on the link it is
    // on, the direction of the last link it crossed (-1: none since it left a processor), and
    // whether its slot in the next buffer was already taken when its processor took up its
    // parent (then the next buffer does not take one again).
    uint32_t cls = 0;
    uint8_t vc = 0;
    int8_t last_dir = -1;
    bool reserved = false;
    bool from_host = false;  // a primary packet from the host, not yet in any buffer
    // Latency statistics (packet_latency.h), 16 bytes: the links crossed since the packet was
    // made, the steps that handed it on so far (nanoseconds, at most 2^32 - 1, about 4.3 s) and
    // when it was made (a primary: its first step); only links write `hops`, only processors the
    // others.
    uint16_t hops = 0;
    uint32_t worked_ns = 0;
    sc_core::sc_time born;
    rt_packet packet{};  // the kernel's packet
};

// Packets cross links as a generic payload (command WRITE, data = the packet's bytes on the wire)
// with this extension: the packet is slot `handle` of packet pool `pool` (packet_pool.h), and
// `credit` the slot it occupies in the sender's buffer, which the receiver gives back once it
// has taken the packet on.
class PacketExtension : public tlm::tlm_extension<PacketExtension> {
  public:
    BufferSpace *credit = nullptr;
    PacketPool *pool = nullptr;
    uint32_t handle = 0;
    tlm::tlm_extension_base *clone() const override { return new PacketExtension(*this); }
    void copy_from(const tlm::tlm_extension_base &other) override
    {
        const auto &o = static_cast<const PacketExtension &>(other);
        credit = o.credit;
        pool = o.pool;
        handle = o.handle;
    }
};

}  // namespace torusrt
