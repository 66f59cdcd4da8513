// run_frames.cpp - the frame loop: camera, mapping, migration, sc_start, per-frame figures.
#include "run_frames.h"

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>

#include "elaboration_mark.h"
#include "kernel_handles.h"
#include "memory_reserve.h"
#include "model_run.h"
#include "motion_update.h"
#include "progress.h"
#include "rt_cost_map.h"
#include "rt_framebuffer.h"
#include "run_stage.h"
#include "series_recording.h"
#include "systemc_messages.h"
#include "torus_system.h"
#include "tracing.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

namespace {

// An animation's frame record in memory with its staged file, and with --stats its JSON tree and
// text (nlohmann's objects are larger than the text they print), per frame: measured as the
// growth of the peak resident size from 2000 to 20000 frames of 1x1 (1.7 KiB, and 7.4 KiB with
// --stats), rounded up; the file names are counted apart.
constexpr uint64_t kFrameRecordBytes = 2048;
constexpr uint64_t kFrameReportBytes = 6144;

// What a machine's modules take is asked for (and given back) before the first is built, per
// processor: 32 KiB, under the 35 KiB a processor (resident; more of address space) the run of
// 64x64 nodes at 16x16 pixels peaks at (150 MB), so that a machine that cannot be built is
// refused before thousands of half-built modules have to be destroyed with next to no memory
// left, and one whose run fits is never refused.
constexpr size_t kMachineProbeBytesPerProcessor = 32 << 10;

// Whether `bytes` can be allocated now (through a volatile pointer, so that the compiler keeps
// the allocation; the pages are never touched).
bool room_for(size_t bytes)
{
    void *(*volatile allocate)(size_t) = std::malloc;
    void *probe = allocate(bytes);
    std::free(probe);
    return probe != nullptr;
}

rt_vec3 box_centre(const rt_box &b) { return rt_vec_scale(rt_vec_add(b.lo, b.hi), 0.5); }

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

// The 8-bit images the run holds at once (one when each frame is handed on as it completes),
// checked against the budget before any frame runs.
void reserve_images(rt_budget &memory, const rt_camera *cam, size_t images)
{
    uint64_t bytes = static_cast<uint64_t>(cam->width) * cam->height * 3 * images;
    std::string what = images == 1 ? "the 8-bit image" : std::to_string(images) + " frames' 8-bit images";
    what += " of " + std::to_string(cam->width) + "x" + std::to_string(cam->height) + " pixels";
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&memory, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(msg);
}

// The per-pixel latency figures (packet_latency.h): a start and a last contribution a pixel.
void reserve_pixel_latency(rt_budget &memory, const rt_camera *cam)
{
    uint64_t bytes = static_cast<uint64_t>(cam->width) * cam->height * PacketLatency::bytes_per_pixel();
    std::string what = "the per-pixel latency figures of " + std::to_string(cam->width) + "x" +
                       std::to_string(cam->height) + " pixels";
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&memory, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(msg);
}

// An animation's pilots (the current frame's, the two before it and adaptive's preview, kept
// from frame to frame) with one pilot's frame buffer and a remapping's Scotch tables, held from
// the run's budget before the first pilot runs.
void reserve_frame_pilots(rt_budget &memory, const rt_scene *scene, const rt_grid *grid, const FramePlan &plan)
{
    if (!plan.animated()) return;
    const rt_camera *cam = rt_scene_camera(scene);
    size_t cells = rt_grid_cell_count(grid), objects = rt_scene_object_count(scene);
    bool by_object = plan.motion && plan.policy == RemapPolicy::adaptive;
    uint64_t tables = rt_cost_pilot_bytes(grid, objects, 0, 0, by_object) - rt_framebuffer_bytes(0, 0);
    uint64_t bytes = 4 * tables + rt_framebuffer_bytes(cam->width, cam->height) +
                     (plan.policy == RemapPolicy::static_map ? 0 : rt_cost_map_bytes(cells));
    std::string what = "the frames' pilots and remapping of " + std::to_string(cells) + " cells";
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&memory, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(msg);
}

// An animation's frame records, kept for the whole run, and with --stats or --frames-csv their
// JSON and CSV, built when the run ends: held from the run's budget before the first frame, so
// that frames x record size that cannot fit is refused at once (docs/memory.md).
void reserve_frame_records(rt_budget &memory, const FramePlan &plan)
{
    if (!plan.animated()) return;
    uint64_t name_bytes = 0;
    for (const std::string &file : plan.files) name_bytes += file.size();
    uint64_t per_frame = kFrameRecordBytes + (plan.report_frames ? kFrameReportBytes : 0);
    uint64_t bytes = plan.frames * per_frame + (plan.report_frames ? 3 : 1) * name_bytes;
    std::string what = "the records of " + std::to_string(plan.frames) + " frames" +
                       (plan.report_frames ? " and their JSON (--stats, --frames-csv)" : "");
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&memory, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(msg);
}

uint64_t created(const PacketLedger &ledger) { return ledger.totals().created[0] + ledger.totals().created[1]; }

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
    std::unique_ptr<SeriesRecording> series;  // --stats-interval
    ElaborationMark *mark = nullptr;          // its time ends the elaboration, inside the first sc_start
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

// The report's run facts. A single image's T(1) is the plan's, or (t1 < 0) this run's image
// time `image_time_s`; an animation's is the sum of its frames' pilots.
RunFacts run_facts(const Machine &m, const FramePlan &plan, const std::vector<FrameRecord> &frames, double image_time_s,
                   double wall_start_s)
{
    RunFacts facts;
    if (plan.animated()) {
        facts.t1_s = frames_t1(frames);
        facts.t1_source = "sum of the frames' pilots";
    } else {
        facts.t1_s = plan.t1_s < 0 ? image_time_s : plan.t1_s;
        facts.t1_source = plan.t1_s < 0 ? "this run" : plan.t1_source;
    }
    facts.elaboration_wall_s = m.elaboration_wall_s;
    facts.sim_wall_s = m.sim_wall_s;
    facts.delta_cycles = sc_core::sc_delta_count();
    facts.wall_s = wall_clock_s() - wall_start_s;
    return facts;
}

// "building the machine (N nodes of C processors)": the stage named if memory runs out.
std::string machine_stage(const SimConfig &config)
{
    std::string cluster = config.cluster > 1 ? " of " + std::to_string(config.cluster) + " processors" : "";
    return "building the machine (" + std::to_string(config.node_count()) + " nodes" + cluster + ")";
}

// Runs the current frame to its end; false on a deadlock. `where` ("frame K: " in an animation)
// starts the message of a run the memory budget stopped.
bool run_frame(const SimConfig &config, Machine &m, const std::string &label, const std::string &where)
{
    // Setting the frame up made its primaries: past the packet limit sc_stop was called, and
    // sc_start would fail (E546).
    if (m.ledger.over_limit()) check_budget_before_start(m.ledger, m.memory, where + "as the frame was set up: ");
    Progress progress(label, ProgressSettings{config.quiet, config.progress_every_s, config.stderr_is_output});
    progress.start_from(m.ledger.totals().consumed[0] + m.ledger.totals().consumed[1]);
    if (progress.active()) m.ledger.set_progress(show_progress, &progress);
    double t0 = wall_clock_s();
    // Stopping at the limit keeps SystemC's 64-bit time from wrapping: every single delay is
    // bounded (check_timing_limits), so none can jump from below the limit past the maximum.
    sc_core::sc_time limit(config.time_limit_s, sc_core::SC_SEC);
    sc_core::sc_time left = limit > sc_core::sc_time_stamp() ? limit - sc_core::sc_time_stamp() : sc_core::SC_ZERO_TIME;
    try {
        sc_core::sc_start(left, sc_core::SC_EXIT_ON_STARVATION);
    } catch (const sc_core::sc_report &) {
        if (systemc_out_of_memory()) {  // cli_main's out-of-memory message, at the stage set
            if (m.series) set_run_stage(std::string(run_stage()) + " and its --stats-interval series");
            throw std::bad_alloc();
        }
        if (!systemc_stack_failed()) throw;
        set_run_stage(machine_stage(config) + ": its processes' stacks");
        throw std::bad_alloc();  // cli_main's out-of-memory message
    }
    double t1 = wall_clock_s();
    if (!m.started) {  // the first sc_start also ended the elaboration
        t0 = m.mark->ended_at(t0);
        m.elaboration_wall_s = t0 - m.elaboration_start_s;
        m.started = true;
    }
    m.sim_wall_s += t1 - t0;
    progress.finish();
    m.ledger.set_progress(nullptr, nullptr);
    try {
        if (m.series) m.series->check();  // a series past its memory stopped the run
        return run_finished(config, *m.top, m.ledger, m.memory);
    } catch (const UserError &e) {
        throw UserError(where + e.what(), e.exit_code());
    }
}

// Frame k's mapping (k > 0) and its record's mapping fields; the owner table is updated.
void next_mapping(Remapper &remapper, const RemapContext &ctx, Machine &m, const FrameLoads &loads, FrameRecord &rec)
{
    RemapDecision d = remapper.decide(ctx, m.owner, loads);
    std::copy(d.owner.begin(), d.owner.end(), m.owner.begin());  // same storage: the modules' pointer stays
    rec.decision = d.decision;
    rec.reason = d.reason;
    rec.predicted_gain_s = d.predicted_gain_s;
    rec.migration = d.migration;
    rec.migration_charged = d.migration_charged;
    rec.mapper_wall_s = d.mapper_wall_s;
}

// Adaptive's host preview of frame k, made while frame k-1 ran for `previous_time_s`: only its
// modelled host time past that delays frame k.
std::unique_ptr<FramePilot> host_preview(const SimConfig &config, rt_scene *scene, const rt_grid *grid, double fraction,
                                         double previous_time_s, FrameRecord &rec)
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
    set_run_stage(machine_stage(config));
    keep_memory_reserve();  // whole again: a failure while the modules are built unwinds through them
    size_t processors = static_cast<size_t>(config.node_count()) * static_cast<size_t>(std::max(config.cluster, 1));
    if (!room_for(processors * kMachineProbeBytesPerProcessor)) throw std::bad_alloc();  // cli_main's message
    rt_replicas replicas = config.replica_table();
    m.top = &keep_until_exit(std::make_unique<TorusSystem>("top", config, scene, grid, m.owner.data(), m.ledger,
                                                           m.fb.get(), HandOverTiming::at_once,
                                                           config.replicated() ? &replicas : nullptr));
    if (!config.vcd_path.empty()) m.tracer = std::make_unique<Tracer>(config, *m.top);
    if (config.stats_interval_s > 0)
        m.series = std::make_unique<SeriesRecording>(config.stats_interval_s, *m.top, m.ledger, m.memory);
    m.mark = &elaboration_mark();
    check_budget_before_start(m.ledger, m.memory, "before the simulation started: ");
}

