// remap_policy.cpp - the four policies of --remap.
#include "remap_policy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <stdexcept>

#include "load_motion.h"
#include "mapping.h"
#include "run_stage.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

namespace {

std::string seconds_text(double s)
{
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6f s", s);
    return buf;
}

std::vector<int32_t> remapped(const RemapContext &ctx, const std::vector<int32_t> &current, const FramePilot &from)
{
    const rt_cost_pilot &p = from.get();
    std::vector<double> move_us(p.cells);
    for (size_t c = 0; c < p.cells; c++)
        move_us[c] = link_transfer_us(ctx.config.timing, cell_move_bytes(ctx.scene, ctx.grid, c));
    std::vector<int32_t> owner(p.cells);
    char msg[RT_MSG_LEN] = "";
    const rt_topology topo = ctx.config.network();
    if (rt_cost_remap(&p, &topo, rt_cost_edge_us(&ctx.config.timing), current.data(), move_us.data(), owner.data(),
                      nullptr, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--remap: ") + msg);
    return owner;
}

}  // namespace

namespace {

std::vector<int32_t> fresh_map(const RemapContext &ctx, const FramePilot &pilot)
{
    std::vector<int32_t> owner(pilot.get().cells);
    char msg[RT_MSG_LEN] = "";
    int fold = mapping_of(ctx.config).remap_fold(ctx.config);
    const rt_topology topo = ctx.config.network();
    if (rt_cost_map_folded(&pilot.get(), &topo, rt_cost_edge_us(&ctx.config.timing), fold, owner.data(), nullptr, msg,
                           sizeof msg) != RT_OK)
        throw UserError(std::string("--remap: ") + msg);
    return owner;
}

struct Candidate {
    const char *name;
    std::vector<int32_t> owner;
};

// Adaptive's guesses of frame j's load from what frames j-1 (and j-2) measured, each also blurred.
enum class Guess { last, trend, moved, objects };
struct GuessKind {
    Guess guess;
    bool blurred;
    const char *name;
};
const GuessKind guesses[] = {{Guess::last, false, "frame"},         {Guess::trend, false, "trend"},
                             {Guess::moved, false, "moved"},        {Guess::last, true, "frame-blurred"},
                             {Guess::trend, true, "trend-blurred"}, {Guess::moved, true, "moved-blurred"},
                             {Guess::objects, false, "objects"},    {Guess::objects, true, "objects-blurred"}};
constexpr double blur_keep =
    0.25;  // a blurred guess keeps this share of a cell's work, the rest goes to its face neighbours

// Frame j's load guessed from frame j-1's (`last`) and j-2's (`before`, the trend only), the
// camera going from pose a (frame j-1) to pose b (frame j), the objects by `shifts` (`objects` only).
std::unique_ptr<FramePilot> guessed_load(const RemapContext &ctx, const GuessKind &g, const FrameLoads &loads)
{
    const FramePilot &last = loads.previous;
    std::unique_ptr<FramePilot> p = g.guess == Guess::trend ? FramePilot::extrapolated(last, *loads.before)
                                    : g.guess == Guess::moved
                                        ? FramePilot::moved(last, ctx.grid, *loads.pose_previous, *loads.pose_next)
                                    : g.guess == Guess::objects ? FramePilot::carried(last, ctx.grid, *loads.shifts)
                                                                : FramePilot::combined(last, last, 1, 0);
    return g.blurred ? FramePilot::blurred(*p, blur_keep) : std::move(p);
}

}  // namespace

// Adaptive without a preview: first the tables proposed for frame k-1 are scored on its measured
// load; then every guess of frame k's load gives a table (a remap from frame k-1's), and the
// scoreboard's best guess is taken if its predicted gain exceeds its migration.
void Remapper::guess_choice(const RemapContext &ctx, const std::vector<int32_t> &current, const FrameLoads &loads,
                            RemapDecision &d)
{
    int nodes = ctx.config.node_count();
    constexpr size_t n = sizeof guesses / sizeof guesses[0];
    if (!m_proposed.empty()) {
        std::vector<double> scores(n, -1);
        for (size_t g = 0; g < n; g++)
            if (!m_proposed[g].empty()) scores[g] = loads.previous.busiest_work_s(m_proposed[g], nodes);
        m_board.record(scores);
    }
    size_t pick = m_board.best();
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const GuessKind &g : guesses) v.emplace_back(g.name);
        return v;
    }();
    std::string tested = m_board.text(names);
    m_proposed.assign(n, {});
    std::unique_ptr<FramePilot> predicted;
    for (size_t g = 0; g < n; g++) {
        if (guesses[g].guess == Guess::trend && !loads.before) continue;
        if (guesses[g].guess == Guess::objects && !loads.shifts) continue;
        auto p = guessed_load(ctx, guesses[g], loads);
        m_proposed[g] = remapped(ctx, current, *p);
        if (g == pick) predicted = std::move(p);
    }
    // The guess picked was scored, so it was made before, and what made it (frame k-2 for the trend) is still here.
    if (!predicted) throw std::logic_error("adaptive: the guess picked gave no table");
    const GuessKind &g = guesses[pick];
    std::vector<int32_t> candidate = m_proposed[pick];
    double w_now = predicted->busiest_work_s(current, nodes);
    double w_new = predicted->busiest_work_s(candidate, nodes);
    double move = migration_cost(ctx.scene, ctx.grid, ctx.routing, nodes, ctx.config.timing, current, candidate).time_s;
    d.predicted_gain_s = w_now > 0 ? loads.previous_time_s * (1 - w_new / w_now) : 0;
    bool take = d.predicted_gain_s > move;
    d.owner = take ? std::move(candidate) : current;
    d.decision = take ? "remap" : "keep";
    size_t scored = m_board.frames();
    d.reason = std::string("adaptive: guess ") + g.name +
               (tested.empty() ? ""
                               : " (back-tested on " + std::to_string(scored) + (scored == 1 ? " frame" : " frames") +
                                     ", mean ratio to the best table: " + tested + ")") +
               ", predicted gain " + seconds_text(d.predicted_gain_s) + (take ? " > " : " <= ") + "migration " +
               seconds_text(move);
}

