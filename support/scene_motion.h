// scene_motion.h - a scene moving by a motion file (--motion): reading the file, the object
// space over every frame, and moving the scene and updating its cell lists frame by frame.
// Both executables use it; the options that name the file are testbench/common/motion_options.h.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel_handles.h"
#include "rt_budget.h"
#include "rt_grid.h"
#include "rt_motion.h"

namespace torusrt {

struct MotionDeleter {
    void operator()(rt_motion *m) const { rt_motion_free(m); }
};
using MotionPtr = std::unique_ptr<rt_motion, MotionDeleter>;

// Reads the --motion file (nullptr when `path` is empty). A bad file is exit 2 with
// "--motion: FILE:LINE: message".
MotionPtr read_motion_file(const std::string &path);

// What one frame's move cost: the update's units against a rebuild of every list.
struct MotionFrameCost {
    uint64_t objects_moved = 0;  // objects whose geometry changed since the frame before
    uint64_t update_units = 0;   // half-space tests of the moved objects (frame 0: every object's)
    uint64_t rebuild_units = 0;  // half-space tests of rebuilding every list
    uint64_t list_entries = 0;   // cell-list entries after the frame's update
};

// A scene moving by a motion: the scene file's objects, the current frame's copy, and its grid
// over the object space of every frame.
class SceneMotion {
  public:
    // Checks the motion against the scene (exit 2, FILE:LINE, when an entry names objects the
    // scene lacks or a frame moves an object too far) and prints one line per entry to stderr
    // unless `quiet`. Takes the scene; frame_scene() is the copy every frame is rendered from.
    SceneMotion(MotionPtr motion, ScenePtr scene, const std::string &path, bool quiet);

    // Moves frame_scene() to frame k and brings `grid` up to date: frame 0 (or a null grid)
    // builds it over the object space with `cells` and `rule`; later frames update it in place.
    // Throws UserError naming the motion file on failure (the budget, memory).
    MotionFrameCost move_to(uint32_t k, GridPtr &grid, const int cells[3], rt_preprocess_count rule, rt_budget *budget);
    // move_to in two steps, for a caller that looks at the lists in between: the objects of
    // frame k (moved() flags those that changed), then the lists of a grid built at an earlier
    // frame, updated in place (throws UserError as move_to).
    void move_objects(uint32_t k);
    MotionFrameCost update_lists(uint32_t k, rt_grid *grid, rt_budget *budget);

    rt_scene *frame_scene() const { return m_frame.get(); }
    uint32_t frame_count() const { return rt_motion_frame_count(m_motion.get()); }
    // One byte per object: 1 if the last move changed its geometry.
    const std::vector<uint8_t> &moved() const { return m_moved; }
    // The file, its entries (with what each matched) and the object space, for the JSON report.
    nlohmann::json json() const;

  private:
    MotionPtr m_motion;
    ScenePtr m_scene;  // as the scene file gives it
    ScenePtr m_frame;  // the current frame's copy
    std::string m_path;
    rt_box m_space;  // every object over every frame, unpadded
    std::vector<uint8_t> m_moved;
};

// A frame's cost as JSON: objects_moved, update_units, rebuild_units, list_entries.
nlohmann::json motion_frame_json(const MotionFrameCost &cost);

}  // namespace torusrt
