"""The fidelity study's fits (experiments/report/fidelity.py): scores, choices, ties, and the
machine files it writes."""
import argparse
import io
import json
import os
import sys
import tempfile
import unittest
from contextlib import redirect_stdout

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import fidelity  # noqa: E402


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f)


class ClaimRoles(unittest.TestCase):
    def test_three_counts_split_fit_targets_from_validation(self):
        from report.verdict import FAILS, HOLDS
        verdicts = [FAILS] * 17
        for i in (4, 7, 8, 9, 16):
            verdicts[i - 1] = HOLDS
        (a, n), (f, nf), (v, nv) = fidelity.counts(verdicts)
        self.assertEqual((a, n), (5, 17))
        self.assertEqual((f, nf), (3, 5), "7, 8, 9 of the fit targets 7, 8, 9, 10, 11")
        self.assertEqual((v, nv), (2, 12), "4 and 16 of the twelve validation claims")
        text = fidelity.counts_text(verdicts)
        self.assertIn("5 of 17 claims hold: 3 of the 5 fit targets", text)
        self.assertIn("2 of the 12 validation claims", text)

    def test_roles(self):
        self.assertEqual(fidelity.role(9), "fit target")
        self.assertIn("derived", fidelity.role(10))
        self.assertEqual(fidelity.role(1), "validation")
        self.assertIn("any space partition", fidelity.role(16))


class Fits(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.res = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def chosen(self, fn):
        out = io.StringIO()
        with redirect_stdout(out):
            fn(argparse.Namespace(results=self.res))
        return out.getvalue().split()

    def stage1(self, units):
        with open(os.path.join(self.res, "stage1.tsv"), "w") as f:
            for (layout, rule), (u1, u16, u32) in units.items():
                path = os.path.join(self.res, "%s-%s.json" % (layout, rule))
                write_json(path, {"preprocess": {"units_parallel_by_p": {"1": u1, "16": u16, "32": u32}}})
                f.write("%s\t%s\t%s\n" % (layout, rule, path))

    def test_units_fit_takes_the_smallest_largest_residual(self):
        self.stage1({("planar", "sequential"): (17552, 1291, 780),   # +86 %
                     ("cube", "per-plane"): (9438, 738, 600),         # +39 % at 32
                     ("tree", "per-plane"): (10000, 800, 470)})       # +8.8 % at 32
        self.assertEqual(self.chosen(fidelity.fit1), ["tree", "per-plane"])
        best = {tuple(c.values()): s for c, s, _ in fidelity.stage1(self.res)}
        self.assertAlmostEqual(best[("tree", "per-plane")], 470 / 432 - 1)

    def test_ties_go_to_today(self):
        self.stage1({("cube", "per-plane"): (9438, 738, 432), ("planar", "sequential"): (9438, 738, 432)})
        self.assertEqual(self.chosen(fidelity.fit1), ["planar", "sequential"])

    def test_penalty_fit(self):
        rows = []
        for bus, t in (("0.5", {"image1": 1.00, "image2": 1.00}), ("2", {"image1": 1.20, "image2": 1.26}),
                       ("4", {"image1": 1.50, "image2": 1.60})):
            for img in ("image1", "image2"):
                for data, v in (("replicated", 1.0), ("shared", t[img])):
                    path = os.path.join(self.res, "%s-%s-%s.json" % (bus, img, data))
                    write_json(path, {"sim_time_s": v})
                    rows.append("%s\t1\t%s\t%s\t%s" % (bus, img, data, path))
        with open(os.path.join(self.res, "stage2.tsv"), "w") as f:
            f.write("\n".join(rows) + "\n")
        self.assertEqual(self.chosen(fidelity.fit2), ["2", "1"])

    def test_machine_files_name_their_timing_beside_them(self):
        out = os.path.join(self.res, "machines")
        fidelity.machines(argparse.Namespace(results=self.res, out=out, rule="per-plane", bus="2", memory="1",
                                             shape="4x4", map="block-cyclic:2", handover="580"))
        with open(os.path.join(out, "paper-1024-shared.toml")) as f:
            text = f.read()
        for line in ('ips="4x4"', 'map="block-cyclic:2"', 'preprocess-count="per-plane"', 'cluster="64"',
                     'data="shared"', 'timing="timing/fitted.timing"'):
            self.assertIn(line + "\n", text)
        with open(os.path.join(out, "timing", "fitted.timing")) as f:
            keys = dict(line.split() for line in f if line.strip() and not line.startswith("#"))
        self.assertEqual((keys["bus_cycle"], keys["memory_access"]), ("2", "1"))
        self.assertEqual((keys["handover_send"], keys["handover_receive"]), ("0", "580"))
        self.assertEqual(keys["shading"], "4600")  # the rest is the calibrated profile's


if __name__ == "__main__":
    unittest.main()
