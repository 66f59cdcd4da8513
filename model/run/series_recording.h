// series_recording.h - the time series of a run (--stats-interval): made with the machine,
// told of its processors, links, buses, queues and packets, and written as CSV after the run.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cluster_bus.h"
#include "packet_ledger.h"
#include "time_series.h"
#include "torus_system.h"

namespace torusrt {

class SeriesRecording {
  public:
    // Most intervals a series may have (the rows take about 50 bytes each in memory).
    static constexpr size_t kMaxRows = 1000000;

    SeriesRecording(double interval_s, TorusSystem &top, PacketLedger &ledger);
    // After the run (the image time): the CSV text. UserError if the interval was too short
    // for kMaxRows.
    std::string finish(const sc_core::sc_time &image_time, int64_t in_flight);

  private:
    // A bus's grants as busy spans.
    struct BusSpans : ClusterBus::GrantObserver {
        TimeSeries *series = nullptr;
        void granted(const ClusterBus::Grant &g) override { series->bus_busy(g.start, g.end); }
    };
    double m_interval_s;
    TimeSeries m_series;
    BusSpans m_bus;
    size_t m_processors, m_buses;
};

}  // namespace torusrt
