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
