"""The shade-tree pruning study of docs/error-vs-runtime.md: tables, findings and plot data from
pruning.csv (columns by name, see pruning.sh)."""
import os

from .csvdata import num
from .plots import write_dat

PSNR_GOOD = 40  # dB: the finding's "close enough"


def scenes(table):
    return list(dict.fromkeys(row["scene"] for row in table.rows))


def runners(table):
    return list(dict.fromkeys(row["runner"] for row in table.rows))


def tables(table):
    out = []
    for scene in scenes(table):
        rows = [r for r in table.rows if r["scene"] == scene]
        head = "| sweep | max-depth | min-weight | PSNR dB | max abs diff | pixels off > 2 | packets |"
        sep = "|---|---:|---:|---:|---:|---:|---:|"
        for runner in runners(table):
            head += " T(1) s | render wall s |" if runner == "render" else " T %s s | wall %s s |" % (runner[4:], runner[4:])
            sep += "---:|---:|"
        out += ["#### %s (%s pixels)" % (scene, rows[0]["total_pixels"]), "", head + " sim image = render |", sep + ":---:|"]
        settings = {}
        for r in rows:
            s = settings.setdefault((r["sweep"], r["max_depth"], r["min_weight"]), {"first": r, "equal": True, "by": {}})
            s["by"][r["runner"]] = r
            s["equal"] = s["equal"] and r["image_equals_render"] == "true"
        for s in settings.values():
            f = s["first"]
            line = "| %s | %s | %s | %s | %s | %s (%.1f %%) | %s |" % (
                f["sweep"], f["max_depth"], f["min_weight"], f["psnr_db"], f["max_abs_diff"], f["pixels_off_gt2"],
                100 * num(f, "pixels_off_gt2") / num(f, "total_pixels"), f["packets"])
            for runner in runners(table):
                r = s["by"].get(runner)
                line += " %.3f | %.3f |" % ((num(r, "image_time_s"), num(r, "wall_s")) if r else (0, 0))
            out.append(line + " %s |" % ("yes" if s["equal"] else "**NO**"))
        out.append("")
    return "\n".join(out).rstrip("\n")


def good(psnr):
    return psnr == "inf" or float(psnr) >= PSNR_GOOD


def depth_fact(table, scene, runner):
    rows = [r for r in table.rows if r["scene"] == scene and r["sweep"] == "max_depth" and r["runner"] == runner]
    full = num(rows[-1], "image_time_s")
    text = "- **%s**:" % scene
    close = next((r for r in rows if good(r["psnr_db"])), None)
    same = next((i for i, r in enumerate(rows) if r["psnr_db"] == "inf"), None)
    if close:
        text += " PSNR reaches 40 dB at max-depth %s (image time on %s %.3f s, %.1f %% of max-depth %s);" % (
            close["max_depth"], runner, num(close, "image_time_s"), 100 * num(close, "image_time_s") / full,
            rows[-1]["max_depth"])
    if same is not None and same < len(rows) - 1:
        text += " the image is identical to the reference from max-depth %s on (%.1f %% of the time)." % (
            rows[same]["max_depth"], 100 * num(rows[same], "image_time_s") / full)
    else:
        text += " no max-depth below %s gives the identical image." % rows[-1]["max_depth"]
    return text


def weight_fact(table, scene, runner):
    rows = [r for r in table.rows if r["scene"] == scene and r["sweep"] == "min_weight" and r["runner"] == runner]
    beyond = [r for r in table.rows if r["scene"] == scene and r["sweep"] == "beyond" and r["runner"] == "render"]
    same = [r["min_weight"] for r in rows if r["psnr_db"] == "inf"]
    text = "  min-weight: the image stays identical up to %s; at %s PSNR is %s dB and the image time %.1f %% of that at 1/512." % (
        same[-1] if same else "(none)", rows[-1]["min_weight"], rows[-1]["psnr_db"],
        100 * num(rows[-1], "image_time_s") / num(rows[0], "image_time_s"))
    if beyond:
        b = beyond[-1]
        text += ("\n  Beyond the defaults (max-depth %s, min-weight %s) the image differs from the default one by PSNR %s "
                 "dB, max %s levels, %s of %s pixels off by more than 2: the defaults are %s." % (
                     b["max_depth"], b["min_weight"], b["psnr_db"], b["max_abs_diff"], b["pixels_off_gt2"],
                     b["total_pixels"], "a sound reference at 8-bit output" if num(b, "pixels_off_gt2") == 0
                     else "themselves a visible approximation"))
    return text


def facts(table):
    """Per scene: the smallest max-depth reaching 40 dB and the identical image, the min-weight
    reached identically, and how far the defaults are from a deeper tree."""
    first_sim = next((r for r in runners(table) if r.startswith("sim-")), "render")
    out = []
    for scene in scenes(table):
        render = [r for r in table.rows if r["scene"] == scene and r["runner"] == "render"]
        if render and all(r["psnr_db"] == "inf" for r in render) and len({r["packets"] for r in render}) == 1:
            out.append("- **%s**: pruning changes nothing: every setting, down to max-depth 0 and up to min-weight 1/8 "
                       "(and the deeper \"beyond\" tree), gives the identical image, the same %s packets and the same "
                       "image time. No surface of this scene spawns reflected or refracted rays (the packet count never "
                       "changes), so every shade tree is a primary ray and its shadow rays, which no setting prunes."
                       % (scene, render[0]["packets"]))
            continue
        out += [depth_fact(table, scene, first_sim), weight_fact(table, scene, first_sim)]
    return "\n".join(out)


def findings(table):
    def psnr(r):
        return 1e300 if r["psnr_db"] == "inf" else float(r["psnr_db"])
    falls, last = "", {}
    for r in table.rows:
        if r["sweep"] != "max_depth":
            continue
        key = "%s %s" % (r["scene"], r["runner"])
        if key in last and psnr(r) < last[key]:
            falls += " %s at depth %s" % (key, r["max_depth"])
        last[key] = psnr(r)
    return {"all_sim_equal": "yes" if all(r["image_equals_render"] == "true" for r in table.rows) else "no",
            "monotone": "yes" if not falls else "no:" + falls}


def plot_data(table, dat):
    """Writes dat/pI.max_depth.dat and dat/pI.min_weight.dat; returns error-pruning.gp's variables."""
    variables, labelled, i = {}, [], 0
    for scene in scenes(table):
        for runner in runners(table):
            i += 1
            for sweep, setting in (("max_depth", "max_depth"), ("min_weight", "min_weight")):
                write_dat(os.path.join(dat, "p%d.%s.dat" % (i, sweep)),
                          [[r["image_time_s"], r["wall_s"], r["psnr_db"], r[setting]] for r in table.rows
                           if r["scene"] == scene and r["runner"] == runner and r["sweep"] == sweep])
            label = "render, T(1)" if runner == "render" else "sim " + runner[4:]
            variables["title%d" % i] = "%s, %s" % (scene[6:] if scene.startswith("paper-") else scene, label)
            labelled.append("1" if runner == "render" else "0")
    variables.update(nseries=i, labelled=" ".join(labelled))
    return variables
