"""A calculation graphplan writes itself passes clean; each injected fault is caught once,
with the right kind, at its position."""

import random
from pathlib import Path

import numpy as np
import pytest

from graphplan.checking.checks import check_work, checker_for, reference_for
from graphplan.checking.diagnosis import Diagnoser
from graphplan.checking.generate import FAULT_KINDS, KIND_OF_FAULT, generate, inject
from graphplan.checking.student import loads_student
from graphplan.files import bundled_example

PRESS = bundled_example("press")
EXAMPLES = Path(PRESS).parent


@pytest.fixture(scope="module")
def press():
    return generate(PRESS)


def _check(gen, tmp="<generated>.toml", **kw):
    return check_work(loads_student(gen.toml(), tmp), **kw)


def _faults_found(report):
    return {(f.position, f.quantity, f.kind) for f in report.findings
            if f.verdict == "wrong" and f.primary}


def test_generated_press_passes_clean(press):
    r = _check(press)
    c = r.counts()
    assert r.findings == () and r.ok
    assert c["wrong"] == c["inaccurate"] == 0
    assert c["ok"] > 300  # every figure of 10 positions was compared, none left out
    assert all(ln.arithmetic in ("ok", "") for ln in r.lines)


@pytest.mark.parametrize("name", ["fourbar", "offset_slider", "scotch_yoke", "shaper",
                                  "sixbar_press"])
def test_generated_work_of_every_dyad_kind_passes_clean(name):
    r = _check(generate(EXAMPLES / f"{name}.toml"))
    assert r.findings == ()
    assert r.counts()["ok"] > 200


PRESS_KINDS = tuple(k for k in FAULT_KINDS if not k.startswith("coriolis"))  # none in a press


@pytest.mark.parametrize("kind", PRESS_KINDS)
@pytest.mark.parametrize("seed", range(4))
def test_each_fault_is_caught_once_with_its_kind(press, kind, seed):
    rng = random.Random(1000 * seed + FAULT_KINDS.index(kind))
    faulty, (fault,) = inject(press, (kind,), rng)
    found = _faults_found(_check(faulty))
    assert found == {(fault.position, fault.quantity, KIND_OF_FAULT[kind])}, fault.line


@pytest.mark.parametrize("seed", range(3))
def test_the_coriolis_factor_left_out_is_named(seed):
    # aᵏA3 = ω3∙vAA3 = … : half of 2·ω3·v_r; k_A3 = aᵏA3/Ka drawn from it only follows
    gen = generate(EXAMPLES / "shaper.toml", positions=("2", "3", "4"))
    faulty, (fault,) = inject(gen, ("coriolis",), random.Random(seed))
    r = _check(faulty)
    assert _faults_found(r) == {(fault.position, fault.quantity, "coriolis")}, fault.line
    follows = [f for f in r.findings if not f.primary and f.position == fault.position]
    assert any(f.quantity == "k_A3" for f in follows)


@pytest.mark.parametrize("seed", range(6))
def test_several_faults_at_once(press, seed):
    rng = random.Random(seed)
    kinds = tuple(rng.sample(PRESS_KINDS, 3))
    faulty, faults = inject(press, kinds, rng)
    assert _faults_found(_check(faulty)) == {(f.position, f.quantity, f.finding_kind)
                                             for f in faults}


@pytest.mark.parametrize("name", ["fourbar", "shaper", "sixbar_press"])
def test_faults_in_other_mechanisms(name):
    gen = generate(EXAMPLES / f"{name}.toml")
    rng = random.Random(7)
    kinds = tuple(k for k in FAULT_KINDS if k != "lever-arm")
    faulty, faults = inject(gen, kinds[:4], rng)
    assert _faults_found(_check(faulty)) == {(f.position, f.quantity, f.finding_kind)
                                             for f in faults}


