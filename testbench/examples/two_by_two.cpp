// two_by_two.cpp - the model used as a library: loads an NFF scene, runs it on a 2x2 torus of
// intersection processors with the default timing, and prints the image time and the packet
// totals. Usage: two_by_two SCENE.nff [WIDTH HEIGHT]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <systemc>

#include "model_run.h"
#include "rt_budget.h"
#include "scene_setup.h"
#include "sim_config.h"
#include "user_error.h"

namespace {

// Created = consumed for both kinds of packet, as the report counts them.
bool conserved(const rt_packet_totals &packets)
{
    for (int kind : {RT_PACKET_RAY, RT_PACKET_SHADOW})
        if (packets.created[kind] != packets.consumed[kind]) return false;
    return true;
}

int run(int argc, char **argv)
{
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: two_by_two SCENE.nff [WIDTH HEIGHT]\n");
        return 2;
    }
    torusrt::SimConfig config;
    config.scene_path = argv[1];
    if (argc == 4) {
        config.width = static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10));
        config.height = static_cast<unsigned>(std::strtoul(argv[3], nullptr, 10));
    }
    config.ips = {2, 2, 1};  // every other machine setting its option's default
    config.memory = rt_budget_make(RT_BUDGET_DEFAULT_BYTES);
    config.quiet = true;
    torusrt::validate(config);

    torusrt::LoadedScene loaded =
        torusrt::load_scene(config.scene_path, config.width, config.height, config.cells, config.quiet, &config.memory);
    double t1 = torusrt::one_processor_time(config, loaded.scene.get(), loaded.grid.get());
    torusrt::ModelOutcome out =
        torusrt::run_model(config, loaded.scene.get(), loaded.grid.get(), t1, "one-processor run", 0);
    if (out.deadlock) {
        std::fprintf(stderr, "two_by_two: deadlock\n%s", out.deadlock_details.c_str());
        return 3;
    }
    const rt_packet_totals &packets = out.report.packets;
    std::printf("image_time_s %.17g\n", out.sim_time_s);
    std::printf("rays created %llu consumed %llu\n", static_cast<unsigned long long>(packets.created[RT_PACKET_RAY]),
                static_cast<unsigned long long>(packets.consumed[RT_PACKET_RAY]));
    if (!conserved(packets)) {
        std::fprintf(stderr, "two_by_two: packet conservation violated\n");
        return 1;
    }
    std::printf("packets conserved\n");
    return 0;
}

}  // namespace

int sc_main(int argc, char **argv)
{
    try {
        return run(argc, argv);
    } catch (const torusrt::UserError &e) {
        std::fprintf(stderr, "two_by_two: %s\n", e.what());
        return e.exit_code();
    } catch (const std::exception &e) {
        std::fprintf(stderr, "two_by_two: %s\n", e.what());
        return 1;
    }
}
