"""The likely mistake named with its fix (issue 23): a decimal comma, a Cyrillic look-alike."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.model.mistakes import lookalike_hint, toml_hint

PRESS = Path(__file__).resolve().parent.parent / "examples" / "press.toml"


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = PRESS.read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "v.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    return path


def test_a_decimal_comma_in_a_variant(tmp_path, capsys):
    path = _variant(tmp_path, "length = 80 ", "length = 0,08 ")
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "decimal comma: write 0.08" in err and "line 18" in err


def test_a_cyrillic_letter_in_a_point_name(tmp_path, capsys):
    path = _variant(tmp_path, 'joints = ["O", "A"]', 'joints = ["О", "A"]')  # Cyrillic О
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err
    assert "'О' is a Cyrillic letter: write 'O'" in err


def test_a_decimal_comma_in_a_student_file(tmp_path, capsys):
    student = tmp_path / "s.toml"
    student.write_text('[work]\nvariant = "bundled:press"\n[general]\nfigures = { m2 = 129,5 }\n',
                       encoding="utf-8")
    assert main(["check", str(student)]) == 2
    assert "decimal comma: write 129.5" in capsys.readouterr().err


@pytest.mark.parametrize("line", ['title = "0,5 м" x', "p = [1,5] x", "q = { a = 1,b = 2 } x",
                                  "x = 1 # 0,5\ny = ", "r = [1,5,]] "])
def test_no_hint_where_a_comma_belongs(line):
    """Files with another error on a line whose commas are right: no decimal-comma hint."""
    with pytest.raises(tomllib.TOMLDecodeError) as exc:
        tomllib.loads(line)
    assert toml_hint(line, str(exc.value)) == ""


@pytest.mark.parametrize("line, fix", [("l = 0,08", "0.08"), ("m = { m2 = 129,5 }", "129.5"),
                                       ("k = -3,5 # note", "-3.5")])
def test_the_hint_where_a_comma_is_a_decimal_one(line, fix):
    with pytest.raises(tomllib.TOMLDecodeError) as exc:
        tomllib.loads(line)
    assert f"write {fix} with a point" in toml_hint(line, str(exc.value))


def test_the_latin_spelling_of_look_alikes():
    assert lookalike_hint("O3") == ""
    assert "write 'OA' in Latin" in lookalike_hint("ОА")
    assert "are Cyrillic letters" in lookalike_hint("ОА")
