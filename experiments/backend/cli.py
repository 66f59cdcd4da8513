"""The command line of the backend package: `run` runs point lists, `task` is a Slurm array task."""
import argparse
import datetime
import os
import resource
import sys
import time

import decimal_number
from memory_exit import leave_if_out_of_memory
from output_files import (OutputError, OutputSet, WriteError, append_text, exit_on_signals, finish_stdout,  # noqa: E501
                          help_on_stdout, input_file, named_stdout, nonempty, os_message, out_folder,
                          refuse_empty_values, refuse_repeated_options, write_lines)
from stream_checks import check_streams

from . import local, points, slurm, task

MAX_JOBS = 1000  # points in flight at most, whatever -j says: GNU parallel and Slurm take no more usefully

RUNS_HEADER = ["started_utc", "mode", "jobs", "hosts", "cores", "points", "points_run", "failed", "wall_s",
               "cpu_s", "load1"]


def parse_backend(text):
    """'local', 'slurm' or 'ssh:HOSTFILE' -> (kind, hostfile)."""
    if text in ("local", "slurm"):
        return text, None
    if text.startswith("ssh:") and len(text) > 4:
        hostfile = text[4:]
        if not os.path.isfile(hostfile):
            raise ValueError("--backend %s: no such sshlogin file '%s'" % (text, hostfile))
        return "ssh", os.path.abspath(hostfile)
    raise ValueError("--backend must be local, ssh:HOSTFILE or slurm, not '%s'" % text)


def in_flight(asked, kind, most):
    """The points in flight: -j (default one per core; unlimited on Slurm), never more than the
    largest phase's points to run (MOST) nor MAX_JOBS."""
    if asked is None:
        return None if kind == "slurm" else min(os.cpu_count() or 1, most)
    return min(asked, most, MAX_JOBS)


def positive(text):
    """-j and --per-task: a whole number from 1 up, in the strict decimal syntax (`010`, ` 2` and
    digits of other scripts refused)."""
    try:
        value = decimal_number.whole(text) if text.isascii() else 0
    except ValueError as e:
        raise argparse.ArgumentTypeError("must be a whole number, 1 or more: %s" % e) from None
    if value < 1:
        raise argparse.ArgumentTypeError("must be a whole number, 1 or more, not '%s'" % text)
    return value


class Parser(argparse.ArgumentParser):
    """A command-line error in one line, `experiments/backend run: MESSAGE`, exit 2, as every
    other refusal of the backend (not the usage block)."""

    def error(self, message):
        self.exit(2, "%s: %s (%s --help for the options)\n" % (self.prog, message, self.prog))


def say(text):
    print(text, flush=True)


def record_run(path, label, jobs, hosts, total, ran, failed, wall, cpu):
    new = not os.path.exists(path) or os.path.getsize(path) == 0
    try:
        load1 = open("/proc/loadavg").read().split()[0]
    except OSError:
        load1 = ""
    started = datetime.datetime.fromtimestamp(time.time() - wall, datetime.timezone.utc)
    row = [started.strftime("%Y-%m-%dT%H:%M:%SZ"), label, str(jobs), hosts, str(os.cpu_count()), str(total),
           str(ran), str(failed), "%.1f" % wall, "" if cpu is None else "%.1f" % cpu, load1]
    append_text(path, ("\t".join(RUNS_HEADER) + "\n" if new else "") + "\t".join(row) + "\n", "--runs")


def report_failures(state, pending, status):
    """Lists every point that was to run and has no result, writes STATE/failed.tsv; returns their number."""
    failed = [p for p in pending if not p.is_done() or (p.identity is not None and not os.path.exists(p.record()))]
    write_lines(os.path.join(state, "failed.tsv"),
                ["%s\t%s\t%s\t%s" % (status.get(p, "no result"), p.done, p.log, p.command) for p in failed], "--state")
    for p in failed:
        why = status.get(p, "no result")
        print("backend: FAILED (%s): %s\n    log %s: %s" % (why, p.command, p.log, points.log_tail(p.log)),
              file=sys.stderr)
    return len(failed)


