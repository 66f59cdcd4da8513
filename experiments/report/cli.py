"""The command line of the report package."""
import argparse
import contextlib
import glob
import os
import subprocess
import sys

from memory_exit import leave_if_out_of_memory
from output_files import (OutputError, OutputSet, exit_on_signals, finish_stdout, help_on_stdout, list_values,
                          named_stdout, nonempty, os_message, out_folder, read_text, refuse_empty_values,
                          refuse_repeated_options, shown)
from stop_signals import run_child
from stream_checks import check_streams

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def check_outputs(inputs, outputs):
    """A command's (option, path) outputs against its (option, path) inputs and each other, before
    anything is written (output_files.OutputSet); OutputError names the option and the file."""
    outs = OutputSet()
    for option, path in inputs:
        outs.add_input(option, path)
    for option, path in outputs:
        outs.add(option, path)
    outs.check()


def made_folders(folder, option="--doc"):
    """Makes FOLDER and the folders above it that are missing; returns those it made, deepest
    first (for the clean-up of a run that fails)."""
    missing = []
    while folder and not os.path.isdir(folder):
        missing.append(folder)
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    for made in reversed(missing):
        try:
            os.mkdir(made)
        except FileExistsError as e:  # a file, or a dangling link, in the folder's place
            raise OutputError("%s: the folder '%s' it writes into is a file, not a folder" % (option, shown(made))) from e
    return missing


def pictures(option, folder, names):
    """The pictures a command writes into FOLDER, as outputs (none to check while it is not made)."""
    return [(option, os.path.join(folder, n)) for n in names] if os.path.isdir(folder) else []


def reproduction(args):
    from . import reproduction as rep
    from .verdict import HOLDS
    res = os.path.abspath(args.results)
    doc = args.doc
    if not doc:
        mode_file = os.path.join(res, "mode")
        full = os.path.exists(mode_file) and open(mode_file).read().strip() == "full"
        doc = os.path.join(REPO, "docs", "reproduction.md") if full else os.path.join(res, "reproduction.md")
    read = [p for pattern in ("*.csv", "*.tsv", "*/*.csv", "*/*.tsv", "plots/*.png", "*/plots/*.png")
            for p in glob.glob(os.path.join(res, pattern))]
    img = os.path.join(os.path.dirname(os.path.realpath(doc)), "img")  # beside the page a link names
    made = made_folders(img)  # the page's folder and its pictures' (the command makes them)
    try:
        check_outputs([("results", p) for p in read],
                      [("--doc", doc)] + pictures("--doc", img, ["reproduction-fig%d.png" % f for f in rep.FIGURE_NUMBERS]))
        by_profile = rep.write(res, doc)
    except BaseException:
        for folder in made:  # a refused or failed run leaves no folder it made (empty ones only)
            with contextlib.suppress(OSError):
                os.rmdir(folder)
        raise
    print("report: %s (%s)" % (doc, "; ".join(
        "%s: %d of %d claims hold" % (p, sum(1 for c in cl if c.verdict == HOLDS), len(cl)) for p, cl in by_profile)))
    return 0


def collect(args):
    from . import collect as collectlib
    res = os.path.abspath(args.results)
    points, bad, differ = collectlib.collect(res)
    print("collect: %d points, %d not ok, %d images differing from the 1-processor image -> %s/fig*.csv"
          % (points, bad, differ, res))
    return 0


def plots(args):
    from . import plots as plotlib
    for png in plotlib.reproduction(os.path.abspath(args.results)):
        print("plot: %s" % png)
    return 0


def error_vs_runtime(args):
    from . import error_vs_runtime as evr
    results = os.path.join(REPO, "experiments", "error_vs_runtime", "results")
    quantum_csv = args.quantum or os.path.join(results, "quantum.csv")
    pruning_csv = args.pruning or os.path.join(results, "pruning.csv")
    doc = args.doc or os.path.join(REPO, "docs", "error-vs-runtime.md")
    img = args.img_dir or os.path.join(REPO, "docs", "img")
    drawn = ["error-quantum.png", "error-quantum-q.png", "error-pruning.png"]
    made = []  # the page's folder and the pictures' (the command makes them; a failed run removes them)
    try:
        made = made_folders(os.path.dirname(os.path.realpath(doc)), "--doc")
        made += made_folders(img, "--img-dir")
        check_outputs([("--quantum", quantum_csv), ("--pruning", pruning_csv)],
                      [("--doc", doc)] + pictures("--img-dir", img, drawn))
        evr.write(quantum_csv, pruning_csv, doc, img, args.command)
    except BaseException:
        for folder in made:
            with contextlib.suppress(OSError):
                os.rmdir(folder)
        raise
    print("report: %s, plots in %s" % (doc, img))
    return 0


