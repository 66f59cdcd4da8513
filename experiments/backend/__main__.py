"""python3 experiments/backend COMMAND ...: run point lists on this machine, over ssh or on Slurm."""
import os
import sys

if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from stop_signals import exit_on_signals  # noqa: E402

# before the imports below: a signal there is named too; Ctrl-C even where a shell started the
# backend in the background (a sweep does), ignoring it
exit_on_signals("experiments/backend", even_ignored=("SIGINT", "SIGQUIT"))
from memory_exit import run  # noqa: E402


def load_main():
    if __package__ in (None, ""):
        from backend.cli import main
    else:
        from .cli import main
    return main


sys.exit(run("experiments/backend", load_main, sys.argv[1:]))
