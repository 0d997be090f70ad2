"""Teaching pages without a browser: the numbers of every caption against independent
routes (the exact kinematic and kinetostatic solvers, a brute-force Wittenbauer), the
pages of every example and position, the frames, the command line and the notebook views.
"""

from __future__ import annotations

import html
import json
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.dynamics import dynamic_model
from graphplan.files import bundled_example, examples_dir
from graphplan.model import load
from graphplan.plans import velocity_plan
from graphplan.project import analyze, sheet_scales
from graphplan.teaching import PLANS, lesson, page_name, teaching_page, write_lesson
from graphplan.teaching.captions import ZERO_MM, localise, mm, num, result_text
from graphplan.teaching.drawing import COLOURS, GREY, frame_svg
from graphplan.teaching.model import Result
from graphplan.teaching.page import CSP

EXAMPLES = sorted(examples_dir().glob("*.toml"))
SVG = "{http://www.w3.org/2000/svg}"
POINT = re.compile(r"[A-Z][a-z]*\d*")
NUMBER = re.compile(r"(?<![\w.])[−-]?\d+(?:\.\d+)?(?:·10\^-?\d+)?")


def parse(s: str) -> float:
    s = s.replace("−", "-")
    if "·10^" in s:
        m, e = s.split("·10^")
        return float(m) * 10 ** int(e)
    return float(s)


@pytest.fixture(scope="session")
def analysis_of(solved):
    """The example's project, solved once for the session (tests/conftest.py)."""
    return solved


@pytest.fixture(scope="module")
def press(analysis_of):
    return analysis_of("press")


def quoted(text: str) -> list[float]:
    return [parse(x) for x in NUMBER.findall(text)]


def assert_quotes(text: str, r: Result) -> None:
    """The caption quotes the length to 0.01 mm and the value to its 4 figures."""
    nums = quoted(text)
    assert any(abs(x - r.mm) <= 0.005 + 1e-12 for x in nums), (text, r.mm)
    tol = 5e-4 * abs(r.value) + ZERO_MM * r.per_mm + 1e-12  # round-off lengths read as 0
    assert any(abs(x - r.value) <= tol for x in nums), (text, r.value)


# ------------------------------------------------------- captions against the solvers


def _exact_vector(kin, table, quantity: str, k: int):
    """|v_X| or |v_X − v_Y| from the exact solver, for a quantity naming model points."""
    sub = quantity.partition("_")[2]
    pts = POINT.findall(sub)
    if "".join(pts) != sub or not all(p in table for p in pts):
        return None
    if len(pts) == 1:
        return float(np.hypot(*table[pts[0]][k]))
    if len(pts) == 2:
        return float(np.hypot(*(table[pts[0]][k] - table[pts[1]][k])))
    return None


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_kinematic_captions_quote_the_exact_velocities_and_accelerations(path, analysis_of):
    """Every v_X, v_XY, a_X the velocity and acceleration lessons read off their plans is
    the exact solver's (closed-form loop equations, not a construction) to round-off, and
    every angular velocity a caption derives is the solver's ω with its sense."""
    a = analysis_of(path)
    kin = a.kin
    checked = {"velocity": 0, "acceleration": 0, "omega": 0}
    for k in range(kin.n):
        for plan, table in (("velocity", kin.vel.points), ("acceleration", kin.acc.points)):
            les = lesson(a, plan, kin.labels[k])
            for r in les.results:
                if plan == "acceleration" and not r.quantity.startswith("a_"):
                    continue
                exact = _exact_vector(kin, table, r.quantity, k)
                if exact is None:
                    continue
                assert r.value == pytest.approx(exact, rel=1e-9, abs=1e-12), (r, k)
                assert_quotes(result_text(r, "en"), r)
                checked[plan] += 1
            for s in les.steps:
                for note in s.notes:
                    m = re.match(r"([ωε])(\w+) = .* = ([\d.]+)(?: rad/s²?, (\S+))?$", note["en"])
                    assert m, note
                    exact = (kin.vel.omega if m[1] == "ω" else kin.acc.epsilon)[m[2]][k]
                    assert float(m[3]) == pytest.approx(abs(exact), rel=1e-3, abs=1e-6)
                    if abs(exact) > 1e-9:
                        assert m[4] == ("counter-clockwise" if exact > 0 else "clockwise")
                    checked["omega"] += 1
    assert checked["velocity"] >= 2 * kin.n and checked["acceleration"] >= kin.n, checked


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_turning_link_gets_its_omega_and_epsilon_derived(path, analysis_of):
    """ω and ε of every link that turns at that instant (a slotted link too: ω3 = v_A3/l_O3A,
    ε3 = aτ_AO3/l_AO3) are derived with numbers in the velocity and acceleration lessons
    (their values are checked against the solver in the test above)."""
    a = analysis_of(path)
    kin = a.kin
    for k in range(kin.n):
        for plan, table in (("velocity", kin.vel.omega), ("acceleration", kin.acc.epsilon)):
            les = lesson(a, plan, kin.labels[k])
            derived = {re.match(r"[ωε](\w+) =", n["en"])[1] for s in les.steps for n in s.notes}
            turning = {ln for ln, w in table.items() if ln != a.mech.crank.link
                       and ln in a.mech.moving_links and abs(w[k]) > 1e-6}
            assert turning <= derived, (plan, kin.labels[k], turning - derived)


