#!/usr/bin/env python3
"""report.py - docs/scaling.md from the scaling study's runs (Python 3 standard library).

Usage: report.py RESULTS_DIR OUT_MD PLOT_DIR STUDY_DIR JOBS WALL_S
RESULTS_DIR holds runs.tsv (one row per scene, machine and processor count) and
busy-paper-image2-512.tsv (machine, node, busy s). Per scene: image time, efficiency and data
memory of every machine at every n; the fastest machine within the memory budget (2x the flat
cyclic mapping's total data memory at the same n); the efficiency at the largest n split into
its measured factors; plots of time against n, time against memory, and busy time per node
before and after replication.
"""
import os
import sys

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, b"experiments/scaling/report.py: out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    import csv
    from output_files import atomic, exit_on_signals
    from report import before_fit
    from report.plots import gnuplot_kind
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/scaling/report.py", e)
    raise

BUDGET = 2.0  # memory budget: this many times the flat cyclic mapping's total data memory
FLAT = ["flat-cyclic", "flat-cost", "flat-cost-r0.5", "flat-cost-r1.0", "flat-scatter", "flat-scatter-r0.5",
        "flat-cyclic-rf", "flat-scatter-rf", "flat-scatter-r0.5-rf"]
RAYS_FIRST = "-rf"  # suffix of a machine run with --queue-order rays-first


def load(path):
    runs = {}
    with open(path, newline="") as f:
        for r in csv.DictReader(f, delimiter="\t"):
            runs[(r["scene"], r["machine"], int(r["n"]))] = r
    return runs


def checked(runs):
    """(every image equal to the renderer's, every run conserved its packets)."""
    return (all(r["image_identical"] == "1" for r in runs.values()),
            all(r["conserved"] == "true" for r in runs.values()))


def machines(runs):
    """The machines in a fixed order: the flat ones, then clusters by m, data and mapping."""
    names = {k[1] for k in runs}
    clusters = sorted(names - set(FLAT), key=lambda s: (int(s.split("-")[0][1:]), s))
    return [m for m in FLAT if m in names] + clusters


def t(r):
    return float(r["sim_time_s"])


def memory(r):
    return float(r["memory_total_bytes"])


def factors(r):
    """Efficiency T(1) / (n T) as the product of three measured factors: work (T(1) over all the
    processors' busy time: what forwarding and waiting add), balance (mean busy over the busiest)
    and tail (the busiest processor's busy time over the image time: it too waits for rays)."""
    n, t1 = int(r["n"]), float(r["t1_s"])
    mean, top = float(r["busy_mean_s"]), float(r["busy_max_s"])
    return {"work": t1 / (n * mean), "balance": mean / top, "tail": top / t(r), "links": float(r["link_util_max"])}


def best_within_budget(runs, scene, n):
    """The fastest machine at n whose total data memory is within BUDGET x flat cyclic's."""
    cap = BUDGET * memory(runs[(scene, "flat-cyclic", n)])
    fits = [r for (s, _, k), r in runs.items() if s == scene and k == n and memory(r) <= cap]
    return min(fits, key=lambda r: (t(r), r["machine"]))


def limit_text(f):
    """The factor that loses most, in words."""
    names = {"work": "work added by forwarding and waiting", "balance": "load balance",
             "tail": "the tail (the busiest processor idle, waiting for dependent rays)"}
    worst = min(("work", "balance", "tail"), key=lambda k: f[k])
    text = names[worst]
    if f["links"] > 0.8:
        text += f"; the busiest link is {100 * f['links']:.0f} % busy"
    return text


