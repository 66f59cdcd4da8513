// frame_report.cpp - JSON, CSV and the summary table of an animation's frames.
#include "frame_report.h"

#include <sstream>

#include "significant.h"
#include "stats_json.h"

namespace torusrt {

namespace {

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

// What a set of transfers between frames sent and how it loaded the links (a migration's, an
// update's).
nlohmann::json transfer_json(const MigrationCost &m)
{
    return {{"list_bytes", m.list_bytes},
            {"object_bytes", m.object_bytes},
            {"byte_hops", m.byte_hops},
            {"max_hops", m.max_hops},
            {"busiest_link_bytes", m.busiest_link_bytes},
            {"link_time_s", m.time_s}};
}

// A frame's update (frames[].motion).
nlohmann::json update_json(const FrameRecord &f)
{
    const MotionUpdate &u = f.update;
    nlohmann::json j = transfer_json(u.transfer);
    j.update({{"objects_moved", u.objects_moved},
              {"entries_sent", u.entries_sent},
              {"update_units", u.units},
              {"update_units_slowest", u.slowest_units},
              {"rebuild_units", u.rebuild_units},
              {"rebuild_units_slowest", u.rebuild_slowest_units},
              {"objects_sent", u.transfer.objects},
              {"bytes", u.transfer.bytes()},
              {"update_time_s", u.update_s},
              {"time_s", u.time_s()},
              {"image_time_ratio", ratio(u.time_s(), f.image_time_s)}});
    return j;
}

// The summary's table of a moving scene's updates and its totals line.
void print_update_table(const std::vector<FrameRecord> &frames, std::FILE *out)
{
    nlohmann::json t = motion_totals_json(frames);
    std::fprintf(out,
                 "  motion       %llu objects moved, %llu units updating the lists (%llu rebuilding them, "
                 "%.1f %%); update %s s + links %s s = %.2f %% of the image time\n",
                 t["objects_moved"].get<unsigned long long>(), t["update_units"].get<unsigned long long>(),
                 t["rebuild_units"].get<unsigned long long>(), 100 * t["update_rebuild_ratio"].get<double>(),
                 sig4(t["update_time_s"].get<double>()).c_str(), sig4(t["link_time_s"].get<double>()).c_str(),
                 100 * t["image_time_ratio"].get<double>());
    std::fprintf(out, "  frame  upd. units  rebuild units     upd. s  objs sent  sent bytes     link s"
                      "  upd/img\n");
    for (const FrameRecord &f : frames) {
        const MotionUpdate &u = f.update;
        std::fprintf(out, "  %5zu %11llu %14llu %10s %10llu %11llu %10s %7.2f%%\n", f.index,
                     static_cast<unsigned long long>(u.units), static_cast<unsigned long long>(u.rebuild_units),
                     sig4(u.update_s).c_str(), static_cast<unsigned long long>(u.transfer.objects),
                     static_cast<unsigned long long>(u.transfer.bytes()), sig4(u.transfer.time_s).c_str(),
                     100 * ratio(u.time_s(), f.image_time_s));
    }
}

}  // namespace

nlohmann::json frame_json(const FrameRecord &f)
{
    const MigrationCost &m = f.migration;
    nlohmann::json migration = transfer_json(m);
    migration.update({{"cells", m.cells}, {"objects", m.objects}, {"charged", f.migration_charged}});
    nlohmann::json j = {
        {"index", f.index},
        {"file", f.file},
        {"camera", camera_pose_json(f.camera)},
        {"start_s", f.start_s},
        {"image_time_s", f.image_time_s},
        {"t1_s", f.t1_s},
        {"efficiency", f.efficiency()},
        {"packets", f.packets},
        {"remap", {{"decision", f.decision}, {"reason", f.reason}, {"predicted_gain_s", f.predicted_gain_s}}},
        {"migration_bytes", m.bytes()},
        {"migration_time_s", f.charged_migration_s()},
        {"migration", migration},
        {"host_pilot",
         {{"pixels", f.preview_pixels}, {"time_s", f.host_pilot_s}, {"charged_s", f.host_pilot_charged_s}}},
        {"pilot_wall_s", f.pilot_wall_s},
        {"mapper_wall_s", f.mapper_wall_s}};
    if (f.moving) j["motion"] = update_json(f);
    return j;
}

nlohmann::json motion_totals_json(const std::vector<FrameRecord> &frames)
{
    MotionUpdate sum;
    double image = 0;
    for (const FrameRecord &f : frames) {
        const MotionUpdate &u = f.update;
        sum.objects_moved += u.objects_moved;
        sum.units += u.units;
        sum.rebuild_units += u.rebuild_units;
        sum.update_s += u.update_s;
        sum.entries_sent += u.entries_sent;
        sum.transfer.objects += u.transfer.objects;
        sum.transfer.list_bytes += u.transfer.list_bytes;
        sum.transfer.object_bytes += u.transfer.object_bytes;
        sum.transfer.time_s += u.transfer.time_s;
        image += f.image_time_s;
    }
    return {{"objects_moved", sum.objects_moved},
            {"update_units", sum.units},
            {"rebuild_units", sum.rebuild_units},
            {"update_rebuild_ratio", ratio(static_cast<double>(sum.units), static_cast<double>(sum.rebuild_units))},
            {"update_time_s", sum.update_s},
            {"entries_sent", sum.entries_sent},
            {"objects_sent", sum.transfer.objects},
            {"bytes", sum.transfer.bytes()},
            {"link_time_s", sum.transfer.time_s},
            {"time_s", sum.time_s()},
            {"image_time_s", image},
            {"image_time_ratio", ratio(sum.time_s(), image)}};
}

nlohmann::json animation_json(const std::vector<FrameRecord> &frames, const RemapSettings &remap)
{
    double image = 0, migration = 0, t1 = 0, host = 0, host_charged = 0, motion = 0;
    uint64_t bytes = 0, remaps = 0;
    for (const FrameRecord &f : frames) {
        image += f.image_time_s;
        migration += f.charged_migration_s();
        t1 += f.t1_s;
        host += f.host_pilot_s;
        host_charged += f.host_pilot_charged_s;
        motion += f.update.time_s();
        bytes += f.migration.bytes();
        if (f.migration.cells > 0) remaps++;
    }
    double total = image + migration + host_charged + motion;
    int n = frames.empty() ? 1 : frames.front().processors;
    nlohmann::json a = {{"frame_count", frames.size()},
                        {"policy", remap.policy},
                        {"total_s", total},
                        {"image_time_s", image},
                        {"migration_time_s", migration},
                        {"migration_share", total > 0 ? migration / total : 0.0},
                        {"migration_bytes", bytes},
                        {"host_pilot_time_s", host},
                        {"host_pilot_charged_s", host_charged},
                        {"motion_time_s", motion},
                        {"mapping_changes", remaps},
                        {"t1_s", t1},
                        {"efficiency", total > 0 ? t1 / (n * total) : 0.0}};
    if (remap.policy == "adaptive") {
        a["pilot_fraction"] = remap.pilot_fraction;
        a["window"] = remap.window;
        a["margin"] = remap.margin;
    }
    return a;
}

std::string frames_csv(const std::vector<FrameRecord> &frames)
{
    std::ostringstream out;
    out.precision(9);
    out << "frame,file,start_s,image_time_s,t1_s,efficiency,packets,decision,migration_bytes,migration_cells,"
           "migration_objects,migration_max_hops,migration_time_s,migration_charged,predicted_gain_s,host_pilot_pixels,"
           "host_pilot_s,host_pilot_charged_s\n";
    for (const FrameRecord &f : frames)
        out << f.index << ',' << f.file << ',' << f.start_s << ',' << f.image_time_s << ',' << f.t1_s << ','
            << f.efficiency() << ',' << f.packets << ',' << f.decision << ',' << f.migration.bytes() << ','
            << f.migration.cells << ',' << f.migration.objects << ',' << f.migration.max_hops << ','
            << f.charged_migration_s() << ',' << (f.migration_charged ? 1 : 0) << ',' << f.predicted_gain_s << ','
            << f.preview_pixels << ',' << f.host_pilot_s << ',' << f.host_pilot_charged_s << '\n';
    return out.str();
}

void print_frame_table(const std::vector<FrameRecord> &frames, const RemapSettings &remap, std::FILE *out)
{
    if (frames.empty()) return;
    nlohmann::json a = animation_json(frames, remap);
    std::string policy = remap.policy;
    if (remap.policy == "adaptive") {
        char buf[96];
        if (remap.pilot_fraction > 0)
            std::snprintf(buf, sizeof buf, " (preview %g of the pixels)", remap.pilot_fraction);
        else
            std::snprintf(buf, sizeof buf, " (guesses judged over %zu frame%s, margin %g)", remap.window,
                          remap.window == 1 ? "" : "s", remap.margin);
        policy += buf;
    }
    std::string motion = frames.front().moving ? " + motion " + sig4(a["motion_time_s"].get<double>()) + " s" : "";
    std::fprintf(out,
                 "  animation    %zu frames, remap %s: total %s s = images %s s + migration %s s (%.1f %%)"
                 " + host pilot %s s%s\n",
                 frames.size(), policy.c_str(), sig4(a["total_s"].get<double>()).c_str(),
                 sig4(a["image_time_s"].get<double>()).c_str(), sig4(a["migration_time_s"].get<double>()).c_str(),
                 100 * a["migration_share"].get<double>(), sig4(a["host_pilot_charged_s"].get<double>()).c_str(),
                 motion.c_str());
    std::fprintf(out, "  frame    image s  effic.  migr. bytes    migr. s  decision\n");
    for (const FrameRecord &f : frames)
        std::fprintf(out, "  %5zu %10s %6.1f%% %12llu %10s  %s\n", f.index, sig4(f.image_time_s).c_str(),
                     100 * f.efficiency(), static_cast<unsigned long long>(f.migration.bytes()),
                     sig4(f.charged_migration_s()).c_str(), f.decision.c_str());
    if (!frames.front().moving) return;
    print_update_table(frames, out);
}

}  // namespace torusrt
