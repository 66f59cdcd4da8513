"""The claim functions of experiments/report on the checked-in CSVs of the reproduction sweep,
and on copies with one row changed, so that each verdict is seen to follow its rule."""
import copy
import os
import sys
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import claims, verdict as v  # noqa: E402
from report.results import Results  # noqa: E402

RESULTS = os.path.join(REPO, "experiments", "results")


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


class ClaimsOnCheckedInData(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.r = Results(RESULTS)

    def test_verdicts_of_the_checked_in_sweep(self):
        # The verdicts of docs/reproduction.md, claim by claim.
        expected = [v.HOLDS, v.HOLDS, v.HOLDS, v.HOLDS, v.HOLDS, v.DIRECTION, v.FAILS, v.HOLDS, v.FAILS,
                    v.FAILS, v.FAILS, v.ONE_IMAGE, v.HOLDS, v.HOLDS, v.FAILS, v.HOLDS, v.DIRECTION]
        self.assertEqual([c.verdict for c in claims.evaluate(self.r)], expected)

    def test_efficiency_floor_flips_when_one_point_drops_below_85(self):
        r = edited(self.r, "f56", "efficiency_busy", 0.84, scene="image1", mapping="cyclic", n=8)
        c = claims.load_balancing_floor(r)
        self.assertEqual(c.verdict, v.ONE_IMAGE)
        self.assertIn("Image 1: lowest 84.0 % (n = 8)", c.ours)
        r = edited(r, "f56", "efficiency_busy", 0.80, scene="image2", mapping="cyclic", n=4)
        self.assertEqual(claims.load_balancing_floor(r).verdict, v.FAILS)

    def test_falls_beyond_16_needs_ten_points(self):
        r = self.r
        for s in ("image1", "image2"):
            e16 = r.f56.value("efficiency_busy", scene=s, mapping="cyclic", n=16)
            r = edited(r, "f56", "efficiency_busy", e16 - 0.05, scene=s, mapping="cyclic", n=64)
        self.assertEqual(claims.falls_beyond_16(r).verdict, v.FAILS)

    def test_mapping_gain_needs_one_scene_above_2x(self):
        r = self.r
        for n in (2, 4, 8, 16, 32, 64, 128, 256, 512):
            b = r.f56.value("efficiency_busy", scene="image2", mapping="block", n=n)
            r = edited(r, "f56", "efficiency_busy", b, scene="image2", mapping="cyclic", n=n)
        # Image 1 stays at 1.97x: below 2x, so no scene passes.
        self.assertEqual(claims.mapping_gain(r).verdict, v.FAILS)

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
        self.assertEqual(claims.replicated_times(r).verdict, v.ONE_IMAGE)
        self.assertIn("0.70 s / 2.05 s", claims.replicated_times(r).ours)

    def test_sharing_cost_in_range_holds(self):
        r = self.r
        for s in ("image1", "image2"):
            t = r.f10.value("sim_time_s", scene=s, data="replicated", m=64)
            r = edited(r, "f10", "sim_time_s", 1.2 * t, scene=s, data="shared", m=64)
        self.assertEqual(claims.sharing_cost(r).verdict, v.HOLDS)

    def test_replicated_efficiency_and_speedup(self):
        r = edited(self.r, "f10", "efficiency_busy", 0.81, scene="image2", data="replicated", m=64)
        self.assertEqual(claims.replicated_efficiency(r).verdict, v.HOLDS)
        r = edited(self.r, "f10", "sim_time_s", 3.0, scene="image1", data="replicated", m=64)
        self.assertEqual(claims.replicated_speedup(r).verdict, v.ONE_IMAGE)

    def test_shared_efficiency_lowest_up_to_12(self):
        r = edited(self.r, "f10", "efficiency_busy", 0.79, scene="image1", data="shared", m=4)
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
