"""Student files written by hand from docs/check-format.md alone (issue 19), for variants
the generator's faults were not tuned on: the engine, the slotter (a Coriolis term, K,
Мур.ж and δ) and the jaw crusher (two groups, a resistance moment) — each as a student
writes it (Russian lines, decimal commas, μl/μv/μa or Kl/Kv/Ka, Фи/Ми, arms h1…h9 of
their own, lengths such as lO3A measured on the drawing, readings at ±0,3 mm, results from
a calculator with π = 3,14).

A correct work comes out clean; a work with three mistakes (each carried on as a student
carries it: a plan drawn from a wrong normal or Coriolis component, loads from it) has
each mistake found once, at its root, with the cause a teacher would write. The files
are in tests/data/students/; each faulty one says its mistakes at its top.
"""

from pathlib import Path

import pytest

from graphplan.checking.checks import check_file

HERE = Path(__file__).parent / "data" / "students"

FAULTS = {
    "engine": {("1", "anBA", "arithmetic"), ("1", "VS2", "scale"), ("1", "Мур", "sign")},
    "slotter": {(None, "K", "formula"), ("2", "aкA3", "coriolis"), ("2", "δ", "arithmetic")},
    "crusher": {("3", "Pи5", "arithmetic"), ("3", "Ka", "scale"), ("3", "R63", "unit")},
}


@pytest.mark.parametrize("name", sorted(FAULTS))
def test_a_correct_handwritten_work_comes_out_clean(name):
    r = check_file(HERE / f"{name}_ok.toml")
    assert not [f for f in r.findings if f.verdict == "wrong"], \
        [f"{f.quantity}: {f.line} — {f.explanation_en}" for f in r.findings]
    c = r.counts()
    assert c["lines_unread"] == 0 and c["ok"] >= 40
    # every line is compared, but a scale stated alone (μF = 100 Н/мм: the student's choice)
    assert all("масштаб" in ln.compared for ln in r.lines if ln.compared), \
        [(ln.text, ln.compared) for ln in r.lines if ln.compared]


@pytest.mark.parametrize("name", sorted(FAULTS))
def test_each_mistake_is_found_once_at_its_root_with_its_cause(name):
    r = check_file(HERE / f"{name}_faults.toml")
    roots = {(f.position, f.quantity, f.kind) for f in r.findings
             if f.verdict == "wrong" and f.primary}
    assert roots == FAULTS[name], \
        [f"{f.kind} {f.quantity}: {f.line} — {f.explanation_en}" for f in r.findings
         if f.verdict == "wrong"]
    # the rest are consequences, each naming what it follows from
    for f in r.findings:
        if f.verdict == "wrong" and not f.primary:
            assert f.kind == "propagated" and f.follows_from, f