def test_similarity_and_normal_steps_write_their_numbers(press):
    # press, position 2: as2 = ab·l_AS2/l_AB = 67.94·0.07/0.2 = 23.78 mm (ab of the plan,
    # l_AS2 = 0.07 m, l_AB = 0.2 m), and aⁿ_BA = ω2²·l_BA = 1.698²·0.2 = 0.5769 m/s²
    v = lesson(press, "velocity", "2")
    sim = next(s for s in v.steps if s.equation.startswith("v_S2"))
    m = re.search(r"as2 = ab·l_AS2/l_AB = ([\d.]+)·([\d.]+)/([\d.]+) = ([\d.]+) мм",
                  sim.text["ru"])
    assert m, sim.text["ru"]
    ab, l_as2, l_ab, as2 = (float(x) for x in m.groups())
    assert ab == pytest.approx(v.results[[r.segment for r in v.results].index("ab")].mm,
                               abs=0.005)
    assert as2 == pytest.approx(ab * l_as2 / l_ab, abs=0.01)
    acc = lesson(press, "acceleration", "2")
    nrm = next(s for s in acc.steps if s.equation.startswith("aⁿ_BA"))
    m = re.search(r"= ([\d.]+)²·([\d.]+) = ([\d.]+) m/s²", nrm.text["en"])
    assert m and float(m[3]) == pytest.approx(float(m[1]) ** 2 * float(m[2]), rel=2e-3)


def test_press_velocity_steps_by_hand(press):
    # Position 2 of the press: ω1 = π·55/30 = 5.7596 rad/s, l_OA = 0.08 m, so
    # v_A = 0.46077 m/s and pa = v_A/Kv = 0.46077/0.005 = 92.15 mm (Kv of sheet 1).
    les = lesson(press, "velocity", "2")
    assert [s.kind for s in les.steps] == ["pole", "lay", "intersect", "read", "similar",
                                           "similar"]
    lay = les.steps[1].results[0]
    assert lay.laid and lay.segment == "pa"
    assert lay.value == pytest.approx(math.pi * 55 / 30 * 0.08, rel=1e-12)
    assert lay.mm == pytest.approx(lay.value / 0.005, rel=1e-12)
    assert result_text(lay, "en") == "v_A = 0.4608 m/s → pa = v_A/Kv = 0.4608/0.005 = 92.15 mm"
    terms = {t.name: t for t in les.steps[2].terms}
    # v_B = v_A + v_BA = v_B4 + v_B3B4: v_B sought, v_A drawn, v_BA ⟂AB, v_B4 = 0, v_B3B4 ∥ guide
    assert (terms["v_B"].direction, terms["v_B"].magnitude) == (None, None)
    assert terms["v_A"].direction == "= pa"
    assert (terms["v_BA"].direction, terms["v_BA"].magnitude) == ("⟂AB", None)
    assert terms["v_B4"].magnitude == "0"
    assert (terms["v_B3B4"].direction, terms["v_B3B4"].magnitude) == ("∥ guide", None)
    pb = les.steps[3].results[0]
    assert result_text(pb, "ru").startswith(f"pb = {mm(pb.mm)} мм → v_B = pb·Kv = ")


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_force_captions_quote_the_exact_reactions(path, analysis_of):
    """Each reaction a force plan's caption reads (segment·Kp) is the exact kinetostatics'
    (a linear solve of all groups at once), and the lever's note quotes the force plans'
    Mур and its own, equal by the power balance."""
    a = analysis_of(path)
    ctx = a  # the project: its loads, forces and sheet scales, solved once
    checked = 0
    for k in range(a.kin.n):
        les = lesson(a, "forces", a.kin.labels[k])
        for r in les.results:
            if r.quantity in ctx.forces.reactions and r.factor == "Kp":
                exact = float(ctx.forces.reactions[r.quantity].magnitude[k])
                assert r.value == pytest.approx(exact, rel=1e-6, abs=1e-6 * max(exact, 1.0))
                assert_quotes(result_text(r, "ru"), r)
                checked += 1
        lever = lesson(a, "zhukovsky", a.kin.labels[k])
        note = lever.steps[-1].notes[0]["en"]
        m_plans, m_lever = quoted(note)[:2]
        exact = float(ctx.forces.M_bal[k])
        scale = max(abs(exact), 1.0)
        assert m_plans == pytest.approx(exact, rel=1e-4, abs=1e-4 * scale)
        assert m_lever == pytest.approx(exact, rel=1e-4, abs=1e-4 * scale)
    assert checked >= a.kin.n


