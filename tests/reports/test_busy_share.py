"""The share of busy processors over time from a VCD trace (experiments/report/busy_share.py), on a
hand-written trace: two processors' busy wires under scopes ip_0 and ip_1, a queue depth beside
them that must not count, and a wire of another scope that must not either."""
import os
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))
from report.busy_share import busy_share  # noqa: E402

# 1 ns units, image time 40 ns. ip_0 is busy 0-10 and 20-40 ns, ip_1 15-25 ns; link_x's wire
# is not a processor's.
TRACE = """$timescale
     1 ns
$end
$scope module SystemC $end
$scope module top $end
$scope module ip_0 $end
$var wire    1  a  busy       $end
$var wire   32  b  queue_depth [31:0]  $end
$upscope $end
$scope module ip_1 $end
$var wire    1  c  busy       $end
$upscope $end
$scope module link_x $end
$var wire    1  d  busy       $end
$upscope $end
$upscope $end
$upscope $end
$enddefinitions $end
#0
1a
0c
1d
b101 b
#10
0a
#15
1c
#20
1a
#25
0c
#40
0a
0d
"""


class BusyShare(unittest.TestCase):
    def setUp(self):
        fd, self.path = tempfile.mkstemp(suffix=".vcd")
        with os.fdopen(fd, "w") as f:
            f.write(TRACE)

    def tearDown(self):
        os.remove(self.path)

    def test_four_bins_worked_by_hand(self):
        # Bins of 10 ns: [0,10) ip_0 busy 10 -> 10/20; [10,20) ip_1 5 -> 5/20;
        # [20,30) ip_0 10 + ip_1 5 -> 15/20; [30,40) ip_0 10 -> 10/20.
        got = busy_share(self.path, 4)
        self.assertEqual([round(s, 9) for s, _ in got], [0.0, 1e-8, 2e-8, 3e-8])
        self.assertEqual([share for _, share in got], [0.5, 0.25, 0.75, 0.5])

    def test_one_bin_is_the_mean_busy_share(self):
        # (30 + 10) ns busy over 2 processors x 40 ns.
        self.assertEqual(busy_share(self.path, 1), [(0.0, 0.5)])

    def test_the_bins_end_with_the_last_busy_span(self):
        # A link's use written 20 ns after the image's end does not stretch the bins.
        with open(self.path, "a") as f:
            f.write("#60\n1d\n")
        self.assertEqual([share for _, share in busy_share(self.path, 4)], [0.5, 0.25, 0.75, 0.5])

    def test_a_processor_busy_at_the_end_of_a_window_counts_to_it(self):
        with open(self.path, "w") as f:
            f.write(TRACE.replace("#40\n0a\n", "#40\n"))
        self.assertEqual(busy_share(self.path, 1), [(0.0, 0.5)])

    def test_a_trace_without_processors_is_refused(self):
        with open(self.path, "w") as f:
            f.write("$timescale 1 ps $end\n#0\n#5\n")
        with self.assertRaises(ValueError):
            busy_share(self.path, 2)


if __name__ == "__main__":
    unittest.main()