namespace {

// Adaptive with a preview: the candidate with the least predicted image time plus migration (keep on a tie).
void adaptive_choice(const RemapContext &ctx, const std::vector<int32_t> &current, const FrameLoads &loads,
                     RemapDecision &d)
{
    int nodes = ctx.config.node_count();
    const FramePilot &preview = *loads.preview;
    std::vector<Candidate> candidates;
    candidates.push_back({"keep", current});
    candidates.push_back({"remap of frame k-1", remapped(ctx, current, loads.previous)});
    if (loads.before) {
        candidates.push_back(
            {"remap of the trend", remapped(ctx, current, *FramePilot::extrapolated(loads.previous, *loads.before))});
        candidates.push_back(
            {"remap of frames k-1 and k-2", remapped(ctx, current, *FramePilot::mean(loads.previous, *loads.before))});
    }
    double w_prev = loads.previous.busiest_work_s(current, nodes);
    double a = w_prev > 0 ? loads.previous_time_s / w_prev : 0;
    double keep_s = a * preview.busiest_work_s(current, nodes);
    size_t best = 0;
    double best_s = keep_s, best_move = 0;
    for (size_t i = 1; i < candidates.size(); i++) {
        double move =
            migration_cost(ctx.scene, ctx.grid, ctx.routing, nodes, ctx.config.timing, current, candidates[i].owner)
                .time_s;
        double t = a * preview.busiest_work_s(candidates[i].owner, nodes) + move;
        if (t < best_s) best = i, best_s = t, best_move = move;
    }
    d.predicted_gain_s = keep_s - (best_s - best_move);
    d.decision = best == 0 ? "keep" : "remap";
    d.reason = std::string("adaptive: ") + candidates[best].name + ", predicted " + seconds_text(best_s) + " (keep " +
               seconds_text(keep_s) + "), migration " + seconds_text(best_move);
    d.owner = std::move(candidates[best].owner);
}

}  // namespace

