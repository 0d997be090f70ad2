"""In a notebook every result shows itself: the analysis, the plans, the sheets, the machine
unit, the checker's report and the lessons (their ``_repr_*_``, as Jupyter calls them)."""

from __future__ import annotations

import html
import re
from pathlib import Path

from graphplan.checking import check_file
from graphplan.drawing import kinematics_sheet
from graphplan.dynamics import machine_unit
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.plans import velocity_plan
from graphplan.project import analyze, sheet_scales
from graphplan.teaching import lesson

ROOT = Path(__file__).resolve().parent.parent


def test_the_analysis_shows_its_tables():
    an = analyze(load(bundled_example("press")))
    text = an._repr_html_()
    assert text.startswith("<pre>") and text.endswith("</pre>")
    # the structure of the press: W = 3n − 2p5 − p4 = 3·3 − 2·4 − 0 = 1
    assert "W = 3·n − 2·p5 − p4 = 3·3 − 2·4 − 0 = 1" in html.unescape(text)


def test_a_plan_and_a_sheet_show_their_drawings():
    an = analyze(load(bundled_example("press")))
    sc = sheet_scales(an.mech, an.kin)
    k = an.kin.labels.index("2")
    vp = velocity_plan(an.mech, an.kin, k, sc.kl, sc.kv)
    svg = vp._repr_svg_()
    assert svg.lstrip().startswith("<svg") and svg.count("<line") + svg.count("<path") >= 3
    sheet = kinematics_sheet(an)._repr_svg_()
    assert re.match(r'<svg[^>]* width="100%"', sheet) and 'viewBox="0 0 841 594"' in sheet


def test_the_machine_unit_shows_its_hand_calculation():
    unit = machine_unit(analyze(load(bundled_example("press"))))
    md = unit._repr_markdown_()
    assert md.startswith("#") and "Jм = JI − Jкр − Jрот·u² = " in md
    assert f"= {unit.to_json()['I_flywheel']:.2f}" in md


def test_the_checkers_report_shows_itself_in_a_frame():
    report = check_file(ROOT / "examples/seed-check/seed.toml")
    frame = report._repr_html_()
    assert frame.startswith("<iframe srcdoc=") and 'sandbox=""' in frame
    page = html.unescape(frame[frame.index('"') + 1:frame.index('" sandbox')])
    assert page.startswith("<!DOCTYPE html>") and "8145,71" in page


def test_a_lesson_shows_its_page():
    les = lesson(analyze(load(bundled_example("press"))), "velocity", "2")
    assert les._repr_html_().startswith("<iframe srcdoc=")
    assert les._repr_svg_().lstrip().startswith("<svg")
