"""Norm control (issue 18's marks) of the variants nobody wrote an example for
(``tests/data/variants/*.toml``, discovered: a variant added there is checked the day it is
added): a two-stroke engine, an in-line compressor, an in-line twin over 720°, a pump with a
kN diagram, a crusher with a force on the jaw, a four-bar clockwise at 12 rad/s, a shaper
cutting part of its stroke, a four-bar with a fixed-direction force, an in-line twin with cranks
at 180°, a two-stage V compressor in кгс/см², a dough mixer loaded at a coupler point, rocking
shears (кулиса → RRR) in rad/s and N, a slotting machine with a rotating кулиса, a two-stage
opposed compressor with its cranks at 180°, a rocking conveyor (RRR → RRP, weights in N), a
double-acting pump with a crosshead (a chamber on each side of the piston), a 60° V diesel with
an articulated rod (the second group on the master rod's lug), a rocking inclined screen (a
resistance on both strokes, the box's weight along a 12° slope)…

Issue 17 holds the assignment families to the sheets issue's norm control: each variant's
sheets are measured with the same measures as the examples' (``norm_measures``):

* every moving link drawn in every position of sheet 1 and every scheme of sheet 2;
* every velocity and acceleration plan's longest vector ≥ 40 mm, their median ≥ 50 mm;
* no text over another text or crossed by a line on sheets 1, 2 and 3;
* at most 40 % empty 20×20 mm tiles on each sheet;
* ``graphplan sheets --page A2`` and ``--page A3`` draw every moving link.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from norm_measures import (
    EMPTY_MAX,
    check_links_on_sheet_1,
    check_links_on_sheet_2,
    check_plans_readable,
    empty_share,
    overlaps,
)

VARIANTS_DIR = Path(__file__).resolve().parent / "data" / "variants"
VARIANTS = sorted(p.stem for p in VARIANTS_DIR.glob("*.toml"))

#: Cases not yet at their mark, (variant, sheet, check), strict xfails: the sheets' helpers
#: (issue 18) remove a case when their change makes it pass. Measured when written: sheet 1
#: 43–56 % empty (the V-twin's 38 %), sheet 2 50–74 %, sheet 3 34–41 % (the loom's 41 % went
#: to 39 % with the scheme of the machine unit under its ΔT(φ)); the Mур(φ) curve
#: of sheet 2 crossed its labels 'a' and '9' (the shaper cutting part of its stroke, the
#: loom).
TODO = {
    *((n, 1, "filled") for n in VARIANTS if n not in ("v_twin_engine", "v_engine_articulated")),
    # rocking_conveyor's sheet 2 reaches the mark with the table of the links' loads (sheet2, s10)
    *((n, 2, "filled") for n in VARIANTS if n != "rocking_conveyor"),
    # Session 8's unseen variants (DEFECTS.md, → sheet1 / → sheet2): the in-line twin's 24
    # positions over 720° thinned to every second one at one Kv (plans 44 mm, the second turn
    # repeating the first); the shears' acceleration plans a, b at 30 mm beside pos. 10's
    # 100 mm at one Ka, and its pole letters 'p, a3, b, s3, d, s4, s5' crossed by the plan's
    # lines. (The two-stage compressor's crank scheme, Kl 0.00025, ran its R21 line over group
    # 4–5's equations, and the loom's too: the crank is drawn at most 4x the groups' scale.)
    # Session 9: the in-line twin draws the 12 velocity plans of one turn (the second turn's
    # positions 13 and 19 are captioned on their twins 1 and 7), still at Kv 0.3: pa = 47 mm,
    # but the two pistons' vectors point opposite ways, so a plan is twice its longest vector
    # tall (94 mm) in rows of 102 mm — as in the opposed compressor (43/44 mm).
    ("inline_twin_180", 1, "plans"),
    ("opposed_compressor", 1, "plans"),
    ("shears_rocking", 1, "plans"),
    ("shears_rocking", 1, "overlaps"),
}


def todo(request, name: str, n: int, check: str) -> None:
    if (name, n, check) in TODO:
        request.applymarker(pytest.mark.xfail(strict=True, reason=(
            f"issue 18: {check} of sheet {n} of the variant {name} not yet at its mark")))


@pytest.fixture
def analysis(solved):
    """``analysis(name)`` → a variant's project, the session's (tests/conftest.py)."""
    return lambda name: solved(VARIANTS_DIR / f"{name}.toml")


@pytest.fixture
def sheet(solved, drawn):
    """``sheet(name, n)`` → sheet ``n`` of a variant, drawn once for the session."""

    def get(name: str, n: int):
        path = VARIANTS_DIR / f"{name}.toml"
        if n == 3:
            assert "delta" in solved(path).mech.settings.get("dynamics", {}), (
                f"{name}: a variant without δ")
        return drawn(path, n)

    return get


def test_the_variants_are_there():
    assert len(VARIANTS) >= 8


@pytest.mark.parametrize("name", VARIANTS)
def test_every_moving_link_is_drawn_in_every_position_of_sheet_1(analysis, sheet, name):
    check_links_on_sheet_1(analysis(name), sheet(name, 1))


@pytest.mark.parametrize("name", VARIANTS)
def test_every_moving_link_is_drawn_in_every_scheme_of_sheet_2(analysis, sheet, name):
    check_links_on_sheet_2(analysis(name), sheet(name, 2))


@pytest.mark.parametrize("name", VARIANTS)
def test_plans_are_large_enough_to_read(sheet, request, name):
    todo(request, name, 1, "plans")
    check_plans_readable(sheet(name, 1))


@pytest.mark.parametrize("n", [1, 2, 3])
@pytest.mark.parametrize("name", VARIANTS)
def test_no_text_over_a_line_or_another_text(sheet, request, name, n):
    todo(request, name, n, "overlaps")
    found = overlaps(sheet(name, n))
    assert found == [], f"{len(found)} overlaps, e.g. {found[:5]}"


@pytest.mark.parametrize("n", [1, 2, 3])
@pytest.mark.parametrize("name", VARIANTS)
def test_sheet_is_filled(sheet, request, name, n):
    todo(request, name, n, "filled")
    assert empty_share(sheet(name, n)) <= EMPTY_MAX


@pytest.mark.parametrize("fmt", ["A2", "A3"])
@pytest.mark.parametrize("name", VARIANTS)
def test_every_variant_draws_on_a2_and_a3(analysis, request, tmp_path, name, fmt):
    """`graphplan sheets --page A2/A3`: sheets 1 and 2 on the format asked, every moving link
    drawn in position 0 of sheet 1 and in a scheme of sheet 2."""
    from graphplan.outputs import write_project

    todo(request, name, 1, fmt)
    write_project(VARIANTS_DIR / f"{name}.toml", tmp_path, page=fmt)
    svg = {n: (tmp_path / f"sheet{n}.svg").read_text(encoding="utf-8") for n in (1, 2)}
    w, h = PAGE[fmt]
    for n in (1, 2):
        assert f'width="{w}"' in svg[n] and f'height="{h}"' in svg[n], n
    for link in analysis(name).mech.moving_links:
        assert re.search(rf'id="pp-0-(?:link|slider)-{re.escape(link)}', svg[1]), link
        assert re.search(rf'id="s2p\d+-(?:link|slider)-{re.escape(link)}', svg[2]), link


@pytest.mark.parametrize("fmt", ["A2", "A3"])
def test_sheet_3_takes_the_format_asked(tmp_path, fmt):
    from graphplan.outputs import write_project

    write_project(VARIANTS_DIR / "fourbar_cw.toml", tmp_path, page=fmt)
    svg = (tmp_path / "sheet3.svg").read_text(encoding="utf-8")
    w, h = PAGE[fmt]
    assert f'width="{w}"' in svg and f'height="{h}"' in svg


PAGE = {"A2": ("594mm", "420mm"), "A3": ("420mm", "297mm")}