def test_a_fault_explains_itself_in_russian_and_english(press):
    faulty, (_fault,) = inject(press, ("unit",), random.Random(1))
    r = _check(faulty, lang="en")
    (f,) = [f for f in r.findings if f.primary]
    # a reaction written in кН with the number of newtons: stated/expected = 1000
    assert f.stated / f.expected == pytest.approx(1000, rel=1e-3)
    assert "1000" in f.explanation_en and "1000" in f.explanation_ru
    assert "единицы" in f.explanation_ru and "unit" in f.explanation_en


def test_value_copied_from_a_neighbouring_variant(press, tmp_path):
    # the neighbour: the press at 70 rpm; its accelerations are (70/55)² = 1.62 times ours
    text = Path(PRESS).read_text(encoding="utf-8").replace("rpm = 55", "rpm = 70")
    nb = tmp_path / "press70.toml"
    nb.write_text(text, encoding="utf-8")
    nref = reference_for(nb)
    label = "2"
    k = nref.index(label)
    from graphplan.checking.generate import _scales

    sc = _scales(press)  # the scales the generated work states (graphplan's sheet scales)
    theirs = nref.reading_mm("πb", k, sc["Кl"], sc["Kv"], sc["Ka"])
    lines = []
    pos = next(p for p in press.positions if p.label == label)
    for ln in pos.lines:
        if ln.lhs == "aB":
            from dataclasses import replace

            ops = (replace(ln.operands[0], text=f"{theirs:.2f}".replace(".", ",")),
                   *ln.operands[1:])
            ln = replace(ln, operands=ops)
        lines.append(ln)
    from dataclasses import replace

    gen = replace(press, positions=tuple(replace(p, lines=tuple(lines)) if p.label == label
                                         else p for p in press.positions))
    r = _check(gen, neighbours=(nb,), lang="en")
    found = [f for f in r.findings if f.primary and f.verdict == "wrong"]
    assert [(f.position, f.quantity, f.kind) for f in found] == [(label, "πb", "other-variant")]
    assert "press70" in found[0].explanation


def test_the_students_polygon_with_graphplans_values_gives_graphplans_reaction_and_mbal():
    # cross-check of the chain the diagnosis uses: R12 = −(ΣF + R43) with the exact loads
    # and R43, and Mур = r_OA × R12, against graphplan's kinetostatics (power balance)
    gen = generate(PRESS, positions=("2", "4", "(2)"))
    checker = checker_for(loads_student(gen.toml(), "<g>.toml"))
    checker.run()
    figs = {}
    from graphplan.checking.diagnosis import Fig

    ref = checker.ref
    for label in ("2", "4", "(2)"):
        k = ref.index(label)
        r43 = float(np.hypot(*ref.forces["rule"].reactions["R43"].vector[k]))
        q = checker.w.vocab[label].lookup("R43")
        o = next(o for o in checker.w.occs if o.q.key == q.key and o.position == label)
        figs[(label, q.key)] = Fig(label, q.key, [o], q, r43, r43, "rule", {}, "", 1, 1,
                                   0.01, "ok")
        dg = Diagnoser(checker, figs)
        r12, off = dg.student_polygon(label)
        assert off == []
        exact = ref.forces["rule"].reactions["R12"].vector[k]
        assert np.allclose(r12, exact, rtol=1e-6, atol=1e-6 * np.hypot(*exact))
        pin = ref.kin.pos.points["A"][k] - ref.kin.pos.points["O"][k]
        m = pin[0] * r12[1] - pin[1] * r12[0]
        assert m == pytest.approx(ref.forces["rule"].M_bal[k], rel=1e-6)


@pytest.mark.parametrize("seed", range(2))
def test_the_coriolis_acceleration_left_out_is_one_fault(seed):
    # the shaper's plan drawn without aᵏ: every acceleration segment that changes follows
    # from the first, which is the fault ("coriolis"), and so do the forces from them
    gen = generate(EXAMPLES / "shaper.toml", positions=("2", "3", "11"))
    faulty, (fault,) = inject(gen, ("coriolis-left-out",), random.Random(seed))
    r = _check(faulty)
    assert _faults_found(r) == {(fault.position, fault.quantity, "coriolis")}, fault.line
    assert len(fault.carried) >= 3
    assert any(not f.primary for f in r.wrong)
