// config_validation_test.cpp - the validator names the option of every bad setting it is given,
// and machine_options writes a machine as the options that rebuild it.
#include <cstring>
#include <map>
#include <string>
#include <unistd.h>

#include "machine_options.h"
#include "model_test.h"
#include "sim_config.h"
#include "user_error.h"

using namespace torusrt;

namespace {

SimConfig good()
{
    SimConfig c;
    rt_timing_defaults(&c.timing);
    c.step = rt_step_params_default();
    return c;
}

// The message of validate(), "" when it passes; every failure must be exit status 2.
std::string problem(const SimConfig &c)
{
    try {
        validate(c);
    } catch (const UserError &e) {
        return e.exit_code() == 2 ? e.what() : "exit status not 2";
    }
    return "";
}

void expect(const SimConfig &c, const std::string &option, const char *what)
{
    std::string p = problem(c);
    EXPECT_EQ(p.compare(0, option.size(), option), 0) << what << ": names " << option << " (" << p << ")";
}

}  // namespace

TEST(ConfigValidation, NamesTheOptionOfEveryBadSetting)
{
    SimConfig c = good();
    c.ips = {0, 1, 1};
    expect(c, "--ips", "no node along x");
    c = good(), c.ips = {64, 64, 2};
    expect(c, "--ips", "8192 nodes");
    c = good(), c.ips = {16, 16, 1}, c.cluster = 32;
    expect(c, "--ips x --cluster", "8192 processors");
    c = good(), c.cluster = 0;
    expect(c, "--cluster", "no processor in a node");
    c = good(), c.cells = {1024, 1024, 1024};
    expect(c, "--cells", "more cells than a grid holds");
    c = good(), c.queue_capacity = kMaxQueue + 1;
    expect(c, "--queue", "a queue too large");
    c = good(), c.mapping = "block-cyclic", c.block = 0;
    expect(c, "--map block-cyclic:B", "block 0");
    c = good(), c.mapping = "file";
    expect(c, "--map-file", "the file mapping without a file");
    c = good(), c.pilot_size = {16, 16};
    expect(c, "--pilot-size", "a pilot size without --map cost");
    c = good(), c.replicate = 0.5;
    expect(c, "--replicate", "a replication budget without --map cost");
    c = good(), c.mapping = "cost", c.replicate = 65;
    expect(c, "--replicate", "a budget above the option table's range (no check of its own)");
    c = good(), c.timing.link_us = 2e6;
    expect(c, "--link-us", "a 2 s link");
    c = good(), c.timing.link_bytes_per_us = 1e-9;
    expect(c, "--link-bytes-per-us", "a link rate that makes a packet take hours");
    c = good(), c.step.max_depth = 1001;
    expect(c, "--max-depth", "depth 1001");
    c = good(), c.quantum_us = 5;
    expect(c, "--quantum", "a quantum with --style at");
    c = good(), c.width = 20000, c.height = 10;
    expect(c, "--size", "an image too wide");
    c = good(), c.trace_to_us = 5;
    expect(c, "--trace-from/--trace-to", "a trace window without --vcd");
    c = good(), c.vcd_path = "t.vcd", c.trace_ips = {1};
    expect(c, "--trace-ips", "a node that does not exist");
    c = good(), c.t1_s = 0;
    expect(c, "--t1", "T(1) of 0 s");
    c = good(), c.time_limit_s = 2e7;
    expect(c, "--time-limit", "a limit past SystemC's time");
}

TEST(ConfigValidation, DefaultMachinePasses) { EXPECT_EQ(problem(good()), "") << "the default machine and run pass"; }

namespace {

// A machine with several options away from their defaults.
SimConfig sample_machine()
{
    SimConfig c = good();
    c.ips = {4, 2, 1};
    c.mapping = "block-cyclic", c.block = 3;
    c.step.min_weight = 1.0 / 3.0;
    c.quantum_us = 0.1, c.style = TimingStyle::lt;
    c.cluster = 2, c.arbiter = "fixed-priority";
    return c;
}

}  // namespace