def sweep_plan(args):
    from . import sweep
    axes = [sweep.parse_axis(a) for a in args.axis]
    if len({n for n, _ in axes}) != len(axes):
        raise ValueError("each --axis option may be given once")
    fixed = args.fixed[1:] if args.fixed[:1] == ["--"] else args.fixed
    sweep.check_fixed(fixed)  # before --out is made
    columns = list_values("--columns", args.columns) if args.columns else sweep.DEFAULT_COLUMNS
    out = out_folder("--out", args.out, [("scene", args.scene)] + sweep.named_files(fixed))
    total, done = sweep.plan(out, args.sim, args.scene, axes, fixed, os.path.join(out, "points.list"), columns,
                             args.y)
    print("sweep: %d points (%d done before), results in %s" % (total, done, out))
    return 0


def sweep_collect(args):
    from . import sweep
    columns = [c for c in args.columns.split(",") if c] if args.columns else sweep.DEFAULT_COLUMNS
    out = os.path.abspath(args.out)
    failed = sweep.collect(out, columns, args.y)
    sweep.report_deadlocked(out)
    sweep.report_failed(out, failed)
    print("sweep: %s/sweep.csv%s" % (out, "" if failed else ", %s/sweep.png" % out))
    return 1 if failed else 0


def compare(args):
    from . import compare as comparelib
    try:
        columns = list_values("--columns", args.columns) if args.columns else None
    except ValueError as e:  # the command line's fault, as an empty --columns is (exit 2)
        raise OutputError(str(e)) from None
    rows, diffs = comparelib.compare(os.path.abspath(args.old), os.path.abspath(args.new), columns)
    for line in diffs:
        print(line)
    print("compare: %d points of %s, %d differences in %s" % (rows, args.old, len(diffs), args.new))
    return 1 if diffs else 0


def machine_as_run_reads_it(path, build, given):
    """{key: value} of the machine file PATH as torusrt-sim reads it: every key, the defaults of
    those it leaves out, each value as a run writes it (`ips="2"` is `2x1x1`), from
    `torusrt-sim --dump-config --config PATH`; None when the default BUILD holds no torusrt-sim,
    OutputError (exit 2) when the --build the user GIVEN holds none."""
    from . import machine_file as mf
    sim = os.path.join(build, "torusrt-sim")
    if not os.access(sim, os.X_OK):
        if given:
            raise OutputError("--build '%s': no torusrt-sim in it (build first, or name the build folder)"
                              % shown(build))
        return None
    done = run_child([sim, "--dump-config", "--config", path], stdin=subprocess.DEVNULL,
                     capture_output=True, text=True, errors="replace")
    if done.returncode != 0:
        raise ValueError("--compare '%s': torusrt-sim does not read it: %s"
                         % (shown(path), shown(done.stderr.strip(), backslash=False)))
    return mf.read_machine_file(done.stdout, "torusrt-sim --dump-config --config %s" % shown(path))


def machine(args):
    import json
    from . import machine_file as mf
    text = read_text(args.report, "report")  # a device or a FIFO refused before reading, naming it
    try:
        try:
            report = json.loads(text)
        except json.JSONDecodeError as e:  # a machine file or another text given as the report
            raise ValueError("line %d column %d: not a JSON run report (torusrt-sim --stats writes one): %s"
                             % (e.lineno, e.colno, e.msg)) from None
        if not isinstance(report, dict):
            raise ValueError("not a JSON report (a %s, not an object)" % type(report).__name__)
        pairs = mf.from_report(report)
        tables = mf.tables_from_report(report)
    except ValueError as e:  # not JSON, or no machine in it: name the report
        raise ValueError("%s: %s" % (shown(args.report), e))
    except RecursionError:  # a hand-made file nested thousands deep
        raise ValueError("%s: not a JSON report (nested too deeply)" % shown(args.report)) from None
    if not args.compare:
        try:
            mf.unknown_bytes(pairs)
        except ValueError as e:
            raise ValueError("%s: %s" % (shown(args.report), e)) from None
        sys.stdout.write(mf.toml_text(pairs, tables))
        return 0
    # The file's syntax first (its own lines named), then its machine as a run reads it.
    written = mf.read_machine_file(read_text(args.compare, "--compare"), shown(args.compare))
    given = args.build is not None
    build = args.build if given else os.environ.get("TORUSRT_BUILD") or os.path.join(REPO, "build")
    values = machine_as_run_reads_it(args.compare, build, given)
    if values is None:
        print("machine: no torusrt-sim in %s (--build): keys compared as written, without the defaults of the "
              "keys the file leaves out" % shown(build), file=sys.stderr)
        values = written
    diff = mf.differences(pairs, values)
    for line in diff:
        print("machine: %s" % shown(line, backslash=False), file=sys.stderr)
    print("machine: %s and %s: %s" % (shown(args.report), shown(args.compare),
                                      "%d keys differ" % len(diff) if diff else "the same %d keys" % len(pairs)))
    return 1 if diff else 0


