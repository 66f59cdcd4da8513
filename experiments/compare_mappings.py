"""compare-mappings - busy time per node of several mappings of one machine, side by side.

    experiments/compare-mappings SCENE.nff [--map LIST] [--out FILE.png] [--build DIR]
                                 [-- TORUSRT-SIM OPTIONS...]

Runs torusrt-sim once per mapping of LIST (default block,cyclic,block-cyclic:3,cost) with the
options after `--` (the machine: --ips, --cluster, --size, ...), and draws each run's busy time
per node, sorted from the busiest down, with the mean, in one PNG (default compare-mappings.png;
gnuplot, layout experiments/plots/compare-mappings.gp). A node's busy time is the sum over its
processors. T(1) is measured once, by the first run, and passed to the others with --t1. Prints
one line per mapping: image time, efficiency, the busiest node's and the mean busy time.
The PNG is written under the output rules of experiments/output_files.py: through a temporary
beside it, a link followed to its file; --out naming the scene or a file named after `--` (and
any file a `--config` machine file names), a folder, a FIFO, a device or a stream (/dev/stdout)
is refused before any run, and so are output options (-o, -oFILE, --stats, --stats-series, --vcd,
...), --map, --map-file, --t1, --help, --version, --dump-config, an animation's options (--frames,
--orbit, --camera-path, --motion) and --stats-interval after `--`, an empty value, and an empty or
repeated mapping in LIST.
Exit status 1 when a run fails (its messages are printed, a byte that is not UTF-8 as \\xNN) or a
write fails (`standard output: cannot write: REASON`, a closed standard output before any run),
2 on a bad command line, 128 + N on a stopping signal (Ctrl-C, TERM, HUP, QUIT, USR1, USR2, ALRM:
`compare-mappings: stopped by SIGINT`; its temporary folder of runs removed).

Example: experiments/compare-mappings scenes/paper-image1.nff --out m.png -- --ips 4x4x4 --size 72x72
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

from output_files import (ANIMATION_OPTIONS, NO_RUN_OPTIONS, OutputError, OutputSet, finish_stdout, help_on_stdout,
                          list_values, named_files, named_stdout, nonempty, os_message, output_options,
                          refuse_repeated_options, shown, staged, unusable_option, write_text)
from stop_signals import run_child
from stream_checks import check_streams

HERE = os.path.dirname(os.path.abspath(__file__))


def shown_lines(text):
    """A child's messages, line by line as shown() shows a name (its own escapes kept)."""
    return "\n".join(shown(line, backslash=False) for line in text.split("\n"))


def node_busy(report):
    """Busy seconds per node, busiest first."""
    busy = {}
    for ip in report["per_ip"]:
        busy[ip["node"]] = busy.get(ip["node"], 0.0) + ip["busy_s"]
    return sorted(busy.values(), reverse=True)


def run(sim, scene, mapping, options, work, t1):
    """One torusrt-sim run; its JSON report."""
    name = mapping.replace(":", "-")
    stats = os.path.join(work, name + ".json")
    cmd = [sim, scene, "-q", "-o", os.path.join(work, name + ".png"), "--stats", stats, "--map", mapping]
    cmd += (["--t1", repr(t1)] if t1 else []) + options
    # a file name's bytes that are not UTF-8 kept as they came, then shown as \xNN
    done = run_child(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                     errors="surrogateescape")
    if done.returncode != 0:
        sys.stderr.write("compare-mappings: --map %s failed (exit %d): %s\n"
                         % (mapping, done.returncode, shown_lines(done.stderr.rstrip("\n"))))
        sys.exit(1)
    try:
        with open(stats) as f:
            report = json.load(f)
    except (OSError, ValueError) as e:  # exit 0 without a report: nothing to compare
        sys.stderr.write("compare-mappings: --map %s: torusrt-sim wrote no report (%s)\n"
                         % (mapping, os_message(e)))
        sys.exit(1)
    why = report_fault(report)
    if why:  # another build's report, or not torusrt-sim's
        sys.stderr.write("compare-mappings: --map %s: the report of %s %s (another version of torusrt-sim?)\n"
                         % (mapping, shown(sim), why))
        sys.exit(1)
    return report


def report_fault(report):
    """Why a run's REPORT cannot be compared: not an object, or a field compare-mappings reads
    missing ("" when it has them all)."""
    def number(x):
        return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
    if not isinstance(report, dict):
        return "is not a JSON object (a %s)" % type(report).__name__
    for field in ("sim_time_s", "t1_s", "efficiency"):
        if not number(report.get(field)):
            return "has no number %s" % field
    ips = report.get("per_ip")
    if not isinstance(ips, list) or not ips or not all(
            isinstance(ip, dict) and isinstance(ip.get("node"), int) and number(ip.get("busy_s")) for ip in ips):
        return "has no per_ip list of nodes and their busy_s"
    return ""


