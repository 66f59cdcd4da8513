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
    TimedPacket() : vc(0), reserved(0), from_host(0) {}
    TimedPacket(const rt_packet &p, const sc_core::sc_time &sent = sc_core::SC_ZERO_TIME)
        : stamp(sent), vc(0), reserved(0), from_host(0), packet(p)
    {
    }

    sc_core::sc_time stamp;  // send time; after a link, arrival time (loosely-timed runs use it)
    // Flow control (flow_control.h): the packet's class, its virtual channel on the link it is
    // on (0 or 1), whether its slot in the next buffer was already taken when its processor took
    // up its parent (then the next buffer does not take one again), and the direction of the
    // last link it crossed (-1: none since it left a processor). Bit fields, so that the hop
    // count fits beside them: these 16 bytes are all a hop touches (packet_pool.h).
    uint32_t cls = 0;
    uint8_t vc : 6;
    uint8_t reserved : 1;
    uint8_t from_host : 1;  // a primary packet from the host, not yet in any buffer
    int8_t last_dir = -1;
    // Latency statistics (packet_latency.h): the links crossed since the packet was made (only
    // links write it), then the steps that handed it on so far (nanoseconds, at most 2^32 - 1,
    // about 4.3 s) and when it was made (a primary: its first step), which only processors write.
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
