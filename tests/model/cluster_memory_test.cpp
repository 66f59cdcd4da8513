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
#include <string>
#include <systemc>
#include <vector>

#include "cluster_memory.h"
#include "cluster_node.h"
#include "model_test.h"
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

// The tiny scene on a 2 x 1 x 1 grid, cell i owned by node i.
class ClusterMemoryHandCount : public testing::Test {
  protected:
    void SetUp() override
    {
        scene = tiny_scene();
        char msg[256] = "";
        grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
        ASSERT_NE(grid, nullptr) << "grid built: " << msg;
    }
    void TearDown() override
    {
        rt_grid_free(grid);
        rt_scene_free(scene);
    }
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    int32_t owner[2] = {0, 1};
};

// What the elaborated 2-node system of 2-processor clusters held and did.
struct Outcome {
    uint64_t max_per_ip_bytes = 0, total_bytes = 0;
    nlohmann::json report;
    size_t clusters = 0, processors = 0;
    size_t node0_memory0_objects = 0, node0_memory1_objects = 0;
    bool node0_memory0_holds2 = false, node0_memory0_holds1 = true;
    bool conserved = false;
    uint64_t outstanding = 1, object_reads = 0;
    std::vector<uint8_t> image, reference;
};

void record_elaboration(TorusSystem &top, Outcome &run)
{
    run.clusters = top.clusters().size(), run.processors = top.processors().size();
    ClusterNode &node0 = *top.clusters()[0];
    run.node0_memory0_objects = node0.memory(0).object_count();
    run.node0_memory1_objects = node0.memory(1).object_count();
    run.node0_memory0_holds2 = node0.memory(0).holds(2), run.node0_memory0_holds1 = node0.memory(0).holds(1);
}

