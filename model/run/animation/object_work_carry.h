// object_work_carry.h - adaptive's `objects` guess on a moving scene (--motion): the host knows
// where every object is in frame k, so each moving object's measured work in frame k-1 (the
// pilot's per-object counter, rt_cost_pilot_run_by_object) goes with it into frame k's cells.
// This is the objects' motion. The camera's is load_motion.h, where the rays move and the
// objects stay; the two are separate guesses.
//
// A moving object's work in cell c (frame k-1) leaves c and lands in the cell holding c's centre
// moved by the object's shift (its bounding box's centre, frame k-1 to k), if frame k lists the
// object there; otherwise it is shared evenly by the cells that list the object in frame k (or
// stays in c when none does). The rest of each cell's work and every face's traffic stay; the
// total is conserved.
#pragma once

#include <cstdint>
#include <vector>

#include "rt_cost_map.h"
#include "rt_grid.h"

namespace torusrt {

// What moved between frames k-1 and k: one flag per object, and each moved object's shift.
struct ObjectShifts {
    std::vector<uint8_t> moved;
    std::vector<rt_vec3> shift;
};

// dst (cells and arrays of src's size, already allocated) = src's load with the moved objects'
// work carried into `next`'s cells (frame k's lists; same cells as src). src.object_us must
// hold the per-object work.
void carry_object_work(const rt_cost_pilot &src, const rt_grid *next, const ObjectShifts &shifts, rt_cost_pilot &dst);

}  // namespace torusrt