TEST(MachineOptions, WritesTheMachineAsOptions)
{
    SimConfig c = sample_machine();
    nlohmann::json j = machine_options_json(c);
    EXPECT_EQ(j["ips"], "4x2x1") << "ips as PXxPYxPZ";
    EXPECT_EQ(j["map"], "block-cyclic:3") << "block-cyclic with its block";
    EXPECT_EQ(j["min-weight"], "0.3333333333333333") << "min-weight in the shortest text that reads back";
    EXPECT_EQ(std::stod(j["min-weight"].get<std::string>()), c.step.min_weight) << "bit for bit";
    EXPECT_EQ(j["quantum"], "0.1us") << "quantum in microseconds, with its unit";
    EXPECT_TRUE(j["arbiter"] == "fixed-priority" && j["style"] == "lt" && j["cluster"] == "2") << "policies by name";
    EXPECT_EQ(j["link-us"], "50") << "link-us from the timing table";
    EXPECT_TRUE(!j.contains("map-file") || j["map-file"] == "") << "no map file";
}

TEST(MachineOptions, FileMappingHasMapFileAndNoMap)
{
    SimConfig c = sample_machine();
    c.mapping = "file", c.map_file = "/maps/m.map";
    nlohmann::json j = machine_options_json(c);
    EXPECT_TRUE(!j.contains("map") && j["map-file"] == "/maps/m.map") << "a file mapping has map-file and no map";
    EXPECT_NE(machine_options_toml(c).find("map-file=\"/maps/m.map\"\n"), std::string::npos)
        << "TOML lines key=\"value\"";
}

TEST(MachineOptions, FilePathsAreWrittenAbsolute)
{
    SimConfig c = sample_machine();
    c.mapping = "file", c.map_file = "./sub/m.map";
    c.timing_file = "t.timing";
    char cwd[4096];
    ASSERT_NE(getcwd(cwd, sizeof cwd), nullptr);
    const std::string here = std::string(cwd) == "/" ? "" : cwd;
    nlohmann::json j = machine_options_json(c);
    EXPECT_EQ(j["map-file"], here + "/sub/m.map") << "a machine file reads a relative path from its own folder";
    EXPECT_EQ(j["timing"], here + "/t.timing") << "so the working folder is written in front";
}

TEST(MachineOptions, EveryOptionOfTheTableIsWrittenAndReadsBack)
{
    MachineConfig m = machine_from_texts({{"--ips", "2x2"}, {"--timing-values", "link=400,host_inject=9"}});
    OptionList list = machine_options(m);
    const std::vector<MachineOption> &table = machine_option_table();
    ASSERT_EQ(list.size(), table.size()) << "one key per option of the table";
    for (size_t i = 0; i < list.size(); i++) EXPECT_EQ(list[i].first, table[i].spec.key) << "in the table's order";
    nlohmann::json j = machine_options_json(m);
    std::string values = j["timing-values"];
    EXPECT_NE(values.find(",link=400,"), std::string::npos) << "--timing-values is written: " << values;
    std::map<std::string, std::string> given;
    for (const auto &kv : list) given["--" + kv.first] = kv.second;
    MachineConfig back = machine_from_texts(given);
    EXPECT_EQ(machine_options(back), list) << "the written machine reads back to the same options";
    EXPECT_EQ(std::memcmp(&back.timing, &m.timing, sizeof m.timing), 0) << "and the same timing table";
    EXPECT_EQ(machine_options_json(machine_from_texts({}))["timing-values"], "") << "not given: empty";
}

TEST(MachineOptions, TomlGroupsEachKeyInItsTable)
{
    MachineConfig m = machine_from_texts({{"--ips", "2x2"}, {"--cluster", "2"}});
    const std::string toml = machine_options_toml(m);
    const nlohmann::json tables = machine_option_tables_json(m);
    std::vector<std::string> seen;
    std::string table;
    size_t keys = 0;
    for (size_t pos = 0; pos < toml.size();) {
        size_t end = toml.find('\n', pos);
        std::string line = toml.substr(pos, end - pos);
        pos = end + 1;
        if (line.empty()) continue;
        if (line.front() == '[') {
            table = line.substr(1, line.size() - 2);
            seen.push_back(table);
            continue;
        }
        std::string key = line.substr(0, line.find('='));
        EXPECT_EQ(tables.value(key, std::string()), table) << key << " in the table the report names";
        keys++;
    }
    EXPECT_EQ(seen, machine_file_tables()) << "every table once, in order";
    EXPECT_EQ(keys, machine_options(m).size()) << "every key once";
    EXPECT_EQ(tables.value("ips", ""), "network");
    EXPECT_EQ(tables.value("quantum", ""), "timing");
    EXPECT_EQ(tables.value("dispatch", ""), "cluster");
    EXPECT_EQ(tables.value("map", ""), "mapping");
}
