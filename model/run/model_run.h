// model_run.h - elaborates and runs one model configuration and collects its results.
// SystemC elaborates once per process, so a second configuration (T(1)) runs in a child process.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernel_handles.h"
#include "packet_ledger.h"
#include "run_report.h"
#include "sim_config.h"
#include "torus_system.h"

namespace torusrt {

struct ModelOutcome {
    bool deadlock = false;         // the network stalled with packets outstanding
    std::string deadlock_details;  // which queues were full (deadlock_text)
    double sim_time_s = 0;         // simulated image time (deadlock: the time of the stall)
    std::vector<uint8_t> rgb8;     // final image (empty after a deadlock)
    RunReport report;              // the full statistics, also after a deadlock
};

// Runs `config` on a loaded scene as one frame of run_frames (run_frames.h): the image under the
// scene's camera. `t1_s` < 0 means "this run is T(1)" (one processor). A VCD trace, if asked
// for, is moved to its final name only when the run succeeds.
ModelOutcome run_model(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, double t1_s,
                       const std::string &t1_source, double wall_start_s);

// Pieces of every run (run_frames) and of the library's callers:
// the machine, kept until the process exits and never taken apart. SystemC elaborates one
// machine per process, and its registries remove every port, export, module and child object
// by a linear search, so destroying a machine object by object takes time quadratic in its
// size (0.85 s at 4096 nodes, more than that run's simulation); the exit frees it at once;
TorusSystem &keep_until_exit(std::unique_ptr<TorusSystem> machine);
// the owner table of config (config.owner_table, or the regular mapping filled in);
std::vector<int32_t> owner_table_of(const SimConfig &config, const rt_grid *grid);
// a warning for nodes that own no cell;
void warn_idle_nodes(const SimConfig &config, const std::vector<int32_t> &owner);
// the ledger's progress callback (ctx: a Progress);
void show_progress(void *ctx, uint64_t consumed, int64_t outstanding);
// after sc_start: UserError if the memory budget's packet limit or the time limit stopped the
// run; otherwise whether every packet was consumed (false: a deadlock);
bool run_finished(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger, rt_budget &memory);

// Throws the memory budget's UserError, `where` in front, when the packets made outside
// sc_start (while elaborating, or setting a frame up) already exceed it; sc_start is not called.
void check_budget_before_start(const PacketLedger &ledger, rt_budget &memory, const std::string &where);
// InternalError (a bug of the model) unless created = consumed.
void check_conservation(const PacketLedger &ledger);

// Prints the human summary of a report on stdout.
void print_summary_stdout(const RunReport &report);

// The settings of the one-processor run for T(1), by one rule: the machine's one-processor form
// (one_processor_machine: each machine option's `one_processor` text) doing the same work (the
// scene, its image size, the memory budget, the time limit) and every other run option at its
// default, so that it traces, writes and shows nothing.
SimConfig one_processor_config(const SimConfig &config);

// T(1) of `config`'s scene: the same model with one processor (and no cluster), run in a child
// process. Throws UserError if that run fails.
double one_processor_time(const SimConfig &config, const rt_scene *scene, const rt_grid *grid);

}  // namespace torusrt
