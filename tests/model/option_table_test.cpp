// option_table_test.cpp - the option tables are the one place of the one-processor run's
// machine and show each option's default: every default text reads back to the default machine
// (or run), and a machine with every option set gives, for T(1), one processor and else itself.
#include <map>
#include <sstream>
#include <string>

#include "machine_options.h"
#include "model_run.h"
#include "model_test.h"
#include "run_options.h"
#include "sim_config.h"

using namespace torusrt;

namespace {

// A value other than the default for every machine option but the two files and the timing
// values (each replaces what the others set); a new option needs one here.
const std::map<std::string, std::string> kEveryOptionSet = {
    {"--ips", "2x2x2"},
    {"--topology", "mesh"},
    {"--route-ties", "plus"},
    {"--cells", "8"},
    {"--preprocess-count", "per-plane"},
    {"--queue", "4"},
    {"--flow", "none"},
    {"--queue-order", "rays-first"},
    {"--timing-profile", "literal"},
    {"--link-us", "20"},
    {"--packet-bytes", "30"},
    {"--link-bytes-per-us", "2"},
    {"--link-setup-us", "3"},
    {"--max-depth", "3"},
    {"--min-weight", "0.01"},
    {"--style", "lt"},
    {"--quantum", "1ms"},
    {"--cluster", "2"},
    {"--data", "shared"},
    {"--arbiter", "fixed-priority"},
    {"--dispatch", "shortest-queue"},
    {"--cell-header-bytes", "8"},
    {"--list-entry-bytes", "2"},
    {"--object-record-bytes", "16"},
    {"--map", "cost:2"},
    {"--pilot-size", "8x8"},
    {"--replicate", "0.5"},
    {"--replica-choice", "hash"},
};
const char *const kNotSet[] = {"--timing", "--timing-values", "--map-file"};

bool not_set(const std::string &name)
{
    for (const char *n : kNotSet)
        if (name == n) return true;
    return false;
}

// What the run options set in a request, as text to compare.
std::string run_settings(const SimRequest &r)
{
    const SimConfig &c = r.config;
    std::ostringstream s;
    s.precision(17);
    s << c.trace_from_us << ' ' << c.trace_to_us << ' ' << c.t1_s << ' ' << c.time_limit_s << ' ' << c.progress_every_s
      << ' ' << c.stats_interval_s << ' ' << c.vcd_path << '|' << c.trace_ips.size() << ' ' << c.write_map << '|'
      << r.load_map << '|' << r.frames_csv << '|' << r.stats_series << '|' << static_cast<int>(r.remap) << ' '
      << r.adaptive.pilot_fraction << ' ' << r.adaptive.window << ' ' << r.adaptive.margin;
    return s.str();
}

}  // namespace

TEST(OptionTable, EveryRunOptionsDefaultTextReadsBackToTheDefaultRun)
{
    const SimRequest defaults;
    for (const RunOption &o : run_option_table()) {
        if (o.spec.default_text.empty()) continue;
        SimRequest read;
        o.read(o.spec, o.spec.default_text, read);
        EXPECT_EQ(run_settings(read), run_settings(defaults))
            << o.spec.long_name() << " '" << o.spec.default_text << "'";
    }
}

// The help's default of each machine option, given on its own, is the machine of no options:
// the same options written back and the same JSON `config` keys (the whole timing table too).
TEST(OptionTable, EveryDefaultTextReadsBackToTheDefaultMachine)
{
    const MachineConfig defaults = machine_from_texts({});
    const nlohmann::json options = machine_options_json(defaults), config = machine_config_json(defaults);
    for (const MachineOption &o : machine_option_table()) {
        if (o.spec.default_text.empty()) continue;
        const MachineConfig read = machine_from_texts({{o.spec.long_name(), o.spec.default_text}});
        EXPECT_EQ(machine_options_json(read), options) << o.spec.long_name() << " '" << o.spec.default_text << "'";
        EXPECT_EQ(machine_config_json(read), config) << o.spec.long_name() << " '" << o.spec.default_text << "'";
    }
}

// torusrt-render's help shows the defaults of the options it shares with the machine's table as
// torusrt-sim's does.
TEST(OptionTable, SharedOptionsShowTheMachinesDefaults)
{
    int shared = 0;
    for (const OptionSpec &s : common_option_specs(""))
        for (const MachineOption &o : machine_option_table())
            if (o.spec.long_name() == s.long_name()) {
                EXPECT_EQ(s.default_text, o.spec.default_text) << s.long_name();
                shared++;
            }
    EXPECT_GE(shared, 5);
}

TEST(OptionTable, TheTestSetsEveryOption)
{
    for (const MachineOption &o : machine_option_table()) {
        const std::string name = o.spec.long_name();
        if (not_set(name)) continue;
        ASSERT_EQ(kEveryOptionSet.count(name), 1u) << name << " has no value in kEveryOptionSet";
        EXPECT_NE(o.write(machine_from_texts(kEveryOptionSet)), o.write(machine_from_texts({}))) << name;
    }
}

TEST(OptionTable, OneProcessorMachineHasOneProcessorAndElseTheMachine)
{
    const MachineConfig machine = machine_from_texts(kEveryOptionSet);
    const MachineConfig one = one_processor_machine(machine);
    EXPECT_EQ(one.processor_count(), 1);
    EXPECT_EQ(one.mapping, "block");
    EXPECT_EQ(one.queue_capacity, 0u);
    EXPECT_EQ(one.style, TimingStyle::at);
    EXPECT_EQ(one.quantum_us, 0.0);
    EXPECT_EQ(one.replicate, 0.0);
    for (const MachineOption &o : machine_option_table()) {
        std::string expected = o.write(machine);
        if (o.one_processor) expected = o.write(machine_from_texts({{o.spec.long_name(), o.one_processor}}));
        EXPECT_EQ(o.write(one), expected) << o.spec.long_name();
    }
}

TEST(OptionTable, OneProcessorRunKeepsTheWorkloadAndWatchesNothing)
{
    SimConfig config;
    static_cast<MachineConfig &>(config) = machine_from_texts(kEveryOptionSet);
    config.scene_path = "scene.nff";
    config.width = 40;
    config.height = 30;
    config.time_limit_s = 5;
    config.vcd_path = "t.vcd";
    config.trace_ips = {0, 1};
    config.trace_from_us = 10;
    config.stats_interval_s = 1e-3;
    config.write_map = "m.map";
    config.t1_s = 2;
    config.owner_table = {0, 1};
    config.replica_first = {0, 0, 1};
    config.replica_extra = {1};
    const SimConfig one = one_processor_config(config);
    EXPECT_EQ(one.processor_count(), 1);
    EXPECT_EQ(one.scene_path, config.scene_path);
    EXPECT_EQ(one.width, 40u);
    EXPECT_EQ(one.height, 30u);
    EXPECT_EQ(one.time_limit_s, 5.0);
    EXPECT_TRUE(one.quiet);
    EXPECT_TRUE(one.vcd_path.empty());
    EXPECT_TRUE(one.trace_ips.empty());
    EXPECT_EQ(one.trace_from_us, 0.0);
    EXPECT_EQ(one.stats_interval_s, 0.0);
    EXPECT_TRUE(one.write_map.empty());
    EXPECT_LT(one.t1_s, 0.0);
    EXPECT_TRUE(one.owner_table.empty());
    EXPECT_FALSE(one.replicated());
}
