"""docs/fidelity.md from the results of the fidelity study, round two (experiments/fidelity/study.sh):
the three counts first, the fitted reading and its residuals, every claim with its role, E_t1 and
E_busy side by side, each stage's table with every candidate's excesses, the trade where a target
is missed, and the robustness readings with those the cap dropped."""
import os

from output_files import atomic

from . import claims, fidelity, paper
from . import fidelity_score as fs
from . import fidelity_stages as st
from .results import Results
from .verdict import HOLDS, summary, verdict

EFFICIENCY_CLAIMS = (1, 2, 3, 12, 14)


def _pct(x):
    return "n/a" if x is None else "%.1f %%" % (100 * x)


def _exc(figures):
    """'t1_image1 0.12, ...' of the nonzero excesses, or 'none'."""
    e = fs.excesses(figures)
    bad = ["%s %.3g" % (k, v) for k, v in sorted(e.items()) if v > 0]
    return ", ".join(bad) if bad else "none"


def _score(figures):
    return " / ".join("%.3g" % x for x in fs.score(fs.excesses(figures)))


def _claims_of(res, name):
    d = os.path.join(res, "sweeps", name, "calibrated")
    try:
        r = Results(d)
        return claims.evaluate(r), r
    except (OSError, ValueError, KeyError, ZeroDivisionError):
        return None, None


# ---- E_t1 and E_busy side by side --------------------------------------------------------------

def efficiency_pair(r, i, column):
    """(figure text, checks passed, checks) of efficiency claim i under one definition:
    column 'efficiency' (E_t1) or 'load_balance' (E_busy)."""
    text, ok, total = [], 0, 0
    for s in (r.scenes if i in (1, 2, 3) else r.cscenes):
        if i == 1:
            vals = [r.f56.value(column, scene=s, mapping="cyclic", n=n) for n in (2, 4, 8, 16)]
            vals = [v for v in vals if v is not None]
            x, good = (min(vals), min(vals) > paper.EFFICIENCY_FLOOR) if vals else (None, False)
        elif i == 2:
            a, b = (r.f56.value(column, scene=s, mapping="cyclic", n=n) for n in (16, 64))
            x, good = (None, False) if a is None or b is None else (a - b, a - b > 0.10)
        elif i == 3:
            ratios = []
            for row in r.f56.where(scene=s, mapping="cyclic"):
                b = r.f56.value(column, scene=s, mapping="block", n=row["n"])
                if int(row["n"]) > 1 and b and row.get(column):
                    ratios.append(float(row[column]) / b)
            x, good = (max(ratios), max(ratios) > paper.MAPPING_GAIN) if ratios else (None, False)
        elif i == 12:
            x = r.f10.value(column, scene=s, data="replicated", m=paper.CLUSTER_M)
            good = x is not None and x >= paper.CLUSTER_EFFICIENCY_FLOOR
        else:
            vals = [float(row[column]) for row in r.f10.where(scene=s, data="shared")
                    if int(row["m"]) <= paper.SHARED_EFFICIENCY_MAX_M and row.get(column)]
            x = min(vals) if vals else None
            good = x is not None and x >= paper.CLUSTER_EFFICIENCY_FLOOR
        if x is None:
            continue
        total += 1
        ok += good
        text.append("%s %s" % (claims.label(s), "%.2fx" % x if i == 3 else
                               ("%.1f points" % (100 * x) if i == 2 else _pct(x))))
    return "; ".join(text) or "n/a", ok, total


def _efficiency_table(L, r, fit_claims):
    L.append("## Efficiency: E_t1 (primary) and E_busy side by side\n")
    L.append("E_t1 = T(1) / (n T(n)), the primary (protocol section 1); E_busy = sum of busy / (n T(n)). "
             "The verdict that counts is E_t1's.\n")
    L.append("| # | claim | E_t1 | verdict (E_t1) | E_busy | verdict (E_busy) |\n| ---: | --- | --- | --- | --- | --- |")
    for i in EFFICIENCY_CLAIMS:
        t1, _, _ = efficiency_pair(r, i, "efficiency")
        busy, ok, total = efficiency_pair(r, i, "load_balance")
        L.append("| %d | %s | %s | **%s** | %s | %s |" % (i, fit_claims[i - 1].text, t1, fit_claims[i - 1].verdict,
                                                        busy, verdict(ok, total)))
    L.append("")


# ---- the stages --------------------------------------------------------------------------------

