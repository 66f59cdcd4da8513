"""The Slurm backend: each phase a job array of K points per task, each phase after the one
before it (--dependency=afterany, so a point whose T(1) failed runs, fails at once and is listed
as failed rather than left pending), [done/N] from squeue while waiting, the failed tasks from
sacct afterwards, scancel on an interrupt."""
import datetime
import os
import re
import shlex
import subprocess
import sys
import time

from output_files import append_text
from stop_signals import run_child

BACKEND = os.path.dirname(os.path.abspath(__file__))
MAX_TASKS = 1000  # below Slurm's default MaxArraySize (1001)


def tasks_for(points, per_task):
    return (points + per_task - 1) // per_task


def sbatch_command(todo, tasks, per_task, jobs, slurm_args, name, after, outdir):
    array = "1-%d" % tasks + ("%%%d" % jobs if jobs else "")
    cmd = ["sbatch", "--parsable", "--job-name", name, "--array", array,
           "--output", os.path.join(outdir, "%A_%a.out")]
    if after:
        cmd.append("--dependency=afterany:%s" % after)
    cmd += shlex.split(slurm_args or "")
    task = ["python3", BACKEND, "task", todo, str(per_task), todo + ".rc"]
    return cmd + ["--wrap", shlex.join(task)]


def submit(phases, state, per_task, jobs, slurm_args, name, say):
    """Submits one array per phase with points; returns [(job id, tasks, points, K)] in order.
    The caller cancels what was submitted if this is interrupted half-way."""
    outdir = os.path.join(state, "slurm")
    os.makedirs(outdir, exist_ok=True)
    submitted, after = [], None
    for number, (todo, points) in enumerate(phases, 1):
        if not points:
            continue
        k = max(per_task, tasks_for(len(points), MAX_TASKS))
        rcdir = todo + ".rc"
        os.makedirs(rcdir, exist_ok=True)
        for old in os.listdir(rcdir):
            os.remove(os.path.join(rcdir, old))
        tasks = tasks_for(len(points), k)
        cmd = sbatch_command(todo, tasks, k, jobs, slurm_args, "%s-phase%d" % (name, number), after, outdir)
        line = shlex.join(cmd)
        say("backend: phase %d, %d points in %d tasks of %d: %s" % (number, len(points), tasks, k, line))
        append_text(os.path.join(state, "submitted"), line + "\n", "--state")
        out = run_child(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                        errors="replace")
        if out.returncode != 0:
            raise RuntimeError("sbatch failed (exit %d): %s" % (out.returncode, out.stderr.strip()))
        job = out.stdout.strip().split(";")[0]
        submitted.append((job, tasks, len(points), k))
        SUBMITTED.append(job)
        after = job
    return submitted


SUBMITTED = []  # job ids, for cancel() on an interrupt


def count_tasks(spec):
    """Array tasks named by squeue's job id field: 12_3 is one, 12_[1-4,7%2] five, 12 one."""
    m = re.fullmatch(r"\d+_\[([^\]]*)\]", spec)
    if not m:
        return 1
    n = 0
    for part in m.group(1).split("%")[0].split(","):
        lo, _, hi = part.partition("-")
        n += int(hi) - int(lo) + 1 if hi else 1
    return n


def queued(jobs):
    """{job id: array tasks still pending, running or completing} from squeue."""
    ids = ",".join(j for j, _, _, _ in jobs)
    out = run_child(["squeue", "-h", "-r", "-j", ids, "-o", "%i %T"], stdout=subprocess.PIPE,
                    stderr=subprocess.PIPE, text=True, errors="replace")
    if out.returncode != 0:
        if "Invalid job id" in out.stderr:  # every job has ended and left the controller's memory
            return {}
        raise RuntimeError("squeue failed: %s" % out.stderr.strip())
    left = {}
    for line in out.stdout.split():
        if "_" in line or line.isdigit():
            job = line.split("_")[0]
            left[job] = left.get(job, 0) + count_tasks(line)
    return left


def wait(jobs, say):
    """Waits until no task of JOBS is queued, printing [done/N] (points of finished tasks) as it
    changes; squeue is asked every second at first, then less often while nothing changes."""
    total = sum(p for _, _, p, _ in jobs)
    last, poll, errors = None, 1.0, 0
    while True:
        try:
            left = queued(jobs)
            errors = 0
        except RuntimeError as e:  # a busy controller: ask again, up to a minute or so
            errors += 1
            if errors > 6:
                raise
            say("backend: %s; asking again" % e)
            time.sleep(10)
            continue
        done = 0
        for job, tasks, points, k in jobs:
            finished = tasks - min(left.get(job, 0), tasks)
            # the last task holds the remainder, and arrays run in task order, so it ends last
            done += min(points, finished * k)
        if done != last:
            say("[%d/%d]" % (done, total))
            last, poll = done, 1.0
        if not left:
            return
        time.sleep(poll)
        poll = min(10.0, poll * 1.5)


