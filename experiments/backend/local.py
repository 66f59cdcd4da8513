"""The GNU parallel backends: this machine (local) or the machines of an sshlogin file (ssh)."""
import csv
import os
import shlex

from stop_signals import run_child


def parallel_command(jobs, joblog, sshloginfile=None):
    cmd = ["parallel", "--will-cite", "--halt", "never", "-j", str(jobs), "--joblog", joblog]
    if sshloginfile:
        cmd += ["--sshloginfile", sshloginfile]
    return cmd


def read_joblog(path):
    """Exit status and signal of each line of a parallel run, by its 1-based line number."""
    out = {}
    if not os.path.exists(path):
        return out
    with open(path, newline="") as f:
        rows = list(csv.reader(f, delimiter="\t"))
    for row in rows[1:]:
        if len(row) >= 8 and row[0].isdigit():
            out[int(row[0])] = (int(row[6]), int(row[7]))
    return out


def run(phases, state, jobs, sshloginfile=None, say=print):
    """Runs each phase's todo list (PHASE = (todo file, points)) with parallel, one phase after
    the other; returns {point: "exit E signal S"} for the points whose command failed."""
    failed = {}
    for number, (todo, points) in enumerate(phases, 1):
        joblog = os.path.join(state, "joblog.phase%d" % number)
        if os.path.exists(joblog):  # a joblog is this run's or none
            os.remove(joblog)
        if not points:
            continue
        cmd = parallel_command(jobs, joblog, sshloginfile)
        say("backend: phase %d, %d points: %s < %s" % (number, len(points), shlex.join(cmd), todo))
        with open(todo) as stdin:
            # the points' progress lines pass through; on a stopping signal parallel may have had
            # it too, and its TERM stops the points
            run_child(cmd, stdin=stdin, stop="terminate")
        for line, (rc, sig) in read_joblog(joblog).items():
            if (rc or sig) and 0 < line <= len(points):
                failed[points[line - 1]] = "exit %d signal %d" % (rc, sig)
    return failed
