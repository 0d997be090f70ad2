"""The checker measured on a class of synthetic students (issue 19).

:func:`graphplan.checking.generate.score` writes 200 works over every example (every
dyad kind: RRR, RRP, RPR, RPP, PRP, six-bars, the engine, compressor, pump, crusher and
slotter families) and a teacher's own crank–rocker (``tests/data/crank_rocker.toml``) —
read off the plans with drafting noise (±0,5 mm,
3–4 significant figures), correct or with faults of every kind planted alone and in
combination (each carried on into the later lines that use it), checks them and scores:

* false alarms: a wrong finding on a line nothing was planted in or carried to (target 0);
* recall: planted faults found as a fault of their own, at their position and name (≥ 0,95);
* root attribution: of the faults reported, the share that are planted ones — a consequence
  charged as a fault lowers it (≥ 0,95);
* cause named right: of the faults found, the share with the planted kind (≥ 0,9).

A student draws on from their own wrong figures (the acceleration plan from a wrong
normal or Coriolis component, the force plans of every group from wrong loads and
reactions): such faults are planted in every variant (``normal``, ``load``, and any
fault that reaches a load), and the plans' readings that follow from them must be
consequences, never faults of their own.

The scores are printed (``pytest -s``, and ``-rA`` shows them in the summary) and kept in
docs/check-format.md. A class of 240 takes about a minute on one core.
"""

from pathlib import Path

import pytest

from graphplan.checking.generate import score
from graphplan.files import bundled_example

EXAMPLES = Path(bundled_example("press")).parent
OWN = Path(__file__).parent / "data" / "crank_rocker.toml"
# variants nobody here wrote the checker (or its generator) for: a two-stroke engine, an
# in-line compressor, a twin engine over 720°, a crank-angle pump, a crusher with a force on
# its jaw, a clockwise four-bar, a four-bar with a fixed-direction force, a shaper cutting
# part of its stroke (tests/data/variants/)
UNSEEN = sorted((Path(__file__).parent / "data" / "variants").glob("*.toml"))
# every example with a drawn force analysis, and variants nobody wrote the checker for
VARIANTS = [*sorted(p for p in EXAMPLES.glob("*.toml")), OWN]


def _report(s) -> str:
    lines = [s.summary()]
    for title, items in (("missed", s.misses), ("cause", s.miscaused),
                         ("false alarms", s.alarms), ("not a planted fault", s.not_roots)):
        lines += [f"  {title}: {x}" for x in items[:20]]
    return "\n".join(lines)


@pytest.mark.parametrize("seed", [0, 1])
def test_a_class_of_240_generated_students(seed):
    s = score(VARIANTS, 240, seed=seed)
    print("\n" + _report(s))
    assert s.works >= 200 and s.variants >= 8
    families = {"engine", "compressor", "pump", "slotter", "crusher"}
    assert families <= {Path(v).stem for v in VARIANTS}
    assert s.false_alarms == 0, _report(s)
    assert s.recall >= 0.95, _report(s)
    assert s.root_attribution >= 0.95, _report(s)
    assert s.cause_accuracy >= 0.9, _report(s)
    assert s.clean_works >= 25 and s.planted >= 150
    assert s.redrawn >= 40  # faults the student drew plans on from, followed


def test_a_class_over_variants_nobody_tuned_the_checker_for():
    s = score(UNSEEN, 130, seed=0)
    print("\n" + _report(s))
    assert s.variants >= 8
    assert s.false_alarms == 0, _report(s)
    assert s.recall >= 0.95, _report(s)
    assert s.root_attribution >= 0.95, _report(s)
    assert s.cause_accuracy >= 0.9, _report(s)
    assert s.clean_works >= 15 and s.redrawn >= 20
