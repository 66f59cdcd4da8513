"""memory_exit - a Python tool whose memory the system refuses (a small `ulimit -v`) ends as the
executables end then: a message naming the tool, exit status 1, not a traceback, wherever it
fails, the loading of its modules at start-up included.

A tool's entry point loads this module first, by hand-written lines that give the same message
when even this one cannot be loaded (its own memory refused), then its other modules under
leave_if_out_of_memory(), then runs its main() under run()."""
import os

MESSAGE = b"%s: out of memory: the system refused the memory the tool asked for (ulimit -v?)\n"

# How the loader and the system word a refusal: an extension module the loader could not map
# (ImportError "...so: failed to map segment from shared object"), ENOMEM's strerror.
REFUSALS = ("failed to map segment", "annot allocate memory")


def refused(program):
    """Ends the program: `PROGRAM: out of memory ...`, exit 1 (written without allocating more)."""
    os.write(2, MESSAGE % program.encode(errors="replace"))
    os._exit(1)


def out_of_memory(error):
    """True when ERROR, or an error it was raised from, is the system refusing memory: a
    MemoryError, an OSError ENOMEM, an ImportError of a module the loader could not map."""
    seen = 0
    while error is not None and seen < 8:
        if isinstance(error, MemoryError):
            return True
        if isinstance(error, OSError) and error.errno == 12:  # ENOMEM, without loading errno
            return True
        if isinstance(error, ImportError) and any(r in str(error) for r in REFUSALS):
            return True
        error, seen = error.__cause__ or error.__context__, seen + 1
    return False


def leave_if_out_of_memory(program, error):
    """refused(PROGRAM) when ERROR is out_of_memory(); otherwise nothing (the caller raises it)."""
    if out_of_memory(error):
        refused(program)


def run(program, load_main, argv):
    """load_main()(argv), the tool's imports included; the system refusing memory anywhere in
    it: refused(). Its status returned, the stopping signals are held (stop_signals.hold_to_the_end):
    the work is done, and the interpreter's shutdown may not be cut short by one."""
    try:
        status = load_main()(argv)
        from stop_signals import hold_to_the_end
        hold_to_the_end()
        return status
    except MemoryError:
        refused(program)
    except Exception as e:  # not a SystemExit: a stop, or an exit after the tool's own message
        leave_if_out_of_memory(program, e)
        raise