def test_scheme_arms_are_the_perpendiculars_measured(press):
    """Each arm drawn on a scheme runs from the moment centre to the foot of the
    perpendicular on the force's line of action, and its length is the arm the caption
    converts (the force plan's reading)."""
    les = lesson(press, "forces", "(3)")
    arms = 0
    for s in les.steps:
        if s.kind not in ("moment", "couple"):
            continue
        byname = {m.name: m for m in s.marks}
        for r in s.results:
            arm = byname.get(r.segment)
            if arm is None:
                assert r.mm == pytest.approx(0.0, abs=1e-9)  # a force through the centre
                continue
            (cx, cy), (fx, fy) = arm.points
            assert math.hypot(fx - cx, fy - cy) == pytest.approx(r.mm, rel=1e-9)
            force = byname[r.factor]
            (ax, ay), (bx, by) = force.points
            # the foot is on the line of action and the arm is perpendicular to it
            assert abs((fx - ax) * (by - ay) - (fy - ay) * (bx - ax)) < 1e-6 * math.hypot(
                bx - ax, by - ay) * max(1.0, math.hypot(fx - ax, fy - ay))
            assert abs((fx - cx) * (bx - ax) + (fy - cy) * (by - ay)) < 1e-6 * max(1.0, r.mm)
            arms += 1
    assert arms >= 1


def test_flywheel_segment_kl_gives_the_wittenbauer_inertia(press):
    """J_I from the caption's kl against a brute force over the grid: the tangents at
    ψmax, ψmin touch ΔT(I_var) where ΔT − k±·I_var is extreme, k± = ω²(1 ± δ)/2, and
    J_I = (b+ − b−)/(ω²δ). The drawn upper tangent lies on or above every point of the
    curve and touches it; the lower one on or below."""
    les = lesson(press, "flywheel")
    m = dynamic_model(press)
    w, delta = m.omega1, m.delta
    from graphplan.dynamics import work_diagrams

    dT, Iv = work_diagrams(m).dT, m.inertia.I_var  # exact ΔT: the grid, whatever n
    kl = next(r for r in les.results if r.segment == "kl")
    b_up = max(dT[i] - w * w * (1 + delta) / 2 * Iv[i] for i in range(len(dT)))
    b_lo = min(dT[i] - w * w * (1 - delta) / 2 * Iv[i] for i in range(len(dT)))
    assert kl.value == pytest.approx((b_up - b_lo) / (w * w * delta), rel=1e-9)
    curve = next(mk for s in les.steps for mk in s.marks if mk.name == "ΔT(JII)")
    pts = np.array(curve.points)
    span = float(np.ptp(pts[:, 1]))
    for name, above in (("tangent-max", True), ("tangent-min", False)):
        line = next(mk for s in les.steps for mk in s.marks if mk.name == name)
        (x0, y0), (x1, y1) = line.points
        y = y0 + (pts[:, 0] - x0) * (y1 - y0) / (x1 - x0)
        gap = (y - pts[:, 1]) if above else (pts[:, 1] - y)
        assert gap.min() > -1e-3 * span  # the whole curve on one side (thinned curve)
        assert gap.min() < 1e-2 * span  # and touching it
    assert_quotes(result_text(kl, "en"), kl)


