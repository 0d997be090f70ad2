"""The student's own chain through the plans (issue 19): a plan drawn on from a wrong
figure is the student's, and every figure read off it "follows from" the root.

Each case plants one fault in a generated work (:mod:`graphplan.checking.generate`,
read with drafting noise of ±0,5 mm) where the student then draws on from it:

* a wrong load in a mechanism of two groups (the six-bar press, the crusher, the
  shapers): the second group's reactions, passed to the first group, its reactions,
  h21 and Mур are read off force plans solved from the student's own loads;
* a wrong tangential reaction (``Rτ24`` with a slip): the polygon closed with it;
* a wrong normal component (``anBA``): the acceleration plan rebuilt from it;
* a Coriolis term without its factor 2 where the plan has two Coriolis terms
  (``aᵏC43`` of the shaper with a rocking slider): only that term is halved.

The checker must report the root once, as a fault of its own, and nothing else as a
fault: the later figures are consequences (``propagated``, "follows from …").
"""

import random
from pathlib import Path

import pytest

from graphplan.checking.checks import check_work, reference_for
from graphplan.checking.generate import Drafting, generate, inject
from graphplan.checking.student import loads_student
from graphplan.files import bundled_example

EXAMPLES = Path(bundled_example("press")).parent


def _planted(variant: str, kind: str, quantity, redrawn: str):
    """The first seed whose fault of ``kind``, put into a line that computes
    ``quantity`` (a predicate on its name), makes the student draw ``redrawn`` again,
    with a figure beyond tolerance: (work, fault, report)."""
    v = EXAMPLES / f"{variant}.toml"
    ref = reference_for(v)
    labels = [p.label for p in generate(v, ref=ref).positions]
    for seed in range(60):
        rng = random.Random(seed)
        pos = tuple(sorted(rng.sample(labels, min(3, len(labels))), key=labels.index))
        gen = generate(v, positions=pos, variant_ref=str(v), ref=ref,
                       drafting=Drafting(0.5, random.Random(seed)))
        try:
            gen2, faults = inject(gen, (kind,), random.Random(seed), ref,
                                  only=lambda ln: quantity(ln.lhs))
        except ValueError:
            continue
        f = faults[0]
        if redrawn not in f.redrawn:
            continue
        report = check_work(loads_student(gen2.toml(), f"<{variant}>.toml"))
        if sum(x.verdict == "wrong" for x in report.findings) >= 3:
            return gen2, f, report
    pytest.fail(f"no seed plants {kind} on the wanted figure of {variant}")


def _only_the_root(fault, report, at_least: int):
    wrong = [f for f in report.findings if f.verdict == "wrong"]
    roots = [f for f in wrong if f.primary]
    assert [(f.position, f.quantity) for f in roots] == [(fault.position, fault.quantity)], \
        [f"{f.kind} {f.quantity}: {f.line} — {f.explanation_en}" for f in roots]
    follows = [f for f in wrong if not f.primary]
    assert len(follows) >= at_least, [f.quantity for f in follows]
    assert all(f.kind == "propagated" and f.follows_from for f in follows)
    return follows


@pytest.mark.parametrize("variant", ["sixbar_press", "crusher", "shaper"])
def test_a_wrong_load_of_the_second_group_is_followed_through_both_groups(variant):
    _gen, fault, report = _planted(variant, "arithmetic",
                                  lambda q: q == "Pи5", "forces")
    follows = _only_the_root(fault, report, 2)
    # the reactions read off the student's own force plans follow from the load
    assert any(f.quantity.endswith("_mm") or f.quantity.startswith("R") for f in follows)
    assert any("force plans" in f.explanation_en or "follows from R" in f.explanation_en
               for f in follows)


def test_a_wrong_tangential_reaction_is_the_polygon_closed_with_it():
    _gen, fault, report = _planted("sixbar_press", "arithmetic",
                                  lambda q: q.startswith("Rτ"), "forces")
    _only_the_root(fault, report, 1)


@pytest.mark.parametrize("variant", ["sixbar_press", "fourbar"])
def test_a_plan_drawn_from_a_wrong_normal_component_follows_from_it(variant):
    _gen, fault, report = _planted(variant, "arithmetic", lambda q: q.startswith("an"),
                                  "acceleration")
    follows = _only_the_root(fault, report, 3)
    assert any("normal component" in f.explanation_en for f in follows)


def test_one_of_two_coriolis_terms_without_its_factor_2():
    _gen, fault, report = _planted("shaper_prp", "coriolis", lambda q: q.startswith("aᵏ"),
                                  "acceleration")
    follows = _only_the_root(fault, report, 3)
    assert next(f for f in report.findings if f.primary and f.verdict == "wrong").kind == \
        "coriolis"
    assert any("Coriolis" in f.explanation_en for f in follows)
