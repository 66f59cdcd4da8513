#!/usr/bin/env python3
"""report.py - docs/motion.md from the motion study's runs (Python 3 standard library).

Usage: report.py RESULTS_DIR OUT_MD PLOT_DIR STUDY_DIR JOBS WALL_S
RESULTS_DIR holds runs.tsv (one row per scene, node count and policy), frames.tsv (one row per
frame of each run) and strip.list (the renderer's frames to put side by side, one path a line from RESULTS_DIR;
the strip is drawn only when those frames exist). Per case (scene, nodes): each policy's total
against the targets, the cell-list update against a rebuild of every list, the update and its
transfers against the render time, and migration bytes; a per-frame time plot per case.
"""
import os
import sys

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, b"experiments/motion/report.py: out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    import csv
    import tempfile
    from output_files import atomic, exit_on_signals
    from report.plots import gnuplot_kind
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/motion/report.py", e)
    raise

POLICIES = ["adaptive", "every-frame", "oracle", "static", "cyclic"]
ORACLE_WITHIN = 0.10   # adaptive within this fraction of oracle's total
EVERY_FRAME_SLACK = 0.01  # adaptive no longer than every-frame's total plus this fraction


def load(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def by_case(runs):
    """{(scene, n): {policy: row}}."""
    out = {}
    for r in runs:
        out.setdefault((r["scene"], int(r["n"])), {})[r["policy"]] = r
    return out


def cases(table):
    """Scenes in name order, the larger machine first."""
    return sorted(table, key=lambda k: (k[0], -k[1]))


def total(r):
    return float(r["total_s"])


def verdicts(table):
    """Per case: (adaptive <= static, adaptive <= every-frame + 1 %, adaptive within 10 % of oracle)."""
    out = {}
    for k, p in table.items():
        a = total(p["adaptive"])
        out[k] = (a <= total(p["static"]), a <= total(p["every-frame"]) * (1 + EVERY_FRAME_SLACK),
                  a <= total(p["oracle"]) * (1 + ORACLE_WITHIN))
    return out


def pct(a, b):
    return f"{100 * (a / b - 1):+.1f} %"


def frame_time(f):
    """What a frame costs the animation: its image, its remap migration and its list update."""
    return sum(float(f[c]) for c in ("image_time_s", "migration_time_s", "update_time_s", "update_link_time_s"))


def update_against_rebuild(frames):
    """Per scene, over the frames after the first of every run: (frames, frames where the update's
    busiest processor has more units than a rebuild's, lowest and highest ratio of the two)."""
    out = {}
    for f in frames:
        if int(f["frame"]) == 0:
            continue
        rebuild = int(f["rebuild_units_slowest"])
        ratio = int(f["update_units_slowest"]) / rebuild if rebuild else 0.0
        n, slower, lo, hi = out.get(f["scene"], (0, 0, float("inf"), 0.0))
        out[f["scene"]] = (n + 1, slower + (int(f["update_units_slowest"]) > rebuild), min(lo, ratio),
                           max(hi, ratio))
    return out


def guesses(frames, scene, n):
    """{guess: frames} of adaptive's remaps in one case."""
    out = {}
    for f in frames:
        if f["scene"] == scene and int(f["n"]) == n and f["policy"] == "adaptive" and f["decision"] == "remap":
            out[f["guess"]] = out.get(f["guess"], 0) + 1
    return out


def target_line(table, v):
    counts = [sum(1 for x in v.values() if x[i]) for i in range(3)]
    met = counts[0] == len(v) and counts[1] == len(v) and counts[2] >= 3
    L = [f"- **Targets** (adaptive's total, updates and migration included): no longer than static in "
         f"{counts[0]} of {len(v)} cases, no longer than every-frame + 1 % in {counts[1]} of {len(v)}, within "
         f"10 % of oracle in {counts[2]} of {len(v)}: **{'met' if met else 'not met'}**."]
    misses = []
    for k in cases(table):
        p, a = table[k], total(table[k]["adaptive"])
        if not v[k][0]:
            misses.append(f"{k[0]} at {k[1]} nodes {pct(a, total(p['static']))} against static")
        if not v[k][1]:
            misses.append(f"{k[0]} at {k[1]} nodes {pct(a, total(p['every-frame']))} against every-frame")
        if not v[k][2]:
            misses.append(f"{k[0]} at {k[1]} nodes {pct(a, total(p['oracle']))} against oracle")
    if misses:
        L[0] = L[0][:-1] + " (" + "; ".join(misses) + ")."
    return L


def findings(table, frames, ok):
    v = verdicts(table)
    L = ["## Findings", ""] + target_line(table, v)
    for k in cases(table):
        p, a = table[k], total(table[k]["adaptive"])
        g = guesses(frames, *k)
        picks = ", ".join(f"{name} {c}" for name, c in sorted(g.items(), key=lambda x: (-x[1], x[0])))
        L.append(f"- {k[0]}, {k[1]} nodes: adaptive {a:.4g} s, {pct(a, total(p['every-frame']))} against every-frame, "
                 f"{pct(a, total(p['oracle']))} against oracle, {pct(a, total(p['static']))} against static cost, "
                 f"{pct(a, total(p['cyclic']))} against cyclic. Its remaps by guess: {picks}.")
    beat = [k for k in cases(table) if total(table[k]["oracle"]) < total(table[k]["adaptive"])]
    L.append(f"- Oracle is shorter than adaptive in {len(beat)} of {len(table)} cases: it maps each frame by that "
             "frame's own measured load, but the cost mapper is a heuristic, so a table fitted to a guess can "
             "run a frame faster than the one fitted to the frame.")
    ub = update_against_rebuild(frames)
    parts = [f"{sc}: slower on {slower} of {n} frames (63 of each run), update / rebuild {lo:.2f} to {hi:.2f}"
             for sc, (n, slower, lo, hi) in sorted(ub.items())]
    never = all(x[1] == 0 for x in ub.values())
    L.append(f"- **The incremental update against a rebuild of every list** (the busiest processor's half-space "
             f"tests, which set the update time): no slower on every frame of both scenes: "
             f"**{'yes' if never else 'NO'}** ({'; '.join(parts)}). Over all processors the update does "
             + ", ".join(f"{100 * int(r['update_units']) / int(r['rebuild_units']):.1f} % of a rebuild's units "
                         f"({sc})" for sc, r in sorted({k[0]: table[k]['adaptive'] for k in table}.items()))
             + ". Where one object moved and a rebuild gives each processor at most one object (as many "
             "processors as objects or more), the rebuild takes as long as its costliest object and the update "
             "as long as the moved one: the ratio reaches 1.00 on frames where they are the same object.")
    share = ", ".join(f"{k[0]} {k[1]} nodes {100 * float(table[k]['adaptive']['motion_time_s']) / total(table[k]['adaptive']):.1f} %"
                      for k in cases(table))
    L.append(f"- **Update and its transfers against the render**: share of adaptive's total spent updating lists "
             f"and sending the moved objects: {share}. The update is the same on every mapping (object o on "
             "processor o mod P); only its transfers depend on where the cells are.")
    mig = ", ".join(f"{k[0]} {k[1]} nodes {int(table[k]['adaptive']['migration_bytes']) / 1e6:.2f} MB remap, "
                    f"{int(table[k]['adaptive']['update_bytes']) / 1e3:.1f} kB update"
                    for k in cases(table))
    worst = max(float(table[k][p]["migration_time_s"]) / total(table[k][p]) for k in table for p in POLICIES)
    L.append(f"- **Migration bytes** over 64 frames (adaptive): {mig}. Remap migration costs at most "
             f"{100 * worst:.2f} % of any total.")
    runs = [r for p in table.values() for r in p.values()]
    L.append(f"- {len(runs)} runs of {max(int(f['frame']) for f in frames) + 1} frames; every frame equal to "
             f"`torusrt-render`'s byte for byte: **{'yes' if ok[0] else 'NO'}**; packets conserved in every run: "
             f"**{'yes' if ok[1] else 'NO'}**.")
    return L + [""]


def checked(runs):
    return (all(r["images_identical"] == "1" for r in runs), all(r["conserved"] == "true" for r in runs))


def case_table(p):
    L = ["| policy | total s | image s | remap migration s | remap bytes | update s | update link s | update bytes "
         "| mapping changes |", "|---" * 9 + "|"]
    for name in POLICIES:
        r = p[name]
        L.append(f"| {name} | {total(r):.4g} | {float(r['image_time_s']):.4g} | {float(r['migration_time_s']):.4g} "
                 f"| {r['migration_bytes']} | {float(r['update_time_s']):.4g} | {float(r['update_link_time_s']):.4g} "
                 f"| {r['update_bytes']} | {r['mapping_changes']} |")
    return L


def update_table(frames, scene, n):
    """Adaptive's updates, every eighth frame."""
    L = ["| frame | objects moved | update units (busiest) | rebuild units (busiest) | ratio | update s | link s "
         "| bytes | image s | (update + link) / image |", "|---" * 10 + "|"]
    rows = [f for f in frames if f["scene"] == scene and int(f["n"]) == n and f["policy"] == "adaptive"]
    for f in rows:
        k = int(f["frame"])
        if k == 0 or (k % 8 and k != 1):
            continue
        up, rb = int(f["update_units_slowest"]), int(f["rebuild_units_slowest"])
        u, link, img = float(f["update_time_s"]), float(f["update_link_time_s"]), float(f["image_time_s"])
        L.append(f"| {k} | {f['objects_moved']} | {up} | {rb} | {up / rb:.2f} | {u:.4g} | {link:.3g} "
                 f"| {f['update_bytes']} | {img:.4g} | {100 * (u + link) / img:.1f} % |")
    return L


def frame_plot(frames, scene, n, plot_dir, gp):
    rows = {}
    for f in frames:
        if f["scene"] == scene and int(f["n"]) == n:
            rows.setdefault(int(f["frame"]), {})[f["policy"]] = frame_time(f)
            if f["policy"] == "adaptive":
                rows[int(f["frame"])]["update"] = float(f["update_time_s"]) + float(f["update_link_time_s"])
    data = os.path.join(plot_dir, f"frames-{scene}-{n}.dat")
    with atomic(data) as out:
        series = POLICIES + ["update"]
        out.write("frame " + " ".join(series) + "\n")
        for k in sorted(rows):
            out.write(f"{k} " + " ".join(f"{rows[k][p]:.6g}" if p in rows[k] else "-" for p in series) + "\n")
    return gnuplot_kind(gp, "frames", data, os.path.join(plot_dir, f"frames-{scene}-{n}.png"),
                   f"{scene}, {n} nodes: time per frame; update: the list update alone (adaptive)", len(series) + 1)


def strip(res, plot_dir, gp):
    """The renderer's frames side by side, when the study's reference frames are at hand."""
    with open(os.path.join(res, "strip.list")) as f:
        files = [os.path.join(res, line.strip()) for line in f if line.strip()]
    if not files or not all(os.path.exists(p) for p in files):
        return None
    with tempfile.NamedTemporaryFile("w", suffix=".list") as f:
        f.write("\n".join(files) + "\n")
        f.flush()
        return gnuplot_kind(gp, "strip", f.name, os.path.join(plot_dir, "strip.png"), "", len(files))


def main(argv):
    exit_on_signals()  # a stopped run leaves no temporary
    res, out_md, plot_dir, study_dir, jobs, wall = argv[1:7]
    gp = os.path.join(study_dir, "plots.gp")
    runs, frames = load(os.path.join(res, "runs.tsv")), load(os.path.join(res, "frames.tsv"))
    table = by_case(runs)
    os.makedirs(plot_dir, exist_ok=True)
    rel = os.path.relpath(plot_dir, os.path.dirname(out_md))
    strip(res, plot_dir, gp)
    scenes = sorted({k[0] for k in table})
    L = ["# Motion: changing scenes, their cell-list updates and the remap policies", ""]
    L += findings(table, frames, checked(runs))
    L += ["## How it was made", "",
          "Generated by `bash experiments/motion/study.sh` (do not edit by hand); "
          f"{wall} s on {jobs} jobs. The two moving scenes, " + " and ".join(f"`scenes/{s}.nff` with "
                                                                             f"`scenes/{s}.motion`" for s in scenes)
          + ", 64 frames of 64x64 pixels (the motion files' frame count), the default timing profile, on a "
          "4x4x4 (64 nodes) and an 8x8x8 (512 nodes) torus. Five policies:", "",
          "- **adaptive**: `--map cost --remap adaptive`: before frame k the host guesses its load and remaps when "
          "the guess gains more than the migration costs; with `--motion` one guess moves frame k-1's measured "
          "work of each moved object into the cells it occupies in frame k (`objects`, "
          "[frames.md](frames.md), `--remap`);",
          "- **every-frame**: `--map cost --remap every-frame`, remapped on frame k-1's measured load;",
          "- **oracle**: `--remap oracle`, each frame mapped on its own measured load, migration free (a bound, "
          "not always reached: the mapper is a heuristic);",
          "- **static**: `--map cost`, fitted to frame 0 and kept;",
          "- **cyclic**: `--map cyclic`, the paper's mapping, kept.", "",
          "Before each frame after the first the machine updates the cell lists of the objects that moved "
          "(`preprocess_unit` a half-space test, object o on processor o mod P, the slowest processor's time) and "
          "sends the list changes and the moved objects' records to the nodes that gain them over the links "
          "([frames.md](frames.md#moving-objects)). Total = the frames' image times + remap migration + updates "
          "and their transfers. A rebuild is every object's units dealt out the same way. Every frame of every "
          "run is compared with `torusrt-render --motion`'s byte for byte.", "",
          f"![frames 0, 8, ..., 56 of each scene, as torusrt-render draws them]({rel}/strip.png)", "",
          "Frames 0, 8, ..., 56 of " + " (top) and ".join(scenes) + " (bottom).", ""]
    for sc in scenes:
        for n in sorted({k[1] for k in table if k[0] == sc}, reverse=True):
            png = frame_plot(frames, sc, n, plot_dir, gp)
            L += [f"## {sc}, {n} nodes", ""] + case_table(table[(sc, n)])
            L += ["", f"Adaptive's cell-list updates (frame 1 and every eighth frame; busiest processor's units):", ""]
            L += update_table(frames, sc, n)
            L += ["", f"![time per frame, {sc}, {n} nodes]({rel}/{png})", ""]
    with atomic(out_md) as f:
        f.write("\n".join(L))
    print(f"motion study: wrote {out_md}")


if __name__ == "__main__":
    sys.exit(memory_exit.run("experiments/motion/report.py", lambda: main, sys.argv))
