// animation_run.cpp - the frame loop: camera, mapping, migration, sc_start, per-frame figures.
#include "animation_run.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "elaboration_mark.h"
#include "kernel_handles.h"
#include "model_run.h"
#include "progress.h"
#include "torus_system.h"
#include "tracing.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

namespace {

void set_camera(rt_scene *scene, const rt_camera_path *path, size_t k)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_scene_set_camera(scene, rt_camera_path_pose(path, k), msg, sizeof msg) != RT_OK)
        throw UserError("frame " + std::to_string(k) + ": " + msg);
}

FramebufferPtr new_frame_buffer(const rt_scene *scene)
{
    const rt_camera *cam = rt_scene_camera(scene);
    FramebufferPtr fb(rt_framebuffer_new(cam->width, cam->height));
    if (!fb) throw UserError("out of memory for the frame buffer");
    return fb;
}

uint64_t created(const PacketLedger &ledger)
{
    return ledger.totals().created[0] + ledger.totals().created[1];
}

// Under LT a frame starts on a quantum boundary, so its quantum syncs fall as in a run alone.
sc_core::sc_time frame_start(const SimConfig &config, double earliest_s)
{
    sc_core::sc_time t = std::max(sc_core::sc_time(earliest_s, sc_core::SC_SEC), sc_core::sc_time_stamp());
    if (config.style != TimingStyle::lt || config.quantum_us <= 0) return t;
    sc_core::sc_time q(config.quantum_us, sc_core::SC_US);
    uint64_t steps = (t.value() + q.value() - 1) / q.value();
    return sc_core::sc_time::from_value(steps * q.value());
}

// The machine, elaborated once, and what goes with it across frames.
struct Machine {
    PacketLedger ledger;
    rt_budget memory;
    std::vector<int32_t> owner;  // the table every module reads; its contents change between frames
    FramebufferPtr fb;
    TorusSystem *top = nullptr;  // kept until the process exits (keep_until_exit)
    std::unique_ptr<Tracer> tracer;
    ElaborationMark *mark = nullptr;  // its time ends the elaboration, inside the first sc_start
    double elaboration_start_s = 0, elaboration_wall_s = 0, sim_wall_s = 0;
    bool started = false;
};

// T(1) of the animation: the sum of the frames' pilots.
double frames_t1(const std::vector<FrameRecord> &frames)
{
    double t1 = 0;
    for (const FrameRecord &f : frames) t1 += f.t1_s;
    return t1;
}

// The report's run facts: T(1) is the sum of the frames' pilots.
RunFacts animation_facts(const Machine &m, double t1_s, double wall_start_s)
{
    RunFacts facts;
    facts.t1_s = t1_s;
    facts.t1_source = "sum of the frames' pilots";
    facts.elaboration_wall_s = m.elaboration_wall_s;
    facts.sim_wall_s = m.sim_wall_s;
    facts.delta_cycles = sc_core::sc_delta_count();
    facts.wall_s = wall_clock_s() - wall_start_s;
    return facts;
}

// Runs the current frame to its end; false on a deadlock.
bool run_frame(const SimConfig &config, Machine &m, size_t k, size_t n)
{
    Progress progress("torusrt-sim frame " + std::to_string(k + 1) + "/" + std::to_string(n), config.quiet);
    m.ledger.set_progress(show_progress, &progress);
    double t0 = wall_clock_s();
    sc_core::sc_time limit(config.time_limit_s, sc_core::SC_SEC);
    sc_core::sc_time left = limit > sc_core::sc_time_stamp() ? limit - sc_core::sc_time_stamp() : sc_core::SC_ZERO_TIME;
    sc_core::sc_start(left, sc_core::SC_EXIT_ON_STARVATION);
    double t1 = wall_clock_s();
    if (!m.started) {  // the first sc_start also ended the elaboration
        t0 = m.mark->ended_at(t0);
        m.elaboration_wall_s = t0 - m.elaboration_start_s;
        m.started = true;
    }
    m.sim_wall_s += t1 - t0;
    progress.finish();
    m.ledger.set_progress(nullptr, nullptr);
    return run_finished(config, *m.top, m.ledger, m.memory);
}

// Frame k's mapping (k > 0) and its record's mapping fields; the owner table is updated.
void next_mapping(Remapper &remapper, const RemapContext &ctx, Machine &m, const FrameLoads &loads, FrameRecord &rec)
{
    RemapDecision d = remapper.decide(ctx, m.owner, loads);
    std::copy(d.owner.begin(), d.owner.end(), m.owner.begin()); // same storage: the modules' pointer stays
    rec.decision = d.decision;
    rec.reason = d.reason;
    rec.predicted_gain_s = d.predicted_gain_s;
    rec.migration = d.migration;
    rec.migration_charged = d.migration_charged;
    rec.mapper_wall_s = d.mapper_wall_s;
}

// Adaptive's host preview of frame k, made while frame k-1 ran for `previous_time_s`: only its
// modelled host time past that delays frame k.
std::unique_ptr<FramePilot> host_preview(const SimConfig &config, rt_scene *scene, const rt_grid *grid,
                                         double fraction, double previous_time_s, FrameRecord &rec)
{
    auto preview = std::make_unique<FramePilot>(config, scene, grid, fraction);
    rec.preview_pixels = preview->pixels();
    rec.host_pilot_s = preview->host_s();
    rec.host_pilot_charged_s = std::max(0.0, preview->host_s() - previous_time_s);
    rec.pilot_wall_s += preview->wall_s();
    return preview;
}