def run(args):
    kind, hostfile = parse_backend(args.backend)
    for f in args.lists:  # a device may never end, a FIFO never open: refused before reading
        input_file(f, "the point list")
    if args.runs:  # refused before any point runs, not after: not a list, not a stream
        outs = OutputSet()
        for f in args.lists:
            outs.add_input("point list", f)
        outs.add("--runs", args.runs)
        outs.check()
    state = out_folder("--state", args.state, [("point list", f) for f in args.lists])
    phases = [points.read(os.path.abspath(f)) for f in args.lists]
    points.assign_logs(phases, os.path.join(state, "logs"))
    todo, cache, made = [], {}, {}
    for phase in phases:
        for p in phase:
            points.identify(p, cache, made)
    points.check_results_are_not_inputs(phases, args.lists)
    points.check_own_files_are_not_inputs(phases, state, args.runs)
    # Made once every list is read and checked: a refused command leaves no folder behind.
    os.makedirs(os.path.join(state, "logs"), exist_ok=True)
    for number, phase in enumerate(phases, 1):
        pending = []
        for p in phase:
            if p.is_done():
                why = points.changed(p)
                if why is None:
                    continue
                say("backend: %s: made by another command or from other inputs (%s); running it again"
                    % (p.done, why))
                # Only a result the backend made (its record is there) is removed: a file without
                # one may be what the command reads (a scene, a machine file), and is left to the
                # command; the run succeeds when it records the point again.
                if os.path.lexists(p.record()):
                    os.remove(p.record())
                    os.remove(p.done)
            pending.append(p)
        path = os.path.join(state, "phase%d.todo" % number)
        points.write_todo(path, pending)
        todo.append((path, pending))
    total = sum(len(p) for p in phases)
    to_run = sum(len(p) for _, p in todo)
    jobs = in_flight(args.jobs, kind, max([len(p) for _, p in todo] + [1]))
    where = {"local": "this machine", "ssh": "the machines of %s" % hostfile, "slurm": "Slurm"}[kind]
    say("backend: %d points in %d phase(s), %d already done, %d to run on %s%s"
        % (total, len(phases), total - to_run, to_run, where, " (-j %d)" % jobs if jobs else ""))
    start, cpu0 = time.time(), resource.getrusage(resource.RUSAGE_CHILDREN)
    if kind == "slurm":  # the CPU time of the points, as the tasks measured it
        status, cpu = slurm.run(todo, state, args.per_task, jobs, args.slurm_args, args.name, say)
    else:
        status = local.run(todo, state, jobs, hostfile, say)
        cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (cpu1.ru_utime - cpu0.ru_utime) + (cpu1.ru_stime - cpu0.ru_stime)
    wall = time.time() - start
    failed = report_failures(state, [p for _, pend in todo for p in pend], status)
    ran = sum(1 for _, pend in todo for p in pend
              if p.is_done() and (p.identity is None or os.path.exists(p.record())))
    say("backend: %d points run, %d failed, %.1f s wall%s" % (ran, failed, wall, "" if cpu is None else
                                                              ", %.1f s CPU" % cpu))
    if args.runs:
        hosts = {"local": "local", "ssh": "sshloginfile %s" % os.path.basename(hostfile or ""), "slurm": "slurm"}[kind]
        record_run(args.runs, args.label, jobs or "", hosts, total, ran, failed, wall, cpu)
    return 1 if failed else 0


def main(argv):
    check_streams("experiments/backend", argv)  # `>> LIST`: refused before any message
    parser = Parser(prog="experiments/backend", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("run", help="run point lists (one per phase, in order): DONE-FILE<TAB>COMMAND per line")
    p.add_argument("lists", nargs="+", metavar="LIST", type=nonempty)
    p.add_argument("--state", required=True, type=nonempty,
                   help="folder for the run's todo lists, joblogs, logs, Slurm output")
    p.add_argument("--backend", default="local", type=nonempty, help="local (default), ssh:HOSTFILE or slurm")
    p.add_argument("-j", "--jobs", type=positive, default=None, help="points in flight (default: local one per "
                   "core, ssh per machine as the sshlogin file says, slurm unlimited); at most the points of the "
                   "largest phase and %d" % MAX_JOBS)
    p.add_argument("--slurm-args", default="", help="more sbatch options, e.g. \"--partition=short --time=0:20:00\"")
    p.add_argument("--per-task", type=positive, default=4, help="points per Slurm array task (default 4)")
    p.add_argument("--name", default="torusrt", type=nonempty, help="the Slurm job name's prefix")
    p.add_argument("--runs", type=nonempty, help="append one line about this run to this TSV file")
    p.add_argument("--label", default="", help="the mode column of that line")
    p.set_defaults(run=run)
    p = sub.add_parser("task", help="(inside a Slurm array task) run this task's lines of a todo list")
    p.add_argument("todo", type=nonempty)
    p.add_argument("per_task", type=int)
    p.add_argument("rcdir")
    p.set_defaults(run=lambda a: task.run(a.todo, a.per_task, a.rcdir))
    refuse_empty_values(parser)
    refuse_repeated_options(parser)
    help_on_stdout(parser)  # --help into a full disk or a closed standard output: named, exit 1
    args = parser.parse_args(argv)
    # Ctrl-C even where a shell started the backend in the background (a sweep does), ignoring it
    exit_on_signals("experiments/backend", even_ignored=("SIGINT", "SIGQUIT"))
    try:
        named_stdout()  # a full disk, a closed pipe or a closed standard output: named, exit 1
        status = args.run(args)
        finish_stdout()
        return status
    except OutputError as e:
        print("experiments/backend: %s" % e, file=sys.stderr)
        return 2
    except WriteError as e:  # the run's own records or standard output: nothing more can be said
        print("experiments/backend: %s" % e, file=sys.stderr)
        return 1
    except (OSError, ValueError, RuntimeError) as e:
        leave_if_out_of_memory("experiments/backend", e)  # ENOMEM: the out-of-memory message, exit 1
        print("experiments/backend: %s" % os_message(e), file=sys.stderr)
        return 2
