// mapping_test.cpp - cell-to-processor mappings and the memory they need.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "rt_grid.h"
#include "rt_mapping.h"
#include "rt_memory.h"
#include "rt_scene.h"

#include "test_support.h"

using namespace torusrt_test;

namespace {

std::vector<int> owners_1d(rt_map_kind kind, int block, int cells, int procs)
{
    std::vector<int> v;
    for (int c = 0; c < cells; c++) v.push_back(rt_mapping_axis_owner(kind, block, c, cells, procs));
    return v;
}

}  // namespace

TEST(MappingAxis, TwentyFourCellsOverFour)
{
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK, 0, 24, 4),
              (std::vector<int>{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3}));
    EXPECT_EQ(owners_1d(RT_MAP_CYCLIC, 0, 24, 4),
              (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}));
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, 2, 24, 4),
              (std::vector<int>{0, 0, 1, 1, 2, 2, 3, 3, 0, 0, 1, 1, 2, 2, 3, 3, 0, 0, 1, 1, 2, 2, 3, 3}));
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, 3, 24, 4),
              (std::vector<int>{0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}));
}

TEST(MappingAxis, TenCellsOverThree)
{
    // floor(c * 3 / 10): blocks of 4, 3, 3.
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK, 0, 10, 3), (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 2, 2, 2}));
    EXPECT_EQ(owners_1d(RT_MAP_CYCLIC, 0, 10, 3), (std::vector<int>{0, 1, 2, 0, 1, 2, 0, 1, 2, 0}));
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, 2, 10, 3), (std::vector<int>{0, 0, 1, 1, 2, 2, 0, 0, 1, 1}));
}

TEST(MappingAxis, BlockCyclicSpecialCases)
{
    for (int n = 1; n <= 48; n++)
        for (int p = 1; p <= n; p++) {
            EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, 1, n, p), owners_1d(RT_MAP_CYCLIC, 0, n, p)) << n << "/" << p;
            if (n % p == 0) {
                EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, n / p, n, p), owners_1d(RT_MAP_BLOCK, 0, n, p))
                    << n << "/" << p;
            }
        }
}

TEST(MappingAxis, EveryProcessorOwnsCellsWhenNotMoreThanCells)
{
    for (rt_map_kind kind : {RT_MAP_BLOCK, RT_MAP_CYCLIC, RT_MAP_BLOCK_CYCLIC})
        for (int n = 1; n <= 40; n++)
            for (int p = 1; p <= n; p++) {
                // Block-cyclic with the largest block that still reaches every processor.
                int block = kind == RT_MAP_BLOCK_CYCLIC ? std::max(1, n / p) : 0;
                std::vector<int> o = owners_1d(kind, block, n, p);
                std::set<int> used(o.begin(), o.end());
                EXPECT_EQ(int(used.size()), p) << "kind " << kind << " " << n << "/" << p;
                EXPECT_GE(*used.begin(), 0);
                EXPECT_LT(*used.rbegin(), p);
                if (kind == RT_MAP_BLOCK) {
                    EXPECT_TRUE(std::is_sorted(o.begin(), o.end()));
                }
            }
}

TEST(MappingAxis, MoreProcessorsThanCells)
{
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK, 0, 3, 8), (std::vector<int>{0, 2, 5}));
    EXPECT_EQ(owners_1d(RT_MAP_CYCLIC, 0, 3, 8), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(owners_1d(RT_MAP_BLOCK_CYCLIC, 2, 3, 8), (std::vector<int>{0, 0, 1}));
}

TEST(MappingAxis, InvalidArgumentsGiveMinusOne)
{
    EXPECT_EQ(rt_mapping_axis_owner(RT_MAP_CYCLIC, 0, 0, 10, 0), -1);
    EXPECT_EQ(rt_mapping_axis_owner(RT_MAP_BLOCK_CYCLIC, 0, 0, 10, 2), -1);
    EXPECT_EQ(rt_mapping_axis_owner(RT_MAP_BLOCK, 0, 10, 10, 2), -1);
}