def findings(runs, scenes, ns, ok):
    top = ns[-1]
    L = ["## Findings", ""]
    for sc in scenes:
        picks = [best_within_budget(runs, sc, n) for n in ns]
        cyc = {n: runs[(sc, "flat-cyclic", n)] for n in ns}
        best = ", ".join(f"n = {int(r['n'])}: {r['machine']} {t(r):.3g} s "
                         f"({t(cyc[int(r['n'])]) / t(r):.2f}x flat cyclic, {100 * float(r['efficiency']):.0f} %)"
                         for r in picks)
        f = factors(picks[-1])
        L.append(f"- **{sc}**, fastest within {BUDGET:g}x cyclic's memory: {best}. At n = {top} its efficiency "
                 f"{100 * float(picks[-1]['efficiency']):.1f} % = work {100 * f['work']:.0f} % x balance "
                 f"{100 * f['balance']:.0f} % x tail {100 * f['tail']:.0f} %; lost most to {limit_text(f)} "
                 f"(busiest link {100 * f['links']:.1f} % busy).")
    gains = []
    for sc in scenes:
        for n in ns:
            base, rep = runs.get((sc, "flat-cost", n)), runs.get((sc, "flat-cost-r1.0", n))
            if base and rep:
                gains.append((t(base) / t(rep), sc, n, int(rep["copy_bytes"]), memory(base)))
    g, sc, n, extra, base_mem = max(gains)
    L.append(f"- Replicated hot cells (hash rule, budget 1.0) shorten the flat cost mapping's image by up to "
             f"{g:.2f}x ({sc}, n = {n}) for {extra} bytes of copies ({100 * extra / base_mem:.2f} % more data); "
             f"they gain more than 5 % at {sum(1 for x in gains if x[0] > 1.05)} of {len(gains)} points.")
    L += scatter_findings(runs, scenes, ns)
    L += order_findings(runs, scenes, ns)
    flat_wins = sum(1 for sc in scenes for n in ns
                    if best_within_budget(runs, sc, n)["machine"].startswith("flat"))
    L.append(f"- The fastest machine within the budget is a flat torus at {flat_wins} of {len(scenes) * len(ns)} "
             "(scene, n) points and a cluster machine at the rest.")
    L.append(f"- {len(runs)} runs; every image equal to `torusrt-render`'s byte for byte: **{'yes' if ok[0] else 'NO'}**; "
             f"packets conserved in every run: **{'yes' if ok[1] else 'NO'}**.")
    return L + [""]


def scatter_findings(runs, scenes, ns):
    """The balanced scatter against the cost mapping, and its cut hot cells against the best static
    mapping (flat cyclic) on paper-image2 at 512 IPs."""
    pairs = [(t(runs[(sc, "flat-cost", n)]) / t(runs[(sc, "flat-scatter", n)]), sc, n)
             for sc in scenes for n in ns if (sc, "flat-cost", n) in runs and (sc, "flat-scatter", n) in runs]
    if not pairs:
        return []
    best = max(pairs)
    L = [f"- The balanced scatter (`--map scatter`) is faster than the cost mapping at "
         f"{sum(1 for p in pairs if p[0] > 1.0)} of {len(pairs)} (scene, n) points, by up to {best[0]:.2f}x "
         f"({best[1]}, n = {best[2]}); per scene at n = {', '.join(str(n) for n in ns)}, cost / scatter image time: "
         + "; ".join(f"{sc} " + ", ".join(f"{p[0]:.2f}" for p in pairs if p[1] == sc) for sc in scenes) + "."]
    key = ("paper-image2", "flat-scatter-r0.5", 512)
    if key in runs and ("paper-image2", "flat-cyclic", 512) in runs:
        r, cyc = runs[key], runs[("paper-image2", "flat-cyclic", 512)]
        rf = runs.get(("paper-image2", "flat-scatter-r0.5-rf", 512))
        also = (f"; under `--queue-order rays-first` {t(rf):.3g} s, {t(cyc) / t(rf):.2f}x, "
                f"{100 * float(rf['efficiency']):.1f} %" if rf else "")
        L.append(f"- paper-image2 at 512 IPs with its hottest cells cut (`--map scatter --replicate 0.5 "
                 f"--replica-choice hash`): {t(r):.3g} s, {t(cyc) / t(r):.2f}x flat cyclic, efficiency "
                 f"{100 * float(r['efficiency']):.1f} %, for {r['copy_bytes']} bytes of copies{also}.")
    return L


