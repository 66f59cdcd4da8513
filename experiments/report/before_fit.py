"""The findings a study page had under the reading before the fit (docs/readings.md): its writer's
findings from that reading's runs, kept beside the study's results as `before-fit.md`, and shown
after the page's own findings so that the two readings stand side by side."""
import os

HEADING = "## Under the reading before the fits"


def section(results_dir):
    """The page section from RESULTS_DIR/before-fit.md, or [] when the study has none. Pictures
    are left out: they are the fitted reading's now."""
    path = os.path.join(results_dir, "before-fit.md")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        body = [line.rstrip("\n") for line in f if not line.startswith("![")]
    while body and not body[0].strip():
        body.pop(0)
    while body and not body[-1].strip():
        body.pop()
    rel = os.path.relpath(path, os.path.join(os.path.dirname(__file__), "..", ".."))
    return [HEADING, "",
            "The same study under the reading before the fits: timing profile `calibrated` (bus cycle and",
            "memory access 0.5 us, nothing charged per cell step), image 1 with its nine flakes in the",
            "plane z = 0 (`scenes/paper-image1-planar.nff`), image 2 `scenes/paper-image2-floor.nff`, and",
            "every tie on an even ring sent the + way (`--route-ties plus`). Its findings, as this page's",
            "writer made them from that reading's runs (`%s`):" % rel, ""] + body + [""]
