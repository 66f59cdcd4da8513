// time_keeper_test.cpp - approximately timed, advance() waits exactly the delay; loosely timed,
// delays accumulate as a local offset and the process synchronises when it reaches the next
// quantum boundary (a multiple of the global quantum); settle() drops an offset that predates a
// wait; sync() with no offset does not wait. An SC_METHOD running the same schedule through the
// _nb calls (each owed wait spent by being triggered that much later) sees the same times.
#include <systemc>
#include <tlm>
#include <vector>

#include "model_test.h"
#include "time_keeper.h"

using model_test::ns;
using sc_core::sc_time;
using sc_core::sc_time_stamp;
using namespace torusrt;

// Simulation time and keeper time after one step of a user's schedule.
struct Sample {
    sc_time simulation, local;
};

// Records a sample after each step; the TESTs compare them with the times worked out by hand.
struct Samples {
    std::vector<Sample> at, lt, lt_method;
};

struct AtUser : sc_core::sc_module {
    TimeKeeper time{false};
    std::vector<Sample> &out;
    AtUser(sc_core::sc_module_name n, std::vector<Sample> &out_) : sc_module(n), out(out_)
    {
        SC_HAS_PROCESS(AtUser);
        SC_THREAD(run);
    }
    void sample() { out.push_back({sc_time_stamp(), time.now()}); }
    void run()
    {
        time.advance(ns(7));
        sample();  // 0
        time.advance(ns(13));
        sample();  // 1
        time.advance_to(ns(15));
        sample();  // 2
        time.advance_to(ns(32));
        sample();  // 3
        time.settle(ns(100));
        sample();  // 4
    }
};

// Global quantum 100 ns, set before this keeper is built (its constructor computes the first
// sync point from it).
struct LtUser : sc_core::sc_module {
    TimeKeeper time{true};
    std::vector<Sample> &out;
    LtUser(sc_core::sc_module_name n, std::vector<Sample> &out_) : sc_module(n), out(out_)
    {
        SC_HAS_PROCESS(LtUser);
        SC_THREAD(run);
    }
    void sample() { out.push_back({sc_time_stamp(), time.now()}); }
    void run()
    {
        for (int i = 0; i < 3; i++) time.advance(ns(30));
        sample();  // 0
        time.advance(ns(30));
        sample();  // 1
        time.advance(ns(50));
        sample();  // 2
        time.advance(ns(40));
        sample();  // 3
        time.advance_to(ns(205));
        sample();  // 4
        time.advance_to(ns(250));
        sample();  // 5
        time.sync();
        sample();  // 6
        time.sync();
        sample();  // 7

        // settle: a wait on an event (here a plain wait) happened while an offset was pending.
        time.advance(ns(20));  // local 270, simulation 250
        sc_time before = time.now();
        sc_core::wait(ns(30));  // simulation 280, later than `before`
        time.settle(before);
        sample();              // 8
        time.advance(ns(10));  // local 290, simulation 280
        before = time.now();
        sc_core::wait(ns(5));  // simulation 285, earlier than `before`
        time.settle(before);
        sample();  // 9
    }
};

// LtUser's schedule up to sample 7, from an SC_METHOD.
struct LtMethodUser : sc_core::sc_module {
    struct Op {
        char kind;  // a: advance, t: advance_to, s: sync
        int ns;
        bool sample;
    };
    TimeKeeper time{true};
    std::vector<Sample> &out;
    std::vector<Op> ops{{'a', 30, false}, {'a', 30, false}, {'a', 30, true},  {'a', 30, true}, {'a', 50, true},
                        {'a', 40, true},  {'t', 205, true}, {'t', 250, true}, {'s', 0, true},  {'s', 0, true}};
    size_t next = 0;
    bool waiting = false;
    LtMethodUser(sc_core::sc_module_name n, std::vector<Sample> &out_) : sc_module(n), out(out_)
    {
        SC_HAS_PROCESS(LtMethodUser);
        SC_METHOD(run);
    }
    TimeWait apply(const Op &op)
    {
        if (op.kind == 'a') return time.advance_nb(ns(op.ns));
        if (op.kind == 't') return time.advance_to_nb(ns(op.ns));
        return time.sync_nb();
    }
    void run()
    {
        if (waiting) {  // the owed wait is over
            time.resumed();
            waiting = false;
            if (ops[next++].sample) out.push_back({sc_time_stamp(), time.now()});
        }
        for (; next < ops.size(); next++) {
            TimeWait w = apply(ops[next]);
            if (w.due) {
                waiting = true;
                next_trigger(w.delay);
                return;
            }
            if (ops[next].sample) out.push_back({sc_time_stamp(), time.now()});
        }
    }
};

