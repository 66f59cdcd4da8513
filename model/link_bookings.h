// link_bookings.h - the crossings a link has booked ahead, for the loosely-timed path, where a
// link is handed packets out of time order (each sender runs up to a quantum ahead): a crossing
// takes the earliest gap at or after the packet's ready time that fits one packet time, so a
// packet handed over late still crosses when the link was free at its time, rather than after
// every crossing booked before it. Approximately timed, packets come in time order and the link's
// busy-until time gives the same start.
//
// Usage: book(ready, now, length) returns the start and books [start, start + length); every
// crossing has the same length. Times are in SystemC ticks (picoseconds).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace torusrt {

class LinkBookings {
  public:
    uint64_t book(uint64_t ready, uint64_t now, uint64_t length)
    {
        forget_ended(now, length);
        if (m_head == m_starts.size() || m_starts.back() + length <= ready) {  // after every booking
            m_starts.push_back(ready);
            return ready;
        }
        auto first = m_starts.begin() + static_cast<std::ptrdiff_t>(m_head);
        // The first booking that ends after `ready`; bookings never overlap, so they end in order.
        auto it = std::lower_bound(first, m_starts.end(), ready,
                                   [length](uint64_t b, uint64_t r) { return b + length <= r; });
        uint64_t start = ready;
        for (; it != m_starts.end() && *it < start + length; ++it) start = *it + length;
        m_starts.insert(it, start);
        return start;
    }
    size_t booked() const { return m_starts.size() - m_head; }

  private:
    // Crossings over by `now` can no longer be in the way: every later one is ready no earlier.
    void forget_ended(uint64_t now, uint64_t length)
    {
        while (m_head < m_starts.size() && m_starts[m_head] + length <= now) m_head++;
        if (m_head >= 64 && 2 * m_head >= m_starts.size()) {
            m_starts.erase(m_starts.begin(), m_starts.begin() + static_cast<std::ptrdiff_t>(m_head));
            m_head = 0;
        }
    }

    std::vector<uint64_t> m_starts;  // booked starts, in time order, from m_head on
    size_t m_head = 0;
};

}  // namespace torusrt
