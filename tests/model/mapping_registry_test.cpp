// mapping_registry_test.cpp - each registered mapping, chosen by name as --map and --map-file
// choose it: the table it fills, the forms --map takes for it, and how it is remapped.
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include "machine_options.h"
#include "mapping.h"
#include "model_test.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "user_error.h"

using namespace torusrt;

namespace {

// Three spheres along the x axis, lit, 16x16 pixels: work in a few cells of the grid.
struct Scene {
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    Scene()
    {
        scene = rt_scene_new();
        rt_scene_set_view(scene, rt_vec(0, 1, 9), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
        rt_material diffuse = rt_material_default();
        diffuse.color = rt_vec(0.8, 0.5, 0.3);
        rt_scene_set_material(scene, &diffuse);
        rt_scene_add_sphere(scene, rt_vec(-2, 0, 0), 1);
        rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1);
        rt_scene_add_sphere(scene, rt_vec(2, 0, 0), 1);
        rt_scene_add_light(scene, rt_vec(3, 6, 8), nullptr);
        char msg[RT_MSG_LEN] = "";
        rt_scene_finish(scene, msg, sizeof msg);
        grid = rt_grid_new(scene, 4, 4, 4, msg, sizeof msg);
    }
    ~Scene()
    {
        rt_grid_free(grid);
        rt_scene_free(scene);
    }
};

// A machine of 2x2x1 nodes over the 4x4x4 grid, mapped as `map` says.
SimConfig machine(const std::string &map)
{
    SimConfig c;
    static_cast<MachineConfig &>(c) = machine_from_texts({{"--ips", "2x2x1"}, {"--cells", "4x4x4"}, {"--map", map}});
    c.step = rt_step_params_default();
    return c;
}

std::vector<int32_t> filled(const SimConfig &c, Scene &s, ReplicaTable &replicas)
{
    std::vector<int32_t> owner(rt_grid_cell_count(s.grid));
    mapping_of(c).fill(c, s.scene, s.grid, owner, replicas);
    return owner;
}

std::vector<int32_t> filled(const SimConfig &c, Scene &s)
{
    ReplicaTable replicas;
    return filled(c, s, replicas);
}

// Node of cell (x, y, z) of the 4x4x4 grid.
int32_t at(const std::vector<int32_t> &owner, int x, int y, int z) { return owner[x + 4 * (y + 4 * z)]; }

std::string refusal(const std::string &map)
{
    try {
        machine(map);
    } catch (const UserError &e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(MappingRegistry, NamesInTheHelpsOrder)
{
    EXPECT_EQ(mapping_names(),
              (std::vector<std::string>{"block", "cyclic", "block-cyclic", "cost", "scatter", "file"}));
    EXPECT_EQ(mapping_forms(), "block, cyclic, block-cyclic:B, cost, cost:K or scatter") << "the table has no form";
    EXPECT_EQ(std::string(file_mapping_name()), "file");
    for (const std::string &name : mapping_names()) EXPECT_EQ(find_mapping(name)->name, name) << "registered as named";
    EXPECT_EQ(find_mapping("diagonal"), nullptr);
}

TEST(MappingRegistry, UnknownNameNamesTheForms)
{
    std::string why = refusal("diagonal");
    EXPECT_NE(why.find("--map 'diagonal': expected block, cyclic"), std::string::npos) << why;
    EXPECT_NE(refusal("file"), "") << "the table is chosen by --map-file only";
}

TEST(MappingRegistry, Block)
{
    Scene s;
    SimConfig c = machine("block");
    std::vector<int32_t> owner = filled(c, s);
    // floor(c * 2 / 4) along x and y: cells 0-1 on node 0 of the axis, 2-3 on node 1.
    EXPECT_EQ(at(owner, 1, 1, 3), 0);
    EXPECT_EQ(at(owner, 2, 0, 0), 1);
    EXPECT_EQ(at(owner, 1, 2, 0), 2);
    EXPECT_EQ(at(owner, 3, 3, 2), 3);
    EXPECT_EQ(mapping_text(c), "block");
    EXPECT_FALSE(mapping_of(c).measured);
    EXPECT_EQ(mapping_of(c).remap_fold(c), 1);
    EXPECT_NE(refusal("block:2"), "") << "block takes no :N";
}

TEST(MappingRegistry, Cyclic)
{
    Scene s;
    SimConfig c = machine("cyclic");
    std::vector<int32_t> owner = filled(c, s);
    // c mod 2 along x and y.
    EXPECT_EQ(at(owner, 0, 0, 1), 0);
    EXPECT_EQ(at(owner, 3, 0, 0), 1);
    EXPECT_EQ(at(owner, 2, 1, 0), 2);
    EXPECT_EQ(at(owner, 1, 3, 3), 3);
    EXPECT_EQ(mapping_text(c), "cyclic");
    EXPECT_EQ(mapping_of(c).no_remap, nullptr);
}

TEST(MappingRegistry, BlockCyclic)
{
    Scene s;
    SimConfig c = machine("block-cyclic:2");
    EXPECT_EQ(c.block, 2);
    std::vector<int32_t> owner = filled(c, s);
    EXPECT_EQ(owner, filled(machine("block"), s)) << "blocks of 2 cells over 2 nodes of 4 cells: block";
    EXPECT_EQ(filled(machine("block-cyclic:1"), s), filled(machine("cyclic"), s)) << "blocks of 1: cyclic";
    EXPECT_EQ(mapping_text(c), "block-cyclic:2") << "written with its block";
    EXPECT_NE(refusal("block-cyclic"), "") << "the block is required";
    EXPECT_NE(refusal("block-cyclic:0").find("--map block-cyclic:B"), std::string::npos);
}

TEST(MappingRegistry, Cost)
{
    Scene s;
    SimConfig c = machine("cost");
    EXPECT_TRUE(mapping_of(c).measured);
    EXPECT_EQ(mapping_text(c), "cost") << "cost is cost:1";
    ReplicaTable replicas;
    std::vector<int32_t> owner = filled(c, s, replicas);
    std::set<int32_t> nodes(owner.begin(), owner.end());
    EXPECT_EQ(*nodes.begin(), 0);
    EXPECT_EQ(*nodes.rbegin(), 3) << "every owner a node of the 2x2x1 machine";
    EXPECT_TRUE(replicas.extra.empty()) << "no --replicate";
    SimConfig folded = machine("cost:3");
    EXPECT_EQ(mapping_text(folded), "cost:3");
    EXPECT_EQ(mapping_of(folded).remap_fold(folded), 3) << "a remap folds as the first frame's mapping";
    EXPECT_NE(refusal("cost:65").find("--map cost:K"), std::string::npos);
}

TEST(MappingRegistry, Scatter)
{
    Scene s;
    SimConfig c = machine("scatter");
    EXPECT_TRUE(mapping_of(c).measured);
    std::vector<int32_t> owner = filled(c, s);
    for (int32_t o : owner) EXPECT_TRUE(o >= 0 && o < 4) << o;
    EXPECT_NE(mapping_of(c).no_remap, nullptr) << "not remapped across frames";
}

TEST(MappingRegistry, File)
{
    Scene s;
    char path[] = "/tmp/mapping_registry_testXXXXXX";
    int fd = mkstemp(path);
    ASSERT_GE(fd, 0);
    std::string table = "torusrt-map 1 4 4 4 4\n";
    for (int i = 0; i < 64; i++) table += std::to_string((i / 3) % 4) + (i % 16 == 15 ? "\n" : " ");
    ASSERT_EQ(write(fd, table.data(), table.size()), static_cast<ssize_t>(table.size()));
    close(fd);
    SimConfig c;
    static_cast<MachineConfig &>(c) =
        machine_from_texts({{"--ips", "2x2x1"}, {"--cells", "4x4x4"}, {"--map-file", path}});
    const Mapping &m = mapping_of(c);
    EXPECT_TRUE(m.from_file);
    EXPECT_EQ(c.mapping, "file");
    m.check_inputs(c);
    std::vector<int32_t> owner = filled(c, s);
    for (int i = 0; i < 64; i++) EXPECT_EQ(owner[i], (i / 3) % 4) << "cell " << i << " as the file says";
    c.ips = {4, 2, 1};  // the header's 4 nodes no longer match
    std::string why;
    try {
        m.check_inputs(c);
    } catch (const UserError &e) {
        why = e.what();
    }
    EXPECT_NE(why.find(std::string("--map-file: ") + path + ":1"), std::string::npos) << why;
    std::remove(path);
}
