"""python3 experiments/backend COMMAND ...: run point lists on this machine, over ssh or on Slurm."""
import os
import sys

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    # experiments/ on the path however the tool is started (a file, -m report, -m experiments.report)
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, b"experiments/backend: out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    from stop_signals import exit_on_signals
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/backend", e)
    raise
try:  # OpenSSL's hashes, which hashlib would otherwise report missing in tracebacks of its own
    import _hashlib  # noqa: F401
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/backend", e)
    if not isinstance(e, ImportError):  # missing for another reason: hashlib's own hashes serve
        raise

# before the imports below: a signal there is named too; Ctrl-C even where a shell started the
# backend in the background (a sweep does), ignoring it
exit_on_signals("experiments/backend", even_ignored=("SIGINT", "SIGQUIT"))


def load_main():
    if __package__ in (None, ""):
        from backend.cli import main
    else:
        from .cli import main
    return main


sys.exit(memory_exit.run("experiments/backend", load_main, sys.argv[1:]))
