"""Tables of the plans: every reading checked against the exact kinematics."""

import csv
import io
import math
import re

import numpy as np
import pytest

from graphplan.geometry import norm
from graphplan.reports.plan_tables import (
    CSV_COLUMNS,
    SUMMARY_CELL,
    plan_readings,
    plan_table_rows,
    plans_csv,
    plans_markdown,
    rate_table_rows,
    summary_rows,
)

EXAMPLES = ("press", "fourbar", "shaper")
NAN_INF = re.compile(r"\b(nan|inf)\b", re.IGNORECASE)


@pytest.fixture
def analysis(solved):
    """``analysis(name)`` → the session's solved project of an example (tests/conftest.py)."""
    return solved


@pytest.fixture
def output(solved):
    """``output(fn, name, lang, precision)`` → one function's output, built once per project
    (a stage of the session's project; the plans take ~30 ms a variant)."""

    def get(fn, name, lang="en", precision=0.0):
        a = solved(name)
        if fn is summary_rows:
            return a.stage(("tables", fn.__name__, lang), lambda: fn(a, lang))
        return a.stage(("tables", fn.__name__, lang, precision),
                       lambda: fn(a, lang, precision))

    return get


@pytest.fixture
def csv_rows(output):
    """``csv_rows(name, precision, lang)`` → the rows of the plans' CSV."""

    def get(name, precision, lang="en"):
        return list(csv.DictReader(io.StringIO(output(plans_csv, name, lang, precision))))

    return get


# --- the solver's value of a reading quantity ----------------------------------------------
# Quantities name points: ``vB`` (point B), ``vBA`` (B relative to A), ``vA3`` (the point of
# link 3 at A: a token that is not a point name is a point name plus a link number),
# ``aⁿBA``/``aτBA`` (components of B about A on the link turning about A), and the
# Coriolis/relative terms ``aᵏ…``/``aʳ…`` of a sliding pair.


def _link_point(a, X, link):
    """Position, velocity, acceleration of the point of ``link`` at X, by rigid-body motion."""
    m, kin = a.mech, a.kin
    R = next(p for p in m.points_of(link) if p != X)
    r = kin.pos.points[X] - kin.pos.points[R]
    w, e = kin.vel.omega[link][:, None], kin.acc.epsilon[link][:, None]
    rp = np.stack([-r[:, 1], r[:, 0]], axis=1)
    return kin.vel.points[R] + w * rp, kin.acc.points[R] + e * rp - w**2 * r


def _vectors(a, token):
    kin = a.kin
    if token in kin.pos.points:
        return kin.vel.points[token], kin.acc.points[token]
    point, link = re.fullmatch(r"([A-Z])(\d+)", token).groups()
    return _link_point(a, point, link)


def _turning_link(a, X, Y):
    m = a.mech
    moving = [ln for ln in m.moving_links if Y in m.points_of(ln)]
    both = [ln for ln in moving if X in m.points_of(ln)]
    return (both or moving)[0]


def solver_value(a, k, plan, quantity):
    """|value| of a quantity from ``kin.vel``/``kin.acc``: a set (of candidates for aᵏ, aʳ)."""
    kin = a.kin
    if quantity.startswith("aᵏ"):
        return {float(norm(c[k])) for c in kin.acc.coriolis.values()}
    if quantity.startswith("aʳ"):
        return {abs(float(s[k])) for s in kin.acc.sliding.values()}
    head = re.match(r"(v|aⁿ|aτ|a)", quantity).group(1)
    tokens = re.findall(r"[A-Z]\d*", quantity[len(head):])
    if head in ("aⁿ", "aτ"):
        X, Y = tokens
        ln = _turning_link(a, X, Y)
        length = float(norm(kin.pos.points[X][k] - kin.pos.points[Y][k]))
        rate = kin.vel.omega[ln][k] ** 2 if head == "aⁿ" else abs(kin.acc.epsilon[ln][k])
        return {float(rate * length)}
    i = 0 if plan == "velocity" else 1
    vec = _vectors(a, tokens[0])[i][k]
    if len(tokens) == 2:
        vec = vec - _vectors(a, tokens[1])[i][k]
    return {float(norm(vec))}


