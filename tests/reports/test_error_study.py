"""The error-against-run-time report (experiments/report quantum.py, pruning.py) on the checked-in
CSVs of the study, and on copies with one row changed, so that each rule is seen to act."""
import copy
import os
import sys
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import pruning, quantum  # noqa: E402
from report.csvdata import Table  # noqa: E402

RESULTS = os.path.join(REPO, "experiments", "error_vs_runtime", "results")


def rows(table, **match):
    return [r for r in table.rows if all(r[k] == v for k, v in match.items())]


class QuantumStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.t = Table.load(os.path.join(RESULTS, "quantum.csv"))

    def edited(self, column, value, **match):
        t = copy.deepcopy(self.t)
        hits = rows(t, **match)
        self.assertTrue(hits, match)
        for r in hits:
            r[column] = str(value)
        return t

    def test_every_configuration_has_one_at_row_and_lt_rows(self):
        for config in quantum.configs(self.t):
            styles = [r["style"] for r in self.t.rows if (r["scene"], r["ips"]) == config]
            self.assertEqual(styles.count("at"), 1, config)
            self.assertGreater(styles.count("lt"), 1, config)

    def test_recommendation_is_within_the_bound_and_so_is_every_smaller_quantum(self):
        for bound in (1, 5):
            for key, best in quantum.recommend(self.t, bound).items():
                for r in quantum.lt_rows(self.t):
                    if "%s, %s" % (r["scene"], r["ips"]) == key and float(r["quantum_s"]) <= best["quantum_s"]:
                        self.assertLessEqual(abs(float(r["err_time_pct"])), bound, (key, r["quantum"]))
                        self.assertLessEqual(abs(float(r["err_eff_pct"])), bound, (key, r["quantum"]))

    def test_one_bad_small_quantum_caps_the_recommendation(self):
        t = self.edited("err_eff_pct", -2.5, scene="paper-image1", ips="4x2x2", style="lt", quantum="1ms")
        one, five = quantum.recommend(t, 1), quantum.recommend(t, 5)
        self.assertEqual(one["paper-image1, 4x2x2"]["quantum"], "100us")
        self.assertEqual(five["paper-image1, 4x2x2"], quantum.recommend(self.t, 5)["paper-image1, 4x2x2"])
        self.assertEqual(quantum.overall(t, 1), "100us")

    def test_error_at_quantum_zero_is_reported(self):
        self.assertEqual(quantum.findings(self.t)["q0_zero"], "yes")
        t = self.edited("err_time_pct", -0.5, scene="paper-image2", ips="4x4x4", style="lt", quantum="0")
        self.assertEqual(quantum.findings(t)["q0_zero"], "no")
        self.assertIn("paper-image2 4x4x4: 0, ", quantum.findings(t)["negatives"])

    def test_an_image_difference_is_reported(self):
        t = self.edited("image_equal", "false", scene="paper-image1", ips="4x4x4", style="lt", quantum="1s")
        self.assertEqual(quantum.findings(t)["all_equal"], "no")
        self.assertIn("**NO**", quantum.tables(t))

    def test_signed_error_precision(self):
        self.assertEqual(quantum.signed_error(0), "0")
        self.assertEqual(quantum.signed_error(26.27), "+26.27")
        self.assertEqual(quantum.signed_error(-0.00891), "-0.0089")
        self.assertEqual(quantum.signed_error(-3.97e-05), "-4.0e-05")


class PruningStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.t = Table.load(os.path.join(RESULTS, "pruning.csv"))

    def test_psnr_never_falls_with_depth_until_a_row_is_changed(self):
        self.assertEqual(pruning.findings(self.t)["monotone"], "yes")
        t = copy.deepcopy(self.t)
        for r in rows(t, scene="paper-image2", sweep="max_depth", max_depth="5"):
            r["psnr_db"] = "1"
        self.assertTrue(pruning.findings(t)["monotone"].startswith("no: paper-image2 "))

    def test_a_scene_without_secondary_rays_is_said_to_be_unchanged(self):
        t = copy.deepcopy(self.t)
        for r in rows(t, scene="paper-image2"):
            r["psnr_db"], r["packets"] = "inf", "1000"
        self.assertIn("**paper-image2**: pruning changes nothing", pruning.facts(t))
        self.assertNotIn("**paper-image2**: pruning changes nothing", pruning.facts(self.t))

    def test_first_depth_reaching_40_db(self):
        t = copy.deepcopy(self.t)
        runner = next(r for r in pruning.runners(t) if r.startswith("sim-"))
        for r in rows(t, scene="paper-image2", sweep="max_depth", runner=runner):
            if r["psnr_db"] != "inf":
                r["psnr_db"] = "39.9"
        r = rows(t, scene="paper-image2", sweep="max_depth", runner=runner, max_depth="3")[0]
        r["psnr_db"] = "40"
        self.assertIn("PSNR reaches 40 dB at max-depth 3", pruning.depth_fact(t, "paper-image2", runner))


if __name__ == "__main__":
    unittest.main()
