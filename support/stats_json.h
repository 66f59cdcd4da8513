// stats_json.h - JSON forms of the kernel's counters, shared by every report.
#pragma once

#include <nlohmann/json.hpp>

#include "rt_camera_path.h"
#include "rt_grid.h"
#include "rt_ops.h"
#include "rt_render.h"

namespace torusrt {

nlohmann::json ops_json(const rt_op_counts &ops);
// {"created": {"ray", "shadow", "total"}, "consumed": {...}, ...}
nlohmann::json packets_json(const rt_packet_totals &totals);
// Preprocessing: serial units and the parallel figure for P = 1, 2, 4, ... 64 and `extra`.
nlohmann::json preprocess_json(const rt_grid *grid, int extra_processors);
// An animation frame's camera: {"from": [x, y, z], "at": [...], "up": [...], "angle": a}
nlohmann::json camera_pose_json(const rt_camera_pose &pose);

}  // namespace torusrt
