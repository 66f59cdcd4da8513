// time_series.h - statistics over time (--stats-interval): the machine's busy time, link and bus
// use summed per interval as the modules report their busy spans, and the packets queued and in
// flight at each interval's end. Made only when asked for: a module without one pays a null
// pointer test per packet.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <systemc>
#include <vector>

#include "queue_registry.h"

namespace torusrt {

class TimeSeries {
  public:
    // Asked before the rows grow by `rows` more: false when their memory does not fit (the
    // series then overflows). Null: they always fit.
    using Grow = std::function<bool(size_t rows)>;
    // Rows are granted in blocks of this many.
    static constexpr size_t kBlockRows = 4096;

    // `links`: the number of link directions (each reports its crossings in time order);
    // `max_rows`: the most intervals kept (beyond: overflowed()); `grow`: the memory's check.
    TimeSeries(const sc_core::sc_time &interval, size_t links, size_t max_rows, Grow grow = nullptr);

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
    const std::deque<Row> &rows() const { return m_rows; }
    uint64_t interval_ps() const { return m_interval; }
    uint64_t end_ps() const { return m_end; }
    // The intervals up to end_ps() (the last one may be shorter).
    size_t row_count() const;
    // The end of interval k, at most the largest time.
    uint64_t interval_end_ps(size_t k) const;
    size_t links() const { return m_links.size(); }
    // More intervals than max_rows were needed, or their memory did not fit (grow said no): the
    // series is incomplete, and a running simulation was stopped.
    bool overflowed() const { return m_overflow != Overflow::none; }
    bool over_budget() const { return m_overflow == Overflow::budget; }
    // The row that did not fit (its interval's start is the simulated time reached).
    size_t overflow_row() const { return m_overflow_row; }

  private:
    struct LinkBin {
        size_t row = 0;
        uint64_t busy = 0;
    };
    enum class Overflow { none, rows, budget };
    Row *row(size_t k);
    void overflow(Overflow why, size_t k);
    // Splits [start, end) over the intervals, adding each piece to field `f` (and calling
    // `piece(k, ps)` for each).
    template <class Piece> void spread(uint64_t start, uint64_t end, Piece piece);
    void close_intervals(const sc_core::sc_time &now, int64_t in_flight);
    void close_link(LinkBin &bin);

    uint64_t m_interval, m_end = 0;  // m_end: the latest end of a busy span, then of the series
    size_t m_max_rows;
    sc_core::sc_time m_next_end;  // the end of the first interval whose end values are not taken
    size_t m_closed = 0;          // intervals whose end values are taken
    std::deque<Row> m_rows;       // grows without copying: no second copy at a reallocation
    size_t m_granted = 0;         // rows whose memory grow() accepted
    Grow m_grow;
    std::vector<LinkBin> m_links;
    const QueueRegistry *m_queues = nullptr;
    Overflow m_overflow = Overflow::none;
    size_t m_overflow_row = 0;
};

}  // namespace torusrt