static Samples simulate()
{
    Samples s;
    tlm::tlm_global_quantum::instance().set(ns(100));
    AtUser at("at", s.at);
    LtUser lt("lt", s.lt);
    LtMethodUser ltm("ltm", s.lt_method);
    sc_core::sc_start();
    return s;
}

static const Samples &run()
{
    static const Samples s = simulate();
    return s;
}

TEST(TimeKeeper, ApproximatelyTimedAdvanceWaitsExactlyTheDelay)
{
    const std::vector<Sample> &at = run().at;
    ASSERT_EQ(at.size(), 5u);
    EXPECT_EQ(at[0].simulation, ns(7)) << "advance(7 ns) waits exactly 7 ns";
    EXPECT_EQ(at[0].local, ns(7)) << "now() is simulation time";
    EXPECT_EQ(at[1].simulation, ns(20)) << "a second advance(13 ns) ends at 7 + 13 = 20 ns";
    EXPECT_EQ(at[2].simulation, ns(20)) << "advance_to a past time (15 ns) does not wait";
    EXPECT_EQ(at[3].simulation, ns(32)) << "advance_to(32 ns) ends at 32 ns";
    EXPECT_EQ(at[4].local, ns(32)) << "settle has no effect";
}

TEST(TimeKeeper, LooselyTimedSyncsAtTheQuantumBoundary)
{
    const std::vector<Sample> &lt = run().lt;
    ASSERT_EQ(lt.size(), 10u);
    EXPECT_EQ(lt[0].simulation, sc_core::SC_ZERO_TIME) << "3 x 30 ns stays below the 100 ns quantum: no wait";
    EXPECT_EQ(lt[0].local, ns(90)) << "local time is 90 ns after 3 x 30 ns";
    EXPECT_EQ(lt[1].simulation, ns(120)) << "the 4th 30 ns reaches the quantum: sync to 120 ns";
    EXPECT_EQ(lt[1].local, ns(120)) << "no offset left after the sync";
    // Next boundary is 200 ns: 120 + 50 = 170 stays local, + 40 = 210 syncs.
    EXPECT_EQ(lt[2].simulation, ns(120)) << "170 ns is before the 200 ns boundary";
    EXPECT_EQ(lt[2].local, ns(170));
    EXPECT_EQ(lt[3].simulation, ns(210)) << "210 ns passes the 200 ns boundary: sync";
    EXPECT_EQ(lt[3].local, ns(210));
}

TEST(TimeKeeper, LooselyTimedAdvanceToAndSync)
{
    const std::vector<Sample> &lt = run().lt;
    ASSERT_EQ(lt.size(), 10u);
    EXPECT_EQ(lt[4].local, ns(210)) << "advance_to a past time (205 ns) keeps local time";
    EXPECT_EQ(lt[5].simulation, ns(210)) << "advance_to(250 ns) is a local offset";
    EXPECT_EQ(lt[5].local, ns(250));
    EXPECT_EQ(lt[6].simulation, ns(250)) << "sync() waits the 40 ns offset";
    EXPECT_EQ(lt[6].local, ns(250));
    EXPECT_EQ(lt[7].simulation, ns(250)) << "sync() with no offset does not wait";
}

TEST(TimeKeeper, LooselyTimedSettleDropsAnOffsetThatPredatesAWait)
{
    const std::vector<Sample> &lt = run().lt;
    ASSERT_EQ(lt.size(), 10u);
    // Local 270 ns, then a 30 ns wait from 250: simulation 280 is past the local time.
    EXPECT_EQ(lt[8].local, ns(280)) << "settle after a wait past the local time: local = simulation time";
    // Local 290 ns, then a 5 ns wait from 280: simulation 285 is before `before` (290).
    EXPECT_EQ(lt[9].simulation, ns(285)) << "settle after a short wait keeps `before`";
    EXPECT_EQ(lt[9].local, ns(290));
}

TEST(TimeKeeper, AMethodThroughTheNbCallsSeesTheThreadsTimes)
{
    const Samples &s = run();
    ASSERT_EQ(s.lt.size(), 10u);
    ASSERT_EQ(s.lt_method.size(), 8u);
    for (size_t i = 0; i < 8; i++) {
        EXPECT_EQ(s.lt_method[i].simulation, s.lt[i].simulation) << "sample " << i;
        EXPECT_EQ(s.lt_method[i].local, s.lt[i].local) << "sample " << i;
    }
    EXPECT_EQ(s.lt_method[1].simulation, ns(120)) << "the method waited for the sync, as the thread";
}