def core_seconds(elapsed, cpus):
    try:
        return float(elapsed) * int(cpus)
    except (TypeError, ValueError):
        return None


def seconds_between(start, end):
    try:
        a, b = (datetime.datetime.strptime(t, "%Y-%m-%dT%H:%M:%S") for t in (start, end))
    except (TypeError, ValueError):
        return None
    return (b - a).total_seconds()


def sacct_rows(jobs):
    """(task, state, exit code, output file) of every array task, from sacct, or where Slurm's
    accounting is off (a cluster without slurmdbd) from scontrol, which keeps ended jobs for
    MinJobAge seconds."""
    ids = ",".join(j for j, _, _, _ in jobs)
    out = run_child(["sacct", "-n", "-P", "-X", "-j", ids, "-o", "JobID,State,ExitCode,ElapsedRaw,AllocCPUS"],
                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                    errors="replace")
    rows = [line.split("|")[:3] + [None, core_seconds(*line.split("|")[3:5])]
            for line in out.stdout.splitlines() if line.count("|") >= 4]
    if out.returncode == 0 and rows:
        return rows, "sacct"
    rows = []
    for job in ids.split(","):
        shown = run_child(["scontrol", "-o", "show", "job", job], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, errors="replace")
        for line in shown.stdout.splitlines():
            f = dict(w.partition("=")[::2] for w in line.split() if "=" in w)
            if "ArrayTaskId" in f:
                rows.append(["%s_%s" % (f.get("ArrayJobId"), f["ArrayTaskId"]), f.get("JobState", "?"),
                             f.get("ExitCode", "?"), f.get("StdOut"),
                             core_seconds(seconds_between(f.get("StartTime"), f.get("EndTime")), f.get("NumCPUs"))])
    if rows:
        return rows, "scontrol (sacct: %s)" % (out.stderr.strip() or "no records")
    return None, "sacct or scontrol (%s)" % out.stderr.strip()


def failed_tasks(jobs, state):
    """Lines naming each task that did not complete, with its state and its output file, then
    one line with the tasks' core-seconds (elapsed times allocated CPUs, whole seconds)."""
    rows, source = sacct_rows(jobs)
    if rows is None:
        return ["backend: the tasks' states are not available from %s" % source]
    out = []
    cores = [r[4] for r in rows if r[4] is not None]
    for task, st, code, log, _ in rows:
        if st.split()[0] != "COMPLETED":
            job, _, index = task.partition("_")
            log = log or os.path.join(state, "slurm", "%s_%s.out" % (job, index))
            out.append("backend: task %s %s (exit %s; from %s), its output: %s" % (task, st, code, source, log))
    if cores:
        out.append("backend: %d tasks took %.0f core-seconds of Slurm's allocation (%s)"
                   % (len(cores), sum(cores), source.split(" ")[0]))
    return out


def point_status(phases):
    """{point: "exit E"} of the points a task ran and saw fail, and the CPU seconds of every
    point run (from the tasks' .rc files)."""
    failed, cpu = {}, 0.0
    for todo, points in phases:
        rcdir = todo + ".rc"
        if not os.path.isdir(rcdir):
            continue
        for name in os.listdir(rcdir):
            with open(os.path.join(rcdir, name)) as f:
                for line in f:
                    index, rc, seconds = (line.strip().split("\t") + ["", ""])[:3]
                    cpu += float(seconds or 0)
                    if rc and rc != "0" and 0 < int(index) <= len(points):
                        failed[points[int(index) - 1]] = "exit %s" % rc
    return failed, cpu


def cancel(say):
    if SUBMITTED:
        cmd = ["scancel"] + SUBMITTED
        say("backend: interrupted: %s" % shlex.join(cmd))
        run_child(cmd)


def run(phases, state, per_task, jobs, slurm_args, name, say=print):
    SUBMITTED.clear()
    try:
        submitted = submit(phases, state, per_task, jobs, slurm_args, name, say)
        if submitted:
            wait(submitted, say)
    except BaseException:
        cancel(say)
        raise
    for line in failed_tasks(submitted, state) if submitted else []:
        print(line, file=sys.stderr if " task " in line else sys.stdout, flush=True)
    return point_status(phases)
