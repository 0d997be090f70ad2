"""The mechanism beside each plan of a lesson, the link a step is about in colour
(graphplan/teaching/scheme.py, graphplan/drawing/scheme.py; issue 23)."""

from __future__ import annotations

import itertools
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.drawing import mechanism_scheme, scheme_links
from graphplan.model import load
from graphplan.project import analyze
from graphplan.teaching import lesson, teaching_page
from graphplan.teaching.scheme import step_links

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


@pytest.fixture(scope="module")
def press():
    return analyze(load(EXAMPLES / "press.toml"))


@pytest.fixture(scope="module")
def shaper():
    return analyze(load(EXAMPLES / "shaper.toml"))


def _links(les):
    return {(s.equation or s.text["en"]): s.links for s in les.steps}


def test_the_scheme_draws_every_moving_link_at_the_position(press):
    k = press.kin.labels.index("2")
    items = mechanism_scheme(press, k)
    drawn = {scheme_links(it) for it in items} - {None}
    assert drawn == set(press.mech.moving_links)
    # the crank pin A of the scheme is where the position puts it, relative to O, at one scale
    labels = {it.text: it.pos for it in items if getattr(it, "text", None) in ("O", "A", "B")}
    (ox, oy), (ax, ay), (bx, by) = labels["O"], labels["A"], labels["B"]
    P = press.kin.pos.points
    ratio_a = ((ax - ox) ** 2 + (ay - oy) ** 2) ** 0.5 / float(
        ((P["A"][k] - P["O"][k]) ** 2).sum() ** 0.5)
    ratio_b = ((bx - ox) ** 2 + (by - oy) ** 2) ** 0.5 / float(
        ((P["B"][k] - P["O"][k]) ** 2).sum() ** 0.5)
    assert ratio_a == pytest.approx(ratio_b, rel=1e-9)  # one scale for the whole scheme


def test_each_step_names_the_links_it_is_about(press, shaper):
    v = _links(lesson(press, "velocity", "2"))
    assert v["v_A = ω1·l_OA"] == ("1",)  # the crank
    assert v["v_B = v_A + v_BA = v_B4 + v_B3B4"] == ("2", "3")  # the group 2–3
    assert v["v_S2: similarity on link 2"] == ("2",)
    s = _links(lesson(shaper, "acceleration", "2"))
    assert s["aᵏ_A3 = 2·ω3·v_AA3"] == ("3",)  # Coriolis: the slotted link 3
    assert s["aⁿ_AO3 = ω3²·l_AO3"] == ("3",)
    f = lesson(press, "forces", "(2)")
    assert {ln for st in f.steps for ln in st.links} == {"1", "2", "3"}
    assert step_links(press.mech, "", "Pole p: points of the frame") == ()


def test_the_page_shows_the_scheme_beside_every_step_with_its_links_in_colour(press):
    les = lesson(press, "velocity", "2")
    page = teaching_page(les, "ru")
    assert page.count('<figure class="mech">') == len(les.steps)
    lit = re.findall(r'<figure class="mech"><svg[^>]*data-links="([^"]+)"', page)
    assert lit == [" ".join(s.links) for s in les.steps if s.links]
    assert lit[1] == "2 3"  # the step v_B = v_A + v_BA: the group 2–3
    assert "Механизм в положении 2; звенья 2, 3 выделены" in page
    assert "The mechanism in position 2; link 1 in colour" in teaching_page(les, "en")


def test_the_flywheel_lesson_has_no_scheme(press):
    les = lesson(press, "flywheel")
    assert les.scheme == ()
    assert '<figure class="mech">' not in teaching_page(les, "ru")


def test_the_lever_uses_kp_as_the_sheets_do(press):
    page = teaching_page(lesson(press, "zhukovsky", "(2)"), "ru")
    assert "Kp = " in page and "Kf" not in re.sub(r"base64,[^)]*\)", "", page)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_the_lessons_scheme_is_readable_on_tall_mechanisms(path, solved):
    """Issue 23: the scheme beside a plan crowded on tall mechanisms (a box of 120 × 90 mm
    shrank the slotter until O1, A, B, O3 and T sat on each other: 5 pairs of letters
    overlapping at position 0, 4 on the shaper). The lesson's scheme is as tall as the
    mechanism (up to 240 mm for 120 mm across) and its letters are placed clear of each
    other, at every position of every example; every point keeps its letter."""
    from graphplan.drawing import Text, item_geometry, text_box
    from graphplan.teaching.scheme import SCHEME_HEIGHT_MM, SCHEME_WIDTH_MM, lesson_scheme

    p = solved(path)
    pts = np.array([q[0] for q in p.kin.pos.points.values()]
                   + [np.asarray(v, float) for v in p.mech.frame_points.values()])
    for k in range(p.kin.n):
        items = lesson_scheme(p, k)
        labels = [it for it in items if isinstance(it, Text)]
        boxes = [text_box(t) for t in labels]
        for (a, ta), (b, tb) in itertools.combinations(zip(boxes, labels, strict=True), 2):
            assert not a.intersects(b), (p.kin.labels[k], ta.text, tb.text)
        written = {n.strip() for t in labels for n in t.text.split(",")}
        assert written == set(p.kin.pos.points), p.kin.labels[k]
    ext = np.ptp(pts, axis=0)
    tall = ext[1] / ext[0] * SCHEME_WIDTH_MM

    def height(items) -> float:
        drawn = [g.bounds for it in items if not isinstance(it, Text)
                 and (g := item_geometry(it)) is not None]
        return max(b[3] for b in drawn) - min(b[1] for b in drawn)

    new, old = height(lesson_scheme(p, 0)), height(mechanism_scheme(p, 0))
    assert new >= old - 1e-9
    # as tall as its shape asks, to within the round scale (1-2-5: at most 2.5 times smaller);
    # the old box of 90 mm drew the slotter 67.5 mm tall where this asks 96 mm or more
    box = min(SCHEME_HEIGHT_MM[1], max(SCHEME_HEIGHT_MM[0], tall))
    assert new >= min(box, tall) / 2.5, (tall, new, old)
