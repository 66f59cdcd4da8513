"""The stopping signals of the Python tools (experiments/stop_signals.py): each ends the program
as the executables end, `PROGRAM: stopped by SIGNAME` and 128 + N, with no traceback and no
temporary left; a second signal does not cut the removal short; an ignored one stays ignored."""
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXP = os.path.join(REPO, "experiments")

# A program that writes half a file and signals itself (twice with "twice") inside the write.
PROGRAM = """import os, signal, sys
sys.path.insert(0, %r)
import output_files as of
of.exit_on_signals("tool")
sig = getattr(signal, sys.argv[1])
with of.atomic(sys.argv[2]) as f:
    f.write("half")
    f.flush()
    os.kill(os.getpid(), sig)
    if sys.argv[3:] == ["twice"]:
        os.kill(os.getpid(), sig)
    f.write("never")
""" % EXP


# Two signals pending at once; then, as a child's terminate() on the way out does, a call that
# has the interpreter look at its signals again.
TWO_AT_ONCE = """import os, signal, sys
sys.path.insert(0, %r)
from stop_signals import exit_on_signals
exit_on_signals("tool")
both = {signal.SIGUSR1, signal.SIGUSR2}
signal.pthread_sigmask(signal.SIG_BLOCK, both)
os.kill(os.getpid(), signal.SIGUSR1)
os.kill(os.getpid(), signal.SIGUSR2)
try:
    signal.pthread_sigmask(signal.SIG_UNBLOCK, both)
finally:
    os.kill(os.getpid(), 0)
""" % EXP


# A signal landing inside Popen, after the child is made and before the Popen object exists: the
# child's start (Popen._execute_child) sends it to the program; the child's process id is kept in
# a file. The child is a stand-in gnuplot that sleeps, started as `report plots` starts gnuplot.
IN_POPEN = """import os, signal, subprocess, sys
sys.path.insert(0, %r)
from stop_signals import exit_on_signals
exit_on_signals("tool")
start = subprocess.Popen._execute_child


def landing(self, *args, **kwargs):
    start(self, *args, **kwargs)
    with open(sys.argv[1], "w") as f:
        f.write(str(self.pid))
    os.kill(os.getpid(), signal.SIGTERM)


subprocess.Popen._execute_child = landing
from report import plots
plots.gnuplot_kind("x.gp", "k", "d.dat", os.path.join(sys.argv[2], "p.png"), "t")
""" % EXP


# A signal landing the moment the temporary is made, before atomic() or staged() has its name:
# tempfile.mkstemp sends it on its way out.
IN_MAKING = """import os, signal, sys, tempfile
sys.path.insert(0, %r)
import output_files as of
of.exit_on_signals("tool")
make = tempfile.mkstemp


def landing(*args, **kwargs):
    made = make(*args, **kwargs)
    os.kill(os.getpid(), signal.SIGTERM)
    return made


tempfile.mkstemp = landing
if sys.argv[1] == "atomic":
    with of.atomic(sys.argv[2]) as f:
        f.write("never")
else:
    with of.staged(sys.argv[2]) as tmp:
        open(tmp, "w").write("never")
""" % EXP


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


# A tool whose interpreter, shutting down, restores SIGTERM's default action and then gets one
# (CPython resets the handlers it installed): the tool's status stands, nothing kills it. With
# "stop", the tool is stopped by SIGUSR1 first.
AT_SHUTDOWN = r"""
import atexit, os, signal, sys
sys.path.insert(0, %r)
import memory_exit, stop_signals
stop_signals.exit_on_signals("tool")
def late():
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    os.kill(os.getpid(), signal.SIGTERM)
atexit.register(late)
def main(argv):
    if argv == ["stop"]:
        os.kill(os.getpid(), signal.SIGUSR1)
    return 0
sys.exit(memory_exit.run("tool", lambda: main, sys.argv[1:]))
""" % EXP


