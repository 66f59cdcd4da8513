"""output_files - every file the Python tools of experiments/ write goes through the rules of
output_rules.py, whose names the tools import from here; run as a program (a study's or the
sweep's stream check, write_file), its main(). This file only gathers them: small, so that under
a small ulimit -v what fails is a module's loading, which is named (memory_exit.py), and not the
reading of this file."""
import os
import sys

# The program a message names: the script a check runs for (`--check-streams sweep ...`), else this file.
PROGRAM = (sys.argv[2] if sys.argv[1:2] in (["--check-streams"], ["--check-places"], ["--stdout"]) and
           len(sys.argv) > 2 else os.path.basename(sys.argv[0]))
if __name__ == "__main__":  # first: under a small ulimit -v loading a module is what fails, this one too
    try:
        import memory_exit
    except (MemoryError, OSError, ImportError):
        os.write(2, PROGRAM.encode(errors="replace") + b": out of memory: the system refused the memory the tool "
                 b"asked for (ulimit -v?)\n")
        os._exit(1)
try:
    from output_rules import *  # noqa: F401,F403
    from output_rules import _identity, _through_stream, exit_on_signals, main  # noqa: F401  (stream_checks.py)
except Exception as e:
    if __name__ == "__main__":
        memory_exit.leave_if_out_of_memory(PROGRAM, e)
    raise

if __name__ == "__main__":
    exit_on_signals()
    sys.exit(memory_exit.run(PROGRAM, lambda: main, sys.argv[1:]))
