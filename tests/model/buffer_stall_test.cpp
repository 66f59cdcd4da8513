// buffer_stall_test.cpp - a BufferSpace's stall time: the simulated time during which at least
// one writer (a thread in take_blocking or a method registered with on_release) waits for room,
// counted once however many wait, on a schedule whose intervals are worked out by hand:
//   0-10 us   A holds the only slot; B (thread) waits from 2 us until A releases at 10: 8 us
//   20-40 us  A holds it; M (method) registers at 25 us, notified at 40 and takes it: 15 us
//   50-60 us  A holds it; B waits from 52 us, M registers at 55 us: 52..60 counted once, 8 us
// Total 31 us; 27 us while the third interval is still open at 56 us. Unbounded: never a stall.
#include <systemc>

#include "buffer_space.h"
#include "model_test.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

namespace {

struct Schedule : sc_core::sc_module {
    BufferSpace space{1};
    sc_core::sc_event method_due, method_room, ignored_room;
    int method_runs = 0;
    bool method_took = false;
    sc_time b_first_got, b_second_got, stalled_at_56;
    unsigned waiting_at_56 = 0;

    explicit Schedule(sc_core::sc_module_name n) : sc_module(n)
    {
        SC_HAS_PROCESS(Schedule);
        SC_THREAD(holder);
        SC_THREAD(blocked_thread);
        SC_THREAD(observer);
        SC_METHOD(writer_method);
        sensitive << method_due << method_room;
        dont_initialize();
    }
    void holder()  // A
    {
        space.take();
        wait(us(10));
        space.release();
        wait(us(10));  // 20 us (B released at 12)
        space.take();
        method_due.notify(us(5));  // M tries at 25 us
        wait(us(20));
        space.release();  // 40 us
        wait(us(10));     // 50 us (M released at 40)
        space.take();
        method_due.notify(us(5));  // M registers again at 55 us
        wait(us(10));
        space.release();  // 60 us
    }
    void blocked_thread()  // B
    {
        wait(us(2));
        space.take_blocking();
        b_first_got = sc_core::sc_time_stamp();
        wait(us(2));
        space.release();  // 12 us
        wait(us(40));     // 52 us
        space.take_blocking();
        b_second_got = sc_core::sc_time_stamp();
        wait(us(10));
        space.release();  // 70 us
    }
    void writer_method()  // M
    {
        method_runs++;
        if (method_runs == 1) {
            space.on_release(method_room);  // 25 us: full
        } else if (method_runs == 2) {
            method_took = space.available();  // 40 us: room
            if (method_took) {
                space.take();
                space.release();
            }
        } else {
            space.on_release(ignored_room);  // 55 us: waits without retrying
        }
    }
    void observer()
    {
        wait(us(56));
        stalled_at_56 = space.stalled_time();
        waiting_at_56 = space.blocked_writers();
    }
};

// The schedule's figures and an unbounded space's.
struct Outcome {
    int method_runs = 0;
    bool method_took = false;
    sc_time b_first_got, b_second_got, stalled_at_56, stalled;
    unsigned waiting_at_56 = 0;
    size_t high_water = 0, used = 0, unbounded_high_water = 0;
    sc_time unbounded_stalled;
};

Outcome simulate()
{
    Schedule s("schedule");
    BufferSpace unbounded(0);
    for (int i = 0; i < 5; i++) unbounded.take();
    sc_core::sc_start();
    Outcome run;
    run.method_runs = s.method_runs, run.method_took = s.method_took;
    run.b_first_got = s.b_first_got, run.b_second_got = s.b_second_got;
    run.stalled_at_56 = s.stalled_at_56, run.waiting_at_56 = s.waiting_at_56, run.stalled = s.space.stalled_time();
    run.high_water = s.space.high_water(), run.used = s.space.used();
    run.unbounded_high_water = unbounded.high_water(), run.unbounded_stalled = unbounded.stalled_time();
    return run;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(BufferSpace, WritersTakeTheSlotWhenItIsReleased)
{
    EXPECT_EQ(run().b_first_got, us(10)) << "B takes the slot when A releases it at 10 us";
    EXPECT_EQ(run().method_runs, 3);
    EXPECT_TRUE(run().method_took) << "M is notified at the release and takes the slot at 40 us";
    EXPECT_EQ(run().b_second_got, us(60)) << "B takes the slot at 60 us";
}

TEST(BufferSpace, StallTimeCountsOverlappingWaitsOnce)
{
    EXPECT_EQ(run().waiting_at_56, 2u) << "two writers wait at 56 us";
    EXPECT_EQ(run().stalled_at_56, us(27)) << "stall time at 56 us: 8 + 15 + 4 (the open interval) = 27 us";
    EXPECT_EQ(run().stalled, us(31)) << "stall time: 8 + 15 + 8 = 31 us, overlapping waits counted once";
}

TEST(BufferSpace, GivesEverySlotBack)
{
    EXPECT_EQ(run().high_water, 1u);
    EXPECT_EQ(run().used, 0u);
}

TEST(BufferSpace, UnboundedNeverStalls)
{
    EXPECT_EQ(run().unbounded_stalled, sc_core::SC_ZERO_TIME) << "no stall";
    EXPECT_EQ(run().unbounded_high_water, 5u);
}
