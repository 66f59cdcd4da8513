// cluster_bus_test.cpp - the cluster bus, its arbiters and the 2-port memory:
//  - arbiters alone: round-robin rotates, fixed priority ranks `top` then ascending index;
//  - a saturated bus (4 masters, each re-requesting 10 us after its transfer ends, demand ~1.7x
//    the bus): fixed priority's lowest-priority master waits far longer (grant wait max) than
//    under round-robin, where no master waits more than 3 transfers; the highest-priority master
//    waits at most one transfer;
//  - every grant goes to one master at a time (the bus's grant log never overlaps);
//  - occupancy = arbitration + ceil(bytes / width) * cycle (+ memory access for a read), with
//    the default table and with a changed one;
//  - loosely-timed: a transfer books the earliest free slot at or after the requester's local
//    time; reads of an object the memory does not hold fail.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "bus_arbiter.h"
#include "cluster_bus.h"
#include "grant_log.h"
#include "model_test.h"
#include "rt_timing.h"
#include "sim_config.h"
#include "two_port_memory.h"

using namespace torusrt;
using sc_core::sc_time;
using sc_core::SC_US;

namespace {

bool near(double a, double b) { return std::fabs(a - b) < 1e-9; }

// A master issuing `count` transfers, `think` apart (from the end of one to the request of the next).
struct TrafficMaster : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<TrafficMaster> socket;
    int count;
    sc_time think, start;
    bool read;
    uint64_t address;
    unsigned bytes;
    std::vector<double> elapsed_us;  // per transfer, request to end
    bool all_ok = true;

    TrafficMaster(sc_core::sc_module_name n, int count_, sc_time think_, sc_time start_, bool read_ = false,
                  uint64_t address_ = 0, unsigned bytes_ = 28)
        : sc_module(n), socket("socket"), count(count_), think(think_), start(start_), read(read_), address(address_),
          bytes(bytes_)
    {
        SC_HAS_PROCESS(TrafficMaster);
        SC_THREAD(run);
    }

    void run()
    {
        unsigned char data[256] = {};
        tlm::tlm_generic_payload t;
        sc_core::wait(start);
        for (int i = 0; i < count; i++) {
            t.set_command(read ? tlm::TLM_READ_COMMAND : tlm::TLM_WRITE_COMMAND);
            t.set_address(address);
            t.set_data_ptr(data);
            t.set_data_length(bytes);
            t.set_streaming_width(bytes);
            t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
            sc_time delay = sc_core::SC_ZERO_TIME, before = sc_core::sc_time_stamp();
            socket->b_transport(t, delay);
            if (!t.is_response_ok()) all_ok = false;
            elapsed_us.push_back((sc_core::sc_time_stamp() - before).to_seconds() * 1e6);
            if (i + 1 < count) sc_core::wait(think);
        }
    }
};

// A bus with `n` saturating masters under one arbiter policy.
struct SaturatedBus {
    std::unique_ptr<BusArbiter> arbiter;
    std::unique_ptr<ClusterBus> bus;
    std::vector<std::unique_ptr<TrafficMaster>> masters;
    GrantLog grants;

    SaturatedBus(const std::string &name, const std::string &policy, const rt_timing &timing, int n)
    {
        arbiter = make_arbiter(policy, (name + "_arbiter").c_str(), n, -1);
        bus = std::make_unique<ClusterBus>((name + "_bus").c_str(), timing, false, n);
        bus->arbiter.bind(*arbiter);
        bus->observe(&grants);
        for (int i = 0; i < n; i++) {
            masters.push_back(std::make_unique<TrafficMaster>((name + "_m" + std::to_string(i)).c_str(), 200,
                                                              sc_time(10, SC_US), sc_core::SC_ZERO_TIME));
            masters.back()->socket.bind(bus->target);
        }
    }
};

bool grants_never_overlap(const std::vector<ClusterBus::Grant> &log, std::string &why)
{
    for (size_t i = 0; i < log.size(); i++) {
        if (log[i].start < log[i].requested) {
            why = "grant before request";
            return false;
        }
        if (i > 0 && log[i].start < log[i - 1].end) {
            why = "transfer " + std::to_string(i) + " started before transfer " + std::to_string(i - 1) + " ended";
            return false;
        }
    }
    return !log.empty();
}

