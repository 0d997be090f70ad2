"""Variants nobody wrote the code for (tests/data/variants/), and the warnings of a machine
that is probably not the one meant.

* The output against its working direction: a resistance given with its own sign (a force
  along a fixed ``angle``) on the working stroke must do negative work there. Each variant
  is flipped each way — the other assembly branch, the other ``output.working``, the other
  sense of rotation — and the warning must fire exactly when the force does positive work,
  name the changes that remove it, and those changes must remove it.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.forces import point_velocity
from graphplan.kinematics import analyse_cycle, link_coordinate, solve_positions
from graphplan.model import load, loads
from graphplan.project import analyze
from graphplan.project.plausibility import load_work

ROOT = Path(__file__).resolve().parent.parent
VARIANTS = ROOT / "tests" / "data" / "variants"


def _text(name: str, **edits: str) -> str:
    text = (VARIANTS / f"{name}.toml").read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _warnings(text: str, source: str) -> tuple[str, ...]:
    return analyze(loads(text, source=source)).warnings


# --- the output against its working direction ----------------------------------------------

BRANCH = {'branch = "+"           # B to the left': 'branch = "-"           # B to the left'}
WORKING = {'working = "+"          # the working swing': 'working = "-"          # the working '
           'swing'}
CW = {'direction = "ccw"': 'direction = "cw"'}


def test_no_warning_as_written():
    for path in sorted(VARIANTS.glob("*.toml")):
        assert analyze(load(path)).warnings == (), path.name


def test_the_other_branch_makes_the_resistance_drive():
    # B below the frame line: the rocker swings over −141°…−101°, and its CCW working swing
    # moves B to the right, with the force Fс along +x
    (w,) = _warnings(_text("fourbar_force", **BRANCH), "fb-branch.toml")
    assert w.startswith("fb-branch.toml: loads[0] (Fс): given on the working stroke, it does "
                        "positive work over it (+")
    assert "\n" not in w
    assert w.endswith('likely fix: output.working = "-" / dyads[0].branch = "+"'), w
    # each fix it names removes the warning
    assert _warnings(_text("fourbar_force", **BRANCH, **WORKING), "fixed.toml") == ()
    assert _warnings(_text("fourbar_force"), "fixed.toml") == ()


def test_the_other_working_sense_makes_the_resistance_drive():
    (w,) = _warnings(_text("fourbar_force", **WORKING), "fb-working.toml")
    assert w.endswith('likely fix: output.working = "+" / dyads[0].branch = "-"'), w


def test_the_other_sense_of_rotation_keeps_the_working_swing():
    # turning the crank the other way swaps the strokes' crank angles, not the rocker's
    # working sense: the force still resists, no warning about it
    assert not any("positive work" in w for w in _warnings(_text("fourbar_force", **CW),
                                                             "fb-cw.toml"))


def test_a_crusher_force_on_the_jaw_flipped():
    text = _text("crusher_force", **{'working = "-"': 'working = "+"'})
    (w,) = _warnings(text, "crusher-plus.toml")
    assert "loads[0] (Fс)" in w and w.endswith('likely fix: output.working = "-"'), w


def test_a_load_on_another_links_working_stroke_out_of_step():
    # the shaper's ram cuts moving left (working = "-"); its rocker 3 then turns CCW, so a
    # moment on the rocker over ITS "working" swing with x taking "-" (CW) comes on the
    # ram's return: 0 % of it in the working stroke; loads[1].working = "+" puts it back
    text = _example("shaper")
    extra = ('[[loads]]\nname = "Mтр"\nkind = "moment"\nlink = "3"\nmax = 100\n'
             'diagram = [[0.0, 1.0], [1.0, 1.0]]\n\n[positions]')
    text = text.replace("[positions]", extra, 1)
    (w,) = _warnings(text, "shaper-m3.toml")
    assert w == ('shaper-m3.toml: loads[1] (Mтр): given on the working stroke of link 3, '
                 'whose x runs with working = "-", it comes while the output makes its idle '
                 'stroke (0 % of it in the working stroke); likely fix: loads[1].working = "+"')
    fixed = text.replace('name = "Mтр"', 'name = "Mтр"\nworking = "+"')
    assert _warnings(fixed, "shaper-m3.toml") == ()


@pytest.mark.parametrize("flip", [{}, BRANCH], ids=["as written", "other branch"])
def test_load_work_is_the_line_integral_of_the_force(flip):
    """The warning's work against an independent sum over the positions alone: the force
    is ``f(x)·600 N`` along +x at B, so ``W = Σ F_x·Δx_B`` (midpoint F, Δx from the plan
    of positions, no velocities), 20 000 steps."""
    mech = loads(_text("fourbar_force", **flip), source="fb.toml")
    cycle = analyse_cycle(mech)
    work, scale = load_work(mech, cycle, 0)
    from graphplan.forces import resistance_loads
    from graphplan.kinematics import solve

    tau = np.linspace(0.0, 2 * math.pi, 20001)
    phi = cycle.origin + mech.crank.sense * tau
    xB = solve_positions(mech, phi).points["B"][:, 0]
    mid = cycle.origin + mech.crank.sense * 0.5 * (tau[1:] + tau[:-1])
    Fx = resistance_loads(mech, solve(mech, mid), cycle)[0].vector[:, 0]
    by_positions = float(np.sum(Fx * np.diff(xB)))
    assert work == pytest.approx(by_positions, rel=1e-4)
    assert scale >= abs(work) > 0
    assert (work < 0) == (not flip)
    # the rocker's travel over the working swing has the stated sign (CCW: θ3 grows)
    lt = cycle.travels[("3", 1)]
    pos = solve_positions(mech, np.asarray(lt.dead_centres))
    q = link_coordinate(mech, "3", pos)[1]
    assert (q[1] - q[0]) % (2 * math.pi) < math.pi


# --- a driving link that cannot turn, a translating driver ----------------------------------


def _example(name: str, **edits: str) -> str:
    text = (ROOT / "examples" / f"{name}.toml").read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _error(tmp_path, capsys, text: str) -> tuple[Path, str]:
    from graphplan.cli import main

    path = tmp_path / "variant.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err  # one line
    return path, err


def test_a_crank_longer_than_the_rod_reaches_two_ranges(tmp_path, capsys):
    # the press (guide vertical through O) with l_OA = 250 > l_AB = 200 mm: A stays within
    # reach of the guide while |x_A| = 0.25·|cos φ| ≤ 0.2, i.e. |cos φ| ≤ 0.8:
    # φ in 36.87°…143.13° and 216.87°…323.13° (acos 0.8 = 36.87°)
    _, err = _error(tmp_path, capsys, _example("press", **{"length = 80 ": "length = 250 "}))
    m = re.search(r"closes only for φ in ([0-9.]+)°…([0-9.]+)° \(([0-9.]+)°\), "
                  r"([0-9.]+)°…([0-9.]+)° \(([0-9.]+)°\), so link 1 can only rock within one "
                  r"of these ranges — shorten crank.length", err)
    assert m, err
    a = math.degrees(math.acos(0.8))
    got = [float(m.group(i)) for i in (1, 2, 4, 5)]
    assert got == pytest.approx([a, 180 - a, 180 + a, 360 - a], abs=0.01)
    assert "exceeds lAB = 0.2 m" in err  # the cause: A too far from the guide


def test_a_four_bar_names_grashof_in_numbers(tmp_path, capsys):
    # crank 300 mm, coupler 350, rocker 300, frame 400: 0.3 + 0.4 = 0.7 > 0.3 + 0.35 = 0.65;
    # |AC|² = 0.3² + 0.4² − 2·0.3·0.4·cos φ ≤ 0.65² ⇔ cos φ ≥ −0.71875: φ within ±135.95°
    _, err = _error(tmp_path, capsys, _example("fourbar", **{"length = 100 ": "length = 300 "}))
    assert "(Grashof: l_min + l_max = 0.3 + 0.4 = 0.7 m > 0.3 + 0.35 = 0.65 m)" in err
    m = re.search(r"closes only for φ in ([0-9.]+)°…([0-9.]+)° \(([0-9.]+)°\), so link 1 can "
                  r"only rock within that range", err)
    assert m, err
    b = math.degrees(math.acos(-0.71875))
    assert [float(m.group(1)), float(m.group(2))] == pytest.approx([360 - b, b], abs=0.01)


@pytest.mark.parametrize(("edit", "key", "words"), [
    ({"[crank]\n": '[crank]\nkind = "slider"\n'}, "crank.kind",
     "the driving link must turn, not slide"),
    ({"[crank]\n": '[crank]\nguide = { link = "4", through = "O", angle = 0 }\n'},
     "crank.guide", "the driving link must turn, not slide"),
    ({"[crank]\n": '[cylinder]\nlink = "1"\nstroke = 200\n\n[crank]\n'}, "cylinder",
     "a translating driver is not supported"),
    ({"[crank]\n": '[driver]\nkind = "hydraulic"\n\n[crank]\n'}, "driver",
     "a translating driver is not supported"),
    ({"[crank]\n": '[driver]\nkind = "crank"\n\n[crank]\n'}, "driver",
     "the driving link is described in [crank]"),
])
def test_a_translating_driver_is_one_line_with_the_reason(tmp_path, capsys, edit, key, words):
    path, err = _error(tmp_path, capsys, _example("fourbar", **edit))
    assert err.startswith(f"graphplan: error: {path}: {key}: {words}"), err
    if "translating" in words or "slide" in words:
        assert "has no ω1 to reduce Mур, Mпр and Jпр to" in err


# --- every unseen variant: the JSON, the A1 sheets, the power balance -----------------------

ALL = sorted(p.stem for p in VARIANTS.glob("*.toml"))


def _no_nan(constant):
    raise AssertionError(f"{constant} in the JSON")


@pytest.mark.parametrize("name", ALL)
def test_analyze_json_and_sheets_of_every_unseen_variant(name, tmp_path, capsys):
    from graphplan.cli import main

    path = VARIANTS / f"{name}.toml"
    out = tmp_path / "a.json"
    assert main(["analyze", str(path), "--json", "-o", str(out)]) == 0
    report = json.loads(out.read_text(encoding="utf-8"), parse_constant=_no_nan)
    assert report["warnings"] == []
    try:
        import jsonschema  # noqa: F401  (the test extra's; without it the schema is not checked)
    except ImportError:
        pass
    else:  # tests/ is on sys.path (conftest): this import failed silently when run alone
        from test_json_contract import validate

        validate(report, "analysis")
    sheets = tmp_path / "sheets"
    assert main(["sheets", str(path), "-o", str(sheets), "--page", "A1"]) == 0
    assert {"sheet1.svg", "sheet2.svg", "sheet3.svg", "analysis.json"} <= {
        f.name for f in sheets.iterdir()}
    for f in sheets.iterdir():
        text = f.read_text(encoding="utf-8")
        assert not re.search(r"\b(nan|inf|infinity)\b", text, re.IGNORECASE), f.name
    json.loads((sheets / "analysis.json").read_text(encoding="utf-8"), parse_constant=_no_nan)
    capsys.readouterr()


@pytest.mark.parametrize("name", ALL)
def test_power_balance_of_every_unseen_variant(name):
    """Σ F·v + Σ M·ω + Mур·ω1 = 0 at every position, with the variant's neglect rule and
    with every load kept, to 1e-9 of the largest power term."""
    from graphplan.forces import compute_loads, load_power, solve_forces

    a = analyze(load(VARIANTS / f"{name}.toml"))
    mech, kin = a.mech, a.kin
    for neglect in (None, 0.0):
        ld = compute_loads(mech, kin, a.cycle, neglect_below=neglect)
        M_bal = solve_forces(mech, kin, ld).M_bal
        terms = [np.einsum("ij,ij->i", f.vector, point_velocity(mech, kin, f.link, f.at))
                 for f in ld.all_forces()]
        terms += [m.moment * kin.vel.omega[m.link] for m in ld.all_moments()]
        scale = float(np.max(np.abs(terms)))
        resid = load_power(mech, kin, ld) + M_bal * mech.crank.omega
        assert scale > 0 and np.all(np.isfinite(M_bal))
        assert np.max(np.abs(resid)) <= 1e-9 * scale, name


def test_the_pump_by_crank_angle_is_the_pump_by_strokes():
    """The same water force given over the crank angle in kN and as gauge pressures over
    the strokes: Mур equal at every position off the dead centres (where the force jumps)."""
    from graphplan.forces import compute_loads, solve_forces

    out = []
    for path in (ROOT / "examples" / "pump.toml", VARIANTS / "pump_crank_angle.toml"):
        a = analyze(load(path))
        ld = compute_loads(a.mech, a.kin, a.cycle, neglect_below=0.0)
        out.append((a.kin.labels, solve_forces(a.mech, a.kin, ld).M_bal))
    (labels, m0), (labels1, m1) = out
    assert labels == labels1
    off = [k for k, lab in enumerate(labels) if lab not in ("0", "6")]
    assert np.allclose(m0[off], m1[off], rtol=1e-9, atol=1e-9 * np.max(np.abs(m0)))


def test_loads_in_kN_are_newtons_inside():
    shaper = load(VARIANTS / "shaper_part.toml")
    cut, friction = shaper.resistances
    assert cut.maximum == pytest.approx(4000.0) and friction.strokes[0][0][1] == 150.0
    fourbar = load(VARIANTS / "fourbar_cw.toml")
    assert fourbar.resistances[0].maximum == pytest.approx(250.0)
    assert fourbar.crank.omega == pytest.approx(-12.0)  # 12 rad/s, clockwise


@pytest.mark.parametrize("spelling", ["кгс/см2", "кгс/см²", "ат", "at", "kgf/cm²"])
def test_pressures_in_the_books_own_spelling(spelling):
    """The two-stage compressor's pressures in кгс/см² as the older task books write them
    (кгс/см², ат): the same gas forces as "kgf/cm2" at every position; the gas force of
    stage II at its ВМТ is (8.5 − 1)·98 066.5 Pa·π·0.075²/4 = 3249.33 N."""
    from graphplan.forces import compute_loads

    def forces(text):
        a = analyze(loads(text, source="v.toml"))
        ld = compute_loads(a.mech, a.kin, a.cycle, neglect_below=0.0)
        return np.array([np.hypot(*f.vector.T) for f in ld.all_forces() if f.name[:2] == "Fг"])

    text = (VARIANTS / "v_two_stage_compressor.toml").read_text(encoding="utf-8")
    assert text.count('pressure_unit = "kgf/cm2"') == 2
    want = forces(text)
    got = forces(text.replace('pressure_unit = "kgf/cm2"', f'pressure_unit = "{spelling}"'))
    assert np.array_equal(got, want)
    assert float(want[1].max()) == pytest.approx(7.5 * 98066.5 * math.pi * 0.075**2 / 4,
                                                 rel=1e-12)


def test_an_extra_position_on_the_grid_is_a_warning():
    """The rotating-кулиса slotter's end dead centre is at φ = 60°, position 8 of its 12
    (300° − 8·30° clockwise): '0'' given there as well would be drawn twice — a warning
    naming the key and both labels; off the grid (the 'a' at 5 % of the stroke) nothing."""
    text = (VARIANTS / "slotter_rotating.toml").read_text(encoding="utf-8")
    twice = text.replace('extra = [{ label = "a"', 'extra = [{ label = "0\'", from = "end" }, '
                         '{ label = "a"')
    (w,) = _warnings(twice, "s.toml")
    assert w.startswith("s.toml: positions.extra[0] ('0''): φ = 60.00°, the crank angle of "
                        "position '8'")
    assert _warnings(text, "s.toml") == ()