RemapPolicy parse_remap_policy(const std::string &text)
{
    if (text == "static") return RemapPolicy::static_map;
    if (text == "every-frame") return RemapPolicy::every_frame;
    if (text == "adaptive") return RemapPolicy::adaptive;
    if (text == "oracle") return RemapPolicy::oracle;
    throw UserError("--remap '" + text + "': expected static, every-frame, adaptive or oracle", 2);
}

const char *remap_policy_name(RemapPolicy policy)
{
    switch (policy) {
    case RemapPolicy::static_map: return "static";
    case RemapPolicy::every_frame: return "every-frame";
    case RemapPolicy::adaptive: return "adaptive";
    case RemapPolicy::oracle: return "oracle";
    }
    return "?";
}

void FramePilot::run(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, bool by_object)
{
    double t0 = wall_clock_s();
    char msg[RT_MSG_LEN] = "";
    auto pilot_run = by_object ? rt_cost_pilot_run_by_object : rt_cost_pilot_run;
    rt_status st = pilot_run(scene, grid, &config.step, &config.timing, &m_pilot, msg, sizeof msg);
    if (st == RT_ERR_NOMEM) {  // cli_main's message: the stage and --memory-budget
        set_run_stage("running a frame's pilot (--remap)");
        throw std::bad_alloc();
    }
    if (st != RT_OK) throw UserError(std::string("frame pilot run: ") + msg);
    m_wall_s = wall_clock_s() - t0;
    m_host_s = m_pilot.total_us * 1e-6;
    const rt_camera *cam = rt_scene_camera(scene);
    m_pixels = static_cast<uint64_t>(cam->width) * cam->height;
}

FramePilot::FramePilot(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, bool by_object)
{
    run(config, scene, grid, by_object);
}

FramePilot::FramePilot(const SimConfig &config, rt_scene *scene, const rt_grid *grid, double fraction)
{
    const rt_camera full = *rt_scene_camera(scene);
    double side = std::sqrt(fraction);
    auto scaled = [side](uint32_t n) { return std::max<uint32_t>(1, static_cast<uint32_t>(n * side)); };
    if (rt_scene_set_resolution(scene, scaled(full.width), scaled(full.height)) != RT_OK)
        throw UserError("--remap-pilot: cannot set the preview's resolution");
    try {
        run(config, scene, grid);
    } catch (...) {
        rt_scene_set_resolution(scene, full.width, full.height);
        throw;
    }
    rt_scene_set_resolution(scene, full.width, full.height);
    double scale = static_cast<double>(full.width) * full.height / static_cast<double>(m_pixels);
    m_pilot.total_us *= scale;
    for (size_t c = 0; c < m_pilot.cells; c++) m_pilot.work_us[c] *= scale;
    for (size_t i = 0; i < m_pilot.cells * RT_CELL_FACES; i++)
        m_pilot.traffic[i] = static_cast<uint64_t>(std::llround(static_cast<double>(m_pilot.traffic[i]) * scale));
}

std::unique_ptr<FramePilot> FramePilot::blank_like(const FramePilot &x)
{
    std::unique_ptr<FramePilot> s(new FramePilot());
    s->m_pilot = x.m_pilot;
    s->m_pilot.object_us = nullptr;  // x's per-object work stays x's
    s->m_pilot.object_us_count = 0;
    s->m_pilot.work_us = static_cast<double *>(std::malloc(x.m_pilot.cells * sizeof(double)));
    s->m_pilot.traffic = static_cast<uint64_t *>(std::malloc(x.m_pilot.cells * RT_CELL_FACES * sizeof(uint64_t)));
    if (!s->m_pilot.work_us || !s->m_pilot.traffic) throw std::bad_alloc();  // the destructor frees
    return s;
}

