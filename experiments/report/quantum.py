"""The timing-style study (LT against AT) of docs/error-vs-runtime.md: tables, the recommended
quantum, the findings and the plot data, from quantum.csv (columns by name, see quantum.sh)."""
import os

from .csvdata import num
from .plots import write_dat

TABLE_HEAD = ("| style | quantum | error sim_time_s % | error efficiency_busy % | wall s | speed-up | speed-up "
              "(simulation only) | events/s | packet-hops/s | delta cycles | image = AT |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|")


def configs(table):
    """(scene, ips) in the order they first appear."""
    return list(dict.fromkeys((row["scene"], row["ips"]) for row in table.rows))


def lt_rows(table, config=None):
    return [row for row in table.rows if row["style"] == "lt"
            and (config is None or (row["scene"], row["ips"]) == config)]


def signed_error(x):
    """A signed error in per cent, with the precision its size deserves."""
    if x == 0:
        return "0"
    a = abs(x)
    return ("%+.2f" if a >= 10 else "%+.4f" if a >= 0.0001 else "%+.1e") % x


def tables(table):
    out = []
    for config in configs(table):
        rows = [row for row in table.rows if (row["scene"], row["ips"]) == config]
        at = "".join("image time %.4f s, efficiency_busy %.2f %%, wall %.3f s (%.3f s simulating)" % (
            num(r, "sim_time_s"), 100 * num(r, "efficiency_busy"), num(r, "wall_s"), num(r, "sim_wall_s"))
            for r in rows if r["style"] == "at")
        out += ["#### %s, %s (%s IPs)" % (config[0], config[1], rows[0]["processors"]), "", "AT: %s." % at, "",
                TABLE_HEAD]
        for r in rows:
            out.append("| %s | %s | %s | %s | %.3f | %.2f | %.2f | %.3g M | %.3g M | %d | %s |" % (
                r["style"].upper(), "-" if r["style"] == "at" else r["quantum"], signed_error(num(r, "err_time_pct")),
                signed_error(num(r, "err_eff_pct")), num(r, "wall_s"), num(r, "speedup"), num(r, "speedup_sim"),
                num(r, "events_per_s") / 1e6, num(r, "packet_hops_per_s") / 1e6, int(num(r, "delta_cycles")),
                "yes" if r["image_equal"] == "true" else "**NO**"))
        out.append("")
    return "\n".join(out).rstrip("\n")


def recommend(table, bound):
    """Per configuration: the largest quantum whose error, and that of every smaller quantum
    tried (sim_time_s and efficiency_busy), is within `bound` per cent ('0' when the smallest
    non-zero one is already out); its quantum_s, the speed-up there, and whether the bound was
    never passed."""
    out = {}
    for config in configs(table):
        rows = lt_rows(table, config)
        if not rows:
            continue
        best = {"quantum": "0", "quantum_s": 0.0, "speedup": num(rows[0], "speedup"), "not_reached": True}
        for r in rows:
            if max(abs(num(r, "err_time_pct")), abs(num(r, "err_eff_pct"))) > bound:
                best["not_reached"] = False
                break
            best.update(quantum=r["quantum"], quantum_s=num(r, "quantum_s"), speedup=num(r, "speedup"))
        out["%s, %s" % config] = best
    return out


def recommend_table(table):
    one, five = recommend(table, 1), recommend(table, 5)
    note = lambda b: " (bound not reached)" if b["not_reached"] else ""
    lines = ["| configuration | largest quantum within 1 % | speed-up there | largest quantum within 5 % | speed-up there |",
             "|---|---:|---:|---:|---:|"]
    for k in sorted(one):
        lines.append("| %s | %s%s | %.2f | %s%s | %.2f |" % (k, one[k]["quantum"], note(one[k]), one[k]["speedup"],
                                                          five[k]["quantum"], note(five[k]), five[k]["speedup"]))
    return "\n".join(lines)


def overall(table, bound):
    """The smallest of the per-configuration recommendations."""
    rec = recommend(table, bound)
    return min(rec.items(), key=lambda kb: (kb[1]["quantum_s"], kb[0]))[1]["quantum"] if rec else ""


def yes_no(ok):
    return "yes" if ok else "no"


def grouped(table, column, below):
    """'scene ips: q1, q2; ...': the LT quanta of each configuration where column < below."""
    parts = []
    for config in configs(table):
        quanta = [r["quantum"] for r in lt_rows(table, config) if num(r, column) < below]
        if quanta:
            parts.append("%s %s: %s" % (config[0], config[1], ", ".join(quanta)))
    return "; ".join(parts)


