// time_keeper_test.cpp - approximately timed, advance() waits exactly the delay; loosely timed,
// delays accumulate as a local offset and the process synchronises when it reaches the next
// quantum boundary (a multiple of the global quantum); settle() drops an offset that predates a
// wait; sync() with no offset does not wait.
#include <systemc>
#include <tlm>

#include "harness.h"
#include "time_keeper.h"

using harness::check;
using sc_core::sc_time;
using sc_core::sc_time_stamp;
using sc_core::SC_NS;
using namespace torusrt;

static sc_time ns(double v) { return sc_time(v, SC_NS); }

struct AtUser : sc_core::sc_module {
    TimeKeeper time{false};
    explicit AtUser(sc_core::sc_module_name n) : sc_module(n)
    {
        SC_HAS_PROCESS(AtUser);
        SC_THREAD(run);
    }
    void run()
    {
        time.advance(ns(7));
        check(sc_time_stamp() == ns(7), "AT: advance(7 ns) waits exactly 7 ns");
        check(time.now() == ns(7), "AT: now() is simulation time");
        time.advance(ns(13));
        check(sc_time_stamp() == ns(20), "AT: a second advance(13 ns) ends at 20 ns");
        time.advance_to(ns(15));
        check(sc_time_stamp() == ns(20), "AT: advance_to a past time does not wait");
        time.advance_to(ns(32));
        check(sc_time_stamp() == ns(32), "AT: advance_to(32 ns) ends at 32 ns");
        time.settle(ns(100));
        check(time.now() == ns(32), "AT: settle has no effect");
    }
};

// Global quantum 100 ns, set before this keeper is built (its constructor computes the first
// sync point from it).
struct LtUser : sc_core::sc_module {
    TimeKeeper time{true};
    explicit LtUser(sc_core::sc_module_name n) : sc_module(n)
    {
        SC_HAS_PROCESS(LtUser);
        SC_THREAD(run);
    }
    void run()
    {
        for (int i = 0; i < 3; i++) time.advance(ns(30));
        check(sc_time_stamp() == sc_core::SC_ZERO_TIME, "LT: 3 x 30 ns stays below the 100 ns quantum: no wait");
        check(time.now() == ns(90), "LT: local time is 90 ns after 3 x 30 ns");
        time.advance(ns(30));
        check(sc_time_stamp() == ns(120), "LT: the 4th 30 ns reaches the quantum: sync to 120 ns");
        check(time.now() == ns(120), "LT: no offset left after the sync");
        // Next boundary is 200 ns: 120 + 50 = 170 stays local, + 40 = 210 syncs.
        time.advance(ns(50));
        check(sc_time_stamp() == ns(120) && time.now() == ns(170), "LT: 170 ns is before the 200 ns boundary");
        time.advance(ns(40));
        check(sc_time_stamp() == ns(210) && time.now() == ns(210), "LT: 210 ns passes the 200 ns boundary: sync");
        time.advance_to(ns(205));
        check(time.now() == ns(210), "LT: advance_to a past time keeps local time");
        time.advance_to(ns(250));
        check(sc_time_stamp() == ns(210) && time.now() == ns(250), "LT: advance_to(250 ns) is a local offset");
        time.sync();
        check(sc_time_stamp() == ns(250) && time.now() == ns(250), "LT: sync() waits the 40 ns offset");
        time.sync();
        check(sc_time_stamp() == ns(250), "LT: sync() with no offset does not wait");

        // settle: a wait on an event (here a plain wait) happened while an offset was pending.
        time.advance(ns(20)); // local 270, simulation 250
        sc_time before = time.now();
        sc_core::wait(ns(30)); // simulation 280, later than `before`
        time.settle(before);
        check(time.now() == ns(280), "LT: settle after a wait past the local time: local = simulation time");
        time.advance(ns(10)); // local 290, simulation 280
        before = time.now();
        sc_core::wait(ns(5)); // simulation 285, earlier than `before`
        time.settle(before);
        check(sc_time_stamp() == ns(285) && time.now() == ns(290), "LT: settle after a short wait keeps `before`");
    }
};

int sc_main(int, char *[])
{
    tlm::tlm_global_quantum::instance().set(ns(100));
    AtUser at("at");
    LtUser lt("lt");
    sc_core::sc_start();
    return harness::finish();
}
