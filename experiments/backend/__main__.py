"""python3 experiments/backend COMMAND ...: run point lists on this machine, over ssh or on Slurm."""
import os
import sys

if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from backend.cli import main
else:
    from .cli import main

sys.exit(main(sys.argv[1:]))