def order_findings(runs, scenes, ns):
    """Each flat machine under --queue-order rays-first against the same machine under the default
    order, and the factors of paper-image1's scatter at 512 IPs under both."""
    pairs = [(t(runs[(sc, mc[:-len(RAYS_FIRST)], n)]) / t(r), sc, mc[:-len(RAYS_FIRST)], n)
             for (sc, mc, n), r in sorted(runs.items())
             if mc.endswith(RAYS_FIRST) and (sc, mc[:-len(RAYS_FIRST)], n) in runs]
    if not pairs:
        return []
    best, worst = max(pairs), min(pairs)
    L = [f"- The rays-first order (`--queue-order rays-first`: the newest ray packet, then the host's next "
         f"primary, then the newest shadow packet) shortens the image at {sum(1 for p in pairs if p[0] > 1.0)} of "
         f"{len(pairs)} (scene, machine, n) points, by up to {best[0]:.2f}x ({best[1]}, {best[2]}, n = {best[3]}); "
         f"its worst point is {worst[0]:.2f}x ({worst[1]}, {worst[2]}, n = {worst[3]})."]
    key = ("paper-image1", "flat-scatter", 512)
    if key in runs and ("paper-image1", "flat-scatter-rf", 512) in runs:
        a, b = runs[key], runs[("paper-image1", "flat-scatter-rf", 512)]
        cyc = runs[("paper-image1", "flat-cyclic", 512)]
        fa, fb = factors(a), factors(b)
        L.append(f"- paper-image1 at 512 IPs under the scatter: {t(a):.3g} s (efficiency "
                 f"{100 * float(a['efficiency']):.1f} %, tail {100 * fa['tail']:.0f} %) under primaries-first, "
                 f"{t(b):.3g} s ({t(cyc) / t(b):.2f}x flat cyclic, efficiency {100 * float(b['efficiency']):.1f} %, "
                 f"tail {100 * fb['tail']:.0f} %) under rays-first; balance {100 * fb['balance']:.0f} % and work "
                 f"{100 * fb['work']:.0f} %, so what is left is the tail: the nodes wait for rays that depend on "
                 "earlier ones ([cell-mappings.md](cell-mappings.md#scatter)).")
    return L


def planar_findings(res):
    """paper-image1 at 512 IPs with the calibrated reading's image 1 (planar-512.tsv), under the
    default timing: the same machines on a scene with more work per sphere."""
    path = os.path.join(res, "planar-512.tsv")
    if not os.path.exists(path):
        return []
    runs = load(path)
    get = {mc: runs.get(("paper-image1-planar", mc, 512)) for mc in ("flat-cyclic", "flat-cost", "flat-scatter-rf")}
    if not all(get.values()):
        return []
    cyc, cost, best = get["flat-cyclic"], get["flat-cost"], get["flat-scatter-rf"]
    ok = all(r["image_identical"] == "1" and r["conserved"] == "true" for r in get.values())
    return [f"- paper-image1 at 512 IPs with the calibrated reading's image 1 (`scenes/paper-image1-planar.nff`: "
            f"the flakes at full size, two lights), under the default timing: cyclic {t(cyc):.3g} s "
            f"({100 * float(cyc['efficiency']):.1f} %), cost {t(cost):.3g} s ({100 * float(cost['efficiency']):.1f} %), "
            f"scatter under rays-first {t(best):.3g} s ({t(cyc) / t(best):.2f}x flat cyclic, efficiency "
            f"{100 * float(best['efficiency']):.1f} %); images equal to the renderer's and packets conserved: "
            f"**{'yes' if ok else 'NO'}**."]


def scene_table(runs, sc, ns, names):
    L = ["| n | machine | nodes x m | image time s | efficiency | memory total | max per processor | work | balance "
         "| tail | busiest link | copies (bytes) |", "|---" * 12 + "|"]
    for n in ns:
        cap = BUDGET * memory(runs[(sc, "flat-cyclic", n)])
        pick = best_within_budget(runs, sc, n)["machine"]
        for mc in names:
            r = runs.get((sc, mc, n))
            if not r:
                continue
            f = factors(r)
            mark = " **(fastest in budget)**" if mc == pick else ("" if memory(r) <= cap else " (over budget)")
            copies = f"{r['copies']} ({r['copy_bytes']})" if int(r["copies"]) else "-"
            L.append(f"| {n} | {mc}{mark} | {r['nodes']} x {r['m']} | {t(r):.4g} | {100 * float(r['efficiency']):.1f} % "
                     f"| {memory(r):.0f} | {r['memory_max_per_ip_bytes']} | {100 * f['work']:.0f} % "
                     f"| {100 * f['balance']:.0f} % | {100 * f['tail']:.0f} % | {100 * f['links']:.1f} % | {copies} |")
    return L


