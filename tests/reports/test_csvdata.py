"""The CSV reader of experiments/report (csvdata.Table.load): a row whose field count is not the
header's, a quote left open and a NUL byte are refused, naming the file and the line."""
import os
import shutil
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report.csvdata import Table  # noqa: E402


class CsvRows(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.path = os.path.join(self.dir, "fig7.csv")

    def tearDown(self):
        shutil.rmtree(self.dir)

    def load(self, text):
        with open(self.path, "w") as f:
            f.write(text)
        return Table.load(self.path)

    def test_a_full_table_reads(self):
        table = self.load("scene,n,status,sim_time_s\na,1,ok,1\nb,2,ok,\n")
        self.assertEqual(table.rows[1], {"scene": "b", "n": "2", "status": "ok", "sim_time_s": ""})

    def test_a_short_row_is_refused_naming_the_file_and_the_line(self):
        for text, line, fields in (("scene,n,status,sim_time_s\na,1,ok,1\na\n", 3, 1),
                                   ("scene,n,status,sim_time_s\nimage1,1,ok\n", 2, 3)):
            with self.assertRaisesRegex(ValueError, "^%s: line %d: %d fields, the header has 4$"
                                        % (self.path, line, fields)):
                self.load(text)

    def test_a_long_row_is_refused(self):
        with self.assertRaisesRegex(ValueError, "line 2: 5 fields, the header has 4"):
            self.load("scene,n,status,sim_time_s\na,1,ok,1,9\n")

    def test_an_open_quote_or_a_nul_byte_is_refused(self):
        with self.assertRaisesRegex(ValueError, "^%s: line 3: .*a quote left open" % self.path):
            self.load('scene,n,status,sim_time_s\na,1,ok,1\nb,2,ok,"2\nc,3,ok,3\n')
        with self.assertRaisesRegex(ValueError, "^%s: line 2: a NUL byte" % self.path):
            self.load("scene,n,status,sim_time_s\na,1,ok,2\0\n")
        self.assertEqual(self.load('scene,n,status,sim_time_s\na,1,ok,"2"\n').rows[0]["sim_time_s"], "2")


if __name__ == "__main__":
    unittest.main()
