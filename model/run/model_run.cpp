// model_run.cpp - what every run shares: the owner table, the machine kept to the exit, the
// checks after sc_start, and T(1) in a child process.
#include "model_run.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <sys/wait.h>
#include <unistd.h>

#include "internal_check.h"
#include "packet_ledger.h"
#include "progress.h"
#include "rt_mapping.h"
#include "run_frames.h"
#include "run_report.h"
#include "run_stage.h"
#include "torus_system.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

// A node that owns no cell never does work: worth a word, since it lowers the efficiency.
void warn_idle_nodes(const SimConfig &config, const std::vector<int32_t> &owner)
{
    if (config.quiet) return;
    std::vector<bool> owns(static_cast<size_t>(config.node_count()), false);
    for (int32_t o : owner)
        if (o >= 0 && o < config.node_count()) owns[static_cast<size_t>(o)] = true;
    long idle = std::count(owns.begin(), owns.end(), false);
    if (idle > 0)
        std::fprintf(stderr,
                     "torusrt-sim: warning: %ld of %d nodes own no cells and stay idle (%zu cells for %d nodes)\n",
                     idle, config.node_count(), owner.size(), config.node_count());
}

bool run_finished(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger, rt_budget &memory)
{
    char msg[RT_MSG_LEN] = "";
    if (ledger.over_limit()) {
        rt_budget_packets_exceeded(&memory, ledger.outstanding_over_limit(), PacketPool::bytes_per_packet(), msg,
                                   sizeof msg);
        throw UserError(msg);  // the tracer's destructor removes the partial trace
    }
    bool finished = ledger.outstanding() == 0 && top.host().done_injecting();
    if ((!finished && sc_core::sc_pending_activity()) || ledger.image_time().to_seconds() > config.time_limit_s) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the simulated time passed the limit of %g s (--time-limit; at most %g s, "
                      "as SystemC's time holds about 1.8e7 s at 1 ps)",
                      config.time_limit_s, kMaxSimTimeS);
        throw UserError(text);
    }
    return finished;
}

void check_budget_before_start(const PacketLedger &ledger, rt_budget &memory, const std::string &where)
{
    if (!ledger.over_limit()) return;  // sc_stop was called outside sc_start: sc_start would fail (E546)
    char msg[RT_MSG_LEN] = "";
    rt_budget_packets_exceeded(&memory, ledger.outstanding_over_limit(), PacketPool::bytes_per_packet(), msg,
                               sizeof msg);
    throw UserError(where + msg);
}

void check_conservation(const PacketLedger &ledger)
{
    const rt_packet_totals &t = ledger.totals();
    TORUSRT_CHECK(ledger.conserved(), "packets created " + std::to_string(t.created[0] + t.created[1]) + ", consumed " +
                                          std::to_string(t.consumed[0] + t.consumed[1]));
}

std::vector<int32_t> owner_table_of(const SimConfig &config, const rt_grid *grid)
{
    int dims[3];
    rt_grid_dims(grid, dims);
    std::vector<int32_t> owner = config.owner_table;
    char msg[RT_MSG_LEN] = "";
    if (owner.empty()) {
        owner.resize(rt_grid_cell_count(grid));
        if (rt_mapping_fill(dims, config.ips.data(), config.mapping, config.block, owner.data(), msg, sizeof msg) !=
            RT_OK)
            throw UserError(std::string("--map: ") + msg, 2);
        place_on_nodes(config.network(), owner);
    }
    return owner;
}

void show_progress(void *ctx, uint64_t consumed, int64_t outstanding)
{
    auto *p = static_cast<Progress *>(ctx);
    // The total is not known in advance: show consumed against consumed + outstanding.
    p->update(consumed, consumed + static_cast<uint64_t>(outstanding > 0 ? outstanding : 0),
              sc_core::sc_time_stamp().to_seconds());
}

TorusSystem &keep_until_exit(std::unique_ptr<TorusSystem> machine)
{
    // Never destroyed, so the list and the machines stay reachable to the end.
    static auto *kept = new std::vector<TorusSystem *>;
    kept->push_back(machine.release());
    return *kept->back();
}

ModelOutcome run_model(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, double t1_s,
                       const std::string &t1_source, double wall_start_s)
{
    FramePlan plan;
    plan.t1_s = t1_s;
    plan.t1_source = t1_source;
    // A single frame under the scene's own camera leaves the scene as it is.
    RunOutcome run = run_frames(config, const_cast<rt_scene *>(scene), grid, plan, wall_start_s);
    ModelOutcome out;
    out.deadlock = run.deadlock;
    out.deadlock_details = std::move(run.deadlock_details);
    out.sim_time_s = run.sim_time_s;
    if (!run.images.empty()) out.rgb8 = std::move(run.images.front());
    out.report = std::move(run.report);
    return out;
}

void print_summary_stdout(const RunReport &report) { print_summary(report, stdout); }

// The T(1) run's exit status when memory ran out: the parent gives the run's out-of-memory message.
constexpr int kT1OutOfMemory = 4;

double one_processor_time(const SimConfig &config, const rt_scene *scene, const rt_grid *grid)
{
    SimConfig one = config;
    one.ips = {1, 1, 1};
    one.cluster = 1;
    one.mapping = RT_MAP_BLOCK;  // one node owns every cell, whatever the mapping
    one.owner_table.clear();
    one.replica_first.clear();
    one.replica_extra.clear();
    one.replicate = 0;
    one.vcd_path.clear();
    one.trace_ips.clear();
    one.stats_interval_s = 0;  // the parent writes the series
    one.quiet = true;
    one.style = TimingStyle::at;
    one.quantum_us = 0;
    one.queue_capacity = 0;  // T(1) is the unconstrained sequential time
    int fds[2];
    if (pipe(fds) != 0) throw UserError("cannot create a pipe for the T(1) run");
    std::fflush(nullptr);
    pid_t pid = fork();
    if (pid < 0) throw UserError("cannot fork the T(1) run");
    if (pid == 0) {
        close(fds[0]);
        int code = 0;
        try {
            ModelOutcome o = run_model(one, scene, grid, -1, "", wall_clock_s());
            if (o.deadlock) code = 3;
            else dprintf(fds[1], "%.17g\n", o.sim_time_s);
        } catch (const std::bad_alloc &) {
            code = kT1OutOfMemory;  // said by the parent, as every run's out-of-memory message
        } catch (const std::exception &e) {
            std::fprintf(stderr, "torusrt-sim: T(1) run: %s\n", e.what());
            code = 1;
        }
        close(fds[1]);
        std::fflush(nullptr);
        _exit(code);
    }
    close(fds[1]);
    char buf[64] = "";
    ssize_t n = read(fds[0], buf, sizeof buf - 1);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == kT1OutOfMemory) {
        set_run_stage("simulating the one-processor run for T(1)");
        throw std::bad_alloc();  // cli_main's out-of-memory message
    }
    if (n <= 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw UserError("the one-processor run for T(1) failed");
    return std::strtod(buf, nullptr);
}

}  // namespace torusrt