def scene_plots(runs, sc, ns, names, plot_dir, gp):
    data = os.path.join(plot_dir, f"time-{sc}.dat")
    with atomic(data) as f:
        f.write("n " + " ".join(names) + "\n")
        for n in ns:
            f.write(f"{n} " + " ".join(f"{t(runs[(sc, m, n)]):.6g}" if (sc, m, n) in runs else "-" for m in names)
                    + "\n")
    time_png = gnuplot_kind(gp, "time", data, os.path.join(plot_dir, f"time-{sc}.png"), f"{sc}: image time",
                       len(names) + 1)
    data = os.path.join(plot_dir, f"memory-{sc}.dat")
    with atomic(data) as f:
        for (s, m, n), r in sorted(runs.items()):
            if s == sc:
                f.write(f"{m} {n} {memory(r):.0f} {t(r):.6g}\n")
    mem_png = gnuplot_kind(gp, "memory", data, os.path.join(plot_dir, f"memory-{sc}.png"),
                      f"{sc}: image time against total data memory (each machine, each n)")
    return time_png, mem_png


def busy_plot(res, plot_dir, gp):
    """Busy time per node, busiest first, of each machine in busy-paper-image2-512.tsv."""
    series = {}
    with open(os.path.join(res, "busy-paper-image2-512.tsv")) as f:
        for line in f:
            mc, _, busy = line.split("\t")
            series.setdefault(mc, []).append(float(busy))
    names = [m for m in FLAT if m in series]
    cols = [sorted(series[m], reverse=True) for m in names]
    data = os.path.join(plot_dir, "busy-paper-image2-512.dat")
    with atomic(data) as f:
        f.write("rank " + " ".join(names) + "\n")
        for i in range(max(len(c) for c in cols)):
            f.write(f"{i} " + " ".join(f"{c[i]:.6g}" for c in cols) + "\n")
    png = gnuplot_kind(gp, "busy", data, os.path.join(plot_dir, "busy-paper-image2-512.png"),
                  "paper-image2, 512 IPs: busy time per node, cost and scatter, with and without copies", len(names) + 1)
    return png, {m: (max(series[m]), sum(series[m]) / len(series[m])) for m in names}


def share_plot(res, plot_dir, gp):
    """The share of busy IPs over time of each order in busy-share-paper-image1-512.tsv; returns the
    PNG and, per order, the bins' (start s, share)."""
    series = {}
    with open(os.path.join(res, "busy-share-paper-image1-512.tsv")) as f:
        for line in f:
            order, start, share = line.split("\t")
            series.setdefault(order, []).append((float(start), float(share)))
    names = list(series)
    data = os.path.join(plot_dir, "busy-share-paper-image1-512.dat")
    # Each order has its own bins (its own image time): the series one after the other, the other
    # columns '-', each closed by a 0 at its image time.
    with atomic(data) as f:
        f.write("t " + " ".join(names) + "\n")
        for j, name in enumerate(names):
            for start, share in series[name]:
                f.write(f"{start:.6g} " + " ".join(f"{share:.4f}" if k == j else "-" for k in range(len(names))) + "\n")
            f.write(f"{series[name][-1][0] + series[name][-1][0] - series[name][-2][0]:.6g} "
                    + " ".join("0" if k == j else "-" for k in range(len(names))) + "\n")
    png = gnuplot_kind(gp, "share", data, os.path.join(plot_dir, "busy-share-paper-image1-512.png"),
                       "paper-image1, 512 IPs, scatter: busy processors over the frame, both queue orders",
                       len(names) + 1)
    return png, series


