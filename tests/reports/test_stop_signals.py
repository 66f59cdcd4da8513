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

    def test_a_second_signal_is_ignored_while_the_first_cleans_up(self):
        done = self.run_program("SIGUSR1", "twice")
        self.assertEqual(done.returncode, 128 + signal.SIGUSR1)
        self.assertEqual(done.stderr, "tool: stopped by SIGUSR1\n")
        self.assertEqual(os.listdir(self.dir), [])

    def test_two_signals_at_once_stop_once_without_a_traceback(self):
        done = subprocess.run([sys.executable, "-c", TWO_AT_ONCE], stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 128 + signal.SIGUSR1)
        self.assertEqual(done.stderr, "tool: stopped by SIGUSR1\n")

    def test_a_signal_ignored_from_the_start_stays_ignored(self):
        done = self.run_program("SIGHUP", ignored=signal.SIGHUP)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(self.dir, "a.csv")) as f:
            self.assertEqual(f.read(), "halfnever")


if __name__ == "__main__":
    unittest.main()
