"""The scaling study's report (experiments/scaling/report.py) on made-up rows: the efficiency's
factors multiply back to it, the memory budget excludes a faster machine that holds too much,
and the findings name the fastest machine within it."""
import importlib.util
import os
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Loaded under its own name: "report" is the experiments' report package to the other tests.
_spec = importlib.util.spec_from_file_location("scaling_report",
                                               os.path.join(REPO, "experiments", "scaling", "report.py"))
report = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(report)


def row(machine, n, time, memory, busy_max, busy_mean, t1=100.0, link=0.1, copies=0, copy_bytes=0):
    return {"scene": "s", "machine": machine, "n": str(n), "nodes": str(n), "m": "1", "sim_time_s": str(time),
            "t1_s": str(t1), "efficiency": str(t1 / (n * time)), "memory_total_bytes": str(memory),
            "memory_max_per_ip_bytes": "1", "busy_max_s": str(busy_max), "busy_mean_s": str(busy_mean),
            "link_util_max": str(link), "copies": str(copies), "copy_bytes": str(copy_bytes),
            "conserved": "true", "image_identical": "1"}


class Scaling(unittest.TestCase):
    def runs(self):
        rows = [row("flat-cyclic", 16, 10.0, 1000, 9.0, 8.0), row("flat-cost", 16, 8.0, 1100, 7.0, 6.5),
                row("flat-cost-r1.0", 16, 7.0, 1200, 6.0, 6.5, copies=3, copy_bytes=100),
                row("m4-replicated-cost", 16, 5.0, 2500, 4.0, 3.0)]  # fastest, but 2.5x cyclic's memory
        return {(r["scene"], r["machine"], int(r["n"])): r for r in rows}

    def test_factors_multiply_to_the_efficiency(self):
        r = self.runs()[("s", "flat-cost", 16)]
        f = report.factors(r)
        self.assertAlmostEqual(f["work"] * f["balance"] * f["tail"], float(r["efficiency"]))
        self.assertAlmostEqual(f["tail"], 7.0 / 8.0)  # the busiest is idle 1 s of 8

    def test_budget_excludes_the_machine_that_holds_too_much(self):
        self.assertEqual(report.best_within_budget(self.runs(), "s", 16)["machine"], "flat-cost-r1.0")

    def test_findings(self):
        text = "\n".join(report.findings(self.runs(), ["s"], [16], (True, True)))
        self.assertIn("n = 16: flat-cost-r1.0 7 s (1.43x flat cyclic", text)
        self.assertIn("up to 1.14x (s, n = 16) for 100 bytes of copies (9.09 % more data)", text)
        self.assertIn("a flat torus at 1 of 1", text)
        self.assertIn("byte for byte: **yes**", text)

    def test_the_worst_factor_is_named(self):
        self.assertIn("load balance", report.limit_text({"work": 0.9, "balance": 0.5, "tail": 0.8, "links": 0.1}))
        text = report.limit_text({"work": 0.9, "balance": 0.95, "tail": 0.6, "links": 0.9})
        self.assertIn("the tail", text)
        self.assertIn("busiest link is 90 % busy", text)


if __name__ == "__main__":
    unittest.main()
