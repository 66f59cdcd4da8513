"""profile_shares.py - where a torusrt-sim run's CPU time goes, from `perf report` text.

Reads the output of `perf report --no-children --sort dso,symbol --stdio -g none` on standard
input and prints one line per part of the simulator: its share of the samples. The parts:
  systemc    the SystemC kernel (libsystemc: events, the scheduler, sc_time)
  kernel     the C ray-tracing kernel (the packet step, intersections, DDA, grid, shading)
  schedule   the model's transport and scheduling classes (wake calendar, queues, pools, hop paths)
  modules    the hardware modules (intersection processor, communication unit, links, host,
             frame buffer, cluster bus, dispatcher, memory)
  reports    reports, JSON, PNG, set-up, and every other function of the model's run code
  runtime    the C and C++ runtime and the operating system (libc, libstdc++, libm, the kernel)
Usage: perf report ... | python3 bench/profile_shares.py LABEL
"""
import re
import sys

SCHEDULE = re.compile(r"WakeCalendar|PacketQueue|ArrivalQueue|TimedWake|ActivationQueue|Pool|Fifo|HopPath|"
                      r"BufferSpace|Credit|TimeKeeper|QuantumKeeper|quantumkeeper")
MODULES = re.compile(r"IntersectionProcessor|CommUnit|ToroidalLink|Host|FrameBuffer|Cluster|Bus|Dispatch|"
                     r"Arbiter|Memory|ProcessorBusPort|LinkInput")
REPORTS = re.compile(r"nlohmann|Report|report|json|Json|Trace|trace|vcd|Vcd|png_|deflate|inflate|crc32")
LINE = re.compile(r"^\s*([0-9.]+)%\s+(\S+)\s+\[(.)\]\s+(.*?)\s*$")


def part(dso, kernel_space, symbol):
    if kernel_space == "k" or dso.startswith("[kernel") or re.match(r"lib(c|m|stdc\+\+|gcc_s|pthread)[.-]", dso) \
            or dso.startswith("ld-linux"):
        return "runtime"
    if dso.startswith("libsystemc") or symbol.startswith("sc_core::") or symbol.startswith("tlm::"):
        return "systemc"
    if dso.startswith("libpng") or dso.startswith("libz") or REPORTS.search(symbol):
        return "reports"
    if SCHEDULE.search(symbol):
        return "schedule"
    if MODULES.search(symbol):
        return "modules"
    if "::" not in symbol and not symbol.startswith("0x") and not symbol.startswith("operator"):
        return "kernel"  # the C kernel's functions (rt_*, and its static helpers)
    return "reports"


def main(argv):
    label = argv[0] if argv else "run"
    shares = {}
    for line in sys.stdin:
        m = LINE.match(line)
        if not m:
            continue
        pct, dso, space, symbol = float(m.group(1)), m.group(2), m.group(3), m.group(4)
        key = part(dso, space, symbol)
        shares[key] = shares.get(key, 0.0) + pct
    order = ["systemc", "kernel", "schedule", "modules", "reports", "runtime"]
    print("%-28s " % label + " ".join("%s %5.1f %%" % (k, shares.get(k, 0.0)) for k in order))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
