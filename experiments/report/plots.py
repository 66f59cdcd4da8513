"""Data files for the checked-in gnuplot scripts (experiments/plots/*.gp), and running them."""
import contextlib
import os

from output_files import OutputSet, staged, write_text
from stop_signals import run_child

from . import paper
from .results import profile_results

FIGURES = (5, 6, 7, 8, 10, 11, 12)  # the pictures reproduction() draws, plots/figN.png
PLOT_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "plots")


def write_dat(path, rows):
    write_text(path, "".join(" ".join(str(v) for v in row) + "\n" for row in rows))


def has_rows(path):
    """Whether the gnuplot data file PATH holds a row."""
    with open(path) as f:
        return any(line.strip() and not line.startswith("#") for line in f)


def series(table, columns, **match):
    """The named columns of the ok rows matching, as text."""
    return [[row[c] for c in columns] for row in table.where(**match)]


def gnuplot_kind(gp, kind, data, png, title, ncol=0):
    """Runs the study script GP for one plot KIND of the data file DATA into PNG; returns the
    PNG's file name (the studies' pages link it beside themselves)."""
    with staged(png) as tmp:
        drawn(os.path.basename(gp), png, ["gnuplot", "-e",
                                          f"kind='{kind}'; data='{data}'; out='{tmp}'; ttl='{title}'; ncol={ncol}", gp])
    return os.path.basename(png)


def gnuplot(script, variables):
    """Runs experiments/plots/SCRIPT with the variables (strings, or numbers) set; the pictures
    `out` and `out_*` name are written through temporaries beside them (output_files)."""
    with contextlib.ExitStack() as stack:
        run_gnuplot(script, {k: stack.enter_context(staged(v)) if k == "out" or k.startswith("out_") else v
                             for k, v in variables.items()}, variables.get("out", ""))


def run_gnuplot(script, variables, png=""):
    assigns = ["plotdir='%s'" % PLOT_DIR]
    for name, value in variables.items():
        assigns.append("%s=%s" % (name, value if isinstance(value, (int, float)) else "'%s'" % value))
    drawn(script, png or variables.get("out", ""), ["gnuplot", "-e", "; ".join(assigns), os.path.join(PLOT_DIR, script)])


def drawn(script, png, command):
    """Runs gnuplot's COMMAND; a failure is a one-line error naming the script and the picture
    (gnuplot's own message, above it on standard error, says why), not the command line."""
    done = run_child(command)
    if done.returncode != 0:
        raise ValueError("plots: gnuplot could not draw %s with %s (exit %d; its message is above)"
                         % (os.path.basename(png) or "the picture", script, done.returncode))


def flat_data(all_r, dat):
    """fig5-8 data files (f56-*.dat of the default reading, f56calibrated-*.dat and so on of the
    others; memory and preprocessing are the default reading's); returns the mappings present."""
    r = all_r[0]
    maps = r.f56.distinct("mapping")
    for x in all_r:
        for s in x.scenes:
            for m in maps:
                write_dat(os.path.join(dat, "f56%s-%s-%s.dat" % (tag(x, r), s, m)),
                          series(x.f56, ["n", "sim_time_s", "load_balance", "efficiency", "t1_s"], scene=s, mapping=m))
    for s in r.scenes:
        for m in maps:
            write_dat(os.path.join(dat, "f7-%s-%s.dat" % (s, m)),
                      series(r.f7, ["n", "total_bytes", "pixel_partitioned_bytes"], scene=s, mapping=m))
        write_dat(os.path.join(dat, "f8-%s.dat" % s), series(r.f8, ["n", "units_parallel", "units_serial"], scene=s))
        pp16 = r.f7.value("pixel_partitioned_bytes", scene=s, n=16)
        lo, hi = paper.MEMORY_RATIO_AT_16
        write_dat(os.path.join(dat, "f7-paper-%s.dat" % s),
                  [[16, pp16 / ((lo + hi) / 2) / 1024, pp16 / hi / 1024, pp16 / lo / 1024]] if pp16 else [])
    write_dat(os.path.join(dat, "f8-paper.dat"), sorted(paper.PREPROCESS_UNITS.items()))
    write_dat(os.path.join(dat, "paper-floor.dat"),
              [[1, 100 * paper.EFFICIENCY_FLOOR], [paper.EFFICIENCY_FLOOR_MAX_N, 100 * paper.EFFICIENCY_FLOOR]])
    return maps


def tag(x, default):
    """The data files' reading tag: '' for the default reading, else its name."""
    return "" if x is default else x.profile


