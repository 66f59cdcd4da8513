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
        hold_to_the_end()  # a second one, also once the interpreter restores the default actions
        with contextlib.suppress(OSError):
            os.write(2, ("%s: stopped by %s\n" % (name, signal.Signals(signum).name)).encode(errors="surrogateescape"))
        raise Stopped(128 + signum)
    for sig in STOP_SIGNALS:
        number = getattr(signal, sig)
        if signal.getsignal(number) != signal.SIG_IGN or sig in even_ignored:
            signal.signal(number, leave)


def hold_to_the_end():
    """Blocks the stopping signals for the rest of the process: once the tool's work is done (or
    its stop has begun), a signal can no longer end it by the default action that the interpreter
    restores while it shuts down (killed, no message, the status not the tool's)."""
    signal.pthread_sigmask(signal.SIG_BLOCK, [getattr(signal, sig) for sig in STOP_SIGNALS])


def _no_signal_pending():
    """Nothing; a Python call, at whose start the interpreter runs the handler of a signal that
    came before the mask was set, before any child is started."""


def _child_start(mask, handled):
    """In the child, before exec: the handled stopping signals to their default action (a signal
    that lands now stops the child, not Python code run in it), then the parent's mask back."""
    def start():
        for number in handled:
            signal.signal(number, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
    return start


def run_child(args, input=None, check=False, stop="kill", **popen):
    """subprocess.run(ARGS, input=INPUT, check=CHECK, **POPEN) that leaves no child behind: the
    stopping signals are blocked while Popen starts the child (a signal landing there, before a
    Popen object exists, would leave the child running, writing a temporary after its clean-up),
    unblocked in the child before exec and in the parent once the Popen object exists; any
    exception from then on (Stopped, a failed read) kills the child (STOP "terminate": sends it
    SIGTERM, for a child that stops its own children on it) and waits for it. Returns the
    subprocess.CompletedProcess."""
    import subprocess  # here: the tools' start-up, a signal's handler, do not load it
    numbers = [getattr(signal, sig) for sig in STOP_SIGNALS]
    if input is not None:
        popen["stdin"] = subprocess.PIPE
    if popen.pop("capture_output", False):
        popen["stdout"] = popen["stderr"] = subprocess.PIPE
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, numbers)
    try:
        _no_signal_pending()
        handled = [n for n in numbers if signal.getsignal(n) not in (signal.SIG_IGN, signal.SIG_DFL)]
        proc = subprocess.Popen(args, preexec_fn=_child_start(mask, handled), **popen)
    except BaseException:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
        raise
    try:
        with proc:
            try:
                signal.pthread_sigmask(signal.SIG_SETMASK, mask)  # a signal pending since the start: here
                out, err = proc.communicate(input)
            except BaseException:
                if stop == "terminate":
                    proc.terminate()
                else:
                    proc.kill()
                proc.wait()
                raise
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
    done = subprocess.CompletedProcess(args, proc.returncode, out, err)
    if check:
        done.check_returncode()
    return done
