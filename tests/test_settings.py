"""The variant's settings, typed, with every default in one place (issue 16, item 2).

``[drawing]``, ``[kinetostatics]`` and ``[title_block]`` are read through
``Mechanism.drawing / .kinetostatics / .title_block`` (graphplan/model/settings.py) and
``[dynamics]`` through ``DynamicsSettings`` — never as raw tables with their defaults
written again at each use (``mech.settings.get("drawing", {}).get("format", "A1")`` stood
in six places, ``"ru"`` and ``0.5`` in two each).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphplan.errors import InputError
from graphplan.model import load, loads
from graphplan.model.settings import DrawingSettings, KinetostaticsSettings, TitleBlockSettings
from graphplan.project import acceleration_positions, solve_project

ROOT = Path(__file__).resolve().parent.parent
PRESS = ROOT / "examples" / "press.toml"

#: the modules that may read the raw tables: the loader checks them, the settings type them
READERS = {"model/loader.py", "model/settings.py", "dynamics/settings.py"}


def test_no_stage_reads_the_raw_settings_tables():
    raw = re.compile(r"\.settings\s*(\.get\(|\[)")
    found = [f"{p.relative_to(ROOT / 'graphplan').as_posix()}:{i}"
             for p in sorted((ROOT / "graphplan").rglob("*.py"))
             if p.relative_to(ROOT / "graphplan").as_posix() not in READERS
             for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if raw.search(line) and "doc.settings" not in line]  # python-docx's own settings
    assert found == []


def test_the_press_settings_typed():
    m = load(PRESS)
    # examples/press.toml: [drawing] Kl = 0.001, reading_mm = 0.5; [kinetostatics]
    # neglect_below = 0.10; [title_block] sheets = 3; format and language by default
    assert m.drawing == DrawingSettings(Kl=0.001, reading_mm=0.5)
    assert (m.drawing.format, m.drawing.language) == ("A1", "ru")
    assert m.kinetostatics.neglect_below == 0.10 and m.kinetostatics.inertia is True
    assert m.title_block.sheets == 3 and m.title_block.sheet is None
    assert m.title_block.litera == "У"


def test_defaults_are_the_types_defaults():
    assert DrawingSettings.of({}) == DrawingSettings()
    assert KinetostaticsSettings.of({}) == KinetostaticsSettings()
    assert TitleBlockSettings.of({}) == TitleBlockSettings()
    d = DrawingSettings(format="A3", Kv=0.01, positions=("1", "(2)"))
    assert DrawingSettings.of({"drawing": d.table()}) == d  # the table round-trips


def test_another_format_drops_the_scales_fixed_for_the_variants_own():
    m = load(PRESS).with_drawing(Kv=0.005, positions=("1", "(2)"))
    a3 = m.on_format("A3")
    assert a3.drawing == DrawingSettings(format="A3", reading_mm=0.5, positions=("1", "(2)"))
    assert m.on_format("A1") is m  # its own format: the same variant
    assert m.drawing.Kl == 0.001 and m.drawing.Kv == 0.005  # the variant is not changed
    with pytest.raises(InputError, match="A1, A2, A3"):
        m.on_format("A0")


def _press_with(extra: str):
    text = PRESS.read_text(encoding="utf-8").replace("[drawing]\n", "[drawing]\n" + extra, 1)
    return loads(text, "press-acc.toml")


def test_the_variant_chooses_its_acceleration_plans():
    m = _press_with('accelerations = ["1", "5"]\n')
    project = solve_project(m)
    labels = project.kin.labels
    assert [labels[k] for k in acceleration_positions(m, project.kin)] == ["1", "5"]
    with pytest.raises(InputError, match=r"press-acc\.toml.*drawing\.accelerations"):
        _press_with('accelerations = ["1", "1"]\n')
    with pytest.raises(InputError, match=r"drawing\.accelerations"):
        acceleration_positions(_press_with('accelerations = ["77"]\n'), project.kin)


def test_the_sense_of_rotation_is_read_from_crank_sense():
    """The crank's sense is derived once (Crank.sense), not again from the sign of ω
    (it was in 11 places with two spellings, ``> 0`` and ``>= 0``)."""
    again = re.compile(r"omega\w*\)?\s*>=?\s*0\b")
    found = [f"{p.relative_to(ROOT / 'graphplan').as_posix()}:{i}"
             for p in sorted((ROOT / "graphplan").rglob("*.py"))
             if p.relative_to(ROOT / "graphplan").as_posix() != "model/mechanism.py"
             for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
             if again.search(line)]
    assert found == []