// The policy and adaptive's settings as the report states them.
RemapSettings remap_settings(RemapPolicy policy, const AdaptiveSettings &a)
{
    return {remap_policy_name(policy), a.pilot_fraction, a.window, a.margin};
}

// The frame loop's state beyond the machine: the pilots of the last frames and the remapper.
struct FrameLoop {
    const SimConfig &config;
    rt_scene *scene;
    const rt_grid *grid;
    const FramePlan &plan;
    Routing routing;
    RemapContext ctx;
    Remapper remapper;
    std::unique_ptr<FramePilot> pilot, previous, before, preview;  // frames k, k-1, k-2; adaptive's preview
    double end_s = 0;                                              // when the last frame ended
    sc_core::sc_time start;                                        // when the current frame started
    rt_camera_pose still;  // the scene's own camera: every frame's without a camera path
    ObjectShifts shifts;   // a moving scene: what moved into the current frame
    // Adaptive on a moving scene counts each object's work, to carry it with the objects.
    bool by_object() const { return plan.motion && plan.policy == RemapPolicy::adaptive; }

    FrameLoop(const SimConfig &c, rt_scene *s, const rt_grid *g, const FramePlan &p)
        : config(c), scene(s), grid(g), plan(p), routing(c.network(), c.route_ties), ctx{c, s, g, routing},
          remapper(p.policy, p.adaptive.window, p.adaptive.margin), still(rt_camera_pose_of(rt_scene_camera(s)))
    {
    }

