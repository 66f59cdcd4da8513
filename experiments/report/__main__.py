"""python3 experiments/report COMMAND ...  (or python3 -m report with experiments/ on the path)."""
import os
import sys

if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from stop_signals import exit_on_signals  # noqa: E402

exit_on_signals("experiments/report")  # before the imports below: a signal there is named too
if __package__ in (None, ""):
    from report.cli import main
else:
    from .cli import main

sys.exit(main(sys.argv[1:]))
