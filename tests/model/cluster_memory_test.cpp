// cluster_memory_test.cpp - the cluster's data-memory figures against a hand count on a tiny
// scene, the placement rule, and the same figures through an elaborated clustered system that
// then renders the reference image.
//
// Scene (sizes from rt_scene.h: a sphere is 4 floats + a material index = 20 bytes, a material
// record 9 x 4 = 36 bytes; a cell list is 4 bytes + 4 per entry):
//   material A: sphere 0 at x = 0 (r 0.5), sphere 1 at x = 1.5 (r 0.5), sphere 2 at x = 3 (r 1.2)
//   material B: sphere 3 at x = 5.5 (r 0.5)
// Object space x in [-0.5, 6] (+ padding); 2 x 1 x 1 cells split at x = 2.75:
//   cell 0 lists {0, 1, 2} (sphere 2 spans 1.8 .. 4.2), cell 1 lists {2, 3}.
// Two nodes, node 0 owns cell 0, node 1 owns cell 1; m = 2 processors per node.
//   node 0: objects {0, 1, 2}, materials {A}, lists 4 + 3 x 4 = 16
//     replicated: 3 x 20 + 36 + 16 = 112 per processor
//     shared (j-th object to processor j mod 2): p0 {0, 2}: 40 + 36 + 16 = 92; p1 {1}: 20 + 36 + 16 = 72
//   node 1: objects {2, 3}, materials {A, B}, lists 4 + 2 x 4 = 12
//     replicated: 2 x 20 + 2 x 36 + 12 = 124 per processor
//     shared: p0 {2}: 20 + 36 + 12 = 68; p1 {3}: 20 + 36 + 12 = 68
//   largest: replicated 124, shared 92; x 4 processors: 496 and 368.
//   whole scene: 4 x 20 + 2 x 36 + (2 x 4 + 5 x 4) = 180; pixel-partitioned 180 x 4 = 720.
// With m = 3: node 0 each processor one object: 20 + 36 + 16 = 72; node 1: p0 {2} 68, p1 {3} 68,
// p2 nothing but the lists: 12. Largest shared 72 (replicated still 124).
// Prints one line per check and "N passed, M failed"; returns non-zero on failure.
#include <cstdio>
#include <string>
#include <systemc>
#include <vector>

#include "cluster_memory.h"
#include "cluster_node.h"
#include "packet_ledger.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_memory.h"
#include "rt_render.h"
#include "rt_scene.h"
#include "run_report.h"
#include "sim_config.h"
#include "torus_system.h"

using namespace torusrt;

namespace {

int g_passed = 0, g_failed = 0;

void check(bool ok, const std::string &what)
{
    std::printf("%s: %s\n", ok ? "PASS" : "FAIL", what.c_str());
    (ok ? g_passed : g_failed)++;
}

template <typename A, typename B> void check_eq(const A &got, const B &want, const std::string &what)
{
    check(got == static_cast<A>(want), what + " (got " + std::to_string(got) + ", want " + std::to_string(want) + ")");
}

rt_scene *tiny_scene()
{
    rt_scene *s = rt_scene_new();
    rt_scene_set_view(s, rt_vec(2.75, 0, 12), rt_vec(2.75, 0, 0), rt_vec(0, 1, 0), 40.0, 24, 8);
    rt_material a = rt_material_default();
    a.color = rt_vec(0.9, 0.2, 0.2);
    rt_scene_set_material(s, &a);
    rt_scene_add_sphere(s, rt_vec(0, 0, 0), 0.5);
    rt_scene_add_sphere(s, rt_vec(1.5, 0, 0), 0.5);
    rt_scene_add_sphere(s, rt_vec(3, 0, 0), 1.2);
    rt_material b = rt_material_default();
    b.color = rt_vec(0.2, 0.9, 0.2);
    b.ks = 0.3;
    rt_scene_set_material(s, &b);
    rt_scene_add_sphere(s, rt_vec(5.5, 0, 0), 0.5);
    rt_scene_add_light(s, rt_vec(2, 8, 10), nullptr);
    char msg[256];
    rt_scene_finish(s, msg, sizeof msg);
    return s;
}

std::vector<uint32_t> list_of(const rt_grid *g, size_t cell)
{
    size_t n = 0;
    const uint32_t *l = rt_grid_cell_objects(g, cell, &n);
    return std::vector<uint32_t>(l, l + n);
}

}  // namespace

