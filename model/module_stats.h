// module_stats.h - the plain statistics each module hands out after a run (its stats()), in
// seconds and counts. The run's report (run_report.h) is assembled from these alone.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rt_ops.h"

namespace torusrt {

// One bounded buffer (from the queue registry). Occupancy and high water count what the
// capacity counts (network packets; host primaries wait in the host).
struct QueueStats {
    std::string name;
    std::string kind;  // "ip", "dispatcher" or "link"
    int node = 0;
    uint64_t buffers_used = 0;     // class (and channel) buffers the run made; 1 under --flow none
    unsigned capacity = 0;         // 0 = unbounded
    uint64_t occupancy = 0;        // packets holding a slot at the end of the run, every class
    uint64_t high_water = 0;       // most slots one class (and channel) buffer held at once
    unsigned waiting_writers = 0;  // writers waiting for room at the end of the run
    double stalled_s = 0;          // simulated time with at least one writer waiting for room
};

struct IpStats {
    double busy_s = 0;
    // Idle time before the last hand-over: waiting with nothing to take up (starved), waiting for
    // room for a step's outputs or to hand them over (blocked); and when the last hand-over ended
    // (the rest of the image time is drained).
    double starved_s = 0, blocked_s = 0, last_done_s = 0;
    uint64_t packets_in = 0, packets_out = 0;
    uint64_t queue_high_water = 0;  // of the input queue, host primaries included
    rt_op_counts ops{};
};

struct LinkStats {
    int from = 0, to = 0, dir = 0;
    uint64_t packets = 0;
    double bytes = 0, busy_s = 0;
    uint64_t queue_high_water = 0;
};

struct CommUnitStats {
    uint64_t routed_local = 0, routed_transit = 0;
    uint64_t held = 0;  // packets held for room further on (at the end of the run)
};

struct HostStats {
    uint64_t injected = 0;  // primaries entering the object space
};

// Waits in SystemC time units (sc_time::value(), picoseconds), so sums stay exact.
struct GrantWait {
    uint64_t grants = 0;
    uint64_t wait_sum = 0, wait_max = 0;
};

struct BusStats {
    double busy_s = 0;
    uint64_t packet_transfers = 0, object_reads = 0;
    double packet_bytes = 0, object_bytes = 0;
    GrantWait all;
    std::vector<GrantWait> per_requester;  // processors 0..m-1, then the communication unit
    int waiting = 0;                       // requesters waiting for a grant at the end of the run
};

struct DispatcherStats {
    std::vector<uint64_t> dispatched;  // per processor of the node
    uint64_t inbox_high_water = 0;     // network packets (primaries come from the host on demand)
};

struct BusPortStats {
    uint64_t remote_reads = 0, local_reads = 0;
};

struct MemoryPortStats {
    uint64_t objects_held = 0, reads_served = 0;
};

}  // namespace torusrt
