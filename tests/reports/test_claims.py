"""The claim functions of experiments/report on the checked-in CSVs of the reproduction sweep
(one folder per timing profile), and on copies with rows changed, so that each verdict is seen
to follow its rule."""
import copy
import os
import sys
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import claims, verdict as v  # noqa: E402
from report.results import PROFILES, Results, profile_results  # noqa: E402

RESULTS = os.path.join(REPO, "experiments", "results")
FLAT_NS = (1, 2, 4, 8, 16, 32, 64, 128, 256, 512)
# The verdicts of docs/reproduction.md, claim by claim.
EXPECTED_CALIBRATED = [v.FAILS, v.HOLDS, v.HOLDS, v.HOLDS, v.HOLDS, v.DIRECTION, v.FAILS, v.HOLDS, v.ONE_IMAGE,
                       v.FAILS, v.DIRECTION, v.FAILS, v.FAILS, v.FAILS, v.FAILS, v.HOLDS, v.DIRECTION]
EXPECTED_LITERAL = [v.FAILS, v.FAILS, v.HOLDS, v.HOLDS, v.HOLDS, v.DIRECTION, v.FAILS, v.HOLDS, v.FAILS,
                    v.FAILS, v.DIRECTION, v.FAILS, v.HOLDS, v.FAILS, v.FAILS, v.HOLDS, v.DIRECTION]


def edited_all(results, table, column, value, keys, **match):
    """edited() for every combination of the keys' values: {column: values}."""
    (k1, v1), (k2, v2) = keys.items()
    for a in v1:
        for b in v2:
            results = edited(results, table, column, value, **{k1: a, k2: b}, **match)
    return results


def edited(results, table, column, value, **match):
    """A deep copy of the results with `column` set to `value` in the rows matching."""
    out = copy.deepcopy(results)
    rows = getattr(out, table).where(ok_only=False, **match)
    assert rows, "no row matches %r" % match
    for row in rows:
        row[column] = str(value)
    return out


class VerdictRule(unittest.TestCase):
    def test_ladder(self):
        self.assertEqual(v.verdict(0, 0), v.NOT_RUN)
        self.assertEqual(v.verdict(2, 2), v.HOLDS)
        self.assertEqual(v.verdict(1, 2), v.ONE_IMAGE)
        self.assertEqual(v.verdict(0, 2), v.FAILS)
        self.assertEqual(v.verdict(1, 2, need_all=False), v.HOLDS)
        self.assertEqual(v.verdict(0, 2, failing=v.DIRECTION), v.DIRECTION)

    def test_summary(self):
        self.assertEqual(v.summary([v.HOLDS, v.FAILS, v.HOLDS]), "3 claims: 2 hold, 1 do not hold.")


class Profiles(unittest.TestCase):
    def test_one_folder_per_profile_default_first(self):
        self.assertEqual([r.profile for r in profile_results(RESULTS)], list(PROFILES))
        self.assertEqual(PROFILES[0], "calibrated")

    def test_profiles_differ_only_in_the_hand_over(self):
        cal, lit = profile_results(RESULTS)
        for row in cal.f56.where():
            self.assertEqual(row["timing_profile"], "calibrated")
            other = lit.f56.where(scene=row["scene"], mapping=row["mapping"], n=row["n"])[0]
            self.assertEqual(other["timing_profile"], "literal")
            # One IP hands nothing over: the same T(1); more IPs: the literal hand-over costs time.
            self.assertEqual(row["t1_s"], other["t1_s"])
            if int(row["n"]) == 1:
                self.assertEqual(row["sim_time_s"], other["sim_time_s"])
            else:
                self.assertLess(float(row["sim_time_s"]), float(other["sim_time_s"]))


