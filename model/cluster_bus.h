// cluster_bus.h - the shared bus of one cluster: every master (the m processors' bus ports and
// the communication unit's dispatcher) reaches it through one TLM-2.0 target socket; the socket
// index is the requester index (processors 0..m-1, the communication unit m). A transfer
// requests the bus, waits for the arbiter's grant and then occupies the bus for
//   bus_arbitration + ceil(bytes / bus_width) * bus_cycle  (+ memory_access for a memory read).
//
// Transactions (generic payload):
//   WRITE - a packet moving between the communication unit and a processor's queue; the bus
//           charges packet_bytes (the timing table's wire size), whatever the data length; the
//           master delivers the packet itself once the transfer has completed.
//   READ  - an object read from a processor's 2-port memory: address = holder << 32 | object,
//           data length = the object's bytes; forwarded to that memory's bus side, whose latency
//           is added to the occupancy.
//
// Approximately-timed (the reference): requests wait in b_transport; the arbiter picks among
// the raised request lines whenever the bus is free (one delta after the last release, so
// requests raised at the same instant compete); grants are strictly one at a time.
// Loosely-timed: no arbitration and no waiting in b_transport. The bus keeps a calendar of booked
// slots; a transfer takes the earliest free slot at or after the requester's local time (the
// delay argument) and the delay is advanced to the slot's end. With temporal decoupling requests
// reach the bus out of local-time order, so they are served first come first booked: grant
// waits are approximate, the arbiter policy has no effect and the owner and request lines stay
// idle in a trace.
#pragma once

#include <map>
#include <memory>
#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_initiator_socket.h>
#include <tlm_utils/multi_passthrough_target_socket.h>
#include <vector>

#include "bus_arbiter.h"
#include "module_stats.h"
#include "rt_timing.h"

namespace torusrt {

class ClusterBus : public sc_core::sc_module {
  public:
    // Transfers from the masters; the binding order gives the requester index.
    tlm_utils::multi_passthrough_target_socket<ClusterBus> target;
    // Bus side of the processors' 2-port memories, in processor order (none: no object reads).
    tlm_utils::multi_passthrough_initiator_socket<ClusterBus, 32, tlm::tlm_base_protocol_types, 0,
                                                  sc_core::SC_ZERO_OR_MORE_BOUND>
        memory;
    sc_core::sc_port<BusArbiterIf> arbiter;  // who gets the bus next

    // `requesters` masters will bind `target`; timing from the table (bus_*, memory_access,
    // packet_bytes).
    ClusterBus(sc_core::sc_module_name name, const rt_timing &timing, bool loosely_timed, int requesters);

    // Bus occupancy of one transfer of `bytes` (arbitration included, memory latency excluded).
    sc_core::sc_time transfer_time(double bytes) const;

    struct GrantStats {
        uint64_t grants = 0;
        sc_core::sc_time wait_sum = sc_core::SC_ZERO_TIME;
        sc_core::sc_time wait_max = sc_core::SC_ZERO_TIME;
        void add(const sc_core::sc_time &w)
        {
            grants++;
            wait_sum += w;
            if (w > wait_max) wait_max = w;
        }
    };
    // One granted transfer.
    struct Grant {
        int requester;
        sc_core::sc_time requested, start, end;
    };
    // Told of every grant, in grant order: the arbitration as a tool built on the library sees it.
    class GrantObserver {
      public:
        virtual ~GrantObserver() = default;
        virtual void granted(const Grant &grant) = 0;
    };

    // Statistics, read after the run.
    int requesters() const { return m_requesters; }
    const sc_core::sc_time &busy_time() const { return m_busy; }
    uint64_t transfers() const { return m_packet_transfers + m_object_reads; }
    uint64_t packet_transfers() const { return m_packet_transfers; }
    uint64_t object_reads() const { return m_object_reads; }
    double packet_bytes() const { return m_packet_bytes; }
    double object_bytes() const { return m_object_bytes; }
    // Requesters waiting for a grant right now (for the deadlock report).
    int waiting() const;
    BusStats stats() const;
    // The observer told of each grant from now on (null: none, the default).
    void observe(GrantObserver *observer) { m_observer = observer; }

    // Traced lines: the owner (-1 idle) and one request line per requester.
    int &owner_trace() { return m_owner; }
    bool &request_trace(int requester) { return m_request_line[requester]; }

  private:
    void b_transport(int id, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay);
    void arbitrate();
    // Loosely timed: books the earliest free slot of `occupancy` at or after `requested`.
    sc_core::sc_time reserve(const sc_core::sc_time &requested, const sc_core::sc_time &occupancy);
    // Bytes on the bus and memory latency of `trans` (forwards reads to the memory).
    double carry(tlm::tlm_generic_payload &trans, sc_core::sc_time &memory_delay);
    void record(int id, const tlm::tlm_generic_payload &trans, double bytes, const sc_core::sc_time &requested,
                const sc_core::sc_time &start, const sc_core::sc_time &occupancy);
    void end_of_elaboration() override;

    rt_timing m_timing;
    bool m_lt;
    int m_requesters;
    int m_owner = -1;
    std::unique_ptr<bool[]> m_request_line;
    std::vector<bool> m_requesting;
    std::vector<std::unique_ptr<sc_core::sc_event>> m_granted;  // one per requester
    sc_core::sc_event m_arbitrate;
    std::map<sc_core::sc_time, sc_core::sc_time> m_reserved;  // loosely timed: booked slots, start -> end
    sc_core::sc_time m_busy = sc_core::SC_ZERO_TIME;
    uint64_t m_packet_transfers = 0, m_object_reads = 0;
    double m_packet_bytes = 0, m_object_bytes = 0;
    GrantStats m_all;
    std::vector<GrantStats> m_per;
    GrantObserver *m_observer = nullptr;
};

}  // namespace torusrt