def _trade(L, ranked, what):
    """For each target the chosen candidate misses: the best candidate that meets it, and its cost."""
    chosen = ranked[0][1]
    for target, e in sorted(fs.excesses(chosen).items()):
        if e <= 0:
            continue
        meets = [c for c in ranked if fs.excesses(c[1])[target] == 0]
        if meets:
            L.append("- **Trade (%s)**: the choice misses %s by %.3g; the best candidate that meets it (%s) has "
                     "excesses %s, score %s against the choice's %s." % (
                         what, target, e, _name(meets[0][3]), _exc(meets[0][1]), _score(meets[0][1]), _score(chosen)))
        else:
            L.append("- **Trade (%s)**: no candidate meets %s; the choice misses it by %.3g." % (what, target, e))
    L.append("")


def _name(choice):
    return ", ".join("%s %s" % kv for kv in choice.items())


def _stage1(L, res, smoke):
    choice, ranked, parts = st.stage1(res, smoke)
    L.append("### Stage 1: scenes and work (F1 + F0), %d combinations\n" % len(ranked))
    L.append("The score is separable: F1 depends on layout x scale x counting rule, F0 on each image's "
             "variant and the cell-step cost: a combination's excesses are those of its rows in the two tables below.\n")
    L.append("| layout | scale | rule | 1 IP | 16 IPs | 32 IPs | F1 excesses |\n| --- | --- | --- | ---: | ---: | ---: | --- |")
    for (layout, scale, rule), u in parts["units"].items():
        L.append("| %s | %s | %s | %d | %d | %d | %s |" % (layout, scale, rule, u[1], u[16], u[32],
                                                       _exc({"units_%d" % n: u[n] for n in u})))
    L.append("\n| image | variant | " + " | ".join("T(1) c=%d" % c for c in fs.CELL_STEP_COSTS) +
             " | F0 excess by c |\n| --- | --- | " + " | ".join("---:" for _ in fs.CELL_STEP_COSTS) + " | --- |")
    variants = sorted({(k[0], k[1]) for k in parts["t1"]})
    for image, spec in variants:
        t = [parts["t1"][(image, spec, c)] for c in fs.CELL_STEP_COSTS]
        ex = [fs.excesses({"t1_" + image: x})["t1_" + image] for x in t]
        L.append("| %s | `%s` | %s | %s |" % (image, spec, " | ".join("%.1f s" % x for x in t),
                                              " / ".join("%.3f" % e for e in ex)))
    L.append("\nThe best 10 combinations (score: excesses sorted from largest; ties by unknowns moved, then "
             "the largest residual against the point values):\n")
    L.append("| rank | image 1 | rule | image 2 | c us | excesses | score | moved |\n"
             "| ---: | --- | --- | --- | ---: | --- | --- | ---: |")
    for k, (_, figures, moved, ch) in enumerate(ranked[:10], 1):
        L.append("| %d | `%s` | %s | `%s` | %s | %s | %s | %d |" % (k, ch["spec1"], ch["rule"], ch["spec2"],
                                                               ch["cell_step"], _exc(figures), _score(figures), moved))
    zero = sum(1 for c in ranked if max(fs.excesses(c[1]).values()) == 0)
    L.append("\n%d of %d combinations meet every stage-1 target." % (zero, len(ranked)))
    _trade(L, ranked, "stage 1")
    L.append("")
    return choice


def _timed_table(L, ranked, keys, fig_keys, title):
    L.append(title + "\n")
    L.append("| " + " | ".join(keys) + " | " + " | ".join(fig_keys) + " | excesses | score |")
    L.append("| " + " | ".join("---" for _ in keys) + " | " + " | ".join("---:" for _ in fig_keys) + " | --- | --- |")
    for _, figures, _, ch, means in ranked:
        cells = [str(ch[k]) for k in keys]
        L.append("| " + " | ".join(cells) + " | " + " | ".join(fig_keys[k](figures, means) for k in fig_keys) +
                 " | %s | %s |" % (_exc(figures), _score(figures)))
    L.append("")


def _spread(m):
    return "%.3f s (%.3f-%.3f, %d runs)" % (m["time"], m["spread"][0], m["spread"][1], m["runs"])


