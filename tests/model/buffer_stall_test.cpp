// buffer_stall_test.cpp - a BufferSpace's stall time: the simulated time during which at least
// one writer (a thread in take_blocking or a method registered with on_release) waits for room,
// counted once however many wait, on a schedule whose intervals are worked out by hand:
//   0-10 us   A holds the only slot; B (thread) waits from 2 us until A releases at 10: 8 us
//   20-40 us  A holds it; M (method) registers at 25 us, notified at 40 and takes it: 15 us
//   50-60 us  A holds it; B waits from 52 us, M registers at 55 us: 52..60 counted once, 8 us
// Total 31 us; 27 us while the third interval is still open at 56 us. Unbounded: never a stall.
#include <systemc>

#include "buffer_space.h"
#include "harness.h"

using harness::check;
using sc_core::sc_time;
using sc_core::SC_US;
using namespace torusrt;

namespace {

sc_time us(double v) { return sc_time(v, SC_US); }

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

}  // namespace

int sc_main(int, char **)
{
    Schedule s("schedule");
    BufferSpace unbounded(0);
    for (int i = 0; i < 5; i++) unbounded.take();
    sc_core::sc_start();
    check(s.b_first_got == us(10), "B takes the slot when A releases it at 10 us");
    check(s.method_runs == 3 && s.method_took, "M is notified at the release and takes the slot at 40 us");
    check(s.b_second_got == us(60), "B takes the slot at 60 us");
    check(s.waiting_at_56 == 2, "two writers wait at 56 us");
    check(s.stalled_at_56 == us(27), "stall time at 56 us: 8 + 15 + 4 (the open interval) = 27 us");
    check(s.space.stalled_time() == us(31), "stall time: 8 + 15 + 8 = 31 us, overlapping waits counted once");
    check(s.space.high_water() == 1 && s.space.used() == 0, "high water 1, every slot given back");
    check(unbounded.stalled_time() == sc_core::SC_ZERO_TIME && unbounded.high_water() == 5,
          "unbounded: high water 5, no stall");
    return harness::finish();
}
