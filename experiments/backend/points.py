"""Point lists and the state of a run: which points are done (their result file exists), which
are to run, where each one's output goes, and what the last run left failed."""
import os
import shlex

from output_files import read_text, write_lines


class Point:
    """One point: DONE is the file whose existence means it is done, COMMAND its shell command."""

    def __init__(self, done, command, source):
        self.done = done
        self.command = command
        self.source = source  # "FILE:LINE", for messages
        self.log = None

    def is_done(self):
        try:
            return os.path.getsize(self.done) > 0
        except OSError:
            return False

    def wrapped(self):
        """The command line the backends run: the point's command, its output into its log; its
        file descriptor 3 is the backend's own output, for a point's progress line."""
        return "( %s ) 3>&1 >%s 2>&1" % (self.command, shlex.quote(self.log))


def read(path):
    """The points of a list file: 'DONE<TAB>COMMAND' per line; blank lines and '#' lines skipped."""
    points = []
    for number, line in enumerate(read_text(path, "the point list").split("\n"), 1):
        if not line.strip() or line.startswith("#"):
            continue
        done, tab, command = line.partition("\t")
        if not tab or not done or not command.strip():
            raise ValueError("%s:%d: expected DONE-FILE<TAB>COMMAND" % (path, number))
        if not os.path.isabs(done):
            raise ValueError("%s:%d: the done file must be an absolute path, not '%s'" % (path, number, done))
        points.append(Point(done, command, "%s:%d" % (path, number)))
    return points


def assign_logs(phases, logdir):
    """Gives every point a log file under LOGDIR named after its done file (relative to the
    folder all done files share), so a point keeps its log name from one run to the next."""
    every = [p for phase in phases for p in phase]
    if not every:
        return
    root = os.path.commonpath([os.path.dirname(p.done) for p in every])
    seen = set()
    for p in every:
        name = os.path.relpath(p.done, root).replace(os.sep, "__")
        if name in seen:
            raise ValueError("%s: the done file %s is listed twice" % (p.source, p.done))
        seen.add(name)
        p.log = os.path.join(logdir, name + ".log")


def write_todo(path, points):
    """The command lines a backend runs, one per line (GNU parallel's input, a Slurm task's list)."""
    write_lines(path, [p.wrapped() for p in points], "--state")


def log_tail(path, lines=3):
    try:
        with open(path, errors="replace") as f:
            text = f.read().strip().splitlines()
    except OSError:
        return "(no log)"
    return " | ".join(text[-lines:]) if text else "(empty log)"
