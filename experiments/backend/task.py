"""The body of one Slurm array task: lines (i-1)K+1 .. iK of a todo list, one after the other,
each line's exit status recorded in RCDIR/i (LINE<TAB>STATUS) for the submitting command."""
import datetime
import os
import socket
import subprocess
import sys


def run(todo, per_task, rcdir):
    index = int(os.environ.get("SLURM_ARRAY_TASK_ID", "0"))
    if index < 1:
        print("backend task: run as a Slurm array task (SLURM_ARRAY_TASK_ID unset)", file=sys.stderr)
        return 2
    with open(todo) as f:
        lines = f.read().splitlines()
    first = (index - 1) * per_task
    status = 0
    with open(os.path.join(rcdir, str(index)), "w") as record:
        for number, line in enumerate(lines[first:first + per_task], first + 1):
            stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
            print("[%s %s] point %d: %s" % (stamp, socket.gethostname(), number, line), flush=True)
            rc = subprocess.call(["bash", "-c", line])
            print("point %d: exit %d" % (number, rc), flush=True)
            record.write("%d\t%d\n" % (number, rc))
            record.flush()
            if rc:
                status = 1
    return status