    // Frame k's camera pose.
    const rt_camera_pose *pose(size_t k) const { return plan.path ? rt_camera_path_pose(plan.path, k) : &still; }

    // Frame 0's table: the run's mapping, or under oracle its own pilot's.
    std::vector<int32_t> first_table()
    {
        if (!plan.animated()) return owner_table_of(config, grid);
        if (plan.path) set_camera(scene, plan.path, 0);
        pilot = std::make_unique<FramePilot>(config, scene, grid, by_object());
        return plan.policy == RemapPolicy::oracle ? oracle_mapping(ctx, *pilot) : owner_table_of(config, grid);
    }

    // Frame k's record before it runs; for k > 0 the objects and the camera move, the mapping is
    // decided and the machine restarts at `start`.
    FrameRecord prepare(Machine &m, size_t k, const std::vector<FrameRecord> &done);
    // A moving scene's frame k > 0: its objects and its cell lists (their growth charged to the
    // machine's memory budget); the update's cost in `rec`.
    void move_objects(Machine &m, size_t k, FrameRecord &rec);
};

void FrameLoop::move_objects(Machine &m, size_t k, FrameRecord &rec)
{
    SceneMotion &motion = *plan.motion;
    size_t objects = rt_scene_object_count(scene);
    std::vector<rt_vec3> centre(objects);
    for (size_t o = 0; o < objects; o++) centre[o] = box_centre(rt_scene_object_bounds(scene, o));
    motion.move_objects(static_cast<uint32_t>(k));
    shifts.moved = motion.moved();
    shifts.shift.assign(objects, rt_vec3{0, 0, 0});
    for (size_t o = 0; o < objects; o++)
        if (shifts.moved[o]) shifts.shift[o] = rt_vec_sub(box_centre(rt_scene_object_bounds(scene, o)), centre[o]);
    std::vector<ObjectCell> old_entries = moved_entries(grid, motion.moved());
    motion.update_lists(static_cast<uint32_t>(k), plan.moving_grid, &m.memory);
    MotionMachine machine{routing, config.node_count(), config.cluster, config.timing, m.owner.data()};
    rec.update = motion_update_cost(scene, grid, motion.moved(), old_entries, machine);
}