// Loosely-timed checks, run from a thread at time 0 with explicit local offsets.
struct LtProbe : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<LtProbe> a, b;
    std::vector<double> ends_us;
    bool unheld_read_failed = false;

    explicit LtProbe(sc_core::sc_module_name n) : sc_module(n), a("a"), b("b")
    {
        SC_HAS_PROCESS(LtProbe);
        SC_THREAD(run);
    }

    double write(tlm_utils::simple_initiator_socket<LtProbe> &s, double local_us)
    {
        unsigned char data[64] = {};
        tlm::tlm_generic_payload t;
        t.set_command(tlm::TLM_WRITE_COMMAND);
        t.set_data_ptr(data);
        t.set_data_length(28);
        t.set_streaming_width(28);
        sc_time delay(local_us, SC_US);
        s->b_transport(t, delay);
        return (sc_core::sc_time_stamp() + delay).to_seconds() * 1e6;
    }

    void run()
    {
        ends_us.push_back(write(a, 100));   // free bus: 100 + 7.25
        ends_us.push_back(write(b, 103));   // overlaps: waits for 107.25, ends 114.5
        ends_us.push_back(write(b, 50));    // earlier local time, free slot: 57.25
        ends_us.push_back(write(a, 92.9));  // 7.25 does not fit before 100: after 114.5 -> 121.75
        unsigned char data[64] = {};
        tlm::tlm_generic_payload t;
        t.set_command(tlm::TLM_READ_COMMAND);
        t.set_address(999);  // memory 0, object 999: not held
        t.set_data_ptr(data);
        t.set_data_length(20);
        t.set_streaming_width(20);
        t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        sc_time delay = sc_core::SC_ZERO_TIME;
        a->b_transport(t, delay);
        unheld_read_failed = t.is_response_error();
    }
};

double to_us(const sc_time &t) { return t.to_seconds() * 1e6; }
// A grant wait of the bus's statistics (in the kernel's time units), in us.
double wait_us(uint64_t value) { return to_us(sc_time::from_value(value)); }

// What the arbiters chose alone (before the run).
struct ArbiterChoices {
    std::vector<int> rr_all;   // round-robin, 5 picks with all 4 lines requesting
    std::vector<int> rr_some;  // then 3 picks with lines 1 and 3 requesting
    int rr_none = 0, fp_all = 0, fp_some = 0, fp_none = 0;
    bool unknown_threw = false;
    size_t named_policies = 0, built_policies = 0;
};

ArbiterChoices choose_alone()
{
    ArbiterChoices c;
    RoundRobinArbiter rr("rr_alone", 4);
    std::vector<bool> all(4, true), some{false, true, false, true};
    for (int i = 0; i < 5; i++) c.rr_all.push_back(rr.pick(all));
    for (int i = 0; i < 3; i++) c.rr_some.push_back(rr.pick(some));
    c.rr_none = rr.pick(std::vector<bool>(4, false));
    FixedPriorityArbiter fp("fp_alone", 5, 4);
    c.fp_all = fp.pick({true, true, true, true, true});
    c.fp_some = fp.pick({false, true, true, true, false});
    c.fp_none = fp.pick({false, false, false, false, false});
    try {
        make_arbiter("lottery", "bad", 2, -1);
    } catch (const std::invalid_argument &) {
        c.unknown_threw = true;
    }
    // Every name the --arbiter option accepts has a factory behind it.
    for (const std::string &name : torusrt::arbiter_policy_names()) {
        c.named_policies++;
        try {
            if (make_arbiter(name, ("named_" + name).c_str(), 2, -1)) c.built_policies++;
        } catch (const std::invalid_argument &) {
        }
    }
    return c;
}

