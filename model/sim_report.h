// sim_report.h - the one place that assembles a run's statistics (after sc_start), writes the
// JSON report and prints the human summary.
#pragma once

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "packet_ledger.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"
#include "torus_system.h"

namespace torusrt {

struct RunFacts {
    double t1_s = 0;          // T(1): the same model with one processor
    std::string t1_source;    // "passed", "one-processor run", "this run"
    double wall_s = 0;        // wall-clock seconds of the whole run
    double sim_wall_s = 0;    // wall-clock seconds inside sc_start
    uint64_t delta_cycles = 0;
};

nlohmann::json build_report(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger,
                            const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                            const RunFacts &facts);

void print_summary(const nlohmann::json &report, std::FILE *out);

// Lists the queues that are full and the processes waiting on them (a stalled network).
std::string deadlock_report(TorusSystem &top);

}  // namespace torusrt