FrameRecord FrameLoop::prepare(Machine &m, size_t k, const std::vector<FrameRecord> &done)
{
    FrameRecord rec;
    rec.index = k;
    rec.file = k < plan.files.size() ? plan.files[k] : "";
    rec.camera = *pose(k);
    rec.moving = plan.motion != nullptr;
    rec.processors = config.processor_count();
    rec.decision = "first";
    rec.reason = plan.policy == RemapPolicy::oracle ? "oracle: this frame's own pilot" : "the run's --map";
    if (k > 0) {
        if (plan.motion) move_objects(m, k, rec);
        if (plan.path) set_camera(scene, plan.path, k);
        before = std::move(previous);
        previous = std::move(pilot);
        pilot = std::make_unique<FramePilot>(config, scene, grid, by_object());
        double previous_time_s = done.back().image_time_s;
        if (plan.policy == RemapPolicy::adaptive && plan.adaptive.pilot_fraction > 0)
            preview = host_preview(config, scene, grid, plan.adaptive.pilot_fraction, previous_time_s, rec);
        next_mapping(remapper, ctx, m,
                     FrameLoads{*previous, previous_time_s, *pilot, before.get(), preview.get(), pose(k - 1), pose(k),
                                by_object() ? &shifts : nullptr},
                     rec);
        if (plan.motion) m.top->place_objects(grid, m.owner.data());
        m.fb.reset();  // the budget holds one frame buffer: the last frame's goes first
        m.fb = new_frame_buffer(scene);
        start = frame_start(config, end_s + rec.charged_migration_s() + rec.host_pilot_charged_s + rec.update.time_s());
        m.top->start_frame(m.fb.get(), m.owner.data(), start);
        rec.start_s = start.to_seconds();
    }
    if (pilot) {
        rec.t1_s = pilot->work_s();
        rec.pilot_wall_s += pilot->wall_s();
    }
    return rec;
}