TEST(MappingFill, ThreeDimensionalIds)
{
    const int cells[3] = {4, 3, 2}, procs[3] = {2, 3, 2};
    std::vector<int32_t> owner(24, -7);
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_mapping_fill(cells, procs, RT_MAP_CYCLIC, 0, owner.data(), msg, sizeof msg), RT_OK) << msg;
    for (int z = 0; z < 2; z++)
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 4; x++) {
                const int32_t c[3] = {x, y, z};
                EXPECT_EQ(owner[rt_grid_index(cells, c)], (x % 2) + 2 * (y % 3 + 3 * (z % 2)));
            }
    ASSERT_EQ(rt_mapping_fill(cells, procs, RT_MAP_BLOCK, 0, owner.data(), msg, sizeof msg), RT_OK) << msg;
    const int32_t last[3] = {3, 2, 1};
    EXPECT_EQ(owner[rt_grid_index(cells, last)], 1 + 2 * (2 + 3 * 1));
    const int32_t first[3] = {1, 0, 0};
    EXPECT_EQ(owner[rt_grid_index(cells, first)], 0);
}

TEST(MappingFill, MoreProcessorsThanCellsWorks)
{
    const int cells[3] = {2, 2, 2}, procs[3] = {4, 4, 4};
    std::vector<int32_t> owner(8, -1);
    char msg[RT_MSG_LEN] = "";
    for (rt_map_kind kind : {RT_MAP_BLOCK, RT_MAP_CYCLIC, RT_MAP_BLOCK_CYCLIC}) {
        ASSERT_EQ(rt_mapping_fill(cells, procs, kind, 1, owner.data(), msg, sizeof msg), RT_OK) << msg;
        std::set<int32_t> used(owner.begin(), owner.end());
        EXPECT_EQ(used.size(), 8u);  // each cell its own processor
        for (int32_t o : owner) EXPECT_TRUE(o >= 0 && o < 64);
    }
}

