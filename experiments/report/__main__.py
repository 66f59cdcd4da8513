"""python3 experiments/report COMMAND ...  (or python3 -m report with experiments/ on the path)."""
import os
import sys

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    # experiments/ on the path however the tool is started (a file, -m report, -m experiments.report)
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, b"experiments/report: out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    from stop_signals import exit_on_signals
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/report", e)
    raise

exit_on_signals("experiments/report")  # before the imports below: a signal there is named too


def load_main():
    if __package__ in (None, ""):
        from report.cli import main
    else:
        from .cli import main
    return main


sys.exit(memory_exit.run("experiments/report", load_main, sys.argv[1:]))