def plot(results, out, work):
    """Writes one data file per mapping and runs the checked-in gnuplot layout into OUT (through
    a temporary beside it)."""
    titles = []
    top = max(max(busy) for _, _, busy in results)
    for i, (mapping, report, busy) in enumerate(results, 1):
        write_text(os.path.join(work, "m-%d.dat" % i), "".join("%d %.6g\n" % (rank, b) for rank, b in enumerate(busy)))
        mean = sum(busy) / len(busy)
        titles.append("%s|image %.4g s, busiest %.4g s = %.3f x mean" %
                      (mapping, report["sim_time_s"], busy[0], busy[0] / mean if mean else 0))
        write_text(os.path.join(work, "m-%d.mean" % i), "%.6g\n" % mean)
    write_text(os.path.join(work, "titles.txt"), "\n".join(titles) + "\n")
    gp = os.path.join(HERE, "plots", "compare-mappings.gp")
    with staged(out, "--out") as tmp:
        args = ["gnuplot", "-e", "dat='%s'; out='%s'; n=%d; top=%.6g; nodes=%d" %
                (work, tmp, len(results), top, len(results[0][2])), gp]
        done = run_child(args, stderr=subprocess.PIPE, text=True, errors="surrogateescape")
        if done.returncode != 0:
            raise OSError("gnuplot failed: %s" % shown_lines(done.stderr.strip()))


def main():
    check_streams("compare-mappings", sys.argv[1:])  # `>> SCENE.nff`: refused before any message
    parser = argparse.ArgumentParser(usage="%(prog)s SCENE.nff [--map LIST] [--out FILE.png] [--build DIR] "
                                     "[-- TORUSRT-SIM OPTIONS...]", description=__doc__.split("\n")[0])
    parser.add_argument("scene", type=nonempty)
    parser.add_argument("--map", default="block,cyclic,block-cyclic:3,cost", type=nonempty)
    parser.add_argument("--out", default="compare-mappings.png", type=nonempty)
    parser.add_argument("--build", default=os.environ.get("TORUSRT_BUILD") or os.path.join(HERE, "..", "build"),
                        type=nonempty)
    refuse_repeated_options(parser)
    help_on_stdout(parser)  # --help into a full disk or a closed standard output: named, exit 1
    argv = sys.argv[1:]
    options = argv[argv.index("--") + 1:] if "--" in argv else []
    args = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    sim = os.path.join(args.build, "torusrt-sim")
    if not os.access(sim, os.X_OK):
        parser.error("no torusrt-sim in %s (build first, or pass --build)" % args.build)
    try:
        maps = list_values("--map", args.map)
    except ValueError as e:
        parser.error(str(e))
    mine = [o for o in options if o.partition("=")[0] in ("--map", "--map-file", "--t1")]
    if mine:
        parser.error("%s after --: compare-mappings gives each run its --map (give the mappings with --map "
                     "before --) and the first run's T(1) as --t1" % mine[0].partition("=")[0])
    written = output_options(options)
    if written:
        parser.error("%s after --: every run would write it into one file; compare-mappings keeps each run's "
                     "image and statistics itself and writes --out" % written[0])
    unusable = unusable_option(options, NO_RUN_OPTIONS + ANIMATION_OPTIONS + ("--stats-interval",))
    if unusable:
        parser.error("%s after --: every run would fail or lose what it gives (help, the version and --dump-config "
                     "run nothing; an animation's -o is a frame pattern; compare-mappings keeps no time series)"
                     % unusable)
    outs = OutputSet()
    outs.add_input("scene", args.scene)
    for option, path in named_files(options):
        outs.add_input(option, path)
    try:
        out = outs.add("--out", args.out)
        outs.check()
    except OutputError as e:
        sys.stderr.write("compare-mappings: %s\n" % e)
        sys.exit(2)
    # The first run's command line checked by torusrt-sim --dump-config (nothing is run), as the
    # sweep checks its first point: an option after -- that every run refuses stops it now.
    done = run_child([sim, args.scene, "--dump-config", "--map", maps[0]] + options, stdin=subprocess.DEVNULL,
                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="surrogateescape")
    if done.returncode != 0:
        sys.stderr.write("compare-mappings: the options after -- do not check out (no run was made): %s\n"
                         % shown((done.stderr.strip().splitlines() or ["exit %d" % done.returncode])[0],
                                 backslash=False))
        sys.exit(2)
    try:
        named_stdout()  # a closed standard output (>&-) ends the command before any run
    except OSError as e:
        sys.stderr.write("compare-mappings: %s\n" % e)
        sys.exit(1)
    results, t1 = [], None
    with tempfile.TemporaryDirectory(prefix="compare-mappings.") as work:
        for mapping in maps:
            report = run(sim, args.scene, mapping, options, work, t1)
            t1 = t1 or report["t1_s"]
            results.append((mapping, report, node_busy(report)))
        try:
            plot(results, out, work)
        except OSError as e:
            sys.stderr.write("compare-mappings: %s\n" % e)
            sys.exit(1)
    try:  # a full disk or a closed pipe: named, exit 1
        print("%-16s %12s %10s %14s %12s" % ("mapping", "image s", "effic.", "busiest node s", "mean s"))
        for mapping, report, busy in results:
            print("%-16s %12.4g %9.1f%% %14.4g %12.4g" % (mapping, report["sim_time_s"], 100 * report["efficiency"],
                                                         busy[0], sum(busy) / len(busy)))
        print("compare-mappings: wrote %s" % shown(args.out))
        finish_stdout()
    except OSError as e:
        sys.stderr.write("compare-mappings: %s\n" % e)
        sys.exit(1)