def findings(table):
    lt = lt_rows(table)
    nonmono, previous = [], None
    for r in lt:
        key = "%s %s" % (r["scene"], r["ips"])
        e = num(r, "err_time_pct")
        if previous and previous[0] == key and abs(e) < abs(previous[1]):
            nonmono.append("%s %s (%.3g %% after %.3g %% at %s)" % (key, r["quantum"], abs(e), abs(previous[1]), previous[2]))
        previous = (key, e, r["quantum"])
    fastest = []
    for config in configs(table):
        rows = lt_rows(table, config)
        if rows:
            best = max(rows, key=lambda r: num(r, "speedup"))
            fastest.append("%s, %s: %.2f at %s (error %+.2f %%)" % (config[0], config[1], num(best, "speedup"),
                                                                   best["quantum"], num(best, "err_time_pct")))
    return {
        "all_equal": yes_no(all(r["image_equal"] == "true" for r in table.rows)),
        "all_det": yes_no(all(r["deterministic"] == "true" for r in table.rows)),
        "q0_zero": yes_no(not any(num(r, "quantum_s") == 0 and (num(r, "err_time_pct") != 0 or num(r, "err_eff_pct") != 0)
                                  for r in lt)),
        "maxspd": "; ".join(fastest),
        "slower": grouped(table, "speedup", 1),
        "negatives": grouped(table, "err_time_pct", 0),
        "nonmono": "; ".join(nonmono),
    }


def g6(x):
    """A number as awk prints it (%.6g), for plot ranges."""
    return float("%.6g" % x)


def pareto_front(rows):
    """The runs no other run beats on both wall time and |error of sim_time_s| (fastest first)."""
    front, best = [], None
    for r in sorted(rows, key=lambda r: (num(r, "wall_s"), abs(num(r, "err_time_pct")))):
        e = abs(num(r, "err_time_pct"))
        if best is None or e < best:
            front.append(r)
            best = e
    return front


def front_text(table):
    """Per configuration, its Pareto front as 'quantum (wall s, error %)', fastest first."""
    out = []
    for config in configs(table):
        rows = [r for r in table.rows if (r["scene"], r["ips"]) == config]
        out.append("%s, %s: %s" % (config[0], config[1], ", ".join(
            "%s (%.3f s, %s %%)" % ("AT" if r["style"] == "at" else r["quantum"], num(r, "wall_s"),
                                   signed_error(num(r, "err_time_pct"))) for r in pareto_front(rows))))
    return out


def plot_data(table, dat):
    """Writes dat/qI.dat, dat/atI.dat, dat/allI.dat and dat/frontI.dat; returns the gnuplot
    variables of error-quantum.gp and error-pareto.gp."""
    variables = {}
    for i, config in enumerate(configs(table), 1):
        rows = [r for r in table.rows if (r["scene"], r["ips"]) == config]
        point = lambda r: [r["wall_s"], abs(num(r, "err_time_pct")), "AT" if r["style"] == "at" else r["quantum"]]
        write_dat(os.path.join(dat, "all%d.dat" % i), [point(r) for r in rows])
        write_dat(os.path.join(dat, "front%d.dat" % i), [point(r) for r in pareto_front(rows)])
        write_dat(os.path.join(dat, "q%d.dat" % i), [[r["wall_s"], r["speedup"], r["err_time_pct"], r["err_eff_pct"],
                                                       r["quantum_s"], r["quantum"]] for r in lt_rows(table, config)])
        write_dat(os.path.join(dat, "at%d.dat" % i), [[r["wall_s"]] for r in table.rows
                                                      if (r["scene"], r["ips"]) == config and r["style"] == "at"])
        variables["title%d" % i] = "%s, %s" % config
    walls = [num(r, "wall_s") for r in table.rows]
    speedups = [num(r, "speedup") for r in table.rows]
    quanta = [num(r, "quantum_s") for r in table.rows if num(r, "quantum_s") > 0]
    smin = min(speedups)
    variables.update(nconf=len(configs(table)), wmin=g6(min(walls) / 1.25), wmax=g6(max(walls) * 1.25),
                     smin=g6(smin - 0.2 if smin > 0.3 else 0.1), smax=g6(max(speedups) + 0.3),
                     qmin=g6(min(quanta) / 2 if quanta else 1e-6), qmax=g6(max(quanta) * 2 if quanta else 1))
    return variables
