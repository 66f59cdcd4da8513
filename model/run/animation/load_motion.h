// load_motion.h - a measured per-cell load moved with the camera from one frame's pose to the
// next's, and blurred (adaptive's guesses of the next frame's load, see remap_policy.h).
// The motion is the rigid one taking pose a's eye frame (origin at `from`; axes: the view
// direction, and `up` made orthogonal to it) to pose b's; for an orbit it is the turn by the
// step angle about `up` through `at`. Each cell's work moves with its centre and is splatted
// trilinearly onto the (up to) eight cells around the moved centre, clamped into the grid, so
// the total is conserved exactly; a centre that lands on a cell centre goes to that cell
// alone. A face's traffic moves the same way, onto the face whose outward normal is nearest
// the moved one.
#pragma once

#include "rt_camera_path.h"
#include "rt_cost_map.h"

#include <vector>

namespace torusrt {

struct RigidMotion {
    double r[3][3];  // rotation, row major
    rt_vec3 from;    // a point of pose a ...
    rt_vec3 to;      // ... and where it goes
    rt_vec3 apply(rt_vec3 p) const;
    rt_vec3 turn(rt_vec3 v) const;  // the rotation alone (directions)
};

// The rigid motion taking pose a to pose b (the identity when they are equal).
RigidMotion camera_motion(const rt_camera_pose &a, const rt_camera_pose &b);

// dst (cells and arrays of src's size, already allocated) = src moved by m over a grid of
// src.dims cells spanning `bounds`; dst.total_us = src.total_us.
void move_load(const rt_cost_pilot &src, const rt_box &bounds, const RigidMotion &m, rt_cost_pilot &dst);

// The neighbour of cell c through face f (order -x, +x, -y, +y, -z, +z), -1 at the boundary.
long neighbour_cell(const int d[3], long c, int f);

// dst = src blurred: `keep` of each cell's work stays, the rest is shared equally by its face
// neighbours inside the grid (a cell without any keeps all); the total is conserved; traffic
// copied unchanged.
void blur_load(const rt_cost_pilot &src, double keep, rt_cost_pilot &dst);

// Packets through each cell: max(packets in, packets out) over its faces.
std::vector<double> cell_visits(const rt_cost_pilot &load);

// The rays move with the camera, the cost of a ray in a cell stays with the cell's objects:
// the visits are moved by m, times each cell's measured work per visit (cells not visited: the
// mean of the cells alike, occupied or empty), scaled to src's total; traffic as move_load.
void move_visits(const rt_cost_pilot &src, const rt_box &bounds, const RigidMotion &m,
                 const std::vector<char> &occupied, rt_cost_pilot &dst);

}  // namespace torusrt