TEST(MappingFill, RejectsBadArguments)
{
    const int cells[3] = {4, 4, 4};
    std::vector<int32_t> owner(64);
    char msg[RT_MSG_LEN] = "";
    const int zero[3] = {2, 0, 2};
    EXPECT_EQ(rt_mapping_fill(cells, zero, RT_MAP_BLOCK, 0, owner.data(), msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("2x0x2"), std::string::npos) << msg;
    const int procs[3] = {2, 2, 2};
    EXPECT_EQ(rt_mapping_fill(cells, procs, RT_MAP_BLOCK_CYCLIC, 0, owner.data(), msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("block"), std::string::npos) << msg;
    // The block size matters only for block-cyclic.
    EXPECT_EQ(rt_mapping_fill(cells, procs, RT_MAP_CYCLIC, 0, owner.data(), msg, sizeof msg), RT_OK);
}

// Hand count: s0 (0,0,0) r 1 with material 0; s1 (4,0,0) r 1 and the
// triangle (6,-1,0) (8,-1,0) (7,1,.5) with material 1. Object space x in
// [-1, 8] (+pad), split at x = 3.5: cell 0 lists {s0, s1}, cell 1 {s1, t2}.
// Sizes: sphere 20 bytes, triangle 88, material 36.
//   owner 0: objects s0 s1 = 40, materials 0 and 1 = 72, lists 4 + 2*4 = 12
//   owner 1: objects s1 t2 = 108, material 1 = 36, lists 4 + 2*4 = 12
//   whole:   objects 128, materials 72, lists 2*4 + 4*4 = 24
TEST(Memory, HandCountTinyScene)
{
    ScenePtr s(rt_scene_new());
    rt_material m0 = rt_material_default(), m1 = rt_material_default();
    m1.ks = 0.5;
    ASSERT_EQ(rt_scene_set_material(s.get(), &m0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m1), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(4, 0, 0), 1.0), RT_OK);
    rt_vec3 v[3] = {rt_vec(6, -1, 0), rt_vec(8, -1, 0), rt_vec(7, 1, 0.5)};
    rt_vec3 n[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    ASSERT_EQ(rt_scene_add_patch(s.get(), v, n, 3), RT_OK);
    ASSERT_EQ(rt_scene_object_bytes(s.get(), 0), 20u);
    ASSERT_EQ(rt_scene_object_bytes(s.get(), 2), 88u);
    ASSERT_EQ(rt_scene_material_bytes(), 36u);

    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new(s.get(), 2, 1, 1, msg, sizeof msg));
    ASSERT_TRUE(g) << msg;
    size_t count;
    const uint32_t *l0 = rt_grid_cell_objects(g.get(), 0, &count);
    ASSERT_EQ(std::vector<uint32_t>(l0, l0 + count), (std::vector<uint32_t>{0, 1}));
    const uint32_t *l1 = rt_grid_cell_objects(g.get(), 1, &count);
    ASSERT_EQ(std::vector<uint32_t>(l1, l1 + count), (std::vector<uint32_t>{1, 2}));

    const int32_t owner[2] = {0, 1};
    rt_memory_use use[2];
    ASSERT_EQ(rt_memory_per_owner(s.get(), g.get(), owner, 2, use), RT_OK);
    EXPECT_EQ(use[0].objects, 2u);
    EXPECT_EQ(use[0].object_bytes, 40u);
    EXPECT_EQ(use[0].material_bytes, 72u);
    EXPECT_EQ(use[0].list_bytes, 12u);
    EXPECT_EQ(rt_memory_total(&use[0]), 124u);
    EXPECT_EQ(use[1].objects, 2u);
    EXPECT_EQ(use[1].object_bytes, 108u);
    EXPECT_EQ(use[1].material_bytes, 36u);
    EXPECT_EQ(use[1].list_bytes, 12u);
    EXPECT_EQ(rt_memory_total(&use[1]), 156u);

    rt_memory_use whole = rt_memory_whole_scene(s.get(), g.get());
    EXPECT_EQ(whole.objects, 3u);
    EXPECT_EQ(whole.object_bytes, 128u);
    EXPECT_EQ(whole.material_bytes, 72u);
    EXPECT_EQ(whole.list_bytes, 24u);
    EXPECT_EQ(rt_memory_total(&whole), 224u);

    // One owner of both cells stores s1 and material 1 once.
    const int32_t single[2] = {0, 0};
    ASSERT_EQ(rt_memory_per_owner(s.get(), g.get(), single, 1, use), RT_OK);
    EXPECT_EQ(use[0].objects, 3u);
    EXPECT_EQ(rt_memory_total(&use[0]), 224u);

    // Cells with an owner outside 0..owners-1 are skipped.
    const int32_t partial[2] = {-1, 0};
    ASSERT_EQ(rt_memory_per_owner(s.get(), g.get(), partial, 1, use), RT_OK);
    EXPECT_EQ(rt_memory_total(&use[0]), 156u);
    EXPECT_EQ(rt_memory_per_owner(s.get(), g.get(), owner, 0, use), RT_ERR_INVALID);
}

TEST(Memory, WholeSceneBoundsEveryOwner)
{
    ScenePtr s(rt_scene_new());
    uint64_t state = 12345;
    auto rnd = [&]() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 200; i++) {
        if (i % 40 == 0) {
            rt_material m = rt_material_default();
            m.kd = rnd();
            ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
        }
        ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(rnd() * 50, rnd() * 50, rnd() * 50), 0.5 + 3 * rnd()), RT_OK);
    }
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new(s.get(), 12, 12, 12, msg, sizeof msg));
    ASSERT_TRUE(g) << msg;
    const int cells[3] = {12, 12, 12}, procs[3] = {2, 2, 2};
    std::vector<int32_t> owner(12 * 12 * 12);
    for (rt_map_kind kind : {RT_MAP_BLOCK, RT_MAP_CYCLIC}) {
        ASSERT_EQ(rt_mapping_fill(cells, procs, kind, 0, owner.data(), msg, sizeof msg), RT_OK);
        std::vector<rt_memory_use> use(8);
        ASSERT_EQ(rt_memory_per_owner(s.get(), g.get(), owner.data(), 8, use.data()), RT_OK);
        rt_memory_use whole = rt_memory_whole_scene(s.get(), g.get());
        uint64_t lists = 0;
        for (const rt_memory_use &u : use) {
            EXPECT_LE(rt_memory_total(&u), rt_memory_total(&whole));
            EXPECT_LE(u.objects, whole.objects);
            EXPECT_LE(u.material_bytes, whole.material_bytes);
            lists += u.list_bytes;
        }
        EXPECT_EQ(lists, whole.list_bytes);  // every cell owned exactly once
    }
}

// The cost pilot and the Scotch mapping (rt_cost_map.h).
#include "rt_cost_map.h"
#include "rt_render.h"
#include "rt_nff.h"

namespace {

struct PilotScene {
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    ~PilotScene()
    {
        rt_grid_free(grid);
        rt_scene_free(scene);
    }
};

}  // namespace

