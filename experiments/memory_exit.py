"""memory_exit - a Python tool whose memory the system refuses (a small `ulimit -v`) ends as the
executables end then: a message naming the tool, exit status 1, not a MemoryError traceback."""
import os


def refused(program):
    """Ends the program: `PROGRAM: out of memory ...`, exit 1 (written without allocating more)."""
    os.write(2, b"%s: out of memory: the system refused the memory the tool asked for (ulimit -v?)\n"
             % program.encode(errors="replace"))
    os._exit(1)


def run(program, load_main, argv):
    """load_main()(argv), the tool's imports included; MemoryError anywhere in it: refused()."""
    try:
        return load_main()(argv)
    except MemoryError:
        refused(program)
