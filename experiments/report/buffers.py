"""buffers.py - the buffer study's page: docs/buffers.md from experiments/buffers/results/runs.tsv
(written by experiments/buffers/study.sh), and its plot through plots/buffers.gp.

Usage: python3 experiments/report/buffers.py RUNS.tsv DOC.md PICS_DIR PLOT.gp --size WxH --wall S --jobs N
Standard library only.
"""
import os
import sys

try:  # first: under a small ulimit -v loading a module is what fails, this one too (memory_exit.py)
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    import memory_exit
except (MemoryError, OSError, ImportError):
    os.write(2, b"experiments/report/buffers.py: out of memory: the system refused the memory the tool "
             b"asked for (ulimit -v?)\n")
    os._exit(1)
try:
    import argparse
    import csv
    from output_files import atomic, exit_on_signals, staged
    from stop_signals import run_child
    from report import before_fit
except Exception as e:
    memory_exit.leave_if_out_of_memory("experiments/report/buffers.py", e)
    raise

UNBOUNDED = 0
WITHIN = 0.05  # "within 5 % of unbounded"


def read_runs(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def cap_label(c):
    return "unbounded" if c == UNBOUNDED else str(c)


def series(rows):
    """{(scene, machine): {flow: {capacity: row}}} in the order of first appearance."""
    out = {}
    for r in rows:
        key = (r["scene"], r["machine"])
        out.setdefault(key, {}).setdefault(r["flow"], {})[int(r["capacity"])] = r
    return out


def ordered_caps(by_cap):
    return sorted(by_cap, key=lambda c: (c == UNBOUNDED, c))


def kb(v):
    return "%.0f KB" % (float(v) / 1000.0) if v not in ("", None) else ""


def base_time(classes):
    """The unbounded run's image time under the class scheme, what the others are compared with;
    None when that run failed or is missing."""
    r = classes.get(UNBOUNDED)
    return float(r["sim_time_s"]) if r is not None and r["status"] == "ok" else None


def comparable(data):
    """The groups whose unbounded run finished (the others have nothing to be compared with)."""
    return {k: flows for k, flows in data.items() if base_time(flows.get("classes", {})) is not None}


def smallest_within(classes):
    base = base_time(classes)
    for c in ordered_caps(classes):
        r = classes[c]
        if c != UNBOUNDED and r["status"] == "ok" and float(r["sim_time_s"]) <= base * (1 + WITHIN):
            return c
    return UNBOUNDED


def packet_bytes(rows):
    """sizeof(rt_packet), from a bounded run's bytes per class over its buffers and capacity."""
    for r in rows:
        if r["status"] == "ok" and int(r["capacity"]) > 0 and r["flow"] == "classes":
            per = float(r["bytes_per_ip_per_class"]) / (float(r["buffers_per_ip_per_class"]) * int(r["capacity"]))
            return "%.0f" % per
    return "?"


def write_plot_data(data, dat_dir):
    os.makedirs(dat_dir, exist_ok=True)
    names = []
    for (scene, machine), flows in data.items():
        classes = flows.get("classes", {})
        base = base_time(classes)
        if base is None:
            continue
        name = "%s-%s" % (scene, machine.replace(" ", "_"))
        with atomic(os.path.join(dat_dir, name + ".dat")) as f:
            f.write("# capacity (unbounded plotted at 128) time/unbounded\n")
            for c in ordered_caps(classes):
                if classes[c]["status"] == "ok":
                    f.write("%d %.6f\n" % (128 if c == UNBOUNDED else c, float(classes[c]["sim_time_s"]) / base))
        names.append(name)
    return names


def run_gnuplot(gp, dat_dir, names, png):
    with staged(png) as tmp:
        cmd = ["gnuplot", "-e", "dat='%s'; out='%s'; series='%s'" % (dat_dir, tmp, " ".join(names)), gp]
        run_child(cmd, check=True)


def detail_table(scene, machine, flows):
    classes, none = flows.get("classes", {}), flows.get("none", {})
    base = base_time(classes)
    lines = ["", "### %s, %s processors" % (scene, machine), ""]
    if base is None:
        r = classes.get(UNBOUNDED)
        lines += ["The unbounded run under the class scheme %s: nothing to compare with." %
                  ("is missing" if r is None else "did not finish (%s)" % r["status"]), ""]
    lines += [
              "| capacity | image time (classes) | vs unbounded | packet memory per processor | image | --flow none |",
              "| --- | --- | --- | --- | --- | --- |"]
    for c in ordered_caps(classes):
        r = classes[c]
        if r["status"] != "ok":
            lines.append("| %s | %s | | | | |" % (cap_label(c), r["status"]))
            continue
        t = float(r["sim_time_s"])
        n = none.get(c)
        none_text = "" if n is None else (n["status"] if n["status"] != "ok" else "%.4f s" % float(n["sim_time_s"]))
        mem = "unbounded" if c == UNBOUNDED else "%s (%s classes)" % (kb(r["bytes_per_ip_used"]), r["classes_used"])
        vs = "%+.1f %%" % (100.0 * (t / base - 1)) if base else ""
        lines.append("| %s | %.4f s | %s | %s | %s | %s |" % (
            cap_label(c), t, vs, mem,
            "identical" if r["image_identical"] == "1" else "DIFFERS", none_text))
    return lines


def summary_table(data):
    lines = ["| scene | processors | unbounded | capacity 1 | smallest capacity within 5 % | its packet memory per processor | one class (`none`) finishes from |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for (scene, machine), flows in data.items():
        classes, none = flows.get("classes", {}), flows.get("none", {})
        base = base_time(classes)
        one = classes.get(1)
        one_text = ("%.4f s (%+.1f %%)" % (float(one["sim_time_s"]), 100 * (float(one["sim_time_s"]) / base - 1))
                    if one and one["status"] == "ok" else one["status"] if one else "")
        s = smallest_within(classes)
        mem = classes[s]["bytes_per_ip_used"] if s != UNBOUNDED else ""
        fin = [c for c in ordered_caps(none) if none[c]["status"] == "ok"]
        lines.append("| %s | %s | %.4f s | %s | %s | %s | %s |" % (
            scene, machine, base, one_text, cap_label(s), kb(mem) if mem else "unbounded",
            cap_label(fin[0]) if fin else "never"))
    return lines


def findings(everything, bad, over):
    """The page's opening: what the class scheme costs and guarantees, and what one class does,
    over the machines whose unbounded run finished."""
    data = comparable(everything)
    costs, within, mems, none_bounded = [], [], [], 0
    for flows in data.values():
        classes, none = flows.get("classes", {}), flows.get("none", {})
        base = base_time(classes)
        if 1 in classes and classes[1]["status"] == "ok":
            costs.append(100 * (float(classes[1]["sim_time_s"]) / base - 1))
        s = smallest_within(classes)
        within.append(s)
        if s != UNBOUNDED:
            mems.append(float(classes[s]["bytes_per_ip_used"]))
        if any(c != UNBOUNDED and none[c]["status"] == "ok" for c in none):
            none_bounded += 1
    bounded = [c for c in within if c != UNBOUNDED]
    out = ["## Findings", "",
           "- Under the class scheme every run finished with the renderer's image and conserved packets: %s; "
           "no buffer held more packets of one class than its capacity: %s."
           % ("yes" if not bad else "NO, %d did not" % len(bad), "yes" if not over else "NO, %d did" % len(over))]
    if costs:
        out.append("- One packet per buffer and class costs %+.1f %% to %+.1f %% of image time against unbounded "
                   "buffers." % (min(costs), max(costs)))
    if bounded:
        out.append("- Within 5 %% of unbounded from a capacity of %d to %d packets per buffer and class, "
                   "%s to %s of packet memory per processor%s." % (
                       min(bounded), max(bounded), kb(min(mems)), kb(max(mems)),
                       "" if len(bounded) == len(within) else "; %d machine(s) need unbounded buffers"
                       % (len(within) - len(bounded))))
    if len(data) < len(everything):
        out.append("- %d of %d machines have no comparison: their unbounded run under the class scheme did not "
                   "finish (section \"Every run\")." % (len(everything) - len(data), len(everything)))
    if none_bounded == 0:
        out.append("- With one class (`--flow none`) every machine deadlocks at every bounded capacity tried; "
                   "only unbounded buffers finish.")
    else:
        out.append("- With one class (`--flow none`), %d of %d machines finish at some bounded capacity; the "
                   "others deadlock at every bounded capacity tried." % (none_bounded, len(data)))
    out.append("")
    return out + summary_table(data)


def main(argv):
    exit_on_signals()  # a stopped run leaves no temporary
    ap = argparse.ArgumentParser()
    ap.add_argument("runs")
    ap.add_argument("doc")
    ap.add_argument("pics")
    ap.add_argument("gp")
    ap.add_argument("--size", required=True)
    ap.add_argument("--wall", required=True)
    ap.add_argument("--jobs", required=True)
    a = ap.parse_args(argv)
    rows = read_runs(a.runs)
    data = series(rows)
    bad = [r for r in rows if r["flow"] == "classes" and (r["status"] != "ok" or r["image_identical"] != "1"
                                                        or r["conserved"] != "true")]
    over = [r for r in rows if r["status"] == "ok" and int(r["capacity"]) != UNBOUNDED
            and int(r["high_water"]) > int(r["capacity"])]
    names = write_plot_data(data, os.path.join(a.pics, "data"))
    png = os.path.join(a.pics, "time-vs-capacity.png")
    run_gnuplot(a.gp, os.path.join(a.pics, "data"), names, png)
    out = ["# How much buffer the machine needs", ""] + findings(data, bad, over)
    out += before_fit.section(os.path.dirname(os.path.abspath(a.runs)))
    out += ["", "Cost of the scheme against unbounded buffers: the capacity-1 column (at capacity 0 the scheme's",
            "times equal one class's). A smaller buffer is not always slower: it changes the order of the work",
            "(a processor takes up first a packet whose outputs have room; primaries are throttled), and",
            "another order can finish sooner.", "",
            "![image time against capacity](buffers/time-vs-capacity.png)", "",
            "## How it was made", "",
           "Generated by `experiments/buffers/study.sh` (%d runs at %s pixels, %s job(s), %s s wall);"
           % (len(rows), a.size, a.jobs, a.wall),
           "do not edit. Image time (`sim_time_s`) of the paper scenes against the capacity of every buffer",
           "(`--queue N`: packets per buffer of each class), fitted timing (the default), cyclic mapping, AT, under the",
           "deadlock-free class scheme (`--flow classes`, docs/model.md \"Flow control\"), with one class",
           "(`--flow none`) beside it. The image size keeps the study under a quarter of an hour on one core;",
           "it is smaller than the paper's, so absolute times are too.", "",
           "Packet memory per processor = %s bytes (`sizeof(rt_packet)`) x buffers of one class per processor"
           % packet_bytes(rows),
           "(13 flat: the input queue and 6 links x 2 virtual channels; 7.5 in clusters of 2) x capacity x classes",
           "used (`flow.bytes_per_ip_used`). A machine built for any scene needs the class bound instead",
           "(`flow.bytes_per_ip_bound`).", "", "## Every run"]
    for (scene, machine), flows in data.items():
        out += detail_table(scene, machine, flows)
    os.makedirs(os.path.dirname(os.path.abspath(a.doc)), exist_ok=True)
    with atomic(a.doc) as f:
        f.write("\n".join(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(memory_exit.run("experiments/report/buffers.py", lambda: main, sys.argv[1:]))
