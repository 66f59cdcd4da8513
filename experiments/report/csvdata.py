"""CSV tables read by column name."""
import csv
import io

from output_files import read_text, shown


class Table:
    """The rows of one CSV file, as dicts keyed by the header's column names."""

    def __init__(self, rows, columns, path=""):
        self.rows = rows
        self.columns = columns
        self.path = path

    @classmethod
    def load(cls, path):
        """The table of the CSV file PATH; OSError or ValueError naming PATH when it is not a
        regular file or not UTF-8 text, and ValueError naming PATH and the line when the header
        names a column twice, a row has more or fewer fields than the header, a quote is left
        open or a NUL byte is there."""
        text = read_text(path, "CSV")
        if "\0" in text:  # binary data, not a table: a value would hold the NUL unseen
            raise ValueError("%s: line %d: a NUL byte (binary data, not a CSV table)"
                             % (shown(path), text.count("\n", 0, text.index("\0")) + 1))
        # strict: a quote left open would swallow the lines after it into one value
        reader = csv.DictReader(io.StringIO(text, newline=""), strict=True)
        read = [0]  # the lines read by the last whole row
        try:
            return cls._rows(reader, path, read)
        except csv.Error as e:
            raise ValueError("%s: line %d: %s (a quote left open?)" % (shown(path), read[0] + 1, e)) from None

    @classmethod
    def _rows(cls, reader, path, read):
        columns = list(reader.fieldnames or [])
        read[0] = reader.line_num
        for i, name in enumerate(columns):  # the last of two would silently win
            if name in columns[:i]:
                raise ValueError("%s: line 1: the column '%s' is named twice" % (shown(path), shown(name)))
        rows = []
        for row in reader:
            if None in row:  # more fields than the header: the extra ones would be dropped unseen
                raise ValueError("%s: line %d: %d fields, the header has %d"
                                 % (shown(path), reader.line_num, len(columns) + len(row[None]), len(columns)))
            if any(value is None for value in row.values()):  # fewer fields (a cut file): None, not text
                given = sum(value is not None for value in row.values())
                raise ValueError("%s: line %d: %d fields, the header has %d"
                                 % (shown(path), reader.line_num, given, len(columns)))
            rows.append(row)
            read[0] = reader.line_num
        return cls(rows, columns, path)

    def where(self, ok_only=True, **match):
        """Rows whose columns equal the given values (compared as text); only status ok rows
        unless ok_only is False."""
        out = []
        for row in self.rows:
            if ok_only and row.get("status") != "ok":
                continue
            if all(row.get(k) == str(v) for k, v in match.items()):
                out.append(row)
        return out

    def text(self, column, **match):
        """The column of the first ok row matching, as text; None if no row or empty."""
        rows = self.where(**match)
        if not rows or rows[0].get(column, "") == "":
            return None
        return rows[0][column]

    def value(self, column, **match):
        """The column of the first ok row matching, as a float; None if no row or empty."""
        t = self.text(column, **match)
        return None if t is None else float(t)

    def distinct(self, column):
        """The column's values in sorted order (every row, whatever its status)."""
        return sorted({row[column] for row in self.rows})


def num(row, column):
    """A row's column as a float, None if empty."""
    t = row.get(column, "")
    return None if t == "" else float(t)
