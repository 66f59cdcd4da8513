// migration_test.cpp - the migration between two frames' mappings counted by hand on a scene of
// two spheres in a 2x1x1 grid (one sphere per cell): bytes (cell list 4 + 4 per entry, plus each
// object record the new owner lacks), hops by dimension-order routing, and the time of the
// busiest link at link_us per packet_bytes piece.
#include <cmath>
#include <systemc>
#include <vector>

#include "harness.h"
#include "migration.h"
#include "rt_grid.h"
#include "rt_scene.h"

using harness::check;
using namespace torusrt;

int sc_main(int, char *[])
{
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 8, 8);
    rt_scene_add_sphere(scene, rt_vec(-3, 0, 0), 1.0); // object 0, cell 0 (x in [-4, 0])
    rt_scene_add_sphere(scene, rt_vec(3, 0, 0), 1.0);  // object 1, cell 1 (x in [0, 4])
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
    size_t n0 = 0, n1 = 0;
    const uint32_t *l0 = rt_grid_cell_objects(grid, 0, &n0);
    const uint32_t *l1 = rt_grid_cell_objects(grid, 1, &n1);
    check(n0 == 1 && l0[0] == 0 && n1 == 1 && l1[0] == 1, "premise: one sphere per cell");
    const uint64_t a = rt_scene_object_bytes(scene, 0), b = rt_scene_object_bytes(scene, 1);
    check(a > 0 && a == b, "premise: two sphere records of the same size");

    rt_timing timing;
    rt_timing_defaults(&timing);
    timing.link_us = 50;
    timing.packet_bytes = 28;
    timing.link_bytes_per_us = 0;

    // The same table: nothing moves.
    Routing ring2({2, 1, 1}, true);
    MigrationCost none = migration_cost(scene, grid, ring2, 2, timing, {0, 1}, {0, 1});
    check(none.bytes() == 0 && none.cells == 0 && none.time_s == 0, "unchanged mapping: 0 bytes, 0 s");

    // Cell 1 moves from node 1 to node 0, one hop: 8 list bytes + sphere 1's record.
    MigrationCost one = migration_cost(scene, grid, ring2, 2, timing, {0, 1}, {0, 0});
    uint64_t want = 8 + b;
    check(one.cells == 1 && one.objects == 1, "one cell and one object move");
    check(one.list_bytes == 8 && one.object_bytes == b && one.bytes() == want, "bytes = 4 + 4 x 1 + record");
    check(one.max_hops == 1 && one.byte_hops == want, "one hop");
    double pieces = std::ceil(static_cast<double>(want) / 28.0);
    check(std::fabs(one.time_s - pieces * 50e-6) < 1e-12, "time = ceil(bytes / 28) x 50 us");

    // On a ring of 4: cell 0 goes 0 -> 2 (0 -> 1 -> 2, a tie goes +), cell 1 goes 1 -> 3
    // (1 -> 2 -> 3). Both cross link 1 -> 2, which sends the two back to back.
    Routing ring4({4, 1, 1}, true);
    MigrationCost two = migration_cost(scene, grid, ring4, 4, timing, {0, 1}, {2, 3});
    uint64_t each = 8 + a;
    check(two.cells == 2 && two.bytes() == 2 * each, "two cells, each 8 + a record");
    check(two.max_hops == 2 && two.byte_hops == 4 * each, "two hops each");
    check(two.busiest_link_bytes == 2 * each, "link 1 -> 2 carries both");
    check(std::fabs(two.time_s - std::ceil(2.0 * each / 28.0) * 50e-6) < 1e-12, "time of the shared link");

    // A node that already holds an object gets only the cell list: both cells list sphere 0.
    rt_scene *big = rt_scene_new();
    rt_scene_set_view(big, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 8, 8);
    rt_scene_add_sphere(big, rt_vec(0, 0, 0), 2.0);
    rt_scene_add_sphere(big, rt_vec(0, 3, 0), 0.5);
    rt_scene_finish(big, msg, sizeof msg);
    rt_grid *g2 = rt_grid_new(big, 2, 1, 1, msg, sizeof msg);
    size_t m0 = 0, m1 = 0;
    rt_grid_cell_objects(g2, 0, &m0);
    rt_grid_cell_objects(g2, 1, &m1);
    check(m0 == 2 && m1 == 2, "premise: both cells list both spheres");
    MigrationCost held = migration_cost(big, g2, ring2, 2, timing, {0, 1}, {0, 0});
    check(held.bytes() == 4 + 4 * 2 && held.objects == 0, "held objects are not sent again: 12 bytes");
    check(std::fabs(held.time_s - 50e-6) < 1e-12, "12 bytes: one piece, 50 us");

    // With a bandwidth, bytes / rate.
    timing.link_bytes_per_us = 4;
    MigrationCost rate = migration_cost(scene, grid, ring2, 2, timing, {0, 1}, {0, 0});
    check(std::fabs(rate.time_s - static_cast<double>(want) / 4 * 1e-6) < 1e-12, "bandwidth: bytes / 4 us");

    rt_grid_free(g2);
    rt_scene_free(big);
    rt_grid_free(grid);
    rt_scene_free(scene);
    return harness::finish();
}