TEST(CostMap, PilotWorkSumsToTheRenderersTimeAndTrafficToItsHandOvers)
{
    PilotScene s;
    char msg[RT_MSG_LEN] = "";
    std::string path = std::string(TORUSRT_SOURCE_DIR) + "/scenes/paper-image2.nff";
    ASSERT_EQ(rt_nff_load(path.c_str(), &s.scene, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    ASSERT_EQ(rt_scene_set_resolution(s.scene, 32, 32), RT_OK);
    s.grid = rt_grid_new(s.scene, 6, 5, 4, msg, sizeof msg);
    ASSERT_NE(s.grid, nullptr) << msg;
    rt_timing t;
    rt_timing_defaults(&t);
    rt_step_params prm = rt_step_params_default();
    rt_cost_pilot pilot;
    ASSERT_EQ(rt_cost_pilot_run(s.scene, s.grid, &prm, &t, &pilot, msg, sizeof msg), RT_OK) << msg;
    // The reference renderer's T(1) from its op counts.
    rt_framebuffer *fb = rt_framebuffer_new(32, 32);
    rt_render_options o = rt_render_options_default();
    rt_render_stats st;
    ASSERT_EQ(rt_render(s.scene, s.grid, &o, fb, &st, msg, sizeof msg), RT_OK) << msg;
    rt_framebuffer_free(fb);
    EXPECT_EQ(pilot.total_us, rt_timing_step_us(&t, &st.ops)) << "integer-valued table: exact";
    uint64_t faces = 0;
    for (size_t i = 0; i < pilot.cells * RT_CELL_FACES; i++) faces += pilot.traffic[i];
    EXPECT_EQ(faces, pilot.ops.handovers_sent) << "every hand-over crosses one face";
    EXPECT_EQ(pilot.ops.handovers_sent, pilot.ops.handovers_received);
    EXPECT_GT(faces, 0u);
    // No packet leaves through the grid's outer faces into nothing.
    for (size_t c = 0; c < pilot.cells; c++) {
        int x = (int)(c % 6);
        EXPECT_EQ(x == 0 ? pilot.traffic[c * RT_CELL_FACES + 0] : 0u, 0u) << "cell " << c;
    }
    for (int torus = 0; torus <= 1; torus++) {
        int nodes[3] = {3, 2, 1};
        std::vector<int32_t> owner(pilot.cells, -1), again(pilot.cells, -2);
        rt_cost_map_facts f;
        const rt_topology topo = torusrt_test::make_topology(torus ? "torus" : "mesh", nodes);
        ASSERT_EQ(rt_cost_map(&pilot, &topo, rt_cost_edge_us(&t), owner.data(), &f, msg, sizeof msg), RT_OK) << msg;
        std::vector<int> used(6, 0);
        for (int32_t n : owner) {
            ASSERT_GE(n, 0);
            ASSERT_LT(n, 6);
            used[n]++;
        }
        for (int n = 0; n < 6; n++) EXPECT_GT(used[n], 0) << "node " << n << " got no cell";
        EXPECT_GE(f.max_node_work_us, f.mean_node_work_us);
        EXPECT_GE(f.cut_hops, f.cut_packets);
        ASSERT_EQ(rt_cost_map(&pilot, &topo, rt_cost_edge_us(&t), again.data(), nullptr, msg, sizeof msg), RT_OK);
        EXPECT_EQ(owner, again) << "reproducible";
    }
    {  // Folded: fold 1 is the plain mapping; fold 2 still uses only real nodes, every one.
        int nodes[3] = {2, 2, 1};
        std::vector<int32_t> plain(pilot.cells), one(pilot.cells), two(pilot.cells);
        double e = rt_cost_edge_us(&t);
        const rt_topology topo = torusrt_test::make_topology("torus", nodes);
        ASSERT_EQ(rt_cost_map(&pilot, &topo, e, plain.data(), nullptr, msg, sizeof msg), RT_OK) << msg;
        ASSERT_EQ(rt_cost_map_folded(&pilot, &topo, e, 1, one.data(), nullptr, msg, sizeof msg), RT_OK) << msg;
        ASSERT_EQ(rt_cost_map_folded(&pilot, &topo, e, 2, two.data(), nullptr, msg, sizeof msg), RT_OK) << msg;
        EXPECT_EQ(plain, one);
        std::set<int32_t> used(two.begin(), two.end());
        EXPECT_EQ(used.size(), 4u);
        EXPECT_GE(*used.begin(), 0);
        EXPECT_LE(*used.rbegin(), 3);
        EXPECT_EQ(rt_cost_map_folded(&pilot, &topo, e, 0, two.data(), nullptr, msg, sizeof msg), RT_ERR_INVALID);
    }
    int bad[3] = {0, 1, 1};
    rt_topology none;
    EXPECT_EQ(rt_topology_make("torus", bad, &none, msg, sizeof msg), RT_ERR_INVALID) << "no machine of 0 nodes";
    std::vector<int32_t> owner(pilot.cells);
    EXPECT_EQ(rt_cost_map(&pilot, nullptr, 1.0, owner.data(), nullptr, msg, sizeof msg), RT_ERR_INVALID);
    rt_cost_pilot_release(&pilot);
}
