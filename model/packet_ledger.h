// packet_ledger.h - packets created and consumed by kind, and the moment the last one went:
// completion detection for the host, the conservation check of every run and the packets'
// latencies (packet_latency.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <systemc>

#include "packet_latency.h"
#include "rt_packet.h"
#include "sim_now.h"
#include "time_series.h"

namespace torusrt {

class PacketLedger {
  public:
    void created(int kind)
    {
        if (m_series) m_series->at(sim_now(), m_outstanding);
        m_totals.created[kind]++;
        // Past the memory budget's packet limit the run stops (checked by run_model).
        if (static_cast<uint64_t>(++m_outstanding) > m_limit) {
            if (!m_over_limit) {
                m_over_limit = true;
                // The run fails with its own message: no "stopped by user" note.
                sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
                sc_core::sc_stop();
            }
            // What is made until the stop counts too: a frame's primaries all come at its start.
            m_over_at = std::max(m_over_at, static_cast<uint64_t>(m_outstanding));
        }
    }
    // Most packets that may be outstanding at once (the memory budget's share).
    void set_limit(uint64_t packets) { m_limit = packets; }
    bool over_limit() const { return m_over_limit; }
    // The most packets outstanding once past the limit: what the run needed when it stopped.
    uint64_t outstanding_over_limit() const { return m_over_at; }
    // `when` is the consumer's local time (its simulated completion).
    void consumed(int kind, const sc_core::sc_time &when)
    {
        if (m_series) m_series->at(sim_now(), m_outstanding);
        m_totals.consumed[kind]++;
        m_outstanding--;
        if (when > m_last) m_last = when;
        if (m_progress && (++m_consumed_count & 1023) == 0) m_progress(m_progress_ctx, m_consumed_count, m_outstanding);
    }
    // Called every 1024 consumed packets (for a progress display).
    void set_progress(void (*fn)(void *, uint64_t consumed, int64_t outstanding), void *ctx)
    {
        m_progress = fn;
        m_progress_ctx = ctx;
    }
    // The series told of the packets in flight as they change (null: none).
    void record_into(TimeSeries *series) { m_series = series; }
    void forwarded() { m_totals.forwarded++; }
    void primary_missed(const sc_core::sc_time &when)
    {
        m_totals.primary_missed++;
        if (when > m_last) m_last = when;
    }
    int64_t outstanding() const { return m_outstanding; }
    bool conserved() const
    {
        return m_totals.created[0] == m_totals.consumed[0] && m_totals.created[1] == m_totals.consumed[1];
    }
    const rt_packet_totals &totals() const { return m_totals; }
    // Simulated image time: when the last packet was consumed.
    sc_core::sc_time image_time() const { return m_last; }
    PacketLatency &latency() { return m_latency; }
    const PacketLatency &latency() const { return m_latency; }

  private:
    rt_packet_totals m_totals{};
    int64_t m_outstanding = 0;
    sc_core::sc_time m_last = sc_core::SC_ZERO_TIME;
    void (*m_progress)(void *, uint64_t, int64_t) = nullptr;
    void *m_progress_ctx = nullptr;
    TimeSeries *m_series = nullptr;
    uint64_t m_consumed_count = 0;
    uint64_t m_limit = UINT64_MAX;
    bool m_over_limit = false;
    uint64_t m_over_at = 0;
    PacketLatency m_latency;
};

}  // namespace torusrt
