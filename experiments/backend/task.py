"""The body of one Slurm array task: lines (i-1)K+1 .. iK of a todo list, one after the other,
each line's exit status and CPU seconds recorded in RCDIR/i (LINE<TAB>STATUS<TAB>CPU) for the
submitting command."""
import datetime
import os
import resource
import socket
import sys

from output_files import write_text
from stop_signals import run_child


def run(todo, per_task, rcdir):
    index = int(os.environ.get("SLURM_ARRAY_TASK_ID", "0"))
    if index < 1:
        print("backend task: run as a Slurm array task (SLURM_ARRAY_TASK_ID unset)", file=sys.stderr)
        return 2
    with open(todo) as f:
        lines = f.read().splitlines()
    first = (index - 1) * per_task
    status = 0
    record, rows = os.path.join(rcdir, str(index)), []
    for number, line in enumerate(lines[first:first + per_task], first + 1):
        stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
        print("[%s %s] point %d: %s" % (stamp, socket.gethostname(), number, line), flush=True)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        rc = run_child(["bash", "-c", line]).returncode
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
        print("point %d: exit %d, %.2f s CPU" % (number, rc, cpu), flush=True)
        rows.append("%d\t%d\t%.3f\n" % (number, rc, cpu))
        write_text(record, "".join(rows))  # after each point, for a task that is cut short
        if rc:
            status = 1
    return status