def _close(x, candidates, rel, abs_):
    return any(x == pytest.approx(c, rel=rel, abs=abs_) for c in candidates)


# --- tests -------------------------------------------------------------------------------


@pytest.mark.parametrize("name", EXAMPLES)
def test_exact_csv_equals_the_kinematics(analysis, csv_rows, name):
    a = analysis(name)
    index = {label: k for k, label in enumerate(a.kin.labels)}
    rows = csv_rows(name, 0.0)
    assert rows and set(rows[0]) == set(CSV_COLUMNS)
    seen = set()
    for r in rows:
        k = index[r["position"]]
        value = float(r["value"])
        assert float(r["exact_value"]) == value
        if r["kind"] == "segment":
            seen.add(r["quantity"])
            tol = 1e-6 * float(r["scale_per_mm"])  # a micrometre of drawing
            assert _close(value, solver_value(a, k, r["plan"], r["quantity"]), 1e-6, tol), r
        else:
            table = a.kin.vel.omega if r["plan"] == "velocity" else a.kin.acc.epsilon
            assert value == pytest.approx(float(table[r["name"]][k]), rel=1e-6, abs=1e-5), r
    # every point of the solver is read on both plans (frame points are the pole)
    moving = [p for p in a.kin.point_names() if p not in a.mech.frame_points]
    assert {f"v{p}" for p in moving} | {f"a{p}" for p in moving} <= seen