// Builds the machine on m's owner table and frame buffer, with its trace; SystemC completes the
// elaboration in the first sc_start.
void elaborate(const SimConfig &config, const rt_scene *scene, const rt_grid *grid, Machine &m)
{
    if (config.style == TimingStyle::lt)
        tlm::tlm_global_quantum::instance().set(sc_core::sc_time(config.quantum_us, sc_core::SC_US));
    m.elaboration_start_s = wall_clock_s();
    rt_replicas replicas = config.replica_table();
    m.top = &keep_until_exit(std::make_unique<TorusSystem>("top", config, scene, grid, m.owner.data(), m.ledger,
                                                           m.fb.get(), HandOverTiming::at_once,
                                                           config.replicated() ? &replicas : nullptr));
    if (!config.vcd_path.empty()) m.tracer = std::make_unique<Tracer>(config, *m.top);
    m.mark = &elaboration_mark();
    check_budget_before_start(m.ledger, m.memory);
}

// The policy and adaptive's settings as the report states them.
RemapSettings remap_settings(RemapPolicy policy, const AdaptiveSettings &a)
{
    return {remap_policy_name(policy), a.pilot_fraction, a.window, a.margin};
}

}  // namespace

AnimationOutcome run_animation(const SimConfig &config, rt_scene *scene, const rt_grid *grid,
                               const rt_camera_path *path, const std::vector<std::string> &files,
                               RemapPolicy policy, const AdaptiveSettings &adaptive, double wall_start_s)
{
    size_t n = rt_camera_path_count(path);
    Machine m;
    m.memory = config.memory;
    m.ledger.set_limit(rt_budget_packets_allowed(&m.memory, PacketPool::bytes_per_packet()));
    Routing routing(config.ips, config.topology == Topology::torus);
    RemapContext ctx{config, scene, grid, routing};
    set_camera(scene, path, 0);
    auto pilot = std::make_unique<FramePilot>(config, scene, grid);
    m.owner = policy == RemapPolicy::oracle ? oracle_mapping(ctx, *pilot) : owner_table_of(config, grid);
    warn_idle_nodes(config, m.owner);
    m.fb = new_frame_buffer(scene);
    elaborate(config, scene, grid, m);

    AnimationOutcome out;
    Remapper remapper(policy, adaptive.window, adaptive.margin);
    std::unique_ptr<FramePilot> previous, before, preview;
    double end_s = 0;
    for (size_t k = 0; k < n; k++) {
        FrameRecord rec;
        rec.index = k;
        rec.file = files[k];
        rec.camera = *rt_camera_path_pose(path, k);
        rec.processors = config.processor_count();
        rec.decision = "first";
        rec.reason = policy == RemapPolicy::oracle ? "oracle: this frame's own pilot" : "the run's --map";
        uint64_t created_before = created(m.ledger);
        sc_core::sc_time start = sc_core::SC_ZERO_TIME;
        if (k > 0) {
            set_camera(scene, path, k);
            before = std::move(previous);
            previous = std::move(pilot);
            pilot = std::make_unique<FramePilot>(config, scene, grid);
            double previous_time_s = out.frames.back().image_time_s;
            if (policy == RemapPolicy::adaptive && adaptive.pilot_fraction > 0)
                preview = host_preview(config, scene, grid, adaptive.pilot_fraction, previous_time_s, rec);
            next_mapping(remapper, ctx, m, FrameLoads{*previous, previous_time_s, *pilot, before.get(), preview.get(),
                                                    rt_camera_path_pose(path, k - 1), rt_camera_path_pose(path, k)}, rec);
            m.fb = new_frame_buffer(scene);
            start = frame_start(config, end_s + rec.charged_migration_s() + rec.host_pilot_charged_s);
            m.top->start_frame(m.fb.get(), m.owner.data(), start);
        }
        rec.start_s = start.to_seconds();
        rec.t1_s = pilot->work_s();
        rec.pilot_wall_s += pilot->wall_s();
        if (!run_frame(config, m, k, n)) {
            out.deadlock = true;
            out.report = collect(config, *m.top, m.ledger, scene, grid, m.owner.data(),
                                 animation_facts(m, 0, wall_start_s), true);
            out.report.frames = out.frames;  // the frames that completed
            out.report.remap = remap_settings(policy, adaptive);
            out.deadlock_details = "frame " + std::to_string(k) + ":\n" + deadlock_text(out.report);
            out.sim_time_s = out.report.sim_time_s;
            return out;
        }
        check_conservation(m.ledger);
        end_s = m.ledger.image_time().to_seconds();
        rec.image_time_s = (m.ledger.image_time() - start).to_seconds();
        rec.packets = created(m.ledger) - created_before;
        const rt_camera *cam = rt_scene_camera(scene);
        out.images.emplace_back(static_cast<size_t>(cam->width) * cam->height * 3);
        rt_framebuffer_to_rgb8(m.fb.get(), out.images.back().data());
        out.frames.push_back(rec);
    }
    out.report = collect(config, *m.top, m.ledger, scene, grid, m.owner.data(),
                         animation_facts(m, frames_t1(out.frames), wall_start_s), false);
    out.report.frames = out.frames;
    out.report.remap = remap_settings(policy, adaptive);
    if (m.tracer) m.tracer->finish();
    return out;
}

}  // namespace torusrt