class StopSignals(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.dir)

    def run_program(self, name, *more, ignored=None):
        def start():
            if ignored:
                signal.signal(ignored, signal.SIG_IGN)
        return subprocess.run([sys.executable, "-c", PROGRAM, name, os.path.join(self.dir, "a.csv")] + list(more),
                              stderr=subprocess.PIPE, text=True, preexec_fn=start)

    def test_each_signal_stops_with_a_message_and_no_temporary(self):
        for name in ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM"):
            done = self.run_program(name)
            self.assertEqual(done.returncode, 128 + getattr(signal, name), name)
            self.assertEqual(done.stderr, "tool: stopped by %s\n" % name)
            self.assertEqual(os.listdir(self.dir), [], name)

    def test_a_signal_as_the_temporary_is_made_leaves_no_temporary(self):
        for how in ("atomic", "staged"):
            done = subprocess.run([sys.executable, "-c", IN_MAKING, how, os.path.join(self.dir, "a.csv")],
                                  stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 128 + signal.SIGTERM, how + ": " + done.stderr)
            self.assertEqual(done.stderr, "tool: stopped by SIGTERM\n", how)
            self.assertEqual(os.listdir(self.dir), [], how)

    def test_a_second_signal_is_ignored_while_the_first_cleans_up(self):
        done = self.run_program("SIGUSR1", "twice")
        self.assertEqual(done.returncode, 128 + signal.SIGUSR1)
        self.assertEqual(done.stderr, "tool: stopped by SIGUSR1\n")
        self.assertEqual(os.listdir(self.dir), [])

    def test_two_signals_at_once_stop_once_without_a_traceback(self):
        done = subprocess.run([sys.executable, "-c", TWO_AT_ONCE], stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 128 + signal.SIGUSR1)
        self.assertEqual(done.stderr, "tool: stopped by SIGUSR1\n")

    def test_a_signal_at_the_interpreters_shutdown_does_not_kill_the_tool(self):
        for args, status, said in (([], 0, ""), (["stop"], 128 + signal.SIGUSR1, "tool: stopped by SIGUSR1\n")):
            with self.subTest(args=args):
                done = subprocess.run([sys.executable, "-c", AT_SHUTDOWN] + args, stderr=subprocess.PIPE, text=True)
                self.assertEqual((done.returncode, done.stderr), (status, said))

    def test_a_signal_ignored_from_the_start_stays_ignored(self):
        done = self.run_program("SIGHUP", ignored=signal.SIGHUP)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(self.dir, "a.csv")) as f:
            self.assertEqual(f.read(), "halfnever")

    def test_a_signal_inside_a_childs_start_stops_the_child_too(self):
        bindir, out = os.path.join(self.dir, "bin"), os.path.join(self.dir, "out")
        os.mkdir(bindir)
        os.mkdir(out)
        with open(os.path.join(bindir, "gnuplot"), "w") as f:
            f.write("#!/bin/sh\nexec sleep 60\n")
        os.chmod(os.path.join(bindir, "gnuplot"), 0o755)
        pidfile = os.path.join(self.dir, "child.pid")
        env = dict(os.environ, PATH=bindir + os.pathsep + os.environ["PATH"])
        done = subprocess.run([sys.executable, "-c", IN_POPEN, pidfile, out], stderr=subprocess.PIPE, text=True,
                              env=env)
        with open(pidfile) as f:
            pid = int(f.read())
        left = alive(pid)
        if left:
            os.kill(pid, signal.SIGKILL)
        self.assertEqual(done.returncode, 128 + signal.SIGTERM, done.stderr)
        self.assertEqual(done.stderr, "tool: stopped by SIGTERM\n")
        self.assertFalse(left, "the child started when the signal landed is still running")
        self.assertEqual(os.listdir(out), [])

    def test_run_child_keeps_what_subprocess_run_gives(self):
        sys.path.insert(0, EXP)
        from stop_signals import run_child
        done = run_child(["sh", "-c", "cat; echo err >&2; exit 3"], input="in", capture_output=True, text=True)
        self.assertEqual((done.returncode, done.stdout, done.stderr), (3, "in", "err\n"))
        with self.assertRaises(subprocess.CalledProcessError):
            run_child(["false"], check=True)
        self.assertEqual(signal.pthread_sigmask(signal.SIG_BLOCK, []), set())

    def test_every_child_of_the_python_tools_is_started_by_run_child(self):
        """The stopping signals are blocked while a child starts only through run_child."""
        starts = ("subprocess.run(", "subprocess.Popen(", "subprocess.call(", "subprocess.check_", "os.system(",
                  "os.popen(", "os.spawn", "os.posix_spawn", "os.fork(", "os.exec")
        found = []
        for root, _, names in os.walk(EXP):
            for name in names:
                path = os.path.join(root, name)
                if name == "stop_signals.py" or "results" in path.split(os.sep):
                    continue
                with open(path, "rb") as f:
                    head = f.read()
                if not (name.endswith(".py") or head.startswith(b"#!/usr/bin/env python3")):
                    continue
                text = head.decode(errors="replace")
                found += ["%s: %s" % (os.path.relpath(path, REPO), s) for s in starts if s in text]
        self.assertEqual(found, [])


if __name__ == "__main__":
    unittest.main()
