"""The animation report's finer-orbit section (experiments/report/animation.py density_section):
each case's gap to oracle at each frame count, the count within 10 %, and whether the gap shrinks,
judged over the cases present at both frame counts."""
import os
import sys
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import animation  # noqa: E402


def run(scene, n, policy, total, frames=None, changes=3):
    r = {"scene": scene, "n": str(n), "policy": policy, "total_s": str(total), "mapping_changes": str(changes),
         "conserved": "true", "images_identical": "1"}
    if frames is not None:
        r["frames"] = str(frames)
    return r


class DensitySection(unittest.TestCase):
    keys = [("paper-image1", 512), ("paper-image1", 64)]
    runs = [run("paper-image1", 512, "adaptive", 12.0), run("paper-image1", 512, "oracle", 10.0),
            run("paper-image1", 64, "adaptive", 11.0), run("paper-image1", 64, "oracle", 10.0)]

    def test_gaps_and_verdict(self):
        dense = [run("paper-image1", 512, "adaptive", 42.0, 128), run("paper-image1", 512, "oracle", 40.0, 128)]
        text = "\n".join(animation.density_section(self.runs, dense, self.keys, 32))
        self.assertIn("| paper-image1, 512 | 32 | 11.25 | 12.000 | 10.000 | +20.0 % | 3 |", text)
        self.assertIn("| paper-image1, 512 | 128 | 2.8125 | 42.000 | 40.000 | +5.0 % | 3 |", text)
        self.assertIn("within 10 % in 1 of 2 cases", text)  # 32 frames: +20 % and +10 %
        self.assertIn("within 10 % in 1 of 1 cases", text)
        # Only the 512-node case has both counts: +20 % against +5 %, not the 32-frame mean of +15 %.
        self.assertIn("Mean gap over the same 1 cases +20.0 % at 32 frames, +5.0 % at 128", text)
        self.assertIn("it shrinks", text)
        self.assertIn("byte for byte: **yes**", text)

    def test_a_wider_gap_is_said(self):
        dense = [run("paper-image1", 512, "adaptive", 50.0, 128), run("paper-image1", 512, "oracle", 40.0, 128)]
        dense[0]["images_identical"] = "0"
        text = "\n".join(animation.density_section(self.runs, dense, self.keys, 32))
        self.assertIn("does not narrow the gap", text)
        self.assertIn("byte for byte: **NO**", text)

    def test_no_finer_orbit_no_section(self):
        self.assertEqual(animation.density_section(self.runs, [], self.keys, 32), [])


if __name__ == "__main__":
    unittest.main()
