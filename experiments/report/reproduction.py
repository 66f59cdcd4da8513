"""docs/reproduction.md: the paper's claims beside the sweep's numbers, tables and plots."""
import os

from output_files import atomic, copy_file

from . import claims as claimlib
from . import paper
from .csvdata import num
from .verdict import HOLDS, summary

MAPS = [("block", "block"), ("cyclic", "cyclic (load-balancing)"), ("bc2", "block-cyclic 2"),
        ("bc3", "block-cyclic 3")]
FIGURE_NUMBERS = (5, 6, 7, 8, 10, 11, 12)


def scene_name(scene):
    return {"image1": "image 1", "image2": "image 2"}.get(scene, scene)


def fig56_table(r, scene):
    rows = [row for row in r.f56.rows if row["scene"] == scene]
    maps = [(key, name) for key, name in MAPS if any(row["mapping"] == key for row in rows)]
    cell = {}
    for row in rows:
        cell[row["mapping"], int(row["n"])] = (
            "%.3g s, %.0f %% / %.0f %%" % (num(row, "sim_time_s"), 100 * num(row, "efficiency"),
                                          100 * num(row, "load_balance"))
            if row["status"] == "ok" else row["status"])
    lines = ["| n |" + "".join(" %s |" % name for _, name in maps), "| ---: |" + " --- |" * len(maps)]
    for n in sorted({int(row["n"]) for row in rows}):
        lines.append("| %d |" % n + "".join(" %s |" % cell.get((key, n), "") for key, _ in maps))
    return "\n".join(lines)


def fig7_table(r):
    cols = sorted({(row["scene"], row["mapping"]) for row in r.f7.rows if row["mapping"] in ("block", "cyclic")})
    cell, pp = {}, {}
    for row in r.f7.rows:
        n = int(row["n"])
        if row["mapping"] in ("block", "cyclic"):
            cell[row["scene"], row["mapping"], n] = (
                "%.1f KiB (1/%.1f)" % (num(row, "total_bytes") / 1024, num(row, "pixel_partitioned_over_total"))
                if row["status"] == "ok" else row["status"])
        if row["status"] == "ok":
            pp[row["scene"], n] = num(row, "pixel_partitioned_bytes")
    lines = ["| n |" + "".join(" %s, %s |" % (scene_name(s), m) for s, m in cols)
             + " pixel-partitioned (image 1 / image 2) |", "| ---: |" + " --- |" * len(cols) + " --- |"]
    for n in sorted({int(row["n"]) for row in r.f7.rows}):
        lines.append("| %d |" % n + "".join(" %s |" % cell.get((s, m, n), "") for s, m in cols)
                     + " %.0f / %.0f KiB |" % (pp.get(("image1", n), 0) / 1024, pp.get(("image2", n), 0) / 1024))
    return "\n".join(lines)


def fig8_table(r):
    lines = ["| n | ours, image 1 (units) | speed-up | paper, image 1 (units) | paper speed-up | ours, image 2 (units) |",
             "| ---: | ---: | ---: | ---: | ---: | ---: |"]
    by_n = {}
    for row in r.f8.rows:
        entry = by_n.setdefault(int(row["n"]), {})
        units = row["units_parallel"] if row["status"] == "ok" else row["status"]
        if row["scene"] == "image1":
            entry.update(u=units, sp=row["speedup"], pu=row["paper_units"], ps=row["paper_speedup"])
        elif row["scene"] == "image2":
            entry["u2"] = units
    times = lambda t: "%.1fx" % float(t) if t else ""
    for n in sorted(by_n):
        e = by_n[n]
        lines.append("| %d | %s | %s | %s | %s | %s |" % (n, e.get("u", ""), times(e.get("sp")), e.get("pu", ""),
                                                        times(e.get("ps")), e.get("u2", "")))
    return "\n".join(lines)


