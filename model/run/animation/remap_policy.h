// remap_policy.h - the mapping across the frames of an animation (--remap): which owner table
// each frame runs under, and why.
//   static      the first frame's mapping (the run's --map) for every frame;
//   every-frame before each frame, SCOTCH_graphRemap from the previous frame's per-cell work
//               and face traffic, the old table as the old partition, and each cell's move
//               cost (one hop of its bytes, see migration.h) against keeping it;
//   adaptive    without a preview (--remap-pilot 0, the default): a SCOTCH_graphRemap as
//               every-frame's, but of a guess of frame k's load, taken only when its predicted
//               gain in image time exceeds its migration time; the gain is
//               T x (1 - W(C) / W(current)) with T frame k-1's image time and W below in the
//               guessed load. The guesses, from what earlier frames measured and the camera
//               path: frame k-1's load (`frame`), the trend max(0, 2 x frame k-1 - frame k-2)
//               (`trend`), frame k-1's load moved with the camera from pose k-1 to pose k
//               (`moved`: its rays move, each cell's work per ray stays, load_motion.h), and
//               on a moving scene, frame k-1's load with each moved object's work carried
//               into its frame-k cells (`objects`: the host knows where the objects will be,
//               object_work_carry.h), and each of them blurred (`-blurred`: a quarter of a
//               cell's work stays, the rest goes to its face neighbours). Before each frame every guess gives a table
//               (a remap from the table in force); once the frame has run, each of those tables is scored by W in the
//               frame's measured load, as a ratio to the least W among them. The guess taken is the one with the least
//               mean ratio over the last
//               --remap-window frames scored (the first in that order on a tie; `frame` for
//               frame 1, before anything is scored; the trend is made from frame 2 on and scored
//               from frame 3 on), unless `frame`'s mean ratio is at most 1 + --remap-margin
//               times that least one: then `frame`.
//               With a preview (--remap-pilot FRACTION > 0): the camera path is known in
//               advance, so the host pilots frame k at FRACTION of the pixels (same view) while
//               the machine renders frame k-1; that preview, scaled to the full pixel count,
//               judges the candidate tables for frame k - keep frame k-1's, and
//               SCOTCH_graphRemap from it of frame k-1's load, of the trend above and of the
//               mean of frames k-1 and k-2 - by predicted image time plus migration time; the
//               least is taken (keep on a tie). The candidates are fitted to measured loads and
//               judged on the preview, so the preview's sampling noise does not favour the one
//               fitted to it;
//   oracle      each frame mapped from its own pilot (SCOTCH_graphMap, as --map cost), its
//               migration free: the bound.
// The preview's predictor: with W(M) the mean work of the busiest tenth of the nodes (at least one)
// under table M in the preview's load, frame k under M is predicted to take a x W(M), where
// a = T / W'(M') is frame k-1's measured image time T over its own measured W' under its table
// M'. The busiest tenth rather than the single busiest node: one hot cell can bound the busiest
// node under every table while the rest of the load still sets the time.
// The host's pilot is charged: its modelled time (the preview's operations under the timing
// table, as T(1) is counted, on one processor) overlaps frame k-1's image time, and only the part
// that exceeds it delays frame k (host_pilot_charged_s, added to the animation's total).
// Per-cell work and face traffic do not depend on the mapping, so each frame's pilot (the same
// packet step with every cell its own owner) gives what the machine measured in that frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "guess_scoreboard.h"
#include "migration.h"
#include "object_work_carry.h"
#include "rt_camera_path.h"
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
    // by_object: also each object's work (rt_cost_pilot_run_by_object), for carried().
    FramePilot(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, bool by_object = false);
    // The host's preview: the scene's camera at `fraction` of the pixels (each side scaled by
    // its square root, at least one pixel), its work and traffic scaled to the full pixel count.
    FramePilot(const SimConfig &config, rt_scene *scene, const rt_grid *grid, double fraction);
    // Cell by cell max(0, wa x a + wb x b) of two loads, work and traffic.
    static std::unique_ptr<FramePilot> combined(const FramePilot &a, const FramePilot &b, double wa, double wb);
    // The next frame's load extrapolated from the last two: 2 x last - before.
    static std::unique_ptr<FramePilot> extrapolated(const FramePilot &last, const FramePilot &before)
    {
        return combined(last, before, 2, -1);
    }
    // The mean of two frames' loads (a table fitted to both views).
    static std::unique_ptr<FramePilot> mean(const FramePilot &a, const FramePilot &b)
    {
        return combined(a, b, 0.5, 0.5);
    }
    // The load blurred: `keep` of each cell's work stays, the rest is shared by its face
    // neighbours (load_motion.h's blur_load); traffic unchanged.
    static std::unique_ptr<FramePilot> blurred(const FramePilot &load, double keep);
    // The load moved with the camera from pose a to pose b: the rays move, each cell's cost per
    // ray stays (load_motion.h's move_visits; occupied = the cell lists anything).
    static std::unique_ptr<FramePilot> moved(const FramePilot &load, const rt_grid *grid, const rt_camera_pose &a,
                                             const rt_camera_pose &b);
    // The load with the moved objects' work carried into `next`'s cells (object_work_carry.h);
    // `load` counted by object.
    static std::unique_ptr<FramePilot> carried(const FramePilot &load, const rt_grid *next, const ObjectShifts &shifts);
    ~FramePilot() { rt_cost_pilot_release(&m_pilot); }
    FramePilot(const FramePilot &) = delete;
    FramePilot &operator=(const FramePilot &) = delete;
    const rt_cost_pilot &get() const { return m_pilot; }
    double work_s() const { return m_pilot.total_us * 1e-6; }  // T(1) of the frame
    // The mean work of the busiest tenth of the nodes (at least one) under `owner`, seconds.
    double busiest_work_s(const std::vector<int32_t> &owner, int nodes) const;
    double wall_s() const { return m_wall_s; }
    double host_s() const { return m_host_s; }  // modelled host time of the run (unscaled)
    uint64_t pixels() const { return m_pixels; }

  private:
    FramePilot() = default;
    static std::unique_ptr<FramePilot> blank_like(const FramePilot &x);  // same size, arrays allocated
    void run(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, bool by_object = false);
    rt_cost_pilot m_pilot{};
    double m_wall_s = 0, m_host_s = 0;
    uint64_t m_pixels = 0;
};