class ClaimsOnCheckedInData(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.r = Results(os.path.join(RESULTS, "calibrated"))
        cls.literal = Results(os.path.join(RESULTS, "literal"))

    def test_verdicts_of_the_checked_in_sweep(self):
        # The verdicts of docs/reproduction.md, claim by claim, under each profile.
        self.assertEqual([c.verdict for c in claims.evaluate(self.r)], EXPECTED_CALIBRATED)
        self.assertEqual([c.verdict for c in claims.evaluate(self.literal)], EXPECTED_LITERAL)

    def test_efficiency_floor_flips_when_one_point_drops_below_85(self):
        r = edited_all(self.r, "f56", "efficiency", 0.9, {"scene": ("image1", "image2"), "n": (2, 4, 8, 16)},
                       mapping="cyclic")
        self.assertEqual(claims.load_balancing_floor(r).verdict, v.HOLDS)
        # Judged by efficiency T(1) / (n T(n)), not by load balance.
        r = edited(r, "f56", "load_balance", 0.1, mapping="cyclic")
        self.assertEqual(claims.load_balancing_floor(r).verdict, v.HOLDS)
        r = edited(r, "f56", "efficiency", 0.84, scene="image1", mapping="cyclic", n=8)
        c = claims.load_balancing_floor(r)
        self.assertEqual(c.verdict, v.ONE_IMAGE)
        self.assertIn("Image 1: lowest 84.0 % (n = 8)", c.ours)
        r = edited(r, "f56", "efficiency", 0.80, scene="image2", mapping="cyclic", n=4)
        self.assertEqual(claims.load_balancing_floor(r).verdict, v.FAILS)

    def test_falls_beyond_16_needs_ten_points(self):
        r = self.r
        for s in ("image1", "image2"):
            e16 = r.f56.value("efficiency", scene=s, mapping="cyclic", n=16)
            r = edited(r, "f56", "efficiency", e16 - 0.05, scene=s, mapping="cyclic", n=64)
        self.assertEqual(claims.falls_beyond_16(r).verdict, v.FAILS)
        r = edited(r, "f56", "efficiency", 0.01, mapping="cyclic", n=64)
        self.assertEqual(claims.falls_beyond_16(r).verdict, v.HOLDS)

    def test_mapping_gain_needs_one_scene_above_2x(self):
        r = self.r
        for s in ("image1", "image2"):
            for n in FLAT_NS[1:]:
                b = r.f56.value("efficiency", scene=s, mapping="block", n=n)
                r = edited(r, "f56", "efficiency", 1.9 * b, scene=s, mapping="cyclic", n=n)
        self.assertEqual(claims.mapping_gain(r).verdict, v.FAILS)
        b = r.f56.value("efficiency", scene="image2", mapping="block", n=64)
        r = edited(r, "f56", "efficiency", 2.1 * b, scene="image2", mapping="cyclic", n=64)
        c = claims.mapping_gain(r)
        self.assertEqual(c.verdict, v.HOLDS)
        self.assertIn("Image 2: up to 2.10x (n = 64)", c.ours)

    def test_memory_above_pixel_partitioned_fails(self):
        r = edited(self.r, "f7", "ratio_to_pixel_partitioned", 1.2, scene="image1", mapping="block", n=4)
        c = claims.memory_below_pixel_partitioned(r)
        self.assertEqual(c.verdict, v.FAILS)
        self.assertEqual(c.ours, "35 of 36 points (block and cyclic, n > 1) below")

    def test_cyclic_below_block_is_mostly(self):
        r = edited(self.r, "f7", "total_bytes", 1, scene="image2", mapping="cyclic", n=32)
        self.assertEqual(claims.cyclic_stores_more(r).verdict, v.MOSTLY)

    def test_memory_ratio_in_range_holds(self):
        r = self.r
        for s in ("image1", "image2"):
            for m in ("block", "cyclic"):
                r = edited(r, "f7", "pixel_partitioned_over_total", 6.5, scene=s, mapping=m, n=16)
        self.assertEqual(claims.memory_ratio_at_16(r).verdict, v.HOLDS)
        r = edited(r, "f7", "pixel_partitioned_over_total", 0.9, scene="image1", mapping="block", n=16)
        self.assertEqual(claims.memory_ratio_at_16(r).verdict, v.FAILS)

    def test_preprocessing_units_within_20_percent_hold(self):
        r = edited(self.r, "f8", "units_parallel", 9000, scene="image1", n=1)
        r = edited(r, "f8", "units_parallel", 800, scene="image1", n=16)
        self.assertEqual(claims.preprocessing_units(r).verdict, v.HOLDS)
        self.assertEqual(claims.preprocessing_speedup(r).verdict, v.FAILS)  # 9000 / 800 = 11.25x

    def test_cluster_times_within_20_percent(self):
        r = edited(self.r, "f10", "sim_time_s", 0.7, scene="image1", data="replicated", m=64)
        r = edited(r, "f10", "sim_time_s", 3.0, scene="image2", data="replicated", m=64)
        self.assertEqual(claims.replicated_times(r).verdict, v.ONE_IMAGE)
        self.assertIn("0.70 s / 3.00 s", claims.replicated_times(r).ours)

    def test_sharing_cost_in_range_holds(self):
        r = self.r
        for s in ("image1", "image2"):
            t = r.f10.value("sim_time_s", scene=s, data="replicated", m=64)
            r = edited(r, "f10", "sim_time_s", 1.2 * t, scene=s, data="shared", m=64)
        self.assertEqual(claims.sharing_cost(r).verdict, v.HOLDS)

    def test_replicated_efficiency_and_speedup(self):
        r = edited(self.r, "f10", "efficiency", 0.81, data="replicated", m=64)
        self.assertEqual(claims.replicated_efficiency(r).verdict, v.HOLDS)
        r = edited(r, "f10", "efficiency", 0.79, scene="image2", data="replicated", m=64)
        self.assertEqual(claims.replicated_efficiency(r).verdict, v.ONE_IMAGE)
        r = self.r
        for s in ("image1", "image2"):
            a = r.f10.value("sim_time_s", scene=s, data="replicated", m=1)
            r = edited(r, "f10", "sim_time_s", a / (0.9 * 64), scene=s, data="replicated", m=64)
        self.assertEqual(claims.replicated_speedup(r).verdict, v.HOLDS)
        a = r.f10.value("sim_time_s", scene="image1", data="replicated", m=1)
        r = edited(r, "f10", "sim_time_s", a / (0.7 * 64), scene="image1", data="replicated", m=64)
        self.assertEqual(claims.replicated_speedup(r).verdict, v.ONE_IMAGE)

    def test_shared_efficiency_lowest_up_to_12(self):
        r = edited(self.r, "f10", "efficiency", 0.9, data="shared")
        self.assertEqual(claims.shared_efficiency(r).verdict, v.HOLDS)
        r = edited(r, "f10", "efficiency", 0.79, scene="image1", data="shared", m=4)
        c = claims.shared_efficiency(r)
        self.assertEqual(c.verdict, v.ONE_IMAGE)
        self.assertIn("lowest 79.0 % (m = 4)", c.ours)

    def test_shared_memory_statements(self):
        r = self.r
        for s in ("image1", "image2"):
            re = r.f10.value("total_bytes", scene=s, data="replicated", m=12)
            r = edited(r, "f10", "total_bytes", 0.4 * re, scene=s, data="shared", m=12)
        self.assertEqual(claims.shared_memory_half(r).verdict, v.HOLDS)
        r = edited(self.r, "f10", "total_bytes", 10 ** 9, scene="image1", data="shared", m=12)
        self.assertEqual(claims.shared_memory_pixel_partitioned(r).verdict, v.ONE_IMAGE)

    def test_replicated_ratio_direction_only_unless_in_range(self):
        r = self.r
        for s in ("image1", "image2"):
            r = edited(r, "f10", "ratio_to_pixel_partitioned", 1 / 6.5, scene=s, data="replicated", m=12)
        self.assertEqual(claims.replicated_memory_ratio(r).verdict, v.HOLDS)

    def test_failed_points_are_not_counted(self):
        r = edited(self.r, "f56", "status", "failed", mapping="cyclic")
        self.assertEqual(claims.load_balancing_floor(r).verdict, v.NOT_RUN)
        self.assertEqual(claims.falls_beyond_16(r).ours, "n/a")


if __name__ == "__main__":
    unittest.main()