def fig10_table(r):
    lines = ["| scene | m | processors | replicated: time, efficiency / load balance, memory | shared: time, "
             "efficiency / load balance, memory, bus use | paper |", "| --- | ---: | ---: | --- | --- | --- |"]
    cell, procs, paper_note = {}, {}, {}
    for row in r.f10.rows:
        key = (row["scene"], int(row["m"]))
        procs[key] = row["processors"]
        if row["status"] == "ok":
            text = "%.3g s, %.0f %% / %.0f %%, %.0f KiB" % (
                num(row, "sim_time_s"), 100 * num(row, "efficiency"), 100 * num(row, "load_balance"),
                num(row, "total_bytes") / 1024)
            if row["data"] == "shared" and row["bus_util_mean"] != "":
                text += ", bus %.0f %%" % (100 * num(row, "bus_util_mean"))
        else:
            text = row["status"]
        cell[row["data"], key] = text
        if row["paper_time_s"]:
            paper_note.setdefault(key, []).append("%s %s s" % (row["data"], row["paper_time_s"]))
    for key in sorted(procs):
        lines.append("| %s | %d | %d | %s | %s | %s |" % (
            scene_name(key[0]), key[1], int(procs[key]), cell.get(("replicated", key), ""),
            cell.get(("shared", key), ""), ", ".join(paper_note.get(key, []))))
    return "\n".join(lines)


def problems(r):
    out = ["- %s, %s mapping, n = %s: **%s**" % (row["scene"], row["mapping"], row["n"], row["status"])
           for row in r.f56.rows if row["status"] != "ok"]
    out += ["- %s, %s data, m = %s: **%s**" % (row["scene"], row["data"], row["m"], row["status"])
            for row in r.f10.rows if row["status"] != "ok"]
    return out


def efficiency_note(r):
    """How much work forwarding adds at 16 IPs, per scene (for the two definitions)."""
    note = ""
    for s in r.scenes:
        t = r.f56.value("efficiency", scene=s, mapping="cyclic", n=16)
        if t is None:
            continue
        busy = r.f56.value("busy_mean_s", scene=s, mapping="cyclic", n=16)
        t_one = r.f56.value("t1_s", scene=s, mapping="cyclic", n=16)
        best = None
        for row in r.f56.where(scene=s, n=16):
            if best is None or num(row, "efficiency") > num(best, "efficiency"):
                best = row
        note += (" %s, %s: the load-balancing mapping's (%s) 16 IPs do %.1f x T(1) of work, and reach %s; "
                 "the best mapping at 16 IPs reaches %.1f %% (%s)." % (r.profile,
                     claimlib.label(s), r.facts.lb_map, 16 * busy / t_one, claimlib.pct(t), 100 * num(best, "efficiency"),
                     best["mapping"]))
    return note


def run_facts(r):
    """The numbers of the 'The run' table."""
    ok_rows = [(row, "n=" + row["n"]) for row in r.f56.where()] + [(row, "m=" + row["m"]) for row in r.f10.where()]
    walls = [(num(row, "wall_s"), "%s/%s/%s" % (row["scene"], row.get("mapping") or row["data"], tag))
             for row, tag in ok_rows]
    slowest = max(walls, key=lambda w: w[0], default=(0.0, ""))
    points = r.f56.rows + r.f10.rows
    return {
        "points": len(points),
        "bad": sum(1 for row in points if row["status"] != "ok"),
        "differ": sum(1 for row in points if row["status"] == "ok" and row["image_identical"] != "yes"),
        "sim_sum": "%.1f" % sum(w for w, _ in walls),
        "slowest": "%.1f" % slowest[0],
        "slowest_name": slowest[1],
    }


def copy_plots(res, img_dir):
    """Copies RESULTS/plots/figN.png to IMG/reproduction-figN.png; returns the numbers copied."""
    os.makedirs(img_dir, exist_ok=True)
    drawn = set()
    for f in FIGURE_NUMBERS:
        target = os.path.join(img_dir, "reproduction-fig%d.png" % f)
        source = os.path.join(res, "plots", "fig%d.png" % f)
        if os.path.exists(source) and os.path.getsize(source) > 0:
            copy_file(source, target, "--doc")  # a link is followed: the file it names is written
            drawn.add(f)
        elif os.path.isfile(target) and not os.path.islink(target):
            os.remove(target)  # an earlier sweep's picture of a figure this one did not draw
    return drawn


