// time_series.h - statistics over time (--stats-interval): the machine's busy time, link and bus
// use summed per interval as the modules report their busy spans, and the packets queued and in
// flight at each interval's end. Made only when asked for: a module without one pays a null
// pointer test per packet.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "queue_registry.h"

namespace torusrt {

class TimeSeries {
  public:
    // `links`: the number of link directions (each reports its crossings in time order);
    // `max_rows`: the most intervals kept (beyond: overflowed()).
    TimeSeries(const sc_core::sc_time &interval, size_t links, size_t max_rows);

    // A processor's busy span.
    void ip_busy(const sc_core::sc_time &start, const sc_core::sc_time &end);
    // Link `link`'s crossing; a link's crossings come in time order.
    void link_busy(size_t link, const sc_core::sc_time &start, const sc_core::sc_time &end);
    // A cluster bus's occupancy.
    void bus_busy(const sc_core::sc_time &start, const sc_core::sc_time &end);
    // Called before the packets in flight change at kernel time `now`: the intervals ended by
    // then take `in_flight` and the queues' occupancy as their end values.
    void at(const sc_core::sc_time &now, int64_t in_flight)
    {
        if (now >= m_next_end) close_intervals(now, in_flight);
    }
    // The queues whose occupancy is summed.
    void watch(const QueueRegistry &queues) { m_queues = &queues; }
    // After the run: closes every link's last interval and the rows up to `end` (the image time)
    // or the end of the last busy span, if later (end_ps()).
    void finish(const sc_core::sc_time &end, int64_t in_flight);

    struct Row {
        uint64_t ip_busy = 0, link_busy = 0, link_max = 0, bus_busy = 0;  // picoseconds
        uint64_t queued = 0;
        int64_t in_flight = 0;
    };
    const std::vector<Row> &rows() const { return m_rows; }
    uint64_t interval_ps() const { return m_interval; }
    uint64_t end_ps() const { return m_end; }
    size_t links() const { return m_links.size(); }
    // More intervals than max_rows were needed: the series is incomplete.
    bool overflowed() const { return m_overflow; }

  private:
    struct LinkBin {
        size_t row = 0;
        uint64_t busy = 0;
    };
    Row *row(size_t k);
    // Splits [start, end) over the intervals, adding each piece to field `f` (and calling
    // `piece(k, ps)` for each).
    template <class Piece> void spread(uint64_t start, uint64_t end, Piece piece);
    void close_intervals(const sc_core::sc_time &now, int64_t in_flight);
    void close_link(LinkBin &bin);

    uint64_t m_interval, m_end = 0;  // m_end: the latest end of a busy span, then of the series
    size_t m_max_rows;
    sc_core::sc_time m_next_end;  // the end of the first interval whose end values are not taken
    size_t m_closed = 0;          // intervals whose end values are taken
    std::vector<Row> m_rows;
    std::vector<LinkBin> m_links;
    const QueueRegistry *m_queues = nullptr;
    bool m_overflow = false;
};

}  // namespace torusrt
