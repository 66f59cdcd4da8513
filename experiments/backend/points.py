"""Point lists and the state of a run: which points are done (their result file exists, made
by the same command from the same input files), which are to run, where each one's output goes,
and what the last run left failed."""
import hashlib
import json
import os
import re
import shlex

from output_files import named_files, read_text, write_lines

# The tools' own folder: its scripts (run_point.sh, output_files.py) are how a point runs, not
# what it computes from.
TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class Point:
    """One point: DONE is the file whose existence means it is done, COMMAND its shell command."""

    def __init__(self, done, command, source):
        self.done = done
        self.command = command
        self.source = source  # "FILE:LINE", for messages
        self.log = None
        self.identity = None  # what made it: set by identify()

    def is_done(self):
        try:
            return os.path.getsize(self.done) > 0
        except OSError:
            return False

    def record(self):
        """The file beside the result that holds the identity it was made with (DONE.id)."""
        return self.done + ".id"

    def wrapped(self):
        """The command line the backends run: the point's command, its output into its log; its
        file descriptor 3 is the backend's own output, for a point's progress line. Once the
        command succeeds, its identity is recorded beside its result."""
        line = "( %s ) 3>&1 >%s 2>&1" % (self.command, shlex.quote(self.log))
        if self.identity is None:
            return line
        tmp = shlex.quote(self.record() + ".tmp") + ".$$"
        return "%s && { printf '%%s\\n' %s >%s && mv -f %s %s; }" % (
            line, shlex.quote(json.dumps(self.identity, sort_keys=True)), tmp, tmp, shlex.quote(self.record()))


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


