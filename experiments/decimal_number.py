"""decimal_number - the strict decimal syntax of every torusrt format (src/number.c;
docs/cli.md, "Decimal only"), for the Python tools that take numbers from the command line:
`[-]DIGITS[.DIGITS][e[+-]DIGITS]`, its integer digits without a leading zero, finite as a
double and, when not written as 0, not 0 as a double. `010`, `0x10`, `+5`, `.5`, `inf`, `1_000`
and `1e-400` are refused with the reason, never read as something else."""
import math
import re

_SYNTAX = re.compile(r"-?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?")


def fault(text):
    """Why TEXT is not a number of the strict syntax ("" when it is one)."""
    digits = text[1:] if text.startswith("-") else text
    if re.match(r"0[xX]", digits):
        return "is not decimal (hexadecimal is not accepted)"
    if re.match(r"0[0-9]", digits):
        return "has a leading zero (decimal only: it could be read as octal: write '%s')" % (
            ("-" if text.startswith("-") else "") + (digits.lstrip("0") or "0"))
    if not _SYNTAX.fullmatch(text):
        return "is not a number (decimal, such as 2, -0.5 or 1e-3)"
    value = float(text)
    if not math.isfinite(value):
        return "is too large (not finite as a double)"
    if value == 0 and re.search(r"[1-9]", re.split(r"[eE]", text)[0]):
        return "is too close to 0 for a double (it would read as 0)"
    return ""


def real(text):
    """TEXT as a float, or ValueError("'TEXT' REASON")."""
    why = fault(text)
    if why:
        raise ValueError("'%s' %s" % (text, why))
    return float(text)


def whole(text):
    """TEXT as an int when it is a whole number of the strict syntax (`580`, not `580.0` nor
    `0580`), or ValueError("'TEXT' REASON")."""
    value = real(text)
    if not re.fullmatch(r"-?[0-9]+", text):
        raise ValueError("'%s' is not a whole number" % text)
    return int(value)