def cluster_data(all_r, dat):
    """fig10-12 data files (f10calibrated-*.dat for the calibrated reading); returns the data modes present."""
    r = all_r[0]
    datas = r.f10.distinct("data")
    m, pm = paper.MEMORY_M, paper.CLUSTER_M
    for x in all_r:
        for s in x.cscenes:
            for d in datas:
                write_dat(os.path.join(dat, "f10%s-%s-%s.dat" % (tag(x, r), s, d)),
                          series(x.f10, ["m", "sim_time_s", "load_balance", "efficiency", "total_bytes",
                                         "pixel_partitioned_bytes", "t1_s", "processors"], scene=s, data=d))
    for s in r.cscenes:
        for d in datas:
            t = paper.cluster_time(s, d)
            write_dat(os.path.join(dat, "f10-paper-%s-%s.dat" % (s, d)), [[pm, t]] if t else [])
        rep = r.f10.value("total_bytes", scene=s, data="replicated", m=m)
        pp = r.f10.value("pixel_partitioned_bytes", scene=s, data="replicated", m=m)
        write_dat(os.path.join(dat, "f12-paper-%s.dat" % s),
                  [[m, rep * paper.SHARED_OVER_REPLICATED / 1024, pp / paper.SHARED_PIXEL_PARTITIONED / 1024]]
                  if rep and pp else [])
    floor = 100 * paper.CLUSTER_EFFICIENCY_FLOOR
    write_dat(os.path.join(dat, "paper-shared-floor.dat"), [[1, floor], [paper.SHARED_EFFICIENCY_MAX_M, floor]])
    write_dat(os.path.join(dat, "paper-replicated-floor.dat"), [[pm, floor]])
    return datas


def reproduction(res):
    """Draws RESULTS/plots/fig5.png ... fig12.png from the reading folders RESULTS/READING (clusters only when the sweep has them);
    returns the PNGs written."""
    all_r = profile_results(res)
    r = all_r[0]
    out = os.path.join(res, "plots")
    dat = os.path.join(out, "data")
    outs = OutputSet()  # no picture or data file over the CSVs it plots, also through a link
    for reading in all_r:
        for name in sorted(os.listdir(reading.dir)):
            if name.endswith((".csv", ".tsv", ".json")):
                outs.add_input("results", os.path.join(reading.dir, name))
    if os.path.isdir(out):
        for f in FIGURES:
            outs.add("results", os.path.join(out, "fig%d.png" % f))
    outs.add_folder("results", dat)
    outs.check()
    os.makedirs(dat, exist_ok=True)
    for name in os.listdir(dat):
        if name.endswith(".dat"):
            os.remove(os.path.join(dat, name))
    for f in (10, 11, 12):
        if os.path.exists(os.path.join(out, "fig%d.png" % f)):
            os.remove(os.path.join(out, "fig%d.png" % f))
    lo, hi = paper.MEMORY_RATIO_AT_16
    # Solid lines: the default reading; dashed: the next one (the reading before the fit).
    # The load-balancing points run each reading's own interleave (run_facts.csv's lb_map).
    common = {"dat": dat, "scenes": " ".join(r.scenes), "main": r.profile,
              "other": all_r[1].profile if len(all_r) > 1 else r.profile,
              "lb_main": r.facts.lb_map, "lb_other": all_r[1].facts.lb_map if len(all_r) > 1 else r.facts.lb_map}
    flat = dict(common, maps=" ".join(flat_data(all_r, dat)),
                xmax=1.3 * max((int(row["n"]) for row in r.f56.rows), default=1))
    if not any(has_rows(os.path.join(dat, name)) for name in os.listdir(dat) if "paper" not in name):
        for f in (5, 6, 7, 8):  # no old plot stays beside the results it does not show
            with contextlib.suppress(FileNotFoundError):
                os.remove(os.path.join(out, "fig%d.png" % f))
        raise ValueError("plots: no point in %s gave a result (see the failed points): no plots drawn" % res)
    titles = {
        "fig5": {}, "fig6": {"paper_floor": "paper: > %.0f %% for n <= %d (load-balancing)" % (
            100 * paper.EFFICIENCY_FLOOR, paper.EFFICIENCY_FLOOR_MAX_N)},
        "fig7": {"paper_ratio": "paper at n = 16: 1/%d to 1/%d of pixel-partitioned" % (lo, hi)},
        "fig8": {"paper_units": "paper, image 1: " + " / ".join(str(paper.PREPROCESS_UNITS[n])
                                                               for n in sorted(paper.PREPROCESS_UNITS))},
    }
    written = []
    for name, extra in titles.items():
        png = os.path.join(out, name + ".png")
        gnuplot(name + ".gp", dict(flat, out=png, **extra))
        written.append(png)
    if r.cscenes:
        clusters = dict(common, scenes=" ".join(r.cscenes), datas=" ".join(cluster_data(all_r, dat)),
                        xmax=1.3 * max((int(row["m"]) for row in r.f10.rows), default=1))
        floor = 100 * paper.CLUSTER_EFFICIENCY_FLOOR
        titles = {
            "fig10": {"paper_%s_%s" % (s, d): "paper, %s, m = %d: %g s" % (d, paper.CLUSTER_M, paper.cluster_time(s, d))
                      for s in r.cscenes for d in ("replicated", "shared") if paper.cluster_time(s, d)},
            "fig11": {"paper_shared_floor": "paper: shared > %.0f %% up to m = %d" % (floor, paper.SHARED_EFFICIENCY_MAX_M),
                      "paper_replicated_floor": "paper: replicated > %.0f %% at m = %d" % (floor, paper.CLUSTER_M)},
            "fig12": {"paper_half": "paper, m = %d: shared < 1/2 of replicated (our replicated / 2)" % paper.MEMORY_M,
                      "paper_twelfth": "paper, m = %d: shared < 1/%d of pixel-partitioned" % (
                          paper.MEMORY_M, paper.SHARED_PIXEL_PARTITIONED)},
        }
        for name, extra in titles.items():
            png = os.path.join(out, name + ".png")
            gnuplot(name + ".gp", dict(clusters, out=png, **extra))
            written.append(png)
    return written
