"""Report generation for torusrt's experiments (Python 3 standard library only).

Modules: csvdata (CSV tables by column name), paper (the paper's numbers), verdict (the one
verdict rule), claims (one function per claim of the paper), reproduction (docs/reproduction.md),
plots (data files for the checked-in gnuplot scripts), sweep (the generic sweep's CSV and plot).
Run as `python3 -m report COMMAND ...` with experiments/ on PYTHONPATH; `--help` lists commands.
"""
