// series_recording.cpp - the series attached to the machine, and its CSV.
#include "series_recording.h"

#include <algorithm>
#include <cstdio>

#include "cluster_node.h"
#include "intersection_processor.h"
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

SeriesRecording::SeriesRecording(double interval_s, TorusSystem &top, PacketLedger &ledger)
    : m_interval_s(interval_s), m_series(sc_core::sc_time(interval_s, sc_core::SC_SEC), top.links().size(), kMaxRows),
      m_processors(top.processors().size()), m_buses(top.clusters().size())
{
    m_bus.series = &m_series;
    for (IntersectionProcessor *p : top.processors()) p->record_into(&m_series);
    for (size_t i = 0; i < top.links().size(); i++) top.links()[i]->record_into(&m_series, i);
    for (const auto &cl : top.clusters()) cl->bus().observe(&m_bus);
    m_series.watch(top.queues());
    ledger.record_into(&m_series);
}

std::string SeriesRecording::finish(const sc_core::sc_time &image_time, int64_t in_flight)
{
    m_series.finish(image_time, in_flight);
    if (m_series.overflowed()) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "--stats-interval %g s: the run needs more than %zu intervals (%g s simulated); give a "
                      "longer interval",
                      m_interval_s, kMaxRows, image_time.to_seconds());
        throw UserError(text, 2);
    }
    std::string csv = "start_s,end_s,ip_busy_share,ip_busy_s,queued,in_flight,link_use_mean,link_use_max";
    csv += m_buses > 0 ? ",bus_use_mean\n" : "\n";
    const uint64_t T = m_series.interval_ps();
    const auto &rows = m_series.rows();
    size_t n = static_cast<size_t>((m_series.end_ps() + T - 1) / T);
    for (size_t k = 0; k < n && k < rows.size(); k++) {
        const TimeSeries::Row &r = rows[k];
        uint64_t start = k * T, end = std::min((k + 1) * T, m_series.end_ps()), len = end - start;
        csv += seconds(start) + "," + seconds(end) + "," + share(r.ip_busy, m_processors, len) + "," +
               seconds(r.ip_busy) + "," + std::to_string(r.queued) + "," + std::to_string(r.in_flight) + "," +
               share(r.link_busy, m_series.links(), len) + "," + share(r.link_max, 1, len);
        csv += m_buses > 0 ? "," + share(r.bus_busy, m_buses, len) + "\n" : "\n";
    }
    return csv;
}

}  // namespace torusrt