def embed(drawn, img_rel, f, title):
    if f in drawn:
        return "![%s](%s/reproduction-fig%d.png)" % (title, img_rel, f)
    return "*(%s: not drawn, no data in this sweep)*" % title


def claims_table(by_profile):
    """One row per claim: the default reading's figure and verdict, then each other reading's."""
    (first, claims), others = by_profile[0], by_profile[1:]
    head = "| # | claim (paper section) | paper | ours, %s | verdict, %s |" % (first, first)
    head += "".join(" ours, %s | verdict, %s |" % (p, p) for p, _ in others) + " notes (%s) |" % first
    lines = [head, "| ---: | --- | --- |" + " --- | --- |" * len(by_profile) + " --- |"]
    for i, c in enumerate(claims):
        row = "| %d | %s | %s | %s | **%s** |" % (i + 1, c.text, c.paper, c.ours, c.verdict)
        row += "".join(" %s | **%s** |" % (cl[i].ours, cl[i].verdict) for _, cl in others)
        lines.append(row + " %s |" % c.notes)
    return "\n".join(lines)


def findings(by_profile, facts):
    """The page's opening: the verdict count per reading, the headline claim, every claim that
    does not hold under the default reading, and whether every image matched."""
    (first, claims), others = by_profile[0], by_profile[1:]
    held = [i + 1 for i, c in enumerate(claims) if c.verdict == HOLDS]
    out = ["## Findings", "",
           "- **%d of %d claims hold** under the %s reading (the default); %s" % (
               len(held), len(claims), first, summary([c.verdict for c in claims]))]
    out += ["- Under the %s reading %d of %d hold; %s" % (
        p, sum(1 for c in cl if c.verdict == HOLDS), len(cl), summary([c.verdict for c in cl]))
        for p, cl in others]
    if claims:
        head = claims[0]
        out.append("- The headline claim, 1 (%s), **%s**: paper %s; ours %s." % (
            head.text, head.verdict, head.paper, head.ours.rstrip(".")))
    out.append("- Claims that hold: %s." % (", ".join(str(i) for i in held) or "none"))
    out += ["", "Claims that do not fully hold (%s reading):" % first, ""]
    out += ["- **%d**. %s: paper %s; ours %s (**%s**)" % (i + 1, c.text, c.paper, c.ours.rstrip("."), c.verdict)
            for i, c in enumerate(claims) if c.verdict != HOLDS] or ["None."]
    out += ["", "- Images: %d of the computed points differ from the one-processor image; %d points did not run."
            % (facts["differ"], facts["bad"]),
            "- What the misses depend on, and which readings of the paper's unknowns fit them best:",
            "  [fidelity.md](fidelity.md).", ""]
    return out


def run_table(all_r, rel):
    """The 'The run' table: how the sweep was made and how long it took."""
    r = all_r[0]
    facts, run, na = run_facts(r), r.runs, claimlib.or_na
    data_links = "; ".join("%s: " % x.profile + " ".join("[%s.csv](%s)" % (n, rel(os.path.join(x.dir, n + ".csv")))
                                                         for n in ("fig5_6", "fig7", "fig8", "fig10_12")) for x in all_r)
    return [
        "| | |",
        "| --- | --- |",
        "| mode | %s (image size %s) |" % (run.get("mode", r.mode), r.facts.image_size),
        "| readings | %s; each with every point |" % "; ".join(
            "%s (timing profile %s, hand-over %s us; image 1 `%s`; load-balancing mapping %s)" % (
                x.profile, x.facts.timing_profile, x.facts.hop_us, x.facts.image1_scene, x.facts.lb_map)
            for x in all_r),
        "| points | %d in the figures (%d not ok) + %d one-processor runs, in the default reading; %s computed by the timed run |" % (
            facts["points"], facts["bad"], r.facts.t1_runs, run.get("points_run", "?")),
        "| wall time of the points | **%s s** on %s with -j %s, %s cores (%s); CPU time %s s; load average at the end %s |" % (
            na(run.get("wall_s")), run.get("hosts", "?"), run.get("jobs", "?"), run.get("cores", "?"),
            run.get("started_utc", "unknown"), na(run.get("cpu_s")), na(run.get("load1"))),
        "| simulator time per point | %s s in all (from the reports' wall_s); the slowest point %s s (%s) |" % (
            facts["sim_sum"], facts["slowest"], na(facts["slowest_name"])),
        "| joblog of the latest sweep | %s points started, spanning %s s |" % (
            na(r.facts.joblog_points), na(r.facts.joblog_span_s)),
        "| images | %d of the computed points differ from the one-processor image (every configuration must "
        "render the same bytes) |" % facts["differ"],
        "| data | %s |" % data_links,
    ]


