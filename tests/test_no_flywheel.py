"""A machine that needs no flywheel (Jм = 0) is a designed case, not a crash.

When the crank (``dynamics.crank_inertia``) and the motor's rotor reduced to it already
have the constant inertia JI that Wittenbauer's diagram asks for, ``Jм = JI − Jкр −
Jрот·u² ≤ 0``: no flywheel. Sheet 3 then says so (with the numbers) where the flywheel
would be drawn and still shows the diagrams and the check ω(φ); the JSON report gives
``flywheel_needed: false`` and ``flywheel: null`` (documented); the tables, the note and
the lesson say it in words; nothing is NaN or infinite. The variants: the crusher with a
heavy eccentric shaft (Jкр = 40 kg·m² against JI ≈ 23 kg·m²) and the engine with a heavy
crankshaft (no motor: Jкр alone).
"""

from __future__ import annotations

import json
import math
import re
import zipfile
from pathlib import Path

import pytest

from graphplan.cli import main
from graphplan.drawing import Group, Text, check_layout, dynamics_sheet, iter_leaves, results_lines
from graphplan.dynamics import machine_unit
from graphplan.model import loads
from graphplan.project import analyze
from graphplan.reports import dynamics_markdown

ROOT = Path(__file__).resolve().parent.parent
HEAVY = {"crusher": ("crank_inertia = 2.0", "crank_inertia = 40.0"),
         "engine": ("crank_inertia = 0.02", "crank_inertia = 50.0")}
NUMBER_WORDS = re.compile(r"\b(nan|inf|infinity)\b", re.IGNORECASE)


def _text(name: str) -> str:
    old, new = HEAVY[name]
    text = (ROOT / "examples" / f"{name}.toml").read_text(encoding="utf-8")
    assert old in text
    return text.replace(old, new)


@pytest.fixture(scope="module")
def units():
    out = {}
    for name in HEAVY:
        a = analyze(loads(_text(name), source=f"{name}-heavy.toml"))
        out[name] = (a, machine_unit(a))
    return out


@pytest.mark.parametrize("name", list(HEAVY))
def test_no_flywheel_when_the_crank_already_has_JI(units, name):
    _, u = units[name]
    fw = u.flywheel
    rotor = fw.I_rotor
    assert not u.flywheel_needed and not fw.needed
    assert fw.I_m == 0.0 and fw.I_m_approx == 0.0
    # Jм before clipping: JI − Jкр − Jрот·u², e.g. crusher 22.87 − 40 − 1.11 = −18.24
    assert fw.I_m_signed == pytest.approx(fw.J_I - fw.I_const - rotor, rel=1e-12)
    assert fw.I_m_signed < 0
    assert u.mounted.mass == 0.0 and u.mounted.D == 0.0
    # the check: simulated without a flywheel, ω stays within δ (more inertia than JI)
    assert u.simulation.I_flywheel == rotor  # the rotor, no flywheel
    assert u.simulation.delta_actual <= fw.delta

    # the limit case: a crank of exactly Jкр = JI − Jрот·u² (JI does not depend on Jкр)
    # needs no flywheel either and runs at δ itself, within the grid's round-off
    old = HEAVY[name][1]
    edge = _text(name).replace(old, f"crank_inertia = {fw.J_I - rotor!r}")
    ue = machine_unit(analyze(loads(edge, source=f"{name}-edge.toml")))
    assert pytest.approx(fw.J_I, rel=1e-12) == ue.flywheel.J_I
    assert ue.flywheel.I_m <= 1e-9 * fw.J_I
    assert ue.simulation.delta_actual == pytest.approx(fw.delta, rel=0.02)


def _walk(items):
    for it in items:
        yield it
        if isinstance(it, Group):
            yield from _walk(it.items)


@pytest.mark.parametrize("name", list(HEAVY))
def test_sheet3_says_no_flywheel_and_keeps_the_diagrams(units, name):
    a, u = units[name]
    for lang, words in (("ru", "Маховик не нужен"), ("en", "No flywheel is needed")):
        sheet = dynamics_sheet(a, lang=lang, unit=u)
        assert check_layout(sheet) == []
        texts = [t.text for t in iter_leaves(sheet.all_items()) if isinstance(t, Text)]
        assert words in texts
        ids = {getattr(it, "id", None) or "" for it in _walk(sheet.all_items())}
        assert not any(i.startswith("s3-fw-outer") or i.startswith("s3-fw-sec") for i in ids)
        assert any(i.startswith("s3-em") for i in ids)  # the energy–mass diagram is drawn
        assert any(i.startswith("s3-omega") for i in ids)
        lines = results_lines(u, lang)
        assert any("≤ 0" in x for x in lines), lines
        assert not any(NUMBER_WORDS.search(x) for x in texts)


def test_report_and_json_say_no_flywheel(units):
    _, u = units["crusher"]
    md = dynamics_markdown(u, "ru")
    assert "маховик не нужен" in md and not NUMBER_WORDS.search(md)
    js = u.to_json()
    assert js["flywheel_needed"] is False and js["flywheel"] is None
    assert js["I_flywheel"] == 0.0
    assert all(math.isfinite(v) for v in js.values() if isinstance(v, float))


@pytest.mark.parametrize("name", list(HEAVY))
def test_every_output_of_the_cli(tmp_path, name):
    """sheets (SVG, tables, JSON), note and lessons: no crash, no NaN or inf anywhere."""
    path = tmp_path / f"{name}-heavy.toml"
    path.write_text(_text(name), encoding="utf-8")
    out = tmp_path / "out"
    assert main(["sheets", str(path), "-o", str(out)]) == 0
    assert main(["note", str(path), "-o", str(tmp_path / "note")]) == 0
    assert main(["teach", str(path), "--plan", "flywheel", "-o", str(tmp_path / "teach")]) == 0
    report = json.loads((out / "analysis.json").read_text(encoding="utf-8"))
    assert report["dynamics"]["flywheel"] is None
    assert "Маховик не нужен" in (out / "sheet3.svg").read_text(encoding="utf-8")
    for f in list(out.iterdir()) + list((tmp_path / "teach").iterdir()):
        text = f.read_text(encoding="utf-8")
        bad = [m for m in NUMBER_WORDS.findall(text)]
        assert not bad, (f.name, bad[:3])
    lesson = (tmp_path / "teach" / "teach-flywheel.html").read_text(encoding="utf-8")
    assert "Маховик не нужен" in lesson
    with zipfile.ZipFile(tmp_path / "note" / "note.docx") as z:
        doc = z.read("word/document.xml").decode("utf-8")
    assert "Маховик не нужен" in doc and not NUMBER_WORDS.search(re.sub("<[^>]+>", " ", doc))