def _lesson_text(les, lang: str = "en") -> str:
    parts = [*les.scales]
    for s in les.steps:
        parts += [s.equation, s.text[lang], *(n[lang] for n in s.notes)]
    return "\n".join(parts)


def _quotes(text: str, value: float, rel: float) -> bool:
    return any(math.isclose(x, value, rel_tol=rel, abs_tol=1e-9) for x in quoted(text))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_flywheel_lesson_is_sheet_3s_machine_unit(path, analysis_of):
    """The flywheel lesson draws sheet 3's machine unit: every scale (Kφ, KM, H, KA, KT, KJ),
    kl, JI, Jм and the flywheel's size and mass are those of drawings/<example>/analysis.json
    (what sheet 3 and dynamics.ru.md write) and of the project's machine unit, and its
    captions hold no table of vectors (the quantities are scalars)."""
    a = analysis_of(path)
    if a.unit is None:
        pytest.skip("no dynamics.delta: no sheet 3")
    u = a.unit
    sheet = json.loads((COMMITTED.parent / path.stem / "analysis.json").read_text("utf-8"))
    dyn = sheet["dynamics"]
    les = lesson(a, "flywheel")
    text = _lesson_text(les)
    fw, wd = u.flywheel, u.flywheel.work
    sc = dyn["scales"]
    for key, mine in (("Kphi", wd.Kphi), ("KM", wd.KM), ("H_mm", wd.H), ("KA", wd.KA),
                      ("KT", fw.KT), ("KI", fw.KI)):
        assert mine == pytest.approx(sc[key], rel=1e-9), key  # the sheet's own scales
        assert _quotes(text, sc[key], 5e-4), (key, sc[key])  # written in the lesson
    kl = next(r for r in les.results if r.segment == "kl")
    assert kl.mm == pytest.approx(dyn["tangents"]["kl_mm"], rel=1e-9)
    assert kl.value == pytest.approx(dyn["J_I"], rel=1e-9)
    for value in (dyn["J_I"], dyn["I_flywheel"], dyn["flywheel"]["mass"], dyn["flywheel"]["D"],
                  dyn["flywheel"]["rim_speed"], dyn["tangents"]["psi_max_deg"],
                  dyn["tangents"]["psi_min_deg"]):
        assert _quotes(text, value, 5e-4), (value, text)
    if dyn["I_rotor_reduced"]:
        assert "Jрот·u²" in text and _quotes(text, dyn["I_rotor_reduced"], 5e-4)
    assert all(not s.terms for s in les.steps)
    for lang in ("ru", "en"):
        assert 'class="terms"' not in teaching_page(les, lang)


# ------------------------------------------------------------- pages of every example


def _check_page(text: str, les, lang: str) -> None:
    assert text.startswith("<!DOCTYPE html>")
    assert f'content="{CSP}"' in text
    assert f'<html lang="{lang}">' in text
    assert "nan" not in re.findall(r"\bnan\b|\binf\b", text.lower())
    # nothing to fetch: no URL but the SVG namespaces and data: fonts
    urls = re.findall(r"""(?:src|href)\s*[=:]\s*["']?(?:url\()?([^"')\s>]+)""", text)
    assert all(u.startswith(("data:", "#")) for u in urls), urls[:3]
    assert not re.search(r"https?://(?!www\.w3\.org/)", text)
    sections = re.findall(r'<section class="step" id="step-(\d+)"', text)
    assert [int(s) for s in sections] == list(range(1, len(les.steps) + 1))
    mms = [float(x) for x in re.findall(r'data-mm="([^"]+)"', text)]
    assert mms == [r.mm for r in les.results]
    answers = re.findall(r'<span class="answer">(.*?)</span></li>', text)
    for r, ans in zip(les.results, answers, strict=True):
        plain = html.unescape(re.sub(r"<[^>]+>", "", ans)).replace("\u00a0", " ")
        assert_quotes(plain, r)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_plan_of_every_position_makes_a_page(path, analysis_of):
    a = analysis_of(path)
    for plan in PLANS:
        for label in (a.kin.labels if plan != "flywheel" else [None]):
            les = lesson(a, plan, label)
            assert les.steps and all(s.panel < len(les.panels) for s in les.steps)
            lang = "en" if len(les.steps) % 2 else "ru"
            page = teaching_page(les, lang)
            _check_page(page, les, lang)
            _check_texts(les, page)