def figure_sections(all_r, img):
    """Figures 5 to 12: the embedded plots and their tables (the heading of figure 5 excepted)."""
    r, out = all_r[0], []
    for x in all_r:
        for s in x.scenes:
            out += ["", "**%s, %s reading**" % (claimlib.label(s), x.profile), "", fig56_table(x, s)]
    out += ["", "### Figure 6: efficiency against IP count", "", img(6, "Figure 6"), "",
            "Efficiency T(1) / (n T(n)); solid lines: the %s reading, dashed: the %s reading. The black bar is"
            % (r.profile, all_r[1].profile if len(all_r) > 1 else r.profile),
            "the paper's \"above 85 % with 16 IPs or fewer\" for the load-balancing mapping. Numbers, with",
            "the load balance: the tables above.",
            "", "### Figure 7: data memory against IP count", "", img(7, "Figure 7"), "",
            "Data memory requirement = largest per-IP data x n (the paper's definition); in brackets the",
            "fraction of the pixel-partitioned system's (whole scene x n). The circle with bar marks the",
            "paper's 1/6 to 1/7 at 16 IPs.", "", fig7_table(r), "",
            "### Figure 8: preprocessing time against IP count", "", img(8, "Figure 8"), "",
            "One unit is one test of an object against the half-space of one cutting plane; the parallel",
            "time is the largest per-IP count when objects are dealt out evenly. Taken from the block-mapping",
            "runs (the preprocessing does not depend on the mapping).", "", fig8_table(r), "",
            "### Figures 10-12: 16 clusters of m processors", "", img(10, "Figure 10"), "", img(11, "Figure 11"),
            "", img(12, "Figure 12"), "",
            "Image time, efficiency / load balance, data memory of all processors, and for shared data the",
            "mean bus utilisation. m = 64 is the paper's 1024-processor system. In the plots of figures 10",
            "and 11, solid lines are the %s reading and dashed the %s one." % (
                r.profile, all_r[1].profile if len(all_r) > 1 else r.profile)]
    for x in all_r:
        out += ["", "**%s reading**" % x.profile, "", fig10_table(x)]
    return out


READING_WHAT = {
    "fitted": "the values the fidelity study fitted ([fidelity.md](fidelity.md)), as the machine files hold them",
    "round-one": "the first fit, made without the work window",
    "calibrated": "the reading before the fits",
    "literal": "the calibrated reading with the paper's table read literally (a hand-over is a packet "
               "creation and an analysis)",
}


def reading_line(x, default):
    """One reading's settings, read from its runs."""
    f = x.facts
    return ("**%s**%s, %s: timing profile `%s` (%s us a hand-over, %s us a cell step), image 1 `scenes/%s`, "
            "image 2 `scenes/%s`, 16 nodes as `%s`, `--route-ties %s`, the load-balancing points on `--map %s`"
            % (x.profile, " (the default)" if default else "", READING_WHAT.get(x.profile, "a reading"),
               f.timing_profile, f.hop_us, f.cell_step_us, f.image1_scene, f.image2_scene, f.shape16,
               f.route_ties, f.lb_map))


