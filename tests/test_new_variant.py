"""graphplan new (issue 23): a variant file from a family, every key explained in Russian,
that loads to the same mechanism as the family's example."""

from __future__ import annotations

import re

import pytest

from graphplan.cli import main
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.model.template import families, family_name

FAMILIES = families()


@pytest.mark.parametrize("family", FAMILIES)
def test_a_new_variant_explains_every_key_and_loads_as_its_family(family, tmp_path, capsys):
    out = tmp_path / f"{family}.toml"
    assert main(["new", family, "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.lstrip().startswith("#") or "=" not in line:
            continue
        key = re.match(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*=", line)
        if key:  # the line above says, in Russian, what the key is
            above = lines[i - 1].strip()
            assert above.startswith(f"# {key[1]}:") and re.search("[а-яё]{3,}", above), (
                family, line)
    new, old = load(out), load(bundled_example(family))
    assert new.points == old.points and new.links == old.links
    assert new.crank == old.crank and new.dyads == old.dyads
    assert "graphplan analyze" in capsys.readouterr().out


def test_russian_family_names_and_english_explanations(tmp_path):
    assert family_name("Двигатель") == "engine" and family_name("дробилка") == "crusher"
    out = tmp_path / "v.toml"
    assert main(["new", "компрессор", "-o", str(out), "--lang", "en"]) == 0
    text = out.read_text(encoding="utf-8")
    assert "# rpm: n1, rev/min" in text


def test_new_never_overwrites_and_names_the_families(tmp_path, capsys):
    out = tmp_path / "mine.toml"
    out.write_text("my work", encoding="utf-8")
    assert main(["new", "press", "-o", str(out)]) == 2
    assert out.read_text(encoding="utf-8") == "my work"
    assert "never overwrites" in capsys.readouterr().err
    assert main(["new", "крокодил", "-o", str(tmp_path / "x.toml")]) == 2
    err = capsys.readouterr().err
    assert "expected one of" in err and "press" in err and "engine" in err
    assert not (tmp_path / "x.toml").exists()


#: Latin words a Russian template may hold in its comments: key names, values, units, kinds
_ALLOWED = re.compile(r"^(?:[a-z_]+|[A-Z][a-z]?\d*|graphplan|TOML|UTF|RRR|RRP|RPR|PRP|RPP|"
                      r"mm|kN|ccw|cw|docs|variant|format|ru|md|stroke|crank|rim|disc|motor|"
                      r"working|idle|both|resists|drives|diagram|start|end|MPa|kPa|Pa|bar|"
                      r"true|false)$")


@pytest.mark.parametrize("family", FAMILIES)
def test_a_russian_new_variant_has_no_english_prose(family, tmp_path):
    """Under --lang ru the file is Russian (issue 23): the example's English comments and
    description are not copied (before: the slotter's file carried 21 English comment lines
    and an English description); each dyad's joints are explained for its kind (before:
    «точка стойки и имя новой точки кривошипа» — the crank's — over every dyad)."""
    out = tmp_path / f"{family}.toml"
    assert main(["new", family, "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    for line in text.splitlines():
        if "#" not in line:
            continue
        comment = line.split("#", 1)[1]
        # "# key: explanation": the key is a name; the explanation's words must be Russian
        comment = re.sub(r"^\s*\[?[\w.]+\]?\s*[:—]", "", comment)
        words = [w for w in re.findall(r"[A-Za-z]{3,}", comment) if not _ALLOWED.match(w)]
        english = [w for w in words if w.lower() == w and len(w) > 3]
        assert len(english) <= 1, (family, line)
    desc = re.search(r'^description = "(.*)"$', text, re.M)
    assert desc and re.search("[а-яё]{4,}", desc[1]) and not re.search(r"[a-z]{4,}", desc[1])
    kinds = re.findall(r'^kind = "(RRR|RRP|RPR|PRP|RPP)"', text, re.M)
    joints = re.findall(r"^# joints: (.*)$", text, re.M)
    assert len(joints) == len(kinds) + 1  # the crank's, then each dyad's
    assert "кривошипа" in joints[0]
    for kind, what in zip(kinds, joints[1:], strict=True):
        assert "кривошипа" not in what, (kind, what)
        n = {"RRR": 3, "RRP": 2, "RPR": 2, "PRP": 1, "RPP": 2}[kind]
        assert what.index("]") > 0 and what[:what.index("]")].count(",") == n - 1, (kind, what)
    assert load(out).dyads == load(bundled_example(family)).dyads
