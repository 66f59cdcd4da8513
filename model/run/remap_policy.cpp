// remap_policy.cpp - the four policies of --remap.
#include "remap_policy.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <functional>

#include "user_error.h"

namespace torusrt {

namespace {

double now_s()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

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
    if (rt_cost_remap(&p, ctx.config.ips.data(), ctx.config.topology == Topology::torus,
                      rt_cost_edge_us(&ctx.config.timing), current.data(), move_us.data(), owner.data(), nullptr, msg,
                      sizeof msg) != RT_OK)
        throw UserError(std::string("--remap: ") + msg);
    return owner;
}

}  // namespace

namespace {

// Adaptive: the every-frame remapping, taken only if its predicted gain exceeds its migration.
void adaptive_choice(const RemapContext &ctx, const std::vector<int32_t> &current, const FramePilot &previous,
                     double previous_time_s, RemapDecision &d)
{
    int nodes = ctx.config.node_count();
    std::vector<int32_t> candidate = remapped(ctx, current, previous);
    double w_now = previous.busiest_work_s(current, nodes);
    double w_new = previous.busiest_work_s(candidate, nodes);
    double move = migration_cost(ctx.scene, ctx.grid, ctx.routing, nodes, ctx.config.timing, current, candidate).time_s;
    d.predicted_gain_s = w_now > 0 ? previous_time_s * (1 - w_new / w_now) : 0;
    bool take = d.predicted_gain_s > move;
    d.owner = take ? std::move(candidate) : current;
    d.decision = take ? "remap" : "keep";
    d.reason = "adaptive: predicted gain " + seconds_text(d.predicted_gain_s) + (take ? " > " : " <= ") +
               "migration " + seconds_text(move);
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

FramePilot::FramePilot(const SimConfig &config, const rt_scene *scene, const rt_grid *grid)
{
    double t0 = now_s();
    char msg[RT_MSG_LEN] = "";
    if (rt_cost_pilot_run(scene, grid, &config.step, &config.timing, &m_pilot, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("frame pilot run: ") + msg);
    m_wall_s = now_s() - t0;
}

FramePilot::FramePilot(const FramePilot &last, const FramePilot &before)
{
    const rt_cost_pilot &a = last.m_pilot, &b = before.m_pilot;
    m_pilot = a;
    m_pilot.work_us = static_cast<double *>(std::malloc(a.cells * sizeof(double)));
    m_pilot.traffic = static_cast<uint64_t *>(std::malloc(a.cells * RT_CELL_FACES * sizeof(uint64_t)));
    if (!m_pilot.work_us || !m_pilot.traffic) {
        rt_cost_pilot_release(&m_pilot);
        throw std::bad_alloc();
    }
    m_pilot.total_us = 0;
    for (size_t c = 0; c < a.cells; c++) {
        m_pilot.work_us[c] = std::max(0.0, 2 * a.work_us[c] - b.work_us[c]);
        m_pilot.total_us += m_pilot.work_us[c];
    }
    for (size_t i = 0; i < a.cells * RT_CELL_FACES; i++)
        m_pilot.traffic[i] = 2 * a.traffic[i] > b.traffic[i] ? 2 * a.traffic[i] - b.traffic[i] : 0;
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

std::vector<int32_t> oracle_mapping(const RemapContext &ctx, const FramePilot &pilot)
{
    std::vector<int32_t> owner(pilot.get().cells);
    char msg[RT_MSG_LEN] = "";
    int fold = ctx.config.mapping == RT_MAP_COST ? ctx.config.block : 1;
    if (rt_cost_map_folded(&pilot.get(), ctx.config.ips.data(), ctx.config.topology == Topology::torus,
                           rt_cost_edge_us(&ctx.config.timing), fold, owner.data(), nullptr, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--remap oracle: ") + msg);
    return owner;
}

RemapDecision decide_mapping(RemapPolicy policy, const RemapContext &ctx, const std::vector<int32_t> &current,
                             const FramePilot &previous, double previous_time_s, const FramePilot *before,
                             const FramePilot &pilot)
{
    RemapDecision d;
    int nodes = ctx.config.node_count();
    double t0 = now_s();
    if (policy == RemapPolicy::static_map) {
        d.owner = current;
        d.reason = "static: the first frame's mapping";
    } else if (policy == RemapPolicy::oracle) {
        d.owner = oracle_mapping(ctx, pilot);
        d.decision = "remap";
        d.reason = "oracle: this frame's own pilot, migration free";
        d.migration_charged = false;
    } else if (policy == RemapPolicy::every_frame) {
        d.owner = remapped(ctx, current, previous);
        d.decision = "remap";
        d.reason = "every-frame: remapped from the previous frame's work";
    } else {
        if (before) adaptive_choice(ctx, current, FramePilot(previous, *before), previous_time_s, d);
        else adaptive_choice(ctx, current, previous, previous_time_s, d);
    }
    d.mapper_wall_s = now_s() - t0;
    d.migration = migration_cost(ctx.scene, ctx.grid, ctx.routing, nodes, ctx.config.timing, current, d.owner);
    return d;
}

}  // namespace torusrt