def intro(run_cmd, r, all_r):
    """How the page is made and the readings it is judged under."""
    return [
        "This page compares every number in the prose of Kubota et al. (sections 6-8 of",
        "[docs/paper.md](paper.md)) with torusrt's model, run over the paper's axes. It is generated:",
        "`%s` runs the sweep (GNU parallel, one torusrt-sim command line per point)," % run_cmd,
        "`experiments/report` (Python) turns the JSON reports into one CSV per figure, the gnuplot scripts",
        "`experiments/plots/*.gp` draw the plots from data files written by `experiments/report`, and",
        "`experiments/report` writes this page, judging each claim in `experiments/report/claims.py`.",
        "How to run it on one machine, over ssh or as a Slurm job array: `experiments/README.md`.",
        "",
        "Every point runs under each reading of the paper's unknowns ([readings.md](readings.md)):",
    ] + ["- " + reading_line(x, i == 0) + (";" if i + 1 < len(all_r) else ".") for i, x in enumerate(all_r)] + [
        "",
        "Claims are judged under the %s reading; the others' figures and verdicts stand beside them." % r.profile,
        "The load-balancing points are labelled *cyclic* in every table and plot. Efficiency is",
        "T(1) / (n T(n)) throughout; busy time / (n T(n)) is shown as *load balance*.",
    ]


def document(res, all_r, doc_dir, drawn):
    """The whole Markdown page; all_r: the Results of each profile, the default first."""
    r = all_r[0]
    rel = lambda p: os.path.relpath(p, doc_dir)
    by_profile = [(x.profile, claimlib.evaluate(x)) for x in all_r]
    run, quick = r.runs, r.mode == "quick"
    na = claimlib.or_na
    run_cmd = "experiments/sweep.sh --quick" if quick else "experiments/sweep.sh"
    if quick:
        timing_note = "This quick sweep took %s s for its points (`experiments/sweep.sh --quick`)." % na(run.get("wall_s"))
    else:
        timing_note = (
            "The full sweep, on one machine with 2 jobs, is `time experiments/sweep.sh -j 2`: about\n"
            "%s s for the points (%s s of CPU), plus a few seconds for collecting, plotting and\n"
            "this page. The target was under 15 minutes on 2 cores; no points were dropped to meet it. A load\n"
            "average above the core count means other work shared the machine, and the wall time is longer than\n"
            "on an idle one." % (na(run.get("wall_s")), na(run.get("cpu_s"))))
    quick_note = ("\n> **Quick mode** (small image, few points): a check that the pipeline works, not a reproduction.\n"
                  "> Numbers here are not comparable with the paper's." if quick else "")
    img = lambda f, title: embed(drawn, "img", f, title)
    out = [
        "# Reproduction of the paper's results",
        "",
        "<!-- Generated by experiments/report (python3 experiments/report reproduction) from %s/*.csv; "
        "do not edit by hand. -->" % rel(os.path.join(res, "*")),
        "",
    ] + findings(by_profile, run_facts(r)) + [
        "## How it was made",
        "",
    ] + intro(run_cmd, r, all_r) + [
        quick_note,
        "",
        "## The run",
        "",
    ] + run_table(all_r, rel) + [
        "",
        timing_note,
        "",
        WHAT_IS_COMPARED.format(creation=paper.TIMING_US["packet_creation"],
                                analysis=paper.TIMING_US["packet_analysis"], handover=paper.HANDOVER_US),
        "  missed intersection test, in the literal reading; nothing in the others.",
        "  With the cyclic mapping nearly every cell crossing changes IP." + "".join(efficiency_note(x) for x in all_r),
        "",
        "## Claims",
        "",
    ] + ["- **%s**%s: %s" % (p, " (default)" if i == 0 else "", summary([c.verdict for c in cl]))
         for i, (p, cl) in enumerate(by_profile)] + [
        "",
        claims_table(by_profile),
        "",
        "## Figures",
        "",
        "### Figure 5: image time against IP count",
        "",
        img(5, "Figure 5"),
        "",
        "The paper gives no times for the flat torus. Solid lines: the %s reading; dashed: the %s one." % (
            r.profile, all_r[1].profile if len(all_r) > 1 else r.profile),
        "Each cell: image time, efficiency / load balance.",
    ]
    out += figure_sections(all_r, img)
    out += ["", "## Points that did not run", ""]
    missing = [line for x in all_r for line in problems(x)]
    if missing:
        out += ["These points are in the CSVs with empty figures. *failed*: torusrt-sim exited non-zero (its",
                "messages are in the point's .log beside the JSON, and sweep.sh listed the command lines);",
                "*missing*: never run. Re-running the sweep retries exactly these.", ""] + missing
    else:
        out.append("None: every point of the sweep produced its report.")
    return "\n".join(out) + "\n", by_profile