Outcome simulate()
{
    Outcome run;
    rt_scene *scene = tiny_scene();
    char msg[256] = "";
    rt_grid *grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
    if (!grid) return run;  // every check of the run then fails; HandCountPremises says why
    int32_t owner[2] = {0, 1};
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
    run.max_per_ip_bytes = mr.max_per_ip_bytes, run.total_bytes = mr.total_bytes;
    run.report = cluster_memory_report(mr.cluster, config.data, config.processor_count(), 720);
    record_elaboration(top, run);
    sc_core::sc_start();

    run.conserved = ledger.conserved(), run.outstanding = ledger.outstanding();
    run.image.resize(cam->width * cam->height * 3), run.reference.resize(run.image.size());
    rt_framebuffer_to_rgb8(fb, run.image.data());
    rt_framebuffer *ref = rt_framebuffer_new(cam->width, cam->height);
    rt_render_options o = rt_render_options_default();
    rt_render_stats st;
    rt_render(scene, grid, &o, ref, &st, msg, sizeof msg);
    rt_framebuffer_to_rgb8(ref, run.reference.data());
    for (const auto &cl : top.clusters()) run.object_reads += cl->bus().object_reads();
    rt_framebuffer_free(ref);
    rt_framebuffer_free(fb);
    rt_grid_free(grid);
    rt_scene_free(scene);
    return run;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST_F(ClusterMemoryHandCount, HandCountPremises)
{
    EXPECT_EQ(list_of(grid, 0), std::vector<uint32_t>({0, 1, 2})) << "cell 0 lists spheres 0 1 2";
    EXPECT_EQ(list_of(grid, 1), std::vector<uint32_t>({2, 3})) << "cell 1 lists spheres 2 3";
    EXPECT_EQ(rt_scene_object_bytes(scene, 0), 20u) << "sphere 20 bytes";
    EXPECT_EQ(rt_scene_material_bytes(), 36u) << "material 36 bytes";
}

TEST_F(ClusterMemoryHandCount, PlacesTheJthObjectOfTheNodeOnProcessorJModM)
{
    std::vector<uint32_t> n0 = cluster_node_objects(grid, owner, 0), n1 = cluster_node_objects(grid, owner, 1);
    EXPECT_EQ(n0, std::vector<uint32_t>({0, 1, 2})) << "node objects ascending";
    EXPECT_EQ(n1, std::vector<uint32_t>({2, 3})) << "node objects ascending";
    EXPECT_EQ(shared_holder(n0, 0, 2), 0);
    EXPECT_EQ(shared_holder(n0, 1, 2), 1);
    EXPECT_EQ(shared_holder(n0, 2, 2), 0);
    EXPECT_EQ(shared_holder(n1, 2, 2), 0);
    EXPECT_EQ(shared_holder(n1, 3, 2), 1);
    EXPECT_EQ(shared_holder(n0, 3, 2), -1) << "-1 if not in the node";
}

TEST_F(ClusterMemoryHandCount, FiguresWithTwoProcessorsPerNode)
{
    ClusterMemoryFigures f = cluster_memory_figures(scene, grid, owner, 2, 2);
    EXPECT_EQ(f.replicated_per_node[0], 112u) << "replicated node 0 per processor: 3 x 20 + 36 + 16";
    EXPECT_EQ(f.replicated_per_node[1], 124u) << "replicated node 1 per processor: 2 x 20 + 2 x 36 + 12";
    EXPECT_EQ(f.shared_per_ip[0][0], 92u) << "shared node 0 processor 0: 40 + 36 + 16";
    EXPECT_EQ(f.shared_per_ip[0][1], 72u) << "shared node 0 processor 1: 20 + 36 + 16";
    EXPECT_EQ(f.shared_per_ip[1][0], 68u) << "shared node 1 processor 0: 20 + 36 + 12";
    EXPECT_EQ(f.shared_per_ip[1][1], 68u) << "shared node 1 processor 1: 20 + 36 + 12";
    EXPECT_EQ(f.replicated_per_processor, 124u) << "replicated largest per processor";
    EXPECT_EQ(f.shared_per_processor, 92u) << "shared largest per processor";
}

TEST_F(ClusterMemoryHandCount, WholeSceneFigure)
{
    rt_memory_use whole = rt_memory_whole_scene(scene, grid);
    EXPECT_EQ(rt_memory_total(&whole), 180u) << "4 x 20 + 2 x 36 + (2 x 4 + 5 x 4)";
}

TEST_F(ClusterMemoryHandCount, ReportsSharedAndReplicated)
{
    ClusterMemoryFigures f = cluster_memory_figures(scene, grid, owner, 2, 2);
    nlohmann::json j = cluster_memory_report(f, DataMode::shared, 4, 720);
    EXPECT_TRUE(j["max_per_ip_bytes"] == 92 && j["total_bytes"] == 368 && j["pixel_partitioned_bytes"] == 720 &&
                j["replicated_per_processor_bytes"] == 124 && j["replicated_total_bytes"] == 496 &&
                j["shared_per_processor_bytes"] == 92 && j["shared_total_bytes"] == 368)
        << "report, shared: " << j.dump();
    nlohmann::json jr = cluster_memory_report(f, DataMode::replicated, 4, 720);
    EXPECT_TRUE(jr["max_per_ip_bytes"] == 124 && jr["total_bytes"] == 496) << "report, replicated: 124 x 4 = 496";
}

TEST_F(ClusterMemoryHandCount, FiguresWithThreeAndOneProcessorsPerNode)
{
    ClusterMemoryFigures f3 = cluster_memory_figures(scene, grid, owner, 2, 3);
    EXPECT_EQ(f3.shared_per_ip[0], std::vector<uint64_t>({72, 72, 72}));
    EXPECT_EQ(f3.shared_per_ip[1], std::vector<uint64_t>({68, 68, 12}));
    EXPECT_EQ(f3.shared_per_processor, 72u) << "largest shared 72";
    EXPECT_EQ(f3.replicated_per_processor, 124u) << "replicated still 124";
    ClusterMemoryFigures f1 = cluster_memory_figures(scene, grid, owner, 2, 1);
    EXPECT_EQ(f1.shared_per_processor, f1.replicated_per_processor) << "m = 1: shared equals replicated";
}

TEST(ClusterMemory, FiguresOfTheElaboratedSystem)
{
    EXPECT_TRUE(run().max_per_ip_bytes == 92 && run().total_bytes == 368 && run().report["max_per_ip_bytes"] == 92 &&
                run().report["total_bytes"] == 368 && run().report["replicated_total_bytes"] == 496)
        << "cluster_memory of the elaborated system: " << run().report.dump();
}

TEST(ClusterMemory, ElaboratesTheClustersAndTheirMemories)
{
    EXPECT_EQ(run().clusters, 2u) << "2 clusters";
    EXPECT_EQ(run().processors, 4u) << "of 2 processors";
    EXPECT_EQ(run().node0_memory0_objects, 2u) << "node 0's memory 0 holds {0, 2}";
    EXPECT_EQ(run().node0_memory1_objects, 1u) << "node 0's memory 1 holds {1}";
    EXPECT_TRUE(run().node0_memory0_holds2 && !run().node0_memory0_holds1);
}

TEST(ClusterMemory, RunRendersTheReferenceImage)
{
    EXPECT_TRUE(run().conserved) << "packets conserved";
    EXPECT_EQ(run().outstanding, 0u) << "run completes";
    EXPECT_TRUE(run().image == run().reference) << "image equals the reference renderer's";
}

TEST(ClusterMemory, SharedDataReadsObjectsOverTheBus)
{
    EXPECT_GT(run().object_reads, 0u) << "shared data: some objects were read over the bus";
}