def _stages23(L, res):
    for name2, name3, label in (("stage2.tsv", "stage3.tsv", ""), ("stage2b.tsv", "stage3b.tsv", ", refinement")):
        if not st.rows(res, name2):
            continue
        _, r2 = st.stage2(res, name2)
        cols2 = {"penalty 1": lambda f, m: "%.3f" % f["penalty_image1"],
                 "penalty 2": lambda f, m: "%.3f" % f["penalty_image2"],
                 "image 1 replicated / shared": lambda f, m: "%s / %s" % (_spread(m[("image1", "replicated")]),
                                                                         _spread(m[("image1", "shared")])),
                 "image 2 replicated / shared": lambda f, m: "%s / %s" % (_spread(m[("image2", "replicated")]),
                                                                         _spread(m[("image2", "shared")]))}
        _timed_table(L, r2, ["bus", "memory"], cols2, "### Stage 2: the bus (F3)%s" % label)
        _trade(L, r2, "stage 2" + label)
        if not st.rows(res, name3):
            continue
        _, r3 = st.stage3(res, name3)
        cols3 = {"image 1": lambda f, m: _spread(m["image1"]), "image 2": lambda f, m: _spread(m["image2"]),
                 "E_t1 / E_busy 1": lambda f, m: "%s / %s" % (_pct(m["image1"]["e_t1"]), _pct(m["image1"]["e_busy"])),
                 "E_t1 / E_busy 2": lambda f, m: "%s / %s" % (_pct(m["image2"]["e_t1"]), _pct(m["image2"]["e_busy"]))}
        _timed_table(L, r3, ["shape", "handover"], cols3, "### Stage 3: the 1024 times (F2)%s" % label)
        _trade(L, r3, "stage 3" + label)
        L.append("")


def _stage4(L, res):
    _, r4 = st.stage4(res)
    L.append("### Stage 4: memory accounting (F4)\n")
    L.append("| cell header B | list entry B | record B (0 natural) | image 1 1/x | image 2 1/x | excesses | score |\n"
             "| ---: | ---: | ---: | ---: | ---: | --- | --- |")
    for _, f, _, ch, _ in r4:
        L.append("| %s | %s | %s | %.2f | %.2f | %s | %s |" % (ch["header"], ch["entry"], ch["record"],
                                                             f["memory_image1"], f["memory_image2"], _exc(f), _score(f)))
    _trade(L, r4, "stage 4")
    L.append("")


# ---- the fitted reading, its residuals, the claims ---------------------------------------------

TARGET_NAMES = (("F0", "t1_image1", "T(1) image 1 (s)"), ("F0", "t1_image2", "T(1) image 2 (s)"),
                ("F1", "units_1", "units on 1 IP"), ("F1", "units_16", "units on 16 IPs"),
                ("F1", "units_32", "units on 32 IPs"), ("F2", "time_image1", "replicated 1024 time image 1 (s)"),
                ("F2", "time_image2", "replicated 1024 time image 2 (s)"), ("F3", "penalty_image1", "penalty image 1"),
                ("F3", "penalty_image2", "penalty image 2"), ("F4", "memory_image1", "pixel-partitioned / cyclic image 1"),
                ("F4", "memory_image2", "pixel-partitioned / cyclic image 2"))


def _fitted(res, smoke):
    """The fitted choices (stage 1's and the machine files') and the stage-5 residual figures."""
    c1 = st.stage1(res, smoke)[0]
    table2, table3 = ("stage2b.tsv", "stage3b.tsv") if st.rows(res, "stage2b.tsv") else ("stage2.tsv", "stage3.tsv")
    c2, c3, c4 = st.stage2(res, table2)[0], st.stage3(res, table3)[0], st.stage4(res)[0]
    v1 = st.parse_spec(c1["spec1"])
    units = st.units_table(res)[(v1["layout"], v1["scale"], c1["rule"])]
    return dict(c1, **c2, **c3, **c4), st.residuals(res, units)