WHAT_IS_COMPARED = """## What is compared, and what differs from the paper

- **The machine** is the paper's: 24 x 24 x 24 cells, 144 x 144 pixels, the V30/8087 operation
  times of section 6 (docs/design.md section 6), 50 us a packet on a link, a 3D torus
  (1 = 1x1x1, 2 = 2x1x1, 4 = 2x2x1, 8 = 2x2x2, 16 = the reading's arrangement (above), 32 = 4x4x2,
  64 = 4x4x4, 128 = 8x4x4, 256 = 8x8x4, 512 = 8x8x8), no host injection cost.
- **The scenes are not the paper's.** The paper describes its two images in one sentence each;
  `scenes/paper-image1.nff` and `paper-image2.nff` are reconstructions (scenes/README.md):
  369 recursively defined diffuse spheres, and a glass and a mirror sphere before 121 small
  spheres. Sizes, positions, camera, lights and material coefficients are ours. Every absolute
  figure (seconds, units, bytes) depends on them; ratios and directions much less.
- **Mappings**: block, cyclic (the paper's load-balancing mapping: block size 1, or blocks of 3
  cells in round one's reading) and block-cyclic with blocks of 2 and 3 cells, which lie in between.
- **Clusters** (figures 10-12): 16 clusters arranged as the flat 16, the load-balancing mapping between
  clusters, m processors per cluster on one bus. The paper's times are for m = 64, i.e.
  **16 x 64 = 1024 processors**; efficiencies are over all 16 m processors.
- **Verdicts**: *holds* when our number satisfies the paper's statement; for the paper's
  absolute figures (seconds, units), when ours is within 20 % (all three of claim 7's unit
  counts); *holds for one image* when a statement made of both images (Fig. 6's gain over block
  included) holds on one; *direction only* when ours goes the same way as a ratio of the paper's
  own numbers (claim 11) but outside its range. "1/6 to 1/7" is judged as 6 to 7 exactly, on the
  mapping the sentence names (the load-balancing one for claim 6, replicated data for claim 17);
  "80 % or more" as at least 80 %, "above 85 %" as more than 85 %; "more so" (claim 5) counts a
  point only where cyclic stores strictly more, *mostly* when that is more than half of the
  points. The rule for each row is in its last column.

### Efficiency and load balance

The paper defines system efficiency as *ideal processing time / actual processing time*. The
model reports two figures:

- **efficiency** = T(1) / (n T(n)): against the one-processor time. This is the paper's
  system efficiency and the one every claim is judged by.
- **load balance** = sum over processors of busy time / (n T(n)): the work the parallel
  machine actually did, spread evenly. The two differ by the work parallelism adds: every time
  a ray crosses into a cell another IP owns, the packet is handed over: created ({creation} us)
  and analysed again ({analysis} us), i.e. {handover} us, more than six DDA steps and more than a"""


def write(res, doc):
    """Writes the page for the results folder `res` (one folder per reading inside) to `doc`
    (atomically); returns (reading, claims) per reading."""
    from .results import profile_results
    all_r = profile_results(res)
    doc_dir = os.path.dirname(os.path.realpath(doc))  # the page's own folder, a link followed
    drawn = copy_plots(res, os.path.join(doc_dir, "img"))
    text, claim_list = document(res, all_r, doc_dir, drawn)
    with atomic(doc) as f:
        f.write(text)
    return claim_list
