// series_recording.h - the time series of a run (--stats-interval): made with the machine,
// told of its processors, links, buses, queues and packets, and written as CSV after the run.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cluster_bus.h"
#include "packet_ledger.h"
#include "rt_budget.h"
#include "time_series.h"
#include "torus_system.h"

namespace torusrt {

class SeriesRecording {
  public:
    // Most intervals a series may have.
    static constexpr size_t kMaxRows = 1000000;
    // The longest CSV line of an interval (three times of 21 characters, four shares of 8, two
    // counts of 20, the commas and the newline): the CSV is made in one piece of this size a row.
    static constexpr size_t kCsvRowBytes = 144;
    // An interval's memory: its row and its CSV line, both held as the CSV is made.
    static constexpr uint64_t kRowBytes = sizeof(TimeSeries::Row) + kCsvRowBytes;

    // The rows' memory is reserved from `memory` as they grow, beside the packets outstanding
    // (whose limit in `ledger` shrinks by as much).
    SeriesRecording(double interval_s, TorusSystem &top, PacketLedger &ledger, rt_budget &memory);
    // UserError naming --stats-interval (and --memory-budget, when that was the bound) when the
    // series outgrew kMaxRows or the budget: the run was stopped there.
    void check() const;
    // After the run (the image time): the CSV text. UserError as check().
    std::string finish(const sc_core::sc_time &image_time, int64_t in_flight);

  private:
    // A bus's grants as busy spans.
    struct BusSpans : ClusterBus::GrantObserver {
        TimeSeries *series = nullptr;
        void granted(const ClusterBus::Grant &g) override { series->bus_busy(g.start, g.end); }
    };
    bool grow(size_t rows);

    double m_interval_s;
    PacketLedger &m_ledger;
    rt_budget &m_memory;
    size_t m_refused_rows = 0;    // the rows grow() could not give memory for
    uint64_t m_refused_left = 0;  // what the budget had left beside the packets then
    TimeSeries m_series;
    BusSpans m_bus;
    size_t m_processors, m_buses;
};

}  // namespace torusrt
