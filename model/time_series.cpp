// time_series.cpp - busy spans split over fixed intervals; end values taken as time passes.
#include "time_series.h"

#include <algorithm>
#include <limits>

namespace torusrt {

namespace {

constexpr uint64_t kLastPs = std::numeric_limits<uint64_t>::max();

}  // namespace

TimeSeries::TimeSeries(const sc_core::sc_time &interval, size_t links, size_t max_rows, Grow grow)
    : m_interval(std::max<uint64_t>(interval.value(), 1)), m_max_rows(max_rows),
      m_next_end(sc_core::sc_time::from_value(m_interval)), m_grow(std::move(grow)), m_links(links)
{
}

size_t TimeSeries::row_count() const
{
    return static_cast<size_t>(m_end / m_interval + (m_end % m_interval != 0));  // no m_end + m_interval: it may wrap
}

uint64_t TimeSeries::interval_end_ps(size_t k) const
{
    return k + 1 > kLastPs / m_interval ? kLastPs : (k + 1) * m_interval;
}

void TimeSeries::overflow(Overflow why, size_t k)
{
    if (m_overflow == Overflow::none) {
        m_overflow = why;
        m_overflow_row = k;
    }
    // The run stops here (run_frames names the reason): nothing more could be recorded. A
    // simulation that is over is not stopped again.
    if (sc_core::sc_is_running()) {
        sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
        sc_core::sc_stop();
    }
}

TimeSeries::Row *TimeSeries::row(size_t k)
{
    if (m_overflow != Overflow::none) return nullptr;
    if (k >= m_max_rows) {
        overflow(Overflow::rows, k);
        return nullptr;
    }
    if (k >= m_granted) {  // the memory of the rows up to k's block, asked for before it is taken
        size_t more = (k / kBlockRows + 1) * kBlockRows - m_granted;
        if (m_grow && !m_grow(more)) {
            overflow(Overflow::budget, k);
            return nullptr;
        }
        m_granted += more;
    }
    if (k >= m_rows.size()) m_rows.resize(k + 1);
    return &m_rows[k];
}

template <class Piece> void TimeSeries::spread(uint64_t start, uint64_t end, Piece piece)
{
    m_end = std::max<uint64_t>(m_end, end);
    while (start < end) {
        size_t k = static_cast<size_t>(start / m_interval);
        uint64_t stop = std::min(end, interval_end_ps(k));
        Row *r = row(k);
        if (!r) return;
        piece(k, *r, stop - start);
        start = stop;
    }
}

void TimeSeries::ip_busy(const sc_core::sc_time &start, const sc_core::sc_time &end)
{
    spread(start.value(), end.value(), [](size_t, Row &r, uint64_t ps) { r.ip_busy += ps; });
}

void TimeSeries::bus_busy(const sc_core::sc_time &start, const sc_core::sc_time &end)
{
    spread(start.value(), end.value(), [](size_t, Row &r, uint64_t ps) { r.bus_busy += ps; });
}

void TimeSeries::close_link(LinkBin &bin)
{
    if (bin.busy == 0) return;
    Row *r = row(bin.row);
    if (r) r->link_max = std::max(r->link_max, bin.busy);
    bin.busy = 0;
}

void TimeSeries::link_busy(size_t link, const sc_core::sc_time &start, const sc_core::sc_time &end)
{
    LinkBin &bin = m_links[link];
    spread(start.value(), end.value(), [this, &bin](size_t k, Row &r, uint64_t ps) {
        r.link_busy += ps;
        if (k != bin.row) {  // the link's earlier interval is complete: its share may be the most
            close_link(bin);
            bin.row = k;
        }
        bin.busy += ps;
    });
}

void TimeSeries::close_intervals(const sc_core::sc_time &now, int64_t in_flight)
{
    uint64_t queued = 0;
    if (m_queues)
        for (const QueueRef &q : m_queues->all())
            if (q.kind != QueueKind::link) queued += static_cast<uint64_t>(*q.depth);
    while (m_next_end <= now) {
        Row *r = row(m_closed);
        if (!r) {
            m_next_end = sc_core::sc_max_time();  // no row to take them: stop looking
            return;
        }
        r->queued = queued;
        r->in_flight = in_flight;
        uint64_t next = interval_end_ps(++m_closed);
        if (next == kLastPs) {  // the last interval time can hold: nothing ends after it
            m_next_end = sc_core::sc_max_time();
            return;
        }
        m_next_end = sc_core::sc_time::from_value(next);
    }
}

void TimeSeries::finish(const sc_core::sc_time &end, int64_t in_flight)
{
    for (LinkBin &bin : m_links) close_link(bin);
    m_end = std::max<uint64_t>(m_end, end.value());
    size_t rows = row_count();
    if (rows > 0 && !row(rows - 1)) return;
    if (rows > 0) close_intervals(sc_core::sc_time::from_value(interval_end_ps(rows - 1)), in_flight);
}

}  // namespace torusrt