std::string progress_label(const FramePlan &plan, size_t k, size_t n)
{
    if (!plan.animated()) return "torusrt-sim";
    return "torusrt-sim frame " + std::to_string(k + 1) + "/" + std::to_string(n);
}

// The outcome of a run stopped by a deadlock in frame k: the report (status "deadlock") and the
// frames that completed.
void deadlocked(const FrameLoop &loop, Machine &m, size_t k, double wall_start_s, RunOutcome &out)
{
    const FramePlan &plan = loop.plan;
    RunFacts facts = run_facts(m, plan, {}, 0, wall_start_s);  // T(1): 0, or the plan's
    out.deadlock = true;
    out.report = collect(loop.config, *m.top, m.ledger, loop.scene, loop.grid, m.owner.data(), facts, true);
    std::string where = plan.animated() ? "frame " + std::to_string(k) + ":\n" : "";
    if (plan.animated()) {
        out.report.frames = out.frames;  // the frames that completed
        out.report.remap = remap_settings(plan.policy, plan.adaptive);
    }
    out.deadlock_details = where + deadlock_text(out.report);
    out.sim_time_s = out.report.sim_time_s;
}

}  // namespace

RunOutcome run_frames(const SimConfig &config, rt_scene *scene, const rt_grid *grid, const FramePlan &plan,
                      double wall_start_s)
{
    size_t n = plan.animated() ? plan.frames : 1;
    Machine m;
    m.memory = config.memory;
    const rt_camera *cam = rt_scene_camera(scene);
    const size_t image_bytes = static_cast<size_t>(cam->width) * cam->height * 3;
    reserve_images(m.memory, cam, plan.frame_done ? 1 : n);
    reserve_frame_pilots(m.memory, scene, grid, plan);
    reserve_frame_records(m.memory, plan);
    reserve_pixel_latency(m.memory, cam);
    m.ledger.set_limit(rt_budget_packets_allowed(&m.memory, PacketPool::bytes_per_packet()));
    m.ledger.latency().set_image(cam->width, cam->height);
    m.ledger.latency().set_link_time(sc_core::sc_time(rt_timing_link_packet_us(&config.timing), sc_core::SC_US));
    FrameLoop loop(config, scene, grid, plan);
    m.owner = loop.first_table();
    warn_idle_nodes(config, m.owner);
    m.fb = new_frame_buffer(scene);
    elaborate(config, scene, grid, m);

    RunOutcome out;
    std::vector<uint8_t> rgb8;    // the frame just completed
    uint64_t created_before = 0;  // the primaries are counted when a frame is set up: elaboration, start_frame
    for (size_t k = 0; k < n; k++) {
        set_run_stage(n > 1 ? "simulating frame " + std::to_string(k) : "simulating the image");
        FrameRecord rec = loop.prepare(m, k, out.frames);
        if (!run_frame(config, m, progress_label(plan, k, n), n > 1 ? "frame " + std::to_string(k) + ": " : "")) {
            deadlocked(loop, m, k, wall_start_s, out);
            return out;  // the tracer's destructor removes the partial trace
        }
        check_conservation(m.ledger);
        loop.end_s = m.ledger.image_time().to_seconds();
        rec.image_time_s = (m.ledger.image_time() - loop.start).to_seconds();
        rec.packets = created(m.ledger) - created_before;
        created_before = created(m.ledger);
        rgb8.resize(image_bytes);
        rt_framebuffer_to_rgb8(m.fb.get(), rgb8.data());
        if (plan.frame_done) plan.frame_done(k, rgb8);
        else out.images.push_back(std::move(rgb8));
        out.frames.push_back(rec);
    }
    out.sim_time_s = loop.end_s;
    out.report = collect(config, *m.top, m.ledger, scene, grid, m.owner.data(),
                         run_facts(m, plan, out.frames, out.sim_time_s, wall_start_s), false);
    if (plan.animated()) {
        out.report.frames = out.frames;
        out.report.remap = remap_settings(plan.policy, plan.adaptive);
    } else {
        out.frames.clear();  // a single image reports no frames
    }
    if (m.series) out.series_csv = m.series->finish(m.ledger.image_time(), m.ledger.outstanding());
    if (m.tracer) m.tracer->finish();
    return out;
}

}  // namespace torusrt