// The saturated buses' figures, per policy; master 3 has the lowest fixed priority.
struct Saturation {
    uint64_t transfers = 0;
    double low_wait_max = 0, high_wait_max = 0, wait_max = 0, low_wait_mean = 0, utilisation = 0;
    bool one_at_a_time = false;
    std::string why;
    std::vector<double> durations;
};

Saturation saturation(const SaturatedBus &b)
{
    Saturation s;
    ClusterBus &bus = *b.bus;
    s.transfers = bus.transfers();
    const BusStats stats = bus.stats();
    s.low_wait_max = wait_us(stats.per_requester[3].wait_max);
    s.high_wait_max = wait_us(stats.per_requester[0].wait_max);
    s.wait_max = wait_us(stats.all.wait_max);
    s.low_wait_mean = wait_us(stats.per_requester[3].wait_sum) / stats.per_requester[3].grants;
    s.utilisation = bus.busy_time().to_seconds() / sc_core::sc_time_stamp().to_seconds();
    s.one_at_a_time = grants_never_overlap(b.grants.grants, s.why);
    for (const auto &g : b.grants.grants) s.durations.push_back(to_us(g.end - g.start));
    return s;
}

struct Outcome {
    ArbiterChoices alone;
    Saturation rr, fp;
    double one = 0;  // one packet transfer, us
    // Lone masters on a free bus: elapsed time of each transfer, and whether all succeeded.
    std::vector<double> w, r1, r3, r20, r21, ww;
    bool w_ok = false, r1_ok = false, r20_ok = false, r21_ok = false, bad_ok = true;
    double packet_bytes = 0, object_bytes = 0;
    uint64_t reads_served = 0;
    // Loosely timed.
    std::vector<double> lt_ends;
    bool lt_unheld_failed = false;
    double lt_wait_max = 0;
};

