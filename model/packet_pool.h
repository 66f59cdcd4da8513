// packet_pool.h - the packets of the network, by handle. A packet enters the pool when it
// leaves a processor side, moves from communication unit to link to communication unit as a
// 32-bit handle (in the arrival queue, the held FIFOs and the link transaction's extension) and
// on into the input queue at its cell's owner (an IP's, or a cluster dispatcher's), which keeps
// the handle until a reader takes the packet up: its body is written once per hop where it
// changes (stamp, channel, last link), never copied on the way; a flat processor that takes no
// reservations steps it in its slot and hands a forwarded packet on by the same handle, any
// other reader copies it out and the slot is free again. One pool serves the whole machine; a freed slot is the next
// one used, so the packets in flight stay in few, warm cache lines. Slots live in fixed chunks: a packet never moves
// while it is in the pool. A slot starts with what a hop uses: the credit, the node the packet is heading for (its
// cell's owner, found once when it enters the pool: the cell does not change on the way) and the packet's hop fields
// (timed_packet.h, the hop count among them), 32 bytes; then the latency fields and the kernel's packet, read again
// only at the owner. Slots are 32-byte aligned and 224 bytes long, so each starts at 0 or 32 bytes into a cache line
// and what a hop touches lies in one line; not cache-line aligned: with thousands of packets waiting in the queues of a
// big run, 224 bytes a slot instead of 256 is what keeps its peak memory down.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "timed_packet.h"

namespace torusrt {

class PacketPool {
  public:
    // Adds `p`, heading for node `owner`.
    uint32_t add(const TimedPacket &p, int32_t owner)
    {
        uint32_t h;
        if (m_free.empty()) {
            h = m_size++;
            if ((h >> kChunkBits) >= m_chunks.size()) m_chunks.push_back(std::make_unique<Slot[]>(kChunk));
        } else {
            h = m_free.back();
            m_free.pop_back();
        }
        Slot &s = slot(h);
        s.item = p;
        s.credit = nullptr;
        s.owner = owner;
        return h;
    }
    // Packet `h`, kept in its slot by a processor that stepped it there, now heads for node
    // `owner` again, holding no buffer slot.
    void reuse(uint32_t h, int32_t owner)
    {
        Slot &s = slot(h);
        s.credit = nullptr;
        s.owner = owner;
    }
    // Packet `h` of `from`, now a packet of this pool: the same handle when `from` is this pool;
    // else a copy (heading for the same node) and `h` is released there.
    uint32_t adopt(PacketPool &from, uint32_t h)
    {
        if (&from == this) return h;
        uint32_t mine = add(from.at(h), from.owner(h));
        from.release(h);
        return mine;
    }
    TimedPacket &at(uint32_t h) { return slot(h).item; }
    // The node owning the cell the packet is in (where it is going; -1: not known yet).
    int32_t owner(uint32_t h) { return slot(h).owner; }
    // The buffer slot the packet holds while it waits at a communication unit (null: none):
    // given back once the packet is taken on.
    BufferSpace *&credit(uint32_t h) { return slot(h).credit; }
    void release(uint32_t h) { m_free.push_back(h); }
    // Packets in the pool now.
    size_t in_use() const { return m_size - m_free.size(); }
    // Memory one outstanding packet takes at most: its slot, its handle in a queue and its
    // entry in the free list (whose array may be twice its size while it grows). The memory
    // budget's packet limit counts packets at this size.
    static constexpr uint64_t bytes_per_packet() { return sizeof(Slot) + 3 * sizeof(uint32_t); }

  private:
    struct alignas(32) Slot {
        BufferSpace *credit = nullptr;
        int32_t owner = -1;
        TimedPacket item;
    };
    static_assert(sizeof(Slot) % 32 == 0 && offsetof(Slot, item) + offsetof(TimedPacket, worked_ns) <= 32,
                  "what a hop touches (the slot's first 32 bytes) lies in one cache line");
    static constexpr uint32_t kChunkBits = 8, kChunk = 1u << kChunkBits;
    Slot &slot(uint32_t h) { return m_chunks[h >> kChunkBits][h & (kChunk - 1)]; }
    std::vector<std::unique_ptr<Slot[]>> m_chunks;
    std::vector<uint32_t> m_free;
    uint32_t m_size = 0;
};

}  // namespace torusrt
