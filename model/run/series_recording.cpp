// series_recording.cpp - the series attached to the machine, and its CSV.
#include "series_recording.h"

#include <algorithm>
#include <cstdio>

#include "cluster_node.h"
#include "intersection_processor.h"
#include "packet_pool.h"
#include "toroidal_link.h"
#include "user_error.h"

namespace torusrt {

namespace {

// Picoseconds as seconds, exactly (12 decimals).
std::string seconds(uint64_t ps)
{
    char text[40];
    std::snprintf(text, sizeof text, "%llu.%012llu", static_cast<unsigned long long>(ps / 1000000000000ull),
                  static_cast<unsigned long long>(ps % 1000000000000ull));
    return text;
}

// A share of `count` resources over `length` picoseconds, 6 decimals.
std::string share(uint64_t busy, uint64_t count, uint64_t length)
{
    char text[40];
    double d = count == 0 || length == 0 ? 0 : static_cast<double>(busy) / (static_cast<double>(count) * length);
    std::snprintf(text, sizeof text, "%.6f", d);
    return text;
}

}  // namespace

SeriesRecording::SeriesRecording(double interval_s, TorusSystem &top, PacketLedger &ledger, rt_budget &memory)
    : m_interval_s(interval_s), m_ledger(ledger), m_memory(memory),
      m_series(sc_core::sc_time(interval_s, sc_core::SC_SEC), top.links().size(), kMaxRows,
               [this](size_t rows) { return grow(rows); }),
      m_processors(top.processors().size()), m_buses(top.clusters().size())
{
    m_bus.series = &m_series;
    for (IntersectionProcessor *p : top.processors()) p->record_into(&m_series);
    for (size_t i = 0; i < top.links().size(); i++) top.links()[i]->record_into(&m_series, i);
    for (const auto &cl : top.clusters()) cl->bus().observe(&m_bus);
    m_series.watch(top.queues());
    ledger.record_into(&m_series);
}

// The rows' memory beside the packets outstanding now; the packets' limit shrinks by as much.
bool SeriesRecording::grow(size_t rows)
{
    if (m_memory.limit == 0) return true;
    const uint64_t bytes = rows * kRowBytes, packet = PacketPool::bytes_per_packet();
    const uint64_t packets = static_cast<uint64_t>(std::max<int64_t>(0, m_ledger.outstanding())) * packet;
    const uint64_t left = rt_budget_left(&m_memory);
    if (packets > left || bytes > left - packets) {
        m_refused_rows = rows;
        m_refused_left = packets > left ? 0 : left - packets;
        return false;
    }
    m_memory.used += bytes;
    m_ledger.set_limit(rt_budget_packets_allowed(&m_memory, packet));
    return true;
}

void SeriesRecording::check() const
{
    if (!m_series.overflowed()) return;
    const size_t k = m_series.overflow_row();
    const double reached_s = static_cast<double>(k) * m_interval_s;
    char text[400];
    if (m_series.over_budget()) {
        char need[32], left[32], limit[32];
        std::snprintf(text, sizeof text,
                      "--stats-interval %g s: memory budget exceeded: the series reached %zu intervals (%g s "
                      "simulated, where the run stopped), and %zu more (%llu bytes each) would take %s, more than "
                      "the %s left beside the packets in flight of the %s --memory-budget; give a longer "
                      "--stats-interval or a larger --memory-budget",
                      m_interval_s, k, reached_s, m_refused_rows, static_cast<unsigned long long>(kRowBytes),
                      rt_budget_format(m_refused_rows * kRowBytes, need, sizeof need),
                      rt_budget_format(m_refused_left, left, sizeof left),
                      rt_budget_format(m_memory.limit, limit, sizeof limit));
    } else {
        std::snprintf(text, sizeof text,
                      "--stats-interval %g s: the run needs more than %zu intervals (it passed %g s simulated, "
                      "stopped there); give a longer interval",
                      m_interval_s, kMaxRows, reached_s);
    }
    throw UserError(text, 2);
}

std::string SeriesRecording::finish(const sc_core::sc_time &image_time, int64_t in_flight)
{
    m_series.finish(image_time, in_flight);
    check();
    std::string csv = "start_s,end_s,ip_busy_share,ip_busy_s,queued,in_flight,link_use_mean,link_use_max";
    csv += m_buses > 0 ? ",bus_use_mean\n" : "\n";
    const uint64_t T = m_series.interval_ps();
    const auto &rows = m_series.rows();
    size_t n = m_series.row_count();
    csv.reserve(csv.size() + std::min(n, rows.size()) * kCsvRowBytes);  // counted in the budget: no doubling
    for (size_t k = 0; k < n && k < rows.size(); k++) {
        const TimeSeries::Row &r = rows[k];
        uint64_t start = k * T, end = std::min(m_series.interval_end_ps(k), m_series.end_ps()), len = end - start;
        csv += seconds(start) + "," + seconds(end) + "," + share(r.ip_busy, m_processors, len) + "," +
               seconds(r.ip_busy) + "," + std::to_string(r.queued) + "," + std::to_string(r.in_flight) + "," +
               share(r.link_busy, m_series.links(), len) + "," + share(r.link_max, 1, len);
        csv += m_buses > 0 ? "," + share(r.bus_busy, m_buses, len) + "\n" : "\n";
    }
    return csv;
}

}  // namespace torusrt
