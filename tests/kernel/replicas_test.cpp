// replicas_test.cpp - the replica table (rt_replicas.h), its memory (rt_memory_per_owner_replicas),
// the greedy replication of the cost mapping (rt_cost_replicate) and map files of version 2.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rt_cost_map.h"
#include "rt_map_file.h"
#include "rt_memory.h"
#include "rt_replicas.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

// The tiny scene of Memory.HandCountTinyScene (mapping_test.cpp): cell 0 lists {s0, s1}, cell 1
// {s1, t2}; s0 material 0, s1 and t2 material 1; sphere 20 bytes, triangle 88, material 36.
struct Tiny {
    ScenePtr scene;
    GridPtr grid;
};

Tiny tiny()
{
    Tiny t{ScenePtr(rt_scene_new()), nullptr};
    rt_material m0 = rt_material_default(), m1 = rt_material_default();
    m1.ks = 0.5;
    rt_scene_set_material(t.scene.get(), &m0);
    rt_scene_add_sphere(t.scene.get(), rt_vec(0, 0, 0), 1.0);
    rt_scene_set_material(t.scene.get(), &m1);
    rt_scene_add_sphere(t.scene.get(), rt_vec(4, 0, 0), 1.0);
    rt_vec3 v[3] = {rt_vec(6, -1, 0), rt_vec(8, -1, 0), rt_vec(7, 1, 0.5)};
    rt_vec3 n[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    rt_scene_add_patch(t.scene.get(), v, n, 3);
    char msg[RT_MSG_LEN] = "";
    t.grid.reset(rt_grid_new(t.scene.get(), 2, 1, 1, msg, sizeof msg));
    return t;
}

}  // namespace

TEST(Replicas, HoldsAndOwnersInOrder)
{
    const int32_t owner[3] = {5, 2, 0};
    const uint32_t first[4] = {0, 2, 2, 3};
    const int32_t extra[3] = {1, 7, 4};
    rt_replicas r{first, extra};
    EXPECT_TRUE(rt_replicas_holds(&r, owner, 0, 5));
    EXPECT_TRUE(rt_replicas_holds(&r, owner, 0, 7));
    EXPECT_FALSE(rt_replicas_holds(&r, owner, 0, 2));
    EXPECT_FALSE(rt_replicas_holds(&r, owner, 1, 1));
    EXPECT_FALSE(rt_replicas_holds(nullptr, owner, 0, 7));  // no table: the primary owner only
    EXPECT_EQ(rt_replicas_extra_count(&r, 0), 2u);
    EXPECT_EQ(rt_replicas_extra_count(&r, 1), 0u);
    // Owners of cell 0 ascending: 1, 5, 7 (the primary in its place).
    EXPECT_EQ(rt_replicas_owner_at(&r, owner, 0, 0), 1);
    EXPECT_EQ(rt_replicas_owner_at(&r, owner, 0, 1), 5);
    EXPECT_EQ(rt_replicas_owner_at(&r, owner, 0, 2), 7);
    EXPECT_EQ(rt_replicas_owner_at(&r, owner, 2, 0), 0);  // 0, then 4
    EXPECT_EQ(rt_replicas_owner_at(&r, owner, 2, 1), 4);
    size_t cells = 0, copies = 0;
    rt_replicas_count(&r, 3, &cells, &copies);
    EXPECT_EQ(cells, 2u);
    EXPECT_EQ(copies, 3u);
}

// Cell 1 copied onto owner 0: owner 0 then holds s0, s1, t2, both materials and both lists
// (20 + 20 + 88 + 72 + 24 = 224, as one owner of both cells); owner 1 is unchanged (156).
TEST(Replicas, MemoryCountsEveryCopy)
{
    Tiny t = tiny();
    ASSERT_TRUE(t.grid);
    const int32_t owner[2] = {0, 1};
    const uint32_t first[3] = {0, 0, 1};
    const int32_t extra[1] = {0};
    rt_replicas r{first, extra};
    rt_memory_use use[2];
    ASSERT_EQ(rt_memory_per_owner_replicas(t.scene.get(), t.grid.get(), owner, &r, 2, nullptr, use), RT_OK);
    EXPECT_EQ(use[0].objects, 3u);
    EXPECT_EQ(rt_memory_total(&use[0]), 224u);
    EXPECT_EQ(rt_memory_total(&use[1]), 156u);
    ASSERT_EQ(rt_memory_per_owner_replicas(t.scene.get(), t.grid.get(), owner, nullptr, 2, nullptr, use), RT_OK);
    EXPECT_EQ(rt_memory_total(&use[0]), 124u);  // no table: as rt_memory_per_owner
}