SCIENTIFIC = re.compile(r"\d[eE][+-]?\d|·10\^")
#: a negative factor written bare after a multiplication or division: 2·-1.383
BARE_NEGATIVE = re.compile(r"[·/×]\s*[-−]\s*\d")


def _visible(page: str) -> str:
    for tag in ("script", "style", "svg"):
        page = re.sub(rf"<{tag}.*?</{tag}>", " ", page, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


def _check_texts(les, page: str) -> None:
    """No exponent in any text of the lesson or its page; no bare negative factor; the
    Coriolis step names the acceleration, its formula with the link's ω and the relative
    velocity, and the rule of its direction; a projection is titled as one and defines u;
    a step titled as an equation of moments is one (ΣM)."""
    assert not SCIENTIFIC.search(_visible(page)), SCIENTIFIC.search(_visible(page))
    for s in les.steps:
        for lang in ("ru", "en"):
            texts = [s.equation, s.text[lang], *(n[lang] for n in s.notes)]
            for t in texts:
                assert not SCIENTIFIC.search(t), (s.number, t)
                assert not BARE_NEGATIVE.search(t), (s.number, t)
        if any(m.role == "coriolis" for m in s.marks):
            m = re.fullmatch(r"aᵏ_\w+ = 2·ω(\w+)·(v_\w+)", s.equation)
            assert m, s.equation
            link, rel = m[1], m[2]
            assert "ускорение кориолиса" in s.text["ru"].lower(), s.text["ru"]
            assert "Coriolis acceleration" in s.text["en"], s.text["en"]
            if f"ω{link} = 0" in s.text["en"]:
                continue
            if f"= −{rel}" in s.text["en"]:  # a slotted link: the sheets' v_AA3 is named, the
                # rule turns its opposite v_A3A, and the sentence says so
                assert (f"вектор относительной скорости, повёрнутый на 90° в сторону вращения "
                        f"ω{link}") in s.text["ru"]
                assert re.search(rf"поворачивается v_\w+ = −{rel} \(вектор .*\) — на 90° "
                                 r"(по|против) часовой стрелк", s.text["ru"]), s.text["ru"]
                assert re.search(rf"the rule turns v_\w+ = −{rel} \(the vector .*\) by 90° "
                                 r"(counter-)?clockwise", s.text["en"]), s.text["en"]
            else:
                assert f"{rel}, повёрнутый на 90° в сторону вращения ω{link}" in s.text["ru"]
                assert f"{rel} turned by 90° in the sense of ω{link}" in s.text["en"]
        if s.kind == "moment":
            assert s.equation.startswith("ΣM"), s.equation
        if "·u" in s.equation:
            assert s.kind == "projection", (s.kind, s.equation)
            assert "u — единичный вектор" in s.text["ru"] and "u is the unit vector" in s.text["en"]


def test_the_page_is_deterministic_and_carries_its_fonts(press):
    les = lesson(press, "acceleration", "(3)")
    one, two = teaching_page(les, "en"), teaching_page(les, "en")
    assert one == two
    from graphplan import fonts

    for fam in fonts.FONT_CHAIN:
        if fonts.find_font_file(fam) is not None:
            assert f"@font-face{{font-family:'{fam}'" in one
    assert len(one) < 400_000


# ------------------------------------------------------------------------- frames


def _items(g):
    return [e for e in g if e.tag != f"{SVG}text" and e.tag != f"{SVG}g"] + \
        [e for sub in g if sub.tag == f"{SVG}g" for e in sub]


def test_frames_colour_the_new_step_over_the_grey_ones(press):
    les = lesson(press, "acceleration", "2")
    earlier = 0
    for s in les.steps:
        root = ET.fromstring(frame_svg(les, s.number))
        groups = {g.get("class"): g for g in root.findall(f"{SVG}g")}
        new, old = groups["new"], groups["old"]
        def paint(g):  # strokes, and the fills of the arrowheads
            return ({e.get("stroke") for e in _items(g)} | {e.get("fill") for e in _items(g)
                                                           if e.tag == f"{SVG}polygon"}) - {
                None, "none"}

        strokes_new, strokes_old = paint(new), paint(old)
        assert strokes_old <= {GREY}
        assert strokes_new <= set(COLOURS.values())
        lines = [e for e in _items(new) if e.tag in (f"{SVG}line", f"{SVG}polyline")]
        if any(m.kind in ("vector", "line") for m in s.marks):
            assert lines, s.number
        n_old = sum(1 for e in _items(old) if e.tag == f"{SVG}line")
        assert n_old >= earlier  # nothing drawn before disappears
        earlier = n_old + len([e for e in lines if e.tag == f"{SVG}line"])
        # every mark lies inside the frame's viewBox (paper y is −y of the plan)
        x, y, w, h = (float(v) for v in root.get("viewBox").split())
        for m in s.marks:
            for px, py in m.points:
                assert x <= px <= x + w and y <= -py <= y + h


def test_frames_for_slides(press, tmp_path):
    les = lesson(press, "velocity", "2")
    files = write_lesson(les, tmp_path, lang="en", frames=True)
    assert files[0] == tmp_path / "teach-velocity-2.html"
    frames = sorted((tmp_path / "teach-velocity-2").glob("*.svg"))
    assert [f.name for f in frames] == [f"step-{i:02d}.svg" for i in range(1, 7)]
    for i, f in enumerate(frames, start=1):
        root = ET.parse(f).getroot()
        assert root.get("width").endswith("mm") and root.get("data-step") == str(i)
        texts = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
        assert any(f"{i}/6" in t for t in texts)
        style = "".join(root.find(f"{SVG}defs").itertext())
        assert "@font-face" in style or not style


# ---------------------------------------------------------------- the command line


def test_command_writes_the_pages(tmp_path, capsys):
    out = tmp_path / "out"
    press = str(bundled_example("press"))
    assert main(["teach", press, "--position", "2", "(2)", "--plan", "velocity", "flywheel",
                 "--lang", "en", "-o", str(out)]) == 0
    names = sorted(p.name for p in out.iterdir())
    assert names == ["teach-flywheel.html", "teach-index.html", "teach-velocity-(2).html",
                     "teach-velocity-2.html"]
    assert capsys.readouterr().out.count("steps") == 3
    assert page_name("forces", "(3)") == "teach-forces-(3).html"
    # a label that loses characters keeps its own name with a hash (issue 23)
    assert re.fullmatch(r"teach-velocity-a_b_c-[0-9a-f]{8}\.html", page_name("velocity", "a b/c"))


@pytest.mark.parametrize("argv, message", [
    (["--position", "9"], r"--position: expected one of 1, 2, .*\(got '9'\)"),
    ([], r"--position: the velocity plan needs a position"),
    (["--position", "1", "--plan", "flywheel"], None),
])
def test_command_errors_are_one_line(tmp_path, capsys, argv, message):
    press = str(bundled_example("press"))
    code = main(["teach", press, *argv, "-o", str(tmp_path)])
    err = capsys.readouterr().err
    if message is None:
        assert code == 0 and err == ""
        return
    assert code == 2
    assert err.count("\n") == 1 and re.search(message, err), err
    assert not list(tmp_path.iterdir())


def test_flywheel_without_delta_is_an_input_error(tmp_path, capsys):
    src = (examples_dir() / "press.toml").read_text(encoding="utf-8")
    variant = tmp_path / "no-delta.toml"
    variant.write_text(re.sub(r"(?m)^delta = .*$", "", src), encoding="utf-8")
    assert main(["teach", str(variant), "--plan", "flywheel", "-o", str(tmp_path)]) == 2
    assert "dynamics.delta is missing" in capsys.readouterr().err


# ---------------------------------------------------------------- notebook views


def test_notebook_views(press):
    sc = sheet_scales(press.mech, press.kin)
    plan = velocity_plan(press.mech, press.kin, 1, sc.kl, sc.kv)
    root = ET.fromstring(plan._repr_svg_())
    arrows = [g for g in root.iter(f"{SVG}g") if g.get("class") == "arrow"]
    assert len(arrows) == len({e.name for s in plan.steps for e in s.elements
                               if e.kind == "segment" and e.start != e.end})
    ctx = press
    from graphplan.plans import force_plans

    fp = force_plans(press.mech, press.kin, ctx.forces, ctx.loads, 1, sc.kl)[0]
    texts = ["".join(t.itertext()) for t in ET.fromstring(fp._repr_svg_()).iter(f"{SVG}text")]
    assert any(q in " ".join(texts) for q in fp.readings)
    from graphplan.drawing import kinematics_sheet

    sheet_svg = kinematics_sheet(press, diagrams=False)._repr_svg_()
    root = ET.fromstring(sheet_svg)
    assert root.get("width") == "100%" and root.get("height") is None
    assert root.get("viewBox") == "0 0 841 594"
    les = lesson(press, "velocity", "2")
    frame = les._repr_html_()
    assert frame.startswith("<iframe srcdoc=") and 'sandbox="allow-scripts"' in frame
    assert html.unescape(re.search(r'srcdoc="([^"]*)"', frame)[1]) == teaching_page(les, "ru")


def test_groups_carry_their_russian_names():
    from graphplan.teaching.captions import group_name

    assert group_name("RPR(2-3)", "ru") == "группа Ассура II класса 2-го порядка ВПВ (звенья 2–3)"
    assert group_name("PRP(4-5)", "ru").endswith("ПВП (звенья 4–5)")
    assert group_name("RRP(2-3)", "en") == "Assur group of class II, order 2, RRP (links 2–3)"


def test_russian_words_replace_the_constructions_english(press):
    les = lesson(press, "velocity", "2")
    text = teaching_page(les, "ru")
    assert "через" in text and " through " not in re.sub(r"<svg.*?</svg>", "", text, flags=re.S)
    assert localise("ΣM_B(link 2): Rτ12·AB = 0", "ru") == "ΣM_B(звено 2): Rτ12·AB = 0"
    assert num(423918.40231) == "423918" and num(0.421887) == "0.4219"
    # never an exponent: a student writes 15850000 N·mm and 0.00001234 m, not 1.585·10^7
    assert num(1.5849e7) == "15850000" and num(1.2341e-5) == "0.00001234"


# ------------------------------------------------------------- the committed pages


COMMITTED = Path(__file__).resolve().parent.parent / "drawings" / "press"


LESSONS = sorted(p for p in COMMITTED.glob("teach-*.html") if p.name != "teach-index.html")


@pytest.mark.parametrize("page", LESSONS, ids=lambda p: p.name)
def test_committed_pages_are_up_to_date(press, page):
    """The pages in drawings/press are what `graphplan teach` writes now (structure and
    every reading; regenerate with the command in graphplan/teaching/command.py)."""
    m = re.fullmatch(r"teach-([a-z]+)(?:-(.+))?\.html", page.name)
    les = lesson(press, m[1], m[2])
    text = page.read_text(encoding="utf-8")
    lang = re.search(r'<html lang="(\w+)">', text)[1]
    fresh = teaching_page(les, lang)

    def shape(t):
        return (re.findall(r'data-kind="(\w+)"', t),
                [round(float(x), 6) for x in re.findall(r'data-mm="([^"]+)"', t)])

    assert shape(text) == shape(fresh)


def test_the_committed_index_lists_every_committed_lesson():
    """drawings/press/teach-index.html is what `graphplan teach` writes for that folder."""
    from graphplan.teaching.index import index_page

    fresh = index_page(COMMITTED, variant="Кривошипный пресс",
                       labels=("1", "2", "3", "4", "5", "6", "7", "8", "(2)", "(3)"))
    links = re.findall(r'href="([^"]+)"', (COMMITTED / "teach-index.html").read_text("utf-8"))
    assert links == re.findall(r'href="([^"]+)"', fresh)
    assert sorted(links) == [p.name for p in LESSONS]


def _page_words(page: str) -> set[str]:
    """Latin words of 3+ letters in a page's visible text (no scripts, styles, drawings),
    the English units after numbers (``232.7 N``, ``0.42 m/s``) and round-off numbers."""
    for tag in ("script", "style", "svg"):
        page = re.sub(rf"<{tag}.*?</{tag}>", " ", page, flags=re.S)
    text = html.unescape(re.sub(r"<[^>]+>", " ", page))
    units = re.findall(r"\d[\s\u00a0](N|N·m|N·mm|mm|m|m/s|m/s²|rad/s|rad/s²)(?![\w/²])", text)
    # round-off (a dead centre's 1e-16 m/s) is written 0, never as a number of 1e-10 or less
    tiny = re.findall(r"\d(?:e-|·10\^-)(?:1\d|[2-9]\d)", text)
    return set(re.findall(r"(?<![\w_·/])[a-zA-Z]{3,}(?![\w_])", text)) | set(units) | set(tiny)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_a_russian_page_speaks_russian(path):
    # the words the page may keep: keys, file names, the kinds of groups, the scales' names
    # (no RRR, RRP…: a Russian page names the groups ВВВ, ВВП, ВПВ, ПВП, ВПП)
    allowed = {"Home", "End", "PgUp", "PgDn", "lOA",
               "DIR", "graphplan", "teach", "toml", "lang", "plan", "position", "examples",
               path.stem, *path.stem.split("_"), "forces", "velocity", "acceleration",
               "zhukovsky", "lAB", "lBC", "lCD", "lO3A", "lAO3"}
    an = analyze(load(path))
    for plan in ("velocity", "acceleration", "forces", "zhukovsky"):
        for label in an.kin.labels:
            words = _page_words(teaching_page(lesson(an, plan, label), "ru")) - allowed
            assert not words, (path.stem, plan, label, sorted(words))


def test_embedded_fonts_keep_their_own_date():
    # fontTools stamps a saved font with the time of saving unless told not to: the pages
    # would then differ from run to run (the committed ones churned on every regeneration)
    import io as _io

    from fontTools.ttLib import TTFont

    from graphplan import fonts
    from graphplan.teaching.webfonts import _subset_woff

    family = fonts.FONT_CHAIN[0]
    woff = _subset_woff(family, "Планvb0123")
    assert woff is not None
    with TTFont(str(fonts.find_font_file(family)), lazy=True) as src:
        original = src["head"].modified
    assert TTFont(_io.BytesIO(woff))["head"].modified == original


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_try_it_asks_directions_and_senses(path, analysis_of):
    """«Проверь себя» asks which way each derived ω and ε turns (the right option is the
    exact solver's sense), where each normal acceleration points (from the point toward
    the centre) and where each Coriolis acceleration points (the relative velocity turned
    by 90° in the sense of ω); the page carries each question with its right option."""
    from graphplan.teaching.questions import SENSES, questions

    a = analysis_of(path)
    kin = a.kin
    asked = {"sense": 0, "normal": 0, "coriolis": 0}
    senses = 0
    for k in range(kin.n):
        for plan, table in (("velocity", kin.vel.omega), ("acceleration", kin.acc.epsilon)):
            les = lesson(a, plan, kin.labels[k])
            page = teaching_page(les, "ru")
            quizzes = re.findall(r'<div class="quiz try-only" data-correct="(\d)"', page)
            n_questions = 0
            for s in les.steps:
                senses += sum(n["en"].endswith("clockwise") for n in s.notes)
                for lang in ("ru", "en"):
                    qs = questions(s, lang)
                    for q in qs:
                        right = q.options[q.correct]
                        assert len(set(q.options)) == len(q.options) >= 2
                        m = re.search(r"(ω|ε)(\d+) ", q.prompt)
                        if right in SENSES[lang]:
                            exact = table[m[2]][k]
                            assert right == SENSES[lang][bool(exact > 0)], (q, exact)
                            asked["sense"] += lang == "ru"
                        elif "aⁿ_" in q.prompt:
                            tip, base = re.search(r"aⁿ_([A-Z][a-z]*\d*)([A-Z]\w*)", q.prompt
                                                  ).groups()
                            assert right.endswith((f"от {tip} к {base}",
                                                   f"from {tip} toward {base}")), q
                            asked["normal"] += lang == "ru"
                        else:
                            assert right.endswith(("в сторону вращения ω" + s.equation.split(
                                "·ω")[1].split("·")[0], "in the sense of ω" + s.equation.split(
                                "·ω")[1].split("·")[0])), q
                            asked["coriolis"] += lang == "ru"
                    if lang == "ru":
                        n_questions += len(qs)
                        for q in qs:
                            assert html.escape(q.prompt, quote=False).replace(
                                "_", "") in page.replace("<sub>", "").replace("</sub>", "")
            assert len(quizzes) == n_questions
    assert asked["sense"] == senses  # every derived ω and ε with a sense is asked
    if any(s.kind == "lay" and "aᵏ" in s.equation for k in range(kin.n)
           for s in lesson(a, "acceleration", kin.labels[k]).steps if "ω" in s.text["en"]
           and " = 0, no Coriolis" not in s.text["en"]):
        assert asked["coriolis"] >= 1