@pytest.mark.parametrize("name", EXAMPLES)
@pytest.mark.parametrize("precision", [0.0, 0.5])
def test_mm_times_scale_is_the_value(csv_rows, name, precision):
    for r in csv_rows(name, precision):
        if r["kind"] == "segment":
            mm, value = float(r["mm"]), float(r["value"])
            assert mm * float(r["scale_per_mm"]) == pytest.approx(value, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("name", EXAMPLES)
def test_drafting_mode_reads_to_half_a_millimetre(csv_rows, output, name):
    n_err = 0
    for r in csv_rows(name, 0.5):
        if r["kind"] == "segment":
            steps = float(r["mm"]) / 0.5
            assert abs(steps - round(steps)) < 1e-9, r
        if r["error_pct"]:
            value, exact = float(r["value"]), float(r["exact_value"])
            assert float(r["error_pct"]) == pytest.approx((value - exact) / exact * 100, rel=1e-9)
            n_err += 1
        else:  # no relative error only where the exact value is zero (or not drawn)
            assert r["exact_value"] in ("", "0.0"), r
    assert n_err > 0
    head, rows = output(plan_table_rows, name, "en", 0.5)
    assert head[-2:] == ["Exact", "Error, %"] and all(len(r) == len(head) for r in rows)


@pytest.mark.parametrize("name", EXAMPLES)
@pytest.mark.parametrize("precision", [0.0, 0.5])
def test_ru_and_en_tables_have_the_same_columns(analysis, output, name, precision):
    for table in (plan_table_rows, rate_table_rows, summary_rows):
        (he, re_), (hr, rr) = (output(table, name, lang, precision) for lang in ("en", "ru"))
        assert len(he) == len(hr) and he != hr
        assert len(re_) == len(rr) > 0
        assert all(len(r) == len(he) for r in re_ + rr)
    assert output(plan_table_rows, name, "ru", precision)[0][:2] == ["Положение", "φ, °"]
    assert output(plan_table_rows, name, "en", precision)[0][:2] == ["Position", "φ, °"]
    with pytest.raises(ValueError, match="language"):
        summary_rows(analysis(name), "de")


@pytest.mark.parametrize("name", EXAMPLES)
@pytest.mark.parametrize("precision", [0.0, 0.5])
def test_no_nan_or_inf_anywhere(output, name, precision):
    texts = [output(fn, name, lang, precision) for fn in (plans_markdown, plans_csv)
             for lang in ("en", "ru")]
    for table in (plan_table_rows, rate_table_rows, summary_rows):
        head, rows = output(table, name, "ru", precision)
        texts.append("\n".join("|".join(r) for r in [head, *rows]))
    for t in texts:
        assert not NAN_INF.search(t)


def test_press_position_2_reads_pa_as_va_over_kv(analysis, output):
    a = analysis("press")
    kl, kv = a.sheet1.kl, a.sheet1.kv
    # By hand: ω1 = π·n1/30 = π·55/30 = 5.7596 rad/s; vA = ω1·lOA = 5.7596·0.08 = 0.4608 m/s.
    # The press gets Kv = 0.01 (m/s)/mm (the sheet's grid of plans; it was 0.005 before
    # the sheet's scales), so pa = vA/Kv = 0.4608/0.01 = 46.08 mm.
    va = math.pi * 55 / 30 * 0.08
    assert va == pytest.approx(0.4608, abs=5e-5)
    pa = va / kv.per_mm
    rows = output(plan_table_rows, "press")[1]
    row = next(r for r in rows if r[0] == "2" and r[2] == "pa")
    assert row[3] == f"{pa:.2f}"
    assert row[4] == f"Kv = {kv.per_mm:g} (m/s)/mm" and row[5] == "vA"
    assert row[6] == "0.4608 m/s"
    md = output(plans_markdown, "press")
    assert kv.basis in md and kl.basis == "Kl = lOA/OA = 0.08/80 = 0.001 m/mm" and kl.basis in md
    section = md.split("## Position 2,")[1].split("## Position")[0]
    assert f"| `pa` | {pa:.2f} |" in section
    assert "ω2 = vBA/lAB = " in section and "ε2 = aτBA/lAB = " in section


def test_rates_as_a_student_writes_them(analysis, output):
    a = analysis("press")
    rows = output(rate_table_rows, "press")[1]
    w2 = next(r for r in rows if r[0] == "2" and r[2] == "2")
    k = a.kin.labels.index("2")
    vba = float(norm(a.kin.vel.points["B"][k] - a.kin.vel.points["A"][k]))
    omega = a.kin.vel.omega["2"][k]
    assert w2[3] == f"ω2 = vBA/lAB = {vba:.4g}/0.2 = {abs(omega):.4g} rad/s"
    assert w2[4] == f"{omega:.4g} rad/s"
    shaper = output(rate_table_rows, "shaper", "ru")[1]
    assert any(r[3].startswith("ω3 = vA3/lO3A = ") for r in shaper)
    assert any(r[3] == "ω5 = 0 (поступательное движение)" for r in shaper)


def test_plan_readings_builds_exact_plans_in_drafting_mode(analysis):
    a = analysis("press")
    exact, drawn = plan_readings(a), plan_readings(a, 0.5)
    assert len(exact) == len(drawn) == a.kin.n
    assert exact[0].exact_velocity is exact[0].velocity
    assert drawn[0].exact_velocity is not drawn[0].velocity
    assert drawn[1].exact_velocity.readings["pb"].value == exact[1].velocity.readings["pb"].value
    assert 0 <= drawn[1].phi_deg < 360
    with pytest.raises(AttributeError):
        drawn[0].label = "x"
    with pytest.raises(ValueError):
        plan_readings(a, -1)


@pytest.mark.parametrize("name", EXAMPLES)
def test_summary_fits_the_sheet(analysis, output, name):
    a = analysis(name)
    head, rows = output(summary_rows, name, "ru")
    assert len(rows) == a.kin.n
    assert all(len(c) <= SUMMARY_CELL for c in head)
    assert all(len(c) <= SUMMARY_CELL for r in rows for c in r)
    assert all(len(r) == len(head) for r in rows)
    for c, h in enumerate(head[2:], start=2):
        sym, quantity = h.split(",")[0], h[0]
        for k, r in enumerate(rows):
            if quantity in "va":
                arr = (a.kin.vel if quantity == "v" else a.kin.acc).points[sym[1:]]
                x = float(norm(arr[k]))
            else:
                x = float((a.kin.vel.omega if quantity == "ω" else a.kin.acc.epsilon)[sym[1:]][k])
            assert float(r[c]) == pytest.approx(x, rel=5e-3, abs=1e-6)
    if name == "shaper":  # the block 2 turns with the rocker 3: ω3 only
        assert "ω3, с⁻¹" in head and "ω2, с⁻¹" not in head
    if name == "press":
        assert head[:4] == ["Пол.", "φ, °", "vB, м/с", "aB, м/с²"] and "ω2, с⁻¹" in head
