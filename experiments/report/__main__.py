"""python3 experiments/report COMMAND ...  (or python3 -m report with experiments/ on the path)."""
import os
import sys

# The command the user ran: the sweep's steps (sweep-plan, sweep-collect) are the sweep's.
PROGRAM = "sweep" if sys.argv[1:2] and sys.argv[1].startswith("sweep-") else "experiments/report"

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    # experiments/ on the path however the tool is started (a file, -m report, -m experiments.report)
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, PROGRAM.encode() + b": out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    from stop_signals import exit_on_signals
except Exception as e:
    memory_exit.leave_if_out_of_memory(PROGRAM, e)
    raise
try:  # OpenSSL's hashes, which hashlib would otherwise report missing in tracebacks of its own
    import _hashlib  # noqa: F401
except Exception as e:
    memory_exit.leave_if_out_of_memory(PROGRAM, e)
    if not isinstance(e, ImportError):  # missing for another reason: hashlib's own hashes serve
        raise

exit_on_signals(PROGRAM)  # before the imports below: a signal there is named too


def load_main():
    if __package__ in (None, ""):
        from report.cli import main
    else:
        from .cli import main
    return main


sys.exit(memory_exit.run(PROGRAM, load_main, sys.argv[1:]))