struct RemapDecision {
    std::vector<int32_t> owner;     // the table for the frame
    std::string decision = "keep";  // "first", "keep" or "remap"
    std::string reason;
    double predicted_gain_s = 0;    // adaptive only: predicted time of keeping minus the choice's
    MigrationCost migration;        // from the previous table to `owner`
    bool migration_charged = true;  // false for oracle
    double mapper_wall_s = 0;
};

struct RemapContext {
    const SimConfig &config;
    const rt_scene *scene;
    const rt_grid *grid;
    const Routing &routing;
};

// --remap-pilot's default (chosen by the animation study, docs/animation.md).
constexpr double default_remap_pilot = 0;

// --remap-window's default: adaptive judges its guesses over this many past frames (chosen by
// the animation study, docs/animation.md).
constexpr size_t default_remap_window = 1;
constexpr size_t max_remap_window = 1000000;

// --remap-margin's default: another guess replaces `frame` when its back-test is better at all
// (0). A margin such as 0.03 suits long animations that turn little per frame, where one frame's
// back-test is mostly noise, and costs up to 3 % at 11 degrees a frame (docs/animation.md).
constexpr double default_remap_margin = 0;

// Adaptive's settings (--remap-pilot, --remap-window, --remap-margin).
struct AdaptiveSettings {
    double pilot_fraction = default_remap_pilot;
    size_t window = default_remap_window;
    double margin = default_remap_margin;
};

// What Remapper::decide sees of frames k-1 and k.
struct FrameLoads {
    const FramePilot &previous;           // frame k-1's measured load
    double previous_time_s;               // frame k-1's measured image time
    const FramePilot &pilot;              // frame k's own full pilot (oracle only)
    const FramePilot *before;             // frame k-2's measured load (null for k = 1)
    const FramePilot *preview;            // frame k's host preview (adaptive only)
    const rt_camera_pose *pose_previous;  // frame k-1's camera
    const rt_camera_pose *pose_next;      // frame k's camera (known in advance)
    const ObjectShifts *shifts =
        nullptr;  // a moving scene: what moved from frame k-1 to k (previous counted by object)
};

// A policy across the frames of one animation, with what adaptive remembers from frame to frame
// (the tables its guesses gave and how they scored).
class Remapper {
  public:
    Remapper(RemapPolicy policy, size_t window, double margin);
    // The table for frame k > 0; `current` is frame k-1's table. Called once per frame, in order.
    RemapDecision decide(const RemapContext &ctx, const std::vector<int32_t> &current, const FrameLoads &loads);

  private:
    void guess_choice(const RemapContext &ctx, const std::vector<int32_t> &current, const FrameLoads &loads,
                      RemapDecision &d);
    RemapPolicy m_policy;
    GuessScoreboard m_board;
    std::vector<std::vector<int32_t>> m_proposed;  // each guess's table for the frame last decided (empty: none)
};

// Oracle's table for a frame from its own pilot (also frame 0's under oracle).
std::vector<int32_t> oracle_mapping(const RemapContext &ctx, const FramePilot &pilot);

}  // namespace torusrt
