"""The named number formats of :mod:`graphplan.numbers`, each by hand-checked examples, and
the rule that they are the package's only ones."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import pytest

from graphplan import numbers as n

ROOT = Path(__file__).resolve().parent.parent / "graphplan"


def test_fmt_is_a_students_number():
    assert n.fmt(0.0) == "0"
    assert n.fmt(0.46083333) == "0.460833"  # 6 significant digits, no trailing zeros
    assert n.fmt(1.5, 4) == "1.5"
    assert n.fmt(1.234e-5, 3) == "1.23·10^-5"  # "g" switches to an exponent below 1e-4


def test_plain_never_has_an_exponent():
    assert n.plain(1.234e-5, 4) == "0.00001234"
    assert n.plain(364219.7, 5) == "364220"  # 5 significant: 3.6422e+05
    assert n.plain(0.5, sign=True) == "+0.5" and n.plain(-0.5, sign=True) == "-0.5"
    assert n.plain(math.inf) == "inf"


def test_the_decimal_comma_of_sheets_and_of_the_note():
    assert n.decimal_comma("Kφ = 0.0218; 1:2.5") == "Kφ = 0,0218; 1:2,5"
    assert n.sheet_text("0.5", "ru") == "0,5" and n.sheet_text("0.5", "en") == "0.5"
    # the note leaves a number that follows a letter, a digit or a point alone
    assert n.note_comma("h = 0.021817, ТММ.01.5, A1.5", "ru") == "h = 0,021817, ТММ.01.5, A1.5"
    assert n.decimal_comma("ТММ.01.5, A1.5") == "ТММ.01,5, A1,5"  # a sheet's rule: all
    assert n.note_comma("0.5", "en") == "0.5"


def test_fixed_has_no_negative_zero():
    assert n.fixed(12.3) == "12.30"
    assert n.fixed(-0.001) == "0.00"  # rounds to −0.00
    assert n.fixed(-0.4, 0) == "0"
    assert n.fixed(-0.00004, 4) == "0.0000"
    assert n.fixed(-1.25, 1) == "-1.2"  # round half to even, as Python's format


def test_figures_keep_trailing_zeros():
    assert n.figures(0.46) == "0.4600"
    assert n.figures(1234.5) == "1234"  # 4 significant
    assert n.figures(0.0) == "0" and n.figures(-0.00001) == "-0.00001"  # outside 1e-3: plain


def test_a_summary_cell_fits_nine_characters():
    assert n.cell(0.0) == "0"
    assert n.cell(0.012345) == "0.01235"
    assert n.cell(123456.0) == "123456"  # 4 significant would need an exponent: whole
    assert n.cell(1234567890.0) == "1.2e+09"  # 10 characters whole: the short exponent
    assert all(len(n.cell(x)) <= 9 for x in (1e-12, -1e-12, 9.87654e20, -123456789.0))


def test_report_numbers_in_english_and_russian():
    assert n.report(4456.123) == "4456.1"
    assert n.report(4456.123, "ru") == "4456,1"
    assert n.report(None) == "—"
    assert n.report(-0.000001, digits=2) == "-1.0e-06"  # below 1e-4: an exponent
    assert n.report(-0.00001) == "-1.0000e-05"  # 10⁻⁵ < 10⁻⁴: 5 significant, exponent
    assert n.report(0.0001234) == "0.0001234"  # 10⁻⁴: still written out
    with pytest.raises(ValueError):
        n.report(math.nan)


def test_written_as_a_student_writes_an_answer():
    assert n.written(4456.123) == "4456,1"
    assert n.written(12.3, decimals=2) == "12,30"
    assert n.written(-0.001, decimals=2) == "0,00"
    assert n.written(1e-6) == "0,000001"  # never an exponent


def test_rough_accuracy_and_general():
    assert (n.rough(11.4), n.rough(1.34), n.rough(0.523), n.rough(math.inf)) == (
        "11", "1.3", "0.52", "∞")
    assert n.general(1e-7) == "1e-07" and n.general(1 / 3) == "0.333333"


def test_csv_and_file_lengths():
    assert n.csv_number(-0.0, "t") == "0.0" and n.csv_number(None, "t") == ""
    assert n.csv_number(0.1 + 0.2, "t") == "0.30000000000000004"
    with pytest.raises(ValueError, match="reached t"):
        n.csv_number(math.inf, "t")
    assert n.trimmed(12.304) == "12.3" and n.trimmed(-0.004) == "0" and n.trimmed(3.0) == "3"
    assert n.trimmed(2.4999, 3) == "2.5"


def test_no_module_but_numbers_strips_trailing_zeros():
    """A new number format goes to graphplan/numbers.py, not into the module that needs it:
    a function anywhere else that strips a formatted number's trailing zeros is a second
    formatter."""
    found = []
    for path in ROOT.rglob("*.py"):
        if path.name == "numbers.py" and path.parent == ROOT:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "rstrip" and node.args
                    and isinstance(node.args[0], ast.Constant) and node.args[0].value == "0"):
                found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    assert found == []