def _findings(L, res, fitted, figures, fit_claims, smoke):
    """The findings after the three counts: the fit, each target met or missed, the cap."""
    if smoke:
        L.append("- **Smoke run** (`study.sh --smoke`): shrunk sizes and candidate lists; no figure here is the "
                 "study's.")
    L.append("- **Fitted reading**: image 1 `%s` (units counted %s), image 2 `%s`, %s us per cell step, bus %s / "
             "memory %s us, %s, hand-over %s us, accounting %s / %s / %s B; cyclic, route-ties split." % (
                 fitted["spec1"], fitted["rule"], fitted["spec2"], fitted["cell_step"], fitted["bus"],
                 fitted["memory"], fitted["shape"], fitted["handover"], fitted["header"], fitted["entry"],
                 fitted["record"]))
    missed = [key for _, key, _ in TARGET_NAMES if key in figures and
              fs.excess(figures[key], fs.TARGETS[key]["lo"], fs.TARGETS[key]["hi"]) > 0]
    L.append("- **Targets on the written files**: %d of %d met%s (the residuals and each stage's trade below)." % (
        sum(1 for _, k, _ in TARGET_NAMES if k in figures) - len(missed),
        sum(1 for _, k, _ in TARGET_NAMES if k in figures), "; missed: " + ", ".join(missed) if missed else ""))
    L.append("- **Verdicts**: " + summary([c.verdict for c in fit_claims]))
    dropped = st.rows(res, "dropped.tsv")
    L.append("- **Robustness**: %d readings run, %d dropped (named below). Protocol: "
             "[fidelity-protocol.md](fidelity-protocol.md), written before the run; the study: "
             "`experiments/fidelity/study.sh` ([experiments.md](experiments.md)).\n" % (
                 len(st.rows(res, "readings.tsv")) - 1, len(dropped)))


def _residuals(L, fitted, figures):
    L.append("## The fitted reading and its residuals (stage 5, measured on the written files)\n")
    L.append("Image 1 `%s`, counting rule %s; image 2 `%s`; `cell_step_packet` %s us; bus cycle %s us, memory "
             "access %s us; 16 nodes as %s, hand-over %s us; cell header %s B, list entry %s B, object record %s "
             "(0: natural); cyclic, `--route-ties split`. The machine files `machines/paper-*.toml` and "
             "`machines/timing/fitted.timing` hold it; the scenes are `scenes/paper-image1.nff` and "
             "`scenes/paper-image2.nff`.\n" % (fitted["spec1"], fitted["rule"], fitted["spec2"], fitted["cell_step"],
                                                fitted["bus"], fitted["memory"], fitted["shape"], fitted["handover"],
                                                fitted["header"], fitted["entry"], fitted["record"]))
    L.append("| target | figure | ours | band | point | excess |\n| --- | --- | ---: | --- | ---: | ---: |")
    for tag, key, text in TARGET_NAMES:
        if key not in figures:
            continue
        t = fs.TARGETS[key]
        e = fs.excess(figures[key], t["lo"], t["hi"])
        L.append("| %s | %s | %.3f | [%.3f, %.3f] | %.3f | %s |" % (tag, text, figures[key], t["lo"], t["hi"],
                                                                  t["point"], "%.3f" % e if e else "met"))
    L.append("")


def _claims_table(L, fit_claims):
    L.append("## Validation: every claim on the fitted machine\n")
    L.append("| # | claim | role | ours | verdict | notes |\n| ---: | --- | --- | --- | --- | --- |")
    for i, c in enumerate(fit_claims, 1):
        L.append("| %d | %s | %s | %s | **%s** | %s |" % (i, c.text, fidelity.role(i), c.ours, c.verdict, c.notes))
    L.append("\n" + summary([c.verdict for c in fit_claims]) + "\n")
    L.append("### The claims that do not hold: measured cause, and what would settle it\n")
    L.append("| # | role | verdict | measured cause (the run's own figures) | the paper detail that would settle it |\n"
             "| ---: | --- | --- | --- | --- |")
    for i, c in enumerate(fit_claims, 1):
        if c.verdict != HOLDS:
            L.append("| %d | %s | %s | %s. %s | %s |" % (i, fidelity.role(i), c.verdict, c.ours.rstrip(". "), c.notes,
                                                         SETTLES[i]))
    L.append("")


def _spreads(L, res):
    from . import fidelity_means
    sp = fidelity_means.spreads(os.path.join(res, "sweeps", "fitted", "calibrated"))
    if not sp:
        return
    L.append("## The validation's cluster points: the mean of each point's runs\n")
    L.append("Each cluster point (claims 9-17) is the mean of its runs at every `bus_arbitration` value "
             "(protocol section 3); the spread is the fastest and the slowest run.\n")
    L.append("| point | mean s | fastest s | slowest s | runs |\n| --- | ---: | ---: | ---: | ---: |")
    for name, (mean, lo, hi, n) in sp.items():
        L.append("| %s | %.4f | %.4f | %.4f | %d |" % (name, mean, lo, hi, n))
    L.append("")