Outcome simulate()
{
    Outcome run;
    rt_timing timing;
    char msg[RT_MSG_LEN] = "";
    // The figures below are for a 0.5 us bus cycle and memory access (the calibrated profile).
    if (rt_timing_profile("calibrated", &timing, msg, sizeof msg) != RT_OK) ADD_FAILURE() << msg;
    run.alone = choose_alone();

    // Saturated buses, one per policy.
    SaturatedBus rr("rr", "round-robin", timing, 4), fp("fp", "fixed-priority", timing, 4);

    // Transfer timing: a lone master on its own bus, with a memory to read from.
    std::vector<uint32_t> held{0, 1, 2, 3};
    auto time_arb = make_arbiter("round-robin", "time_arbiter", 6, -1);
    ClusterBus time_bus("time_bus", timing, false, 6);
    time_bus.arbiter.bind(*time_arb);
    TwoPortMemory time_mem("time_mem", timing, held, 0, 1);
    time_bus.memory.bind(time_mem.bus_side);
    TrafficMaster w("w", 1, sc_core::SC_ZERO_TIME, sc_time(1, SC_US));                    // packet write
    TrafficMaster r1("r1", 1, sc_core::SC_ZERO_TIME, sc_time(20, SC_US), true, 1, 1);     // read 1 byte
    TrafficMaster r3("r3", 1, sc_core::SC_ZERO_TIME, sc_time(40, SC_US), true, 2, 3);     // read 3 bytes
    TrafficMaster r20("r20", 1, sc_core::SC_ZERO_TIME, sc_time(60, SC_US), true, 3, 20);  // a sphere
    TrafficMaster bad("bad", 1, sc_core::SC_ZERO_TIME, sc_time(80, SC_US), true, 7, 20);  // not held
    TrafficMaster r21("r21", 1, sc_core::SC_ZERO_TIME, sc_time(100, SC_US), true, 0, 21);
    for (auto *m : {&w, &r1, &r3, &r20, &bad, &r21}) m->socket.bind(time_bus.target);

    // A changed timing table: 4-byte bus, 0.125 us cycle, 0.1 us arbitration, 30-byte packets.
    rt_timing wide = timing;
    wide.bus_width_bytes = 4;
    wide.bus_cycle_us = 0.125;
    wide.bus_arbitration_us = 0.1;
    wide.packet_bytes = 30;
    auto wide_arb = make_arbiter("fixed-priority", "wide_arbiter", 1, -1);
    ClusterBus wide_bus("wide_bus", wide, false, 1);
    wide_bus.arbiter.bind(*wide_arb);
    TrafficMaster ww("ww", 3, sc_time(5, SC_US), sc_time(1, SC_US));
    ww.socket.bind(wide_bus.target);

    // Loosely timed.
    auto lt_arb = make_arbiter("round-robin", "lt_arbiter", 2, -1);
    ClusterBus lt_bus("lt_bus", timing, true, 2);
    lt_bus.arbiter.bind(*lt_arb);
    TwoPortMemory lt_mem("lt_mem", timing, held, 0, 1);
    lt_bus.memory.bind(lt_mem.bus_side);
    LtProbe probe("probe");
    probe.a.bind(lt_bus.target);
    probe.b.bind(lt_bus.target);

    sc_core::sc_start();

    run.rr = saturation(rr), run.fp = saturation(fp);
    run.one = to_us(rr.bus->transfer_time(timing.packet_bytes));
    run.w = w.elapsed_us, run.r1 = r1.elapsed_us, run.r3 = r3.elapsed_us, run.r20 = r20.elapsed_us;
    run.r21 = r21.elapsed_us, run.ww = ww.elapsed_us;
    run.w_ok = w.all_ok, run.r1_ok = r1.all_ok, run.r20_ok = r20.all_ok, run.r21_ok = r21.all_ok;
    run.bad_ok = bad.all_ok;
    run.packet_bytes = time_bus.packet_bytes(), run.object_bytes = time_bus.object_bytes();
    run.reads_served = time_mem.reads_served();
    run.lt_ends = probe.ends_us, run.lt_unheld_failed = probe.unheld_read_failed;
    run.lt_wait_max = wait_us(lt_bus.stats().all.wait_max);
    return run;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(BusArbiter, RoundRobinRotatesAndSkipsIdleLines)
{
    EXPECT_EQ(run().alone.rr_all, std::vector<int>({0, 1, 2, 3, 0})) << "rotates 0 1 2 3 0 when all request";
    EXPECT_EQ(run().alone.rr_some, std::vector<int>({1, 3, 1})) << "skips idle lines";
    EXPECT_EQ(run().alone.rr_none, -1) << "-1 with no request";
}

TEST(BusArbiter, FixedPriorityRanksTopThenAscendingIndex)
{
    EXPECT_EQ(run().alone.fp_all, 4) << "grants `top` (the comm unit) first";
    EXPECT_EQ(run().alone.fp_some, 1) << "lower index wins";
    EXPECT_EQ(run().alone.fp_none, -1) << "-1 with no request";
}

TEST(BusArbiter, UnknownPolicyIsRejectedByName)
{
    EXPECT_TRUE(run().alone.unknown_threw);
    EXPECT_EQ(run().alone.named_policies, 2u);
    EXPECT_EQ(run().alone.built_policies, run().alone.named_policies) << "every --arbiter name is built";
}

TEST(ClusterBus, SaturatedBusCompletesEveryTransfer)
{
    std::printf("saturated bus: one transfer %.2f us; grant wait max of master 3: round-robin %.2f us, "
                "fixed-priority %.2f us; utilisation rr %.3f fp %.3f\n",
                run().one, run().rr.low_wait_max, run().fp.low_wait_max, run().rr.utilisation, run().fp.utilisation);
    EXPECT_EQ(run().rr.transfers, 800u) << "4 masters x 200 transfers";
    EXPECT_EQ(run().fp.transfers, 800u);
}

TEST(ClusterBus, RoundRobinWaitsAtMostThreeTransfers)
{
    EXPECT_LE(run().rr.wait_max, 3 * run().one + 1e-9) << "no master waits more than 3 transfers";
}

TEST(ClusterBus, FixedPriorityStarvesTheLowestMaster)
{
    EXPECT_LE(run().fp.high_wait_max, run().one + 1e-9) << "master 0 waits at most one transfer";
    EXPECT_GT(run().fp.low_wait_max, 3 * run().rr.low_wait_max) << "master 3's grant wait max > 3 x round-robin's";
    EXPECT_GT(run().fp.low_wait_mean, run().rr.low_wait_mean) << "master 3's mean wait exceeds round-robin's";
}

TEST(ClusterBus, GrantsOneMasterAtATime)
{
    EXPECT_TRUE(run().rr.one_at_a_time) << "round-robin bus: " << run().rr.why;
    EXPECT_TRUE(run().fp.one_at_a_time) << "fixed-priority bus: " << run().fp.why;
}

TEST(ClusterBus, PacketTransferOccupiesArbitrationPlusCycles)
{
    // Default table: 0.25 us arbitration + ceil(28 / 2) = 14 cycles of 0.5 us = 7.25 us.
    EXPECT_TRUE(near(run().one, 0.25 + 14 * 0.5)) << run().one;
    for (double d : run().fp.durations) EXPECT_TRUE(near(d, run().one)) << d;
    ASSERT_EQ(run().w.size(), 1u);
    EXPECT_TRUE(near(run().w[0], 7.25)) << "packet write: 0.25 + ceil(28/2) x 0.5 = 7.25 us, got " << run().w[0];
}

TEST(ClusterBus, ReadOccupiesArbitrationCyclesAndTheMemoryAccess)
{
    ASSERT_TRUE(run().r1.size() == 1 && run().r3.size() == 1 && run().r20.size() == 1 && run().r21.size() == 1);
    EXPECT_TRUE(near(run().r1[0], 0.25 + 1 * 0.5 + 0.5)) << "1-byte read: arbitration + 1 cycle + memory = 1.25 us";
    EXPECT_TRUE(near(run().r3[0], 0.25 + 2 * 0.5 + 0.5)) << "3-byte read: arbitration + 2 cycles + memory = 1.75 us";
    EXPECT_TRUE(near(run().r20[0], 0.25 + 10 * 0.5 + 0.5)) << "20-byte read: 5.75 us";
    EXPECT_TRUE(near(run().r21[0], 0.25 + 11 * 0.5 + 0.5)) << "21-byte read: 6.25 us";
}

TEST(ClusterBus, ReadsOfUnheldObjectsFail)
{
    EXPECT_TRUE(run().w_ok && run().r1_ok && run().r20_ok && run().r21_ok) << "reads of held objects succeed";
    EXPECT_FALSE(run().bad_ok) << "a read of an unheld object fails";
}

TEST(ClusterBus, CountsPacketAndObjectBytesApart)
{
    EXPECT_EQ(run().packet_bytes, 28);
    EXPECT_EQ(run().object_bytes, 1 + 3 + 20 + 21);
    EXPECT_EQ(run().reads_served, 4u);
}

TEST(ClusterBus, ChangedTimingTable)
{
    ASSERT_EQ(run().ww.size(), 3u);
    EXPECT_TRUE(near(run().ww[0], 0.1 + 8 * 0.125)) << "0.1 + ceil(30/4) x 0.125 = 1.1 us";
    EXPECT_TRUE(near(run().ww[2], 1.1));
}

TEST(ClusterBus, LooselyTimedBooksTheEarliestFreeSlot)
{
    // 100 + 7.25; 103 overlaps, waits for 107.25; 50 fits before: 57.25; 92.9 + 7.25 does not fit
    // before 100: after 114.5.
    ASSERT_EQ(run().lt_ends.size(), 4u);
    EXPECT_TRUE(near(run().lt_ends[0], 107.25)) << run().lt_ends[0];
    EXPECT_TRUE(near(run().lt_ends[1], 114.5)) << run().lt_ends[1];
    EXPECT_TRUE(near(run().lt_ends[2], 57.25)) << run().lt_ends[2];
    EXPECT_TRUE(near(run().lt_ends[3], 121.75)) << run().lt_ends[3];
    EXPECT_TRUE(run().lt_unheld_failed) << "a read of an unheld object fails";
    EXPECT_TRUE(near(run().lt_wait_max, 121.75 - 7.25 - 92.9)) << "grant wait = slot start - local time";
}