int sc_main(int, char **)
{
    rt_scene *scene = tiny_scene();
    char msg[256] = "";
    rt_grid *grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
    check(grid != nullptr, "grid built");
    if (!grid) return 1;
    check(list_of(grid, 0) == std::vector<uint32_t>({0, 1, 2}), "cell 0 lists spheres 0 1 2 (hand count premise)");
    check(list_of(grid, 1) == std::vector<uint32_t>({2, 3}), "cell 1 lists spheres 2 3 (hand count premise)");
    check(rt_scene_object_bytes(scene, 0) == 20 && rt_scene_material_bytes() == 36, "sphere 20 bytes, material 36");
    int32_t owner[2] = {0, 1};

    // Placement.
    std::vector<uint32_t> n0 = cluster_node_objects(grid, owner, 0), n1 = cluster_node_objects(grid, owner, 1);
    check(n0 == std::vector<uint32_t>({0, 1, 2}) && n1 == std::vector<uint32_t>({2, 3}), "node objects ascending");
    check(shared_holder(n0, 0, 2) == 0 && shared_holder(n0, 1, 2) == 1 && shared_holder(n0, 2, 2) == 0 &&
              shared_holder(n1, 2, 2) == 0 && shared_holder(n1, 3, 2) == 1 && shared_holder(n0, 3, 2) == -1,
          "placement: j-th object of the node to processor j mod m; -1 if not in the node");

    // Figures, m = 2.
    ClusterMemoryFigures f = cluster_memory_figures(scene, grid, owner, 2, 2);
    check_eq(f.replicated_per_node[0], 112, "replicated node 0 per processor");
    check_eq(f.replicated_per_node[1], 124, "replicated node 1 per processor");
    check_eq(f.shared_per_ip[0][0], 92, "shared node 0 processor 0");
    check_eq(f.shared_per_ip[0][1], 72, "shared node 0 processor 1");
    check_eq(f.shared_per_ip[1][0], 68, "shared node 1 processor 0");
    check_eq(f.shared_per_ip[1][1], 68, "shared node 1 processor 1");
    check_eq(f.replicated_per_processor, 124, "replicated largest per processor");
    check_eq(f.shared_per_processor, 92, "shared largest per processor");
    rt_memory_use whole = rt_memory_whole_scene(scene, grid);
    check_eq(rt_memory_total(&whole), 180, "whole scene");
    nlohmann::json j = cluster_memory_report(f, DataMode::shared, 4, 720);
    check(j["max_per_ip_bytes"] == 92 && j["total_bytes"] == 368 && j["pixel_partitioned_bytes"] == 720 &&
              j["replicated_per_processor_bytes"] == 124 && j["replicated_total_bytes"] == 496 &&
              j["shared_per_processor_bytes"] == 92 && j["shared_total_bytes"] == 368,
          "report, shared: " + j.dump());
    nlohmann::json jr = cluster_memory_report(f, DataMode::replicated, 4, 720);
    check(jr["max_per_ip_bytes"] == 124 && jr["total_bytes"] == 496, "report, replicated: 124 x 4 = 496");

    // m = 3 and m = 1.
    ClusterMemoryFigures f3 = cluster_memory_figures(scene, grid, owner, 2, 3);
    check(f3.shared_per_ip[0] == std::vector<uint64_t>({72, 72, 72}) &&
              f3.shared_per_ip[1] == std::vector<uint64_t>({68, 68, 12}) && f3.shared_per_processor == 72 &&
              f3.replicated_per_processor == 124,
          "m = 3: 72 72 72 / 68 68 12, largest shared 72, replicated 124");
    ClusterMemoryFigures f1 = cluster_memory_figures(scene, grid, owner, 2, 1);
    check(f1.shared_per_processor == f1.replicated_per_processor, "m = 1: shared equals replicated");

    // The same through an elaborated 2-node system of 2-processor clusters, run to completion.
    SimConfig config;
    config.cells = {2, 1, 1};
    config.ips = {2, 1, 1};
    config.cluster = 2;
    config.data = DataMode::shared;
    rt_timing_defaults(&config.timing);
    config.step = rt_step_params_default();
    const rt_camera *cam = rt_scene_camera(scene);
    rt_framebuffer *fb = rt_framebuffer_new(cam->width, cam->height);
    PacketLedger ledger;
    TorusSystem top("top", config, scene, grid, owner, ledger, fb);
    MemoryReport mr = cluster_memory(config, scene, grid, owner, 720);
    nlohmann::json mj = cluster_memory_report(mr.cluster, config.data, config.processor_count(), 720);
    check(mr.max_per_ip_bytes == 92 && mr.total_bytes == 368 && mj["max_per_ip_bytes"] == 92 &&
              mj["total_bytes"] == 368 && mj["replicated_total_bytes"] == 496,
          "cluster_memory of the elaborated system");
    check(top.clusters().size() == 2 && top.processors().size() == 4, "2 clusters of 2 processors elaborated");
    check(top.clusters()[0]->memory(0).object_count() == 2 && top.clusters()[0]->memory(1).object_count() == 1 &&
              top.clusters()[0]->memory(0).holds(2) && !top.clusters()[0]->memory(0).holds(1),
          "node 0's memories hold {0, 2} and {1}");
    sc_core::sc_start();
    check(ledger.conserved() && ledger.outstanding() == 0, "run completes, packets conserved");
    std::vector<uint8_t> got(cam->width * cam->height * 3), want(got.size());
    rt_framebuffer_to_rgb8(fb, got.data());
    rt_framebuffer *ref = rt_framebuffer_new(cam->width, cam->height);
    rt_render_options o = rt_render_options_default();
    rt_render_stats st;
    rt_render(scene, grid, &o, ref, &st, msg, sizeof msg);
    rt_framebuffer_to_rgb8(ref, want.data());
    check(got == want, "image equals the reference renderer's");
    uint64_t reads = 0;
    for (const auto &cl : top.clusters()) reads += cl->bus().object_reads();
    check(reads > 0, "shared data: some objects were read over the bus (" + std::to_string(reads) + ")");

    rt_framebuffer_free(ref);
    rt_framebuffer_free(fb);
    rt_grid_free(grid);
    rt_scene_free(scene);
    std::printf("%d passed, %d failed\n", g_passed, g_failed);
    return g_failed == 0 ? 0 : 1;
}
