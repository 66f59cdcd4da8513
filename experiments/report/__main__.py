"""python3 experiments/report COMMAND ...  (or python3 -m report with experiments/ on the path)."""
import os
import sys

if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from stop_signals import exit_on_signals  # noqa: E402

from memory_exit import run  # noqa: E402

exit_on_signals("experiments/report")  # before the imports below: a signal there is named too


def load_main():
    if __package__ in (None, ""):
        from report.cli import main
    else:
        from .cli import main
    return main


sys.exit(run("experiments/report", load_main, sys.argv[1:]))