// Pilot work 1 us (cell 0, node 0) and 9 us (cell 1, node 1); data 124 and 156 bytes; the hash
// rule's prediction (an even split).
//   fraction 1: room 124 and 156. Round 1: the busiest is node 1, its cell 1 (9 us); node 0
//   takes a copy for 12 (list) + 88 (t2) bytes, ending at 1 + 4.5 = 5.5 < 9, node 1 at 4.5.
//   Round 2: the busiest is node 0 (5.5); cell 1 has no new owner left; cell 0 (1 us) goes to
//   node 1 for 12 + 20 (s0) + 36 (material 0) = 68 <= 156 bytes: both end at 5.0 < 5.5.
//   Round 3: node 0 (5.0, the lower of a tie) has nothing left to copy: stop.
//   fraction 0.5: room 62 and 78; the copy of cell 1 (100 bytes) does not fit in node 0, and no
//   copy of it can lower node 1 elsewhere: no copies, the busiest stays at 9.
TEST(Replicas, CostReplicationByHand)
{
    Tiny t = tiny();
    ASSERT_TRUE(t.grid);
    double work[2] = {1, 9};
    uint64_t traffic[2 * RT_CELL_FACES] = {};
    rt_cost_pilot pilot{{2, 1, 1}, 2, work, traffic, 10, {}, nullptr, 0};
    const int two[3] = {2, 1, 1};
    const rt_topology two_nodes = torusrt_test::make_topology("torus", two);
    const int32_t owner[2] = {0, 1};
    uint32_t first[3];
    int32_t *extra = nullptr;
    size_t count = 0;
    rt_cost_map_facts facts{};
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_cost_replicate(&pilot, t.scene.get(), t.grid.get(), &two_nodes, RT_REPLICA_HASH, owner, 1.0, nullptr,
                                first, &extra, &count, &facts, msg, sizeof msg),
              RT_OK)
        << msg;
    ASSERT_EQ(count, 2u);
    EXPECT_EQ(std::vector<uint32_t>(first, first + 3), (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(extra[0], 1);  // cell 0 also on node 1
    EXPECT_EQ(extra[1], 0);  // cell 1 also on node 0
    EXPECT_DOUBLE_EQ(facts.max_node_work_us, 5.0);
    std::free(extra);
    ASSERT_EQ(rt_cost_replicate(&pilot, t.scene.get(), t.grid.get(), &two_nodes, RT_REPLICA_HASH, owner, 0.5, nullptr,
                                first, &extra, &count, &facts, msg, sizeof msg),
              RT_OK);
    EXPECT_EQ(count, 0u);
    EXPECT_EQ(first[2], 0u);
    EXPECT_DOUBLE_EQ(facts.max_node_work_us, 9.0);
    std::free(extra);
}

namespace {

std::string written(const int dims[3], int nodes, const int32_t *owner, const rt_replicas *r)
{
    char *buf = nullptr;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    char msg[RT_MSG_LEN] = "";
    rt_status st = rt_map_file_write_replicas(f, "mem.map", dims, nodes, owner, r, msg, sizeof msg);
    std::fclose(f);
    std::string text = st == RT_OK ? std::string(buf, len) : "";
    std::free(buf);
    return text;
}

// Parses `text` as a table of 2x3x1 cells on 8 nodes; "" on success, else the message.
std::string parse(const std::string &text, int32_t *owner, uint32_t *first, std::vector<int32_t> &extra)
{
    const int dims[3] = {2, 3, 1};
    int32_t *e = nullptr;
    size_t count = 0;
    char msg[RT_MSG_LEN] = "";
    rt_status st = rt_map_file_parse_replicas("t.map", text.data(), text.size(), dims, 8, owner, first, &e, &count, msg,
                                              sizeof msg);
    extra.assign(e, e + count);
    std::free(e);
    return st == RT_OK ? "" : msg;
}

}  // namespace

TEST(MapFileV2, RoundTripWithSeveralOwners)
{
    const int dims[3] = {2, 3, 1};
    const int32_t owner[6] = {0, 1, 2, 3, 4, 5};
    const uint32_t first[7] = {0, 0, 3, 3, 4, 4, 4};
    const int32_t extra[4] = {0, 5, 7, 6};
    rt_replicas r{first, extra};
    std::string text = written(dims, 8, owner, &r);
    EXPECT_EQ(text.rfind("torusrt-map 2 2 3 1 8\n", 0), 0u) << text;
    EXPECT_NE(text.find("0 1,0,5,7\n"), std::string::npos) << text;
    int32_t back[6];
    uint32_t back_first[7];
    std::vector<int32_t> back_extra;
    ASSERT_EQ(parse(text, back, back_first, back_extra), "");
    EXPECT_EQ(std::vector<int32_t>(back, back + 6), std::vector<int32_t>(owner, owner + 6));
    EXPECT_EQ(std::vector<uint32_t>(back_first, back_first + 7), std::vector<uint32_t>(first, first + 7));
    EXPECT_EQ(back_extra, std::vector<int32_t>(extra, extra + 4));
    // Extra owners in any order are read ascending; the primary owner is the first listed.
    ASSERT_EQ(parse("torusrt-map 2 2 3 1 8\n0 1,7,5,0 2 3,6 4 5\n", back, back_first, back_extra), "");
    EXPECT_EQ(back[1], 1);
    EXPECT_EQ(back_extra, std::vector<int32_t>(extra, extra + 4));
}

TEST(MapFileV2, OneOwnerTablesStayVersionOne)
{
    const int dims[3] = {2, 3, 1};
    const int32_t owner[6] = {0, 1, 2, 3, 4, 5};
    const uint32_t none[7] = {0, 0, 0, 0, 0, 0, 0};
    rt_replicas r{none, nullptr};
    std::string text = written(dims, 8, owner, &r);
    EXPECT_EQ(text, written(dims, 8, owner, nullptr));
    EXPECT_EQ(text.rfind("torusrt-map 1 2 3 1 8\n", 0), 0u) << text;
    int32_t back[6];
    uint32_t back_first[7];
    std::vector<int32_t> back_extra;
    ASSERT_EQ(parse(text, back, back_first, back_extra), "");  // version 1 is still read
    EXPECT_EQ(std::vector<int32_t>(back, back + 6), std::vector<int32_t>(owner, owner + 6));
    EXPECT_TRUE(back_extra.empty());
    EXPECT_EQ(back_first[6], 0u);
}

TEST(MapFileV2, BadEntriesNameFileAndLine)
{
    int32_t owner[6];
    uint32_t first[7];
    std::vector<int32_t> extra;
    auto starts = [&](const char *text, const char *message) {
        std::string got = parse(text, owner, first, extra);
        EXPECT_EQ(got.rfind(message, 0), 0u) << got;
    };
    starts("torusrt-map 1 2 3 1 8\n0 1,2\n2 3 4 5\n", "t.map:2: several owners");
    starts("torusrt-map 2 2 3 1 8\n0 1\n2 3,3 4 5\n", "t.map:3: cell 3: node 3 listed twice");
    starts("torusrt-map 2 2 3 1 8\n0 1\n2 3,1,1 4 5\n", "t.map:3: cell 3: node 1 listed twice");
    starts("torusrt-map 2 2 3 1 8\n0 1,\n2 3 4 5\n", "t.map:2: cell 1: expected a node id");
    starts("torusrt-map 2 2 3 1 8\n0 1,8 2 3 4 5\n", "t.map:2: cell 1: expected a node id");
    starts("torusrt-map 3 2 3 1 8\n0 1 2 3 4 5\n", "t.map:1: unsupported");
    std::string longer = "torusrt-map 2 2 3 1 8\n0";
    for (int i = 0; i < 2100; i++) longer += ",1";
    EXPECT_EQ(parse(longer + " 1 2 3 4 5\n", owner, first, extra).rfind("t.map:2: an entry longer than 4095", 0), 0u);
    // The one-owner reader refuses version 2 rather than drop its extra owners.
    const int dims[3] = {2, 3, 1};
    char msg[RT_MSG_LEN] = "";
    std::string v2 = "torusrt-map 2 2 3 1 8\n0 1 2 3 4 5\n";
    EXPECT_EQ(rt_map_file_parse("t.map", v2.data(), v2.size(), dims, 8, owner, msg, sizeof msg), RT_ERR_PARSE);
}

// The nearest rule's prediction on the same cells: every packet entering cell 1 comes from cell
// 0 (10 across the face between them), held by node 0. A copy of cell 1 on node 0 would take all
// of them (node 0 is 0 hops from itself): node 0 would end at 1 + 9 = 10, above node 1's 9, so no
// copy is made and the busiest stays at 9.
TEST(Replicas, CostReplicationNearestFollowsTheTraffic)
{
    Tiny t = tiny();
    ASSERT_TRUE(t.grid);
    double work[2] = {1, 9};
    uint64_t traffic[2 * RT_CELL_FACES] = {};
    traffic[0 * RT_CELL_FACES + 1] = 10;  // out of cell 0 through its +x face
    rt_cost_pilot pilot{{2, 1, 1}, 2, work, traffic, 10, {}, nullptr, 0};
    const int two[3] = {2, 1, 1};
    const rt_topology two_nodes = torusrt_test::make_topology("torus", two);
    const int32_t owner[2] = {0, 1};
    uint32_t first[3];
    int32_t *extra = nullptr;
    size_t count = 0;
    rt_cost_map_facts facts{};
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_cost_replicate(&pilot, t.scene.get(), t.grid.get(), &two_nodes, RT_REPLICA_NEAREST, owner, 1.0,
                                nullptr, first, &extra, &count, &facts, msg, sizeof msg),
              RT_OK)
        << msg;
    EXPECT_EQ(count, 0u);
    EXPECT_DOUBLE_EQ(facts.max_node_work_us, 9.0);
    std::free(extra);
}
