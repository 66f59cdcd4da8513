"""output_files - every file the Python tools of experiments/ write goes through the rules of
output_rules.py, whose names the tools import from here; run as a program (a study's or the
sweep's stream check, write_file), its main(). This file only gathers them: small, so that under
a small ulimit -v what fails is a module's loading, which is named (memory_exit.py), and not the
reading of this file."""
import os
import sys

if __name__ == "__main__":  # first: under a small ulimit -v loading a module is what fails, this one too
    try:
        import memory_exit
    except (MemoryError, OSError, ImportError):
        os.write(2, b"output_files.py: out of memory: the system refused the memory the tool asked for "
                 b"(ulimit -v?)\n")
        os._exit(1)
try:
    from output_rules import *  # noqa: F401,F403
    from output_rules import _identity, _through_stream, exit_on_signals, main  # noqa: F401  (stream_checks.py)
except Exception as e:
    if __name__ == "__main__":
        memory_exit.leave_if_out_of_memory(os.path.basename(sys.argv[0]), e)
    raise

if __name__ == "__main__":
    exit_on_signals()
    sys.exit(memory_exit.run(os.path.basename(sys.argv[0]), lambda: main, sys.argv[1:]))
