// frame_report.h - the per-frame figures of an animation: its JSON `frames` entries and
// `animation` totals, the --frames-csv table, and the summary's compact frame table.
#pragma once

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "migration.h"
#include "motion_update.h"
#include "rt_camera_path.h"

namespace torusrt {

struct FrameRecord {
    size_t index = 0;
    std::string file;  // the frame's PNG
    rt_camera_pose camera{};
    double start_s = 0;       // simulated time the frame's primaries start from
    double image_time_s = 0;  // frame start to its last contribution
    double t1_s = 0;          // the frame's sequential work (its pilot)
    int processors = 1;
    uint64_t packets = 0;  // packets created in the frame
    std::string decision;  // "first", "keep" or "remap"
    std::string reason;
    double predicted_gain_s = 0;
    MigrationCost migration;  // before the frame
    bool migration_charged = true;
    uint64_t preview_pixels = 0;      // adaptive's host preview of the frame (0: none)
    double host_pilot_s = 0;          // its modelled host time
    double host_pilot_charged_s = 0;  // the part past the previous frame's image time
    double pilot_wall_s = 0, mapper_wall_s = 0;
    bool moving = false;  // a moving scene (--motion): `update` holds its update
    MotionUpdate update;  // the cell-list update before the frame (none before frame 0)
    double efficiency() const { return image_time_s > 0 ? t1_s / (processors * image_time_s) : 0; }
    double charged_migration_s() const { return migration_charged ? migration.time_s : 0; }
};

// The policy of an animation and, for adaptive, its settings (the reading the run was made under).
struct RemapSettings {
    std::string policy;         // remap_policy_name
    double pilot_fraction = 0;  // --remap-pilot (adaptive)
    size_t window = 0;          // --remap-window (adaptive without a preview)
    double margin = 0;          // --remap-margin (adaptive without a preview)
};

nlohmann::json frame_json(const FrameRecord &frame);
// Totals: frame_count, policy (and adaptive's pilot_fraction, window and margin), total_s = sum of
// image times + charged migration + charged host pilot time + a moving scene's updates, and its
// parts.
nlohmann::json animation_json(const std::vector<FrameRecord> &frames, const RemapSettings &remap);
// A moving scene's figures over every frame: objects moved, units of the updates and of rebuilds,
// update and link time, what was sent, and the time against the frames' image time.
nlohmann::json motion_totals_json(const std::vector<FrameRecord> &frames);
// One header line and one row per frame (columns in docs/frames.md).
std::string frames_csv(const std::vector<FrameRecord> &frames);
// The summary's table (nothing for a single image).
void print_frame_table(const std::vector<FrameRecord> &frames, const RemapSettings &remap, std::FILE *out);

}  // namespace torusrt
