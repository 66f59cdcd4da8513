"""stop_signals - the stopping signals of the Python tools of experiments/, handled as the
executables handle them (support/signal_cleanup.cpp; docs/cli.md): a message naming the signal,
exit status 128 + its number, and no temporary left, since the signal ends the program as an
exception that every output's clean-up sees (output_files.atomic, staged, a temporary folder)."""
import contextlib
import os
import signal
import sys

# The signals that stop the executables (support/signal_cleanup.cpp) but SIGPIPE, which Python
# ignores from its start so that a write into a closed pipe is an error naming the output.
STOP_SIGNALS = ("SIGINT", "SIGTERM", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM")


class Stopped(SystemExit):
    """A stopping signal: exit status 128 + its number, after the temporaries are removed."""


def exit_on_signals(program=None, even_ignored=()):
    """Each of STOP_SIGNALS (Ctrl-C included) ends the program as the executables end:
    `PROGRAM: stopped by SIGNAME` on standard error and Stopped (a SystemExit, 128 + the
    signal's number), so that an unfinished file's temporary is removed on the way out; the
    signals are ignored from then on, so that a second one cannot cut the removal short. A
    signal the program was started ignoring (nohup) stays ignored, but those of EVEN_IGNORED
    (names: a shell starts a command in the background ignoring SIGINT and SIGQUIT)."""
    name = program or os.path.basename(sys.argv[0] or "python3")

    def ignore(signum, frame):
        """A signal after the first: nothing (SIG_IGN itself would make a signal already pending
        end in CPython's "ignored due to race condition" traceback)."""

    def leave(signum, frame):
        for sig in STOP_SIGNALS:
            signal.signal(getattr(signal, sig), ignore)
        with contextlib.suppress(OSError):
            os.write(2, ("%s: stopped by %s\n" % (name, signal.Signals(signum).name)).encode(errors="surrogateescape"))
        raise Stopped(128 + signum)
    for sig in STOP_SIGNALS:
        number = getattr(signal, sig)
        if signal.getsignal(number) != signal.SIG_IGN or sig in even_ignored:
            signal.signal(number, leave)