def _robustness(L, res, readings):
    L.append("## Robustness: each claim with one unknown moved at a time\n")
    names = [n for n in readings if n != "fitted"]
    L.append("Each column is the fitted reading with one unknown at another value (protocol section 5, in its "
             "order); a reading re-ran the points its unknown can move (its scope) and took the fitted reading's "
             "others. Cells: the verdict under E_t1, with E_busy's after a slash for the efficiency claims.\n")
    L.append("| # | " + " | ".join(names) + " | holds in (E_t1) | holds in (E_busy) |")
    L.append("| ---: | " + " | ".join("---" for _ in names) + " | ---: | ---: |")
    for i in range(1, 18):
        cells, ok, okb, n_all = [], 0, 0, 0
        for n in names:
            cl, r = readings[n]
            if cl is None:
                cells.append("n/a")
                continue
            n_all += 1
            ok += cl[i - 1].verdict == HOLDS
            cell = "yes" if cl[i - 1].verdict == HOLDS else "no"
            if i in EFFICIENCY_CLAIMS:
                _, p, t = efficiency_pair(r, i, "load_balance")
                okb += p == t > 0
                cell += " / " + ("yes" if p == t > 0 else "no")
            cells.append(cell)
        L.append("| %d | %s | %d of %d | %s |" % (i, " | ".join(cells), ok, n_all,
                                                  "%d of %d" % (okb, n_all) if i in EFFICIENCY_CLAIMS else ""))
    dropped = st.rows(res, "dropped.tsv")
    L.append("")
    if dropped:
        L.append("**Dropped readings** (%d, from the end of the protocol's list): %s.\n" % (
            len(dropped), ", ".join("%s (%s)" % (d[0], d[1]) for d in dropped)))
    else:
        L.append("No reading was dropped.\n")


def write(res, doc, smoke=False):
    """Writes DOC from the study's results in RES."""
    fitted, figures = _fitted(res, smoke)
    readings = {row[0]: _claims_of(res, row[0]) for row in st.rows(res, "readings.tsv")}
    fit_claims, r = readings["fitted"]
    verdicts = [c.verdict for c in fit_claims]
    L = ["# Fidelity, round two: the paper's unknowns fitted on its hard numbers\n", "## Findings\n"]
    L += fidelity.counts_lines(verdicts)
    _findings(L, res, fitted, figures, fit_claims, smoke)
    L.append("<!-- Generated by experiments/fidelity/study.sh (python3 experiments/report fidelity page); "
             "do not edit by hand. -->\n")
    _residuals(L, fitted, figures)
    _claims_table(L, fit_claims)
    _efficiency_table(L, r, fit_claims)
    _spreads(L, res)
    _robustness(L, res, readings)
    L.append("## The stages: every candidate's excesses\n")
    _stage1(L, res, smoke)
    _stages23(L, res)
    _stage4(L, res)
    wall = st.rows(res, "wall.tsv")
    if wall:
        L.append("The study took **%s s** of wall time on %s jobs (load average %s at its end; cap %s s).\n" % (
            wall[0][2], wall[0][1], wall[0][3], wall[0][4]))
    with atomic(doc) as f:
        f.write("\n".join(L) + "\n")
    return 0


# For each claim, the detail of the paper that would settle it where the model misses it.
SETTLES = {
    1: "the per-IP busy times or Fig. 6's values at 16 IPs, and the scenes' exact geometry (where the hot spots are)",
    2: "Fig. 6's values past 16 IPs",
    3: "Fig. 6's values for block mapping, and the scenes' hot spots",
    4: "what a cell list and an object record cost (sec. 7 gives no bytes)",
    5: "what a cell list and an object record cost, and the spheres' sizes",
    6: "the bytes per cell header, list entry and object record (sec. 7 gives none)",
    7: "the counting rule and image 1's sphere sizes and positions",
    8: "the counting rule and image 1's sphere sizes and positions",
    9: "the arrangement of the 16 clusters, the scenes' work and the hand-over cost",
    10: "the bus cycle and 2-port memory access times",
    11: "the bus cycle and 2-port memory access times",
    12: "each image's one-processor time T(1) (the work the paper's machine did)",
    13: "the bus's cost per packet transfer and the communication unit's timing",
    14: "the bus cycle and 2-port memory access times",
    15: "the share of the cell lists in a node's data (the accounting)",
    16: "the bytes per cell header, list entry and object record",
    17: "the bytes per cell header, list entry and object record",
}