std::unique_ptr<FramePilot> FramePilot::moved(const FramePilot &load, const rt_grid *grid, const rt_camera_pose &a,
                                              const rt_camera_pose &b)
{
    std::unique_ptr<FramePilot> s = blank_like(load);
    std::vector<char> occupied(load.m_pilot.cells);
    for (size_t c = 0; c < occupied.size(); c++) {
        size_t n = 0;
        rt_grid_cell_objects(grid, c, &n);
        occupied[c] = n > 0;
    }
    move_visits(load.m_pilot, rt_grid_bounds(grid), camera_motion(a, b), occupied, s->m_pilot);
    return s;
}

std::unique_ptr<FramePilot> FramePilot::carried(const FramePilot &load, const rt_grid *next, const ObjectShifts &shifts)
{
    std::unique_ptr<FramePilot> s = blank_like(load);
    carry_object_work(load.m_pilot, next, shifts, s->m_pilot);
    return s;
}

std::unique_ptr<FramePilot> FramePilot::blurred(const FramePilot &load, double keep)
{
    std::unique_ptr<FramePilot> s = blank_like(load);
    blur_load(load.m_pilot, keep, s->m_pilot);
    return s;
}

std::unique_ptr<FramePilot> FramePilot::combined(const FramePilot &x, const FramePilot &y, double wx, double wy)
{
    std::unique_ptr<FramePilot> s = blank_like(x);
    const rt_cost_pilot &a = x.m_pilot, &b = y.m_pilot;
    s->m_pilot.total_us = 0;
    for (size_t c = 0; c < a.cells; c++) {
        s->m_pilot.work_us[c] = std::max(0.0, wx * a.work_us[c] + wy * b.work_us[c]);
        s->m_pilot.total_us += s->m_pilot.work_us[c];
    }
    for (size_t i = 0; i < a.cells * RT_CELL_FACES; i++)
        s->m_pilot.traffic[i] = static_cast<uint64_t>(std::llround(
            std::max(0.0, wx * static_cast<double>(a.traffic[i]) + wy * static_cast<double>(b.traffic[i]))));
    return s;
}

double FramePilot::busiest_work_s(const std::vector<int32_t> &owner, int nodes) const
{
    std::vector<double> work(static_cast<size_t>(nodes), 0.0);
    for (size_t c = 0; c < m_pilot.cells; c++) work[static_cast<size_t>(owner[c])] += m_pilot.work_us[c];
    size_t top = std::max<size_t>(1, work.size() / 10);
    std::partial_sort(work.begin(), work.begin() + static_cast<long>(top), work.end(), std::greater<double>());
    double sum = 0;
    for (size_t i = 0; i < top; i++) sum += work[i];
    return sum / static_cast<double>(top) * 1e-6;
}

std::vector<int32_t> oracle_mapping(const RemapContext &ctx, const FramePilot &pilot) { return fresh_map(ctx, pilot); }

Remapper::Remapper(RemapPolicy policy, size_t window, double margin)
    : m_policy(policy), m_board(sizeof guesses / sizeof guesses[0], window, margin)
{
}

RemapDecision Remapper::decide(const RemapContext &ctx, const std::vector<int32_t> &current, const FrameLoads &loads)
{
    RemapDecision d;
    int nodes = ctx.config.node_count();
    double t0 = wall_clock_s();
    if (m_policy == RemapPolicy::static_map) {
        d.owner = current;
        d.reason = "static: the first frame's mapping";
    } else if (m_policy == RemapPolicy::oracle) {
        d.owner = oracle_mapping(ctx, loads.pilot);
        d.decision = "remap";
        d.reason = "oracle: this frame's own pilot, migration free";
        d.migration_charged = false;
    } else if (m_policy == RemapPolicy::every_frame) {
        d.owner = remapped(ctx, current, loads.previous);
        d.decision = "remap";
        d.reason = "every-frame: remapped from the previous frame's work";
    } else {
        if (loads.preview) adaptive_choice(ctx, current, loads, d);
        else guess_choice(ctx, current, loads, d);
    }
    d.mapper_wall_s = wall_clock_s() - t0;
    d.migration = migration_cost(ctx.scene, ctx.grid, ctx.routing, nodes, ctx.config.timing, current, d.owner);
    return d;
}

}  // namespace torusrt