def main(argv):
    check_streams("experiments/report", argv)  # `>> REPORT.json`: refused before any message
    parser = argparse.ArgumentParser(prog="experiments/report", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("reproduction", help="write the comparison with the paper from a sweep's CSVs")
    p.add_argument("results", help="the sweep's results folder (fig5_6.csv, fig7.csv, fig8.csv, fig10_12.csv)")
    p.add_argument("--doc", help="the page to write (default docs/reproduction.md for a full sweep, "
                                 "RESULTS/reproduction.md otherwise); plots are copied to img/ beside it")
    p.set_defaults(run=reproduction)
    p = sub.add_parser("collect", help="the sweep's JSON reports (RESULTS/points.tsv) into fig5_6.csv, fig7.csv, "
                                       "fig8.csv and fig10_12.csv")
    p.add_argument("results")
    p.set_defaults(run=collect)
    p = sub.add_parser("plots", help="draw RESULTS/plots/fig*.png with experiments/plots/*.gp")
    p.add_argument("results")
    p.set_defaults(run=plots)
    p = sub.add_parser("error-vs-runtime", help="write docs/error-vs-runtime.md and its plots from the study's CSVs")
    p.add_argument("--quantum", help="quantum.csv (default experiments/error_vs_runtime/results/quantum.csv)")
    p.add_argument("--pruning", help="pruning.csv (default experiments/error_vs_runtime/results/pruning.csv)")
    p.add_argument("--doc", help="the page (default docs/error-vs-runtime.md)")
    p.add_argument("--img-dir", help="where the plots go (default docs/img)")
    p.add_argument("--command", default="experiments/error_vs_runtime/study.sh",
                   help="the command line the page says produced it")
    p.set_defaults(run=error_vs_runtime)
    p = sub.add_parser("sweep-plan", help="(experiments/sweep) write OUT/points.tsv and the point list "
                                          "OUT/points.list (JSON, tab, command)")
    p.add_argument("--out", required=True)
    p.add_argument("--sim", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--axis", action="append", required=True)
    p.add_argument("--columns", default="", help="checked before any point runs, as --y")
    p.add_argument("--y", default="sim_time_s")
    p.add_argument("fixed", nargs=argparse.REMAINDER)
    p.set_defaults(run=sweep_plan)
    p = sub.add_parser("sweep-collect", help="(experiments/sweep) OUT/sweep.csv and OUT/sweep.png from the points")
    p.add_argument("--out", required=True)
    p.add_argument("--columns", default="")
    p.add_argument("--y", default="sim_time_s")
    p.set_defaults(run=sweep_collect)
    p = sub.add_parser("compare", help="the same points of two sweeps must report the same values "
                                       "(every column but wall_s); exit 1 on any difference")
    p.add_argument("old", type=nonempty, help="a results folder (fig*.csv, in profile subfolders or not)")
    p.add_argument("new", type=nonempty, help="the results folder to hold against it")
    p.add_argument("--columns", default=None, type=nonempty, help="compare only these columns (comma-separated)")
    p.set_defaults(run=compare)
    p = sub.add_parser("machine", help="the machine file (torusrt-sim --config) of a JSON report's config.options")
    p.add_argument("report", type=nonempty)
    p.add_argument("--compare", metavar="M.toml", type=nonempty,
                   help="compare with this machine file key by key instead, as torusrt-sim reads it (the defaults "
                        "of the keys it leaves out)")
    p.add_argument("--build", type=nonempty,
                   help="the build folder whose torusrt-sim reads the --compare file (default $TORUSRT_BUILD, "
                        "else build/); one given must hold torusrt-sim (exit 2)")
    p.set_defaults(run=machine)
    from . import fidelity
    fidelity.add_commands(sub)
    refuse_empty_values(parser)  # '' is never "the default": --doc '' would rewrite docs/
    refuse_repeated_options(parser)
    help_on_stdout(parser)  # --help into a full disk or a closed standard output: named, exit 1
    args = parser.parse_args(argv)
    prog = "sweep" if args.command.startswith("sweep-") else "experiments/report"  # the command the user ran
    exit_on_signals(prog)
    try:
        named_stdout()  # a full disk, a closed pipe or a closed standard output: named, exit 1
        status = args.run(args)
        finish_stdout()
        return status
    except OutputError as e:  # an output refused before anything was written: the command line's fault
        print("%s: %s" % (prog, shown(e, backslash=False)), file=sys.stderr)
        return 2
    except ValueError as e:
        print("%s: %s" % (prog, shown(e, backslash=False)), file=sys.stderr)
        return 2 if args.command == "sweep-plan" else 1  # the sweep's command line, checked before any run
    except (OSError, KeyError, subprocess.CalledProcessError) as e:
        leave_if_out_of_memory(prog, e)  # ENOMEM: the tools' out-of-memory message, as a MemoryError
        print("%s: %s" % (prog, shown(os_message(e), backslash=False)), file=sys.stderr)
        return 1
