// remap_policy.h - the mapping across the frames of an animation (--remap): which owner table
// each frame runs under, and why.
//   static      the first frame's mapping (the run's --map) for every frame;
//   every-frame before each frame, SCOTCH_graphRemap from the previous frame's per-cell work
//               and face traffic, the old table as the old partition, and each cell's move
//               cost (one hop of its bytes, see migration.h) against keeping it;
//   adaptive    a SCOTCH_graphRemap as every-frame's, but of the load extrapolated from the
//               last two frames (per cell max(0, 2 x frame k-1 - frame k-2); frame 0's alone
//               before frame 1), taken only when its predicted gain in image time exceeds its
//               migration time;
//   oracle      each frame mapped from its own pilot (SCOTCH_graphMap, as --map cost), its
//               migration free: the bound.
// Adaptive's predictor: with W(M) the mean work of the busiest tenth of the nodes (at least one)
// under table M in the extrapolated load, and T the previous frame's measured image time, frame
// k under M is predicted to take T x W(M) / W(current); the candidate C gains
// T x (1 - W(C) / W(current)) and is taken when that exceeds C's migration time (migration.h).
// The busiest tenth rather than the single busiest node: one hot cell can bound the busiest
// node under every table while the rest of the load still sets the time.
// Per-cell work and face traffic do not depend on the mapping, so each frame's pilot (the same
// packet step with every cell its own owner) gives what the machine measured in that frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "migration.h"
#include "rt_cost_map.h"
#include "sim_config.h"

namespace torusrt {

enum class RemapPolicy { static_map, every_frame, adaptive, oracle };

// "static", "every-frame", "adaptive" or "oracle"; UserError (exit 2) otherwise.
RemapPolicy parse_remap_policy(const std::string &text);
const char *remap_policy_name(RemapPolicy policy);

// A pilot run of the scene's current camera (released on destruction).
class FramePilot {
  public:
    FramePilot(const SimConfig &config, const rt_scene *scene, const rt_grid *grid);
    // The next frame's load extrapolated from the last two: per cell and face
    // max(0, 2 x last - before) (the load keeps moving as it did).
    FramePilot(const FramePilot &last, const FramePilot &before);
    ~FramePilot() { rt_cost_pilot_release(&m_pilot); }
    FramePilot(const FramePilot &) = delete;
    FramePilot &operator=(const FramePilot &) = delete;
    const rt_cost_pilot &get() const { return m_pilot; }
    double work_s() const { return m_pilot.total_us * 1e-6; } // T(1) of the frame
    // The mean work of the busiest tenth of the nodes (at least one) under `owner`, seconds.
    double busiest_work_s(const std::vector<int32_t> &owner, int nodes) const;
    double wall_s() const { return m_wall_s; }

  private:
    rt_cost_pilot m_pilot;
    double m_wall_s = 0;
};

struct RemapDecision {
    std::vector<int32_t> owner;      // the table for the frame
    std::string decision = "keep";   // "first", "keep" or "remap"
    std::string reason;
    double predicted_gain_s = 0;     // adaptive only
    MigrationCost migration;         // from the previous table to `owner`
    bool migration_charged = true;   // false for oracle
    double mapper_wall_s = 0;
};

struct RemapContext {
    const SimConfig &config;
    const rt_scene *scene;
    const rt_grid *grid;
    const Routing &routing;
};

// The table for frame k > 0: `current` is frame k-1's table, `previous` its pilot and
// `previous_time_s` its measured image time, `before` frame k-2's pilot (null for k = 1),
// `pilot` frame k's own pilot (oracle).
RemapDecision decide_mapping(RemapPolicy policy, const RemapContext &ctx, const std::vector<int32_t> &current,
                             const FramePilot &previous, double previous_time_s, const FramePilot *before,
                             const FramePilot &pilot);

// Oracle's table for a frame from its own pilot (also frame 0's under oracle).
std::vector<int32_t> oracle_mapping(const RemapContext &ctx, const FramePilot &pilot);

}  // namespace torusrt