def main(argv):
    exit_on_signals()  # a stopped run leaves no temporary
    res, out_md, plot_dir, study_dir, jobs, wall = argv[1:7]
    gp = os.path.join(study_dir, "plots.gp")
    runs = load(os.path.join(res, "runs.tsv"))
    os.makedirs(plot_dir, exist_ok=True)
    scenes = sorted({k[0] for k in runs}, key=lambda s: (not s.startswith("paper"), s))
    ns = sorted({k[2] for k in runs})
    names = machines(runs)
    rel = os.path.relpath(plot_dir, os.path.dirname(out_md))
    L = ["# Scaling: which machine for a given number of processors", ""] + findings(runs, scenes, ns, checked(runs))
    planar = planar_findings(res)
    if planar:
        L = L[:-2] + planar + L[-2:]  # before the count of runs
    L += before_fit.section(res)
    L += ["## How it was made", "",
          "Generated by `bash experiments/scaling/study.sh` (do not edit by hand); "
          f"{wall} s on {jobs} jobs. Each scene at its own size under the fitted profile (the default); T(1) from the "
          "one-processor run. Machines at each processor count n:", "",
          "- **flat-cyclic**, **flat-cost**: a flat torus of n IPs, `--map cyclic` or `--map cost`;",
          "- **flat-cost-r0.5**, **flat-cost-r1.0**: `--map cost --replicate 0.5` or `1.0` with `--replica-choice "
          "hash` (under `nearest` the rays into a hot cell mostly come from one node and reach one owner; "
          "[cell-mappings.md](cell-mappings.md#replicated-cells));",
          "- **flat-scatter**, **flat-scatter-r0.5**: `--map scatter`, the measured cells dealt to the least "
          "loaded node, hottest first; `-r0.5` with `--replicate 0.5 --replica-choice hash`, the hottest cells cut "
          "into pieces on several nodes ([cell-mappings.md](cell-mappings.md#scatter));",
          "- **flat-cyclic-rf**, **flat-scatter-rf**, **flat-scatter-r0.5-rf**: the same machines with "
          "`--queue-order rays-first` ([model.md](model.md#intersectionprocessor-intersection_processorh));",
          "- **mM-DATA-MAP**: n / M nodes of M processors (`--cluster M`), `--data replicated` or `shared`, "
          "`--map cyclic` or `cost`, wherever n / M is at least 4.", "",
          "Memory is the data memory of the report (`memory.total_bytes`: object records, materials and cell "
          "lists over all processors, copies included). The budget is "
          f"{BUDGET:g}x flat-cyclic's total at the same n. The efficiency T(1) / (n T) is split into measured "
          "factors: **work** = T(1) / (n x mean busy time), what forwarding and waiting for the bus add; "
          "**balance** = mean busy / busiest; **tail** = busiest / image time, the busiest processor's idle time "
          "waiting for rays that depend on earlier ones; their product is the efficiency. **busiest link** is "
          "the highest link utilisation.", ""]
    for sc in scenes:
        time_png, mem_png = scene_plots(runs, sc, ns, names, plot_dir, gp)
        L += [f"## {sc}", ""] + scene_table(runs, sc, ns, names)
        L += ["", f"![image time against n, {sc}]({rel}/{time_png})", "",
              f"![image time against memory, {sc}]({rel}/{mem_png})", ""]
    png, busy = busy_plot(res, plot_dir, gp)
    L += ["## Busy time per node with and without copies (paper-image2, 512 IPs)", "",
          "Per node, busiest first: " + "; ".join(f"{m} busiest {b[0]:.3f} s, mean {b[1]:.3f} s"
                                                  for m, b in busy.items()) + ".", "",
          f"![busy time per node]({rel}/{png})", ""]
    png, share = share_plot(res, plot_dir, gp)
    L += ["## Busy processors over the frame (paper-image1, 512 IPs, scatter)", "",
          "The share of the 512 IPs busy in each fortieth of the image time, from a `--vcd` trace of each "
          "order (`python3 -m report.busy_share`, run in `experiments/`): "
          + "; ".join(f"{name}: image {v[-1][0] + v[-1][0] - v[-2][0]:.3f} s, above 80 % busy in "
                      f"{sum(1 for _, x in v if x > 0.8)} of {len(v)} bins, below 50 % in the last "
                      f"{len(v) - max(i for i, (_, x) in enumerate(v) if x >= 0.5) - 1}"
                      for name, v in share.items()) + ".", "",
          f"![busy processors over the frame]({rel}/{png})", ""]
    with atomic(out_md) as f:
        f.write("\n".join(L))
    print(f"scaling study: wrote {out_md}")


if __name__ == "__main__":
    sys.exit(memory_exit.run("experiments/scaling/report.py", lambda: main, sys.argv))
