// motion_update.h - what a moving scene's cell-list update costs the machine between two frames
// (--motion; docs/frames.md, Moving objects).
//
// Object o is handled by processor o mod P (P processors in all, the paper's dealing of the
// preprocessing: docs/design.md section 4), which keeps its scene-file record and lists it again
// when it moves: its units are the kernel's half-space tests of the update
// (rt_grid_units_of_object after rt_grid_update). A processor takes its units x `preprocess_unit`
// (the timing table); the update takes as long as the slowest processor.
// Then the handler's node tells every other node whose cells gain or lose the object: 4 bytes per
// list entry added or removed (an entry as rt_memory counts it), and the object's record
// (rt_scene_object_bytes) to a node whose cells listed it nowhere before. A node that held the
// object already moves its copy itself (every node holds the motion). These transfers load the
// links as a migration's do (migration.h: dimension-order paths, each link's bytes back to back,
// the busiest link's time). The next frame starts after the update and the transfers.
#pragma once

#include <cstdint>
#include <vector>

#include "migration.h"
#include "routing.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "rt_timing.h"

namespace torusrt {

// One cell-list entry: an object listed in a cell.
struct ObjectCell {
    uint32_t object;
    uint32_t cell;
};

// The entries of the objects flagged in `moved` (one byte per object), by object, then cell.
std::vector<ObjectCell> moved_entries(const rt_grid *grid, const std::vector<uint8_t> &moved);

// The cost of one update between two frames.
struct MotionUpdate {
    uint64_t objects_moved = 0;          // objects whose geometry changed
    uint64_t units = 0;                  // the update's half-space tests, every processor's
    uint64_t slowest_units = 0;          // the busiest processor's
    uint64_t rebuild_units = 0;          // a rebuild of every list on one processor
    uint64_t rebuild_slowest_units = 0;  // a rebuild dealt out as above: the busiest processor's
    double update_s = 0;                 // slowest_units x preprocess_unit
    uint64_t entries_sent = 0;           // list entries added or removed at another node
    // The transfers: objects = records sent, list_bytes = 4 per entry sent, object_bytes, the
    // links' figures (cells stays 0).
    MigrationCost transfer;
    double time_s() const { return update_s + transfer.time_s; }
};

// The machine the update runs on.
struct MotionMachine {
    const Routing &routing;
    int nodes;
    int processors_per_node;
    const rt_timing &timing;
    const int32_t *owner;  // cell -> node
};

// The update that brought `grid` to `scene`'s geometry: `moved` as given to rt_grid_update and
// `before` = moved_entries of the grid before it.
MotionUpdate motion_update_cost(const rt_scene *scene, const rt_grid *grid, const std::vector<uint8_t> &moved,
                                const std::vector<ObjectCell> &before, const MotionMachine &machine);

}  // namespace torusrt
