"""The motion study's report (experiments/motion/report.py) on made-up rows: the three targets are
read per case, a missed one names its case and margin, and the update is compared with a rebuild
frame by frame on the busiest processor's units."""
import importlib.util
import os
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Loaded under its own name: "report" is the experiments' report package to the other tests.
_spec = importlib.util.spec_from_file_location("motion_report",
                                               os.path.join(REPO, "experiments", "motion", "report.py"))
report = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(report)


def run(scene, n, policy, total, migration=0.0, motion=1.0):
    return {"scene": scene, "n": str(n), "policy": policy, "total_s": str(total), "image_time_s": str(total - motion),
            "migration_time_s": str(migration), "migration_bytes": "1000", "motion_time_s": str(motion),
            "update_time_s": str(motion), "update_link_time_s": "0", "update_bytes": "100", "update_units": "30",
            "rebuild_units": "100", "mapping_changes": "0", "conserved": "true", "images_identical": "1"}


def frame(scene, k, update, rebuild, policy="adaptive", guess="objects"):
    return {"scene": scene, "n": "64", "policy": policy, "frame": str(k), "update_units_slowest": str(update),
            "rebuild_units_slowest": str(rebuild), "decision": "remap" if k else "first", "guess": guess}


def table(adaptive, every, oracle, static):
    rows = [run("s", 64, "adaptive", adaptive), run("s", 64, "every-frame", every), run("s", 64, "oracle", oracle),
            run("s", 64, "static", static), run("s", 64, "cyclic", 200.0)]
    return report.by_case(rows)


class Motion(unittest.TestCase):
    def test_targets_are_read_per_case(self):
        self.assertEqual(report.verdicts(table(100.0, 99.5, 95.0, 120.0))[("s", 64)], (True, True, True))
        # 1.5 % over every-frame and 20 % over oracle; longer than static.
        self.assertEqual(report.verdicts(table(120.0, 118.2, 100.0, 110.0))[("s", 64)], (False, False, False))

    def test_a_miss_names_its_case_and_margin(self):
        t = table(120.0, 118.2, 100.0, 110.0)
        text = report.target_line(t, report.verdicts(t))[0]
        self.assertIn("**not met**", text)
        self.assertIn("s at 64 nodes +9.1 % against static", text)
        self.assertIn("s at 64 nodes +20.0 % against oracle", text)

    def test_update_against_rebuild_frame_by_frame(self):
        frames = [frame("s", 0, 0, 0), frame("s", 1, 20, 100), frame("s", 2, 100, 100), frame("s", 3, 120, 100)]
        n, slower, lo, hi = report.update_against_rebuild(frames)["s"]
        self.assertEqual((n, slower), (3, 1))  # frame 0 is the first build, not an update
        self.assertAlmostEqual(lo, 0.2)
        self.assertAlmostEqual(hi, 1.2)

    def test_findings_count_the_guesses_and_the_checks(self):
        t = table(100.0, 99.5, 95.0, 120.0)
        frames = [frame("s", 0, 0, 0), frame("s", 1, 20, 100), frame("s", 2, 30, 100, guess="trend"),
                  frame("s", 3, 30, 100)]
        text = "\n".join(report.findings(t, frames, (True, False)))
        self.assertIn("objects 2, trend 1", text)
        self.assertIn("no slower on every frame of both scenes: **yes**", text)
        self.assertIn("packets conserved in every run: **NO**", text)


if __name__ == "__main__":
    unittest.main()
