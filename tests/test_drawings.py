"""The committed drawings are up to date: ``graphplan sheets examples/*.toml -o drawings``.

Compared structurally, not byte for byte: the same elements in the same order,
the same attributes and texts, every number within 0.01 mm. The diagrams that
matplotlib draws inside a figure are compared by their box only (matplotlib's own
path output is not graphplan's and changes between its releases).
"""

import csv
import io
import json
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from graphplan.model import load
from graphplan.outputs import project_files
from graphplan.project import analyze

ROOT = Path(__file__).resolve().parent.parent
VARIANTS = sorted((ROOT / "examples").glob("*.toml"))
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e-?\d+)?")
REGENERATE = "regenerate them with: graphplan sheets examples/*.toml -o drawings"


def _same_text(a: str, b: str, where: str) -> None:
    """Equal strings, except that numbers may differ by 0.01."""
    na, nb = NUMBER.findall(a), NUMBER.findall(b)
    assert NUMBER.sub("#", a) == NUMBER.sub("#", b), f"{where}: {a[:80]!r} != {b[:80]!r}"
    for x, y in zip(na, nb, strict=True):
        assert abs(float(x) - float(y)) <= 0.0100001, f"{where}: {x} != {y}"


def _same_tree(a: ET.Element, b: ET.Element, where: str) -> None:
    assert a.tag == b.tag, f"{where}: <{a.tag}> != <{b.tag}>"
    here = f"{where}/{a.tag.split('}')[-1]}[{a.get('id') or ''}]"
    assert set(a.attrib) == set(b.attrib), f"{here}: attributes differ"
    for k in a.attrib:
        _same_text(a.get(k), b.get(k), f"{here}@{k}")
    _same_text((a.text or "").strip(), (b.text or "").strip(), here)
    if a.get("class") == "figure":  # matplotlib's picture: its box only
        sa, sb = a[0], b[0]
        for k in ("x", "y", "width", "height"):
            _same_text(sa.get(k), sb.get(k), f"{here}/svg@{k}")
        return
    assert len(a) == len(b), f"{here}: {len(a)} children != {len(b)}"
    for ca, cb in zip(a, b, strict=True):
        _same_tree(ca, cb, here)


def _same_json(a, b, where="$"):
    if isinstance(a, dict):
        assert a.keys() == b.keys(), where
        for k in a:
            _same_json(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _same_json(x, y, f"{where}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12), f"{where}: {a} != {b}"
    else:
        assert a == b, where


def test_every_example_has_its_drawings():
    assert VARIANTS, "no examples"
    for v in VARIANTS:
        assert (ROOT / "drawings" / v.stem / "sheet1.svg").is_file(), f"{v.stem}: {REGENERATE}"


@pytest.mark.parametrize("variant", VARIANTS, ids=lambda p: p.stem)
def test_committed_drawings_match_a_fresh_run(variant, monkeypatch):
    monkeypatch.chdir(ROOT)  # the report names its variant as the command was given it
    variant = variant.relative_to(ROOT)
    folder = ROOT / "drawings" / variant.stem
    if not folder.is_dir():
        pytest.fail(f"drawings/{variant.stem} is missing: {REGENERATE}")
    fresh = project_files(analyze(load(variant)))
    for name, text in fresh.items():
        path = folder / name
        assert path.is_file(), f"{path} is missing: {REGENERATE}"
        old = path.read_text(encoding="utf-8")
        where = f"drawings/{variant.stem}/{name} is out of date ({REGENERATE})"
        if name.endswith(".svg"):
            _same_tree(ET.fromstring(old), ET.fromstring(text), where)
        elif name.endswith(".json"):
            _same_json(json.loads(old), json.loads(text), where)
        elif name.endswith(".csv"):
            ra, rb = list(csv.reader(io.StringIO(old))), list(csv.reader(io.StringIO(text)))
            assert len(ra) == len(rb), where
            for x, y in zip(ra, rb, strict=True):
                _same_text(",".join(x), ",".join(y), where)
        else:
            _same_text(old, text, where)