def file_hash(path, cache):
    """The SHA-256 of a file's content (once per file and run)."""
    if path not in cache:
        digest = hashlib.sha256()
        with open(path, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                digest.update(chunk)
        cache[path] = digest.hexdigest()
    return cache[path]


def _words(text):
    """The words of a command line, and the value of each NAME=VALUE and --option=VALUE word."""
    try:
        words = shlex.split(text)
    except ValueError:  # an unbalanced quote: the words as they stand
        words = text.split()
    return words + [w.partition("=")[2] for w in words if "=" in w]


def _inputs(point, words, cwd, made):
    """The files WORDS name (relative to CWD) that the point reads: the result of another point
    of the run (a key of MADE, there or not yet), or a regular file but the point's own outputs
    (its result and every file named after it: DONE.png, DONE.log, ...) and the tools' own
    scripts."""
    own = os.path.splitext(point.done)[0]
    found = set()
    for word in words:
        if not word or "\0" in word:
            continue
        path = os.path.normpath(os.path.join(cwd, word))
        if path == point.done or (path.startswith(own + ".") and path != point.record()):
            continue  # its own outputs; its identity record is the backend's, checked as an input
        if path in made or (not path.startswith(TOOLS + os.sep) and os.path.isfile(path)):
            found.add(path)
    return found


def identify(point, cache, made, cwd=None):
    """Sets POINT.identity, what the point is made from: its command line and, for every file it
    reads, the content's SHA-256 (the executable, the scene, a timing or machine file, a study's
    point script, and every file such a script names by an absolute path: the executable and the
    inputs a study's point function reads) or, for the result of a point of an earlier phase
    (a T(1) report), that point's own identity; MADE maps the results of the points identified
    so far to their identities' SHA-256, and gets this point's."""
    cwd = cwd or os.getcwd()
    words = _words(point.command)
    files = _inputs(point, words, cwd, made)
    try:  # the files a --config machine file names (timing=, map-file=) are read too
        files |= _inputs(point, [path for _, path in named_files(words)], cwd, made)
    except (OSError, ValueError, RecursionError):
        pass  # a machine file that cannot be read: the point's run says so
    for path in sorted(files):
        if path.endswith(".sh") and path not in made:
            try:
                with open(path, errors="replace") as f:
                    text = f.read(1 << 22)
            except OSError:
                continue
            files |= _inputs(point, re.findall(r"/[^\s'\"=;:()<>|&$`]+", text), cwd, made)
    point.identity = {"command": point.command,
                      "inputs": {path: "point " + made[path] if path in made else file_hash(path, cache)
                                 for path in sorted(files)}}
    made[point.done] = hashlib.sha256(json.dumps(point.identity, sort_keys=True).encode()).hexdigest()


def changed(point):
    """Why POINT's result was made by another command or from other inputs, else None: its
    identity record (DONE.id) missing, or another command line, or an input file changed, added
    or gone."""
    try:
        with open(point.record()) as f:
            made = json.loads(f.read())
        if not isinstance(made, dict) or not isinstance(made.get("inputs"), dict):
            raise ValueError("not an identity record")
    except FileNotFoundError:
        return "no record of what it was made from (%s)" % point.record()
    except (OSError, ValueError) as e:
        return "%s: %s" % (point.record(), e)
    if made.get("command") != point.command:
        return "its command line changed"
    now, then = point.identity["inputs"], made["inputs"]
    for path in sorted(set(now) | set(then)):
        if now.get(path) != then.get(path):
            return "%s %s since it was made" % (path, "changed" if path in now and path in then else
                                                 "is new" if path in now else "is no longer named")
    return None


def check_own_files_are_not_inputs(phases, state, runs=None):
    """ValueError naming the list line when a point reads a file the backend itself writes: a
    point's identity record (DONE.id) or log, the state folder's phase lists, joblogs, failed.tsv,
    `submitted`, a file of its logs/ or slurm/ folder, or the --runs file."""
    every = [p for phase in phases for p in phase]
    own = {}
    for p in every:
        own[p.record()] = "the identity record of the point of %s" % p.source
        own[p.log] = "the log of the point of %s" % p.source
    for number in range(1, len(phases) + 1):
        own[os.path.join(state, "phase%d.todo" % number)] = "the backend's command list of phase %d" % number
        own[os.path.join(state, "joblog.phase%d" % number)] = "the backend's joblog of phase %d" % number
    for name in ("failed.tsv", "submitted"):
        own[os.path.join(state, name)] = "the backend's %s" % name
    if runs:
        own[os.path.abspath(runs)] = "the --runs file"
    by_file = {}
    for path, what in own.items():
        try:
            st = os.stat(path)
            by_file[(st.st_dev, st.st_ino)] = what
        except OSError:
            pass
    if runs:  # nor is it a point's result
        for p in every:
            if os.path.realpath(runs) == os.path.realpath(p.done):
                raise ValueError("%s: the done file %s is the --runs file: refused, nothing removed or run"
                                 % (p.source, p.done))
    folders = [os.path.join(os.path.realpath(state), name) + os.sep for name in ("logs", "slurm")]
    for p in every:
        for path, what in p.identity["inputs"].items():
            if what.startswith("point "):
                continue
            hit = own.get(os.path.normpath(path))
            if hit is None:
                try:
                    st = os.stat(path)
                    hit = by_file.get((st.st_dev, st.st_ino))
                except OSError:
                    pass
            if hit is None and os.path.realpath(path).startswith(tuple(folders)):
                hit = "a file of the backend's %s folder" % os.path.dirname(os.path.realpath(path))
            if hit:
                raise ValueError("%s: reads %s, which is %s and the backend writes: refused, nothing removed or run"
                                 % (p.source, path, hit))


def check_results_are_not_inputs(phases, lists):
    """ValueError naming the list line when a point's result file is a point list or a file
    another point reads other than as an earlier phase's result."""
    listed = {os.path.realpath(f) for f in lists}
    every = [p for phase in phases for p in phase]
    read = {}  # plain input files of the points (not earlier results) -> the first point reading it
    for p in every:
        for path, what in p.identity["inputs"].items():
            if not what.startswith("point "):
                read.setdefault(path, p)
    for p in every:
        why = ("is the point list %s" % p.done if os.path.realpath(p.done) in listed else
               "is read by the point of %s" % read[p.done].source if p.done in read else None)
        if why:
            raise ValueError("%s: the done file %s %s: refused, nothing removed or run" % (p.source, p.done, why))
