"""Planted errors for the force-plan redraws (tests/test_drawing_check_forces_redrawn.py):
which error to put into which plan, and whether the checker found it."""

from __future__ import annotations

import numpy as np

from graphplan.checking.drawing.sample_forces import ForcePlant, omitted


def _named(p) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    out = {}
    for st in p.steps:
        for e in st.elements:
            if e.kind == "segment" and e.name not in out and e.role != "arm":
                out[e.name] = (np.asarray(e.start, float), np.asarray(e.end, float))
    return out


def _length(v) -> float:
    return float(np.hypot(*(v[1] - v[0])))


def plants(ref, label: str, i: int) -> list[ForcePlant]:
    """Every error that can be planted in plan ``i`` of position ``label`` so that a
    teacher sees it: Kp doubled; the vertex where the longest force of 10–120 mm that
    another force starts from ends moved 3.2 mm on along it; a load (or tangential
    component) no longer than 40 % of the plan's largest force, whose omission moves the
    forces ≥ 3 mm (groups only); the plan of the position half a cycle on or the next
    after it, at its own Kp (its forces ≥ 3 mm off this position's at that Kp); two names of forces
    drawn apart, ≥ 3 mm and 30 % different in length, swapped."""
    plans = ref.analysis.force_plans(ref.index(label))
    p = plans[i]
    vs = _named(p)
    out = [ForcePlant("scale", label, i)]
    starts = [v[0] for v in vs.values()]
    chain = [n for n, v in vs.items() if 10.0 <= _length(v) <= 120.0 and
             any(np.allclose(v[1], s) for s in starts)]
    if chain:
        out.append(ForcePlant("moved", label, i, force=max(chain, key=lambda n: _length(vs[n]))))
    if not p.group.startswith("crank"):
        best = None
        big = max(_length(v) for v in vs.values())
        for q, _a, _b in p.polygons["group"]:
            if q not in vs or _length(vs[q]) > 0.4 * big:
                continue  # the plan's main force: left out, the plan is gone
            try:
                new = {n: (a, b) for n, a, b in omitted(p, q)}
            except ValueError:
                continue
            shift = max(float(np.hypot(*(new[n][0] - v[0]))) + float(np.hypot(*(new[n][1] -
                        v[1]))) for n, v in vs.items() if n in new)
            if shift >= 3.0 and (best is None or shift > best[0]):
                best = (shift, q)
        if best:
            out.append(ForcePlant("omit", label, i, force=best[1]))
    labels = list(ref.labels)
    k = labels.index(label)
    for step in range(len(labels) // 2, len(labels)):
        other = labels[(k + step) % len(labels)]
        q = ref.analysis.force_plans(ref.index(other))[i]
        f = p.scale.per_mm / q.scale.per_mm  # this position's forces at q's Kp
        ws = _named(q)
        diff = max((float(np.hypot(*((ws[n][1] - ws[n][0]) - (v[1] - v[0]) * f)))
                    for n, v in vs.items() if n in ws), default=0.0)
        if diff >= 3.0:
            out.append(ForcePlant("position", label, i, other=other))
            break
    single = {n: v for n, v in vs.items() if _length(v) >= 2.0 and
              sum(np.allclose(v[0], w[0]) and np.allclose(v[1], w[1]) for w in vs.values()) == 1}
    pairs = [(abs(_length(single[a]) - _length(single[b])), a, b) for a in single for b in single
             if a < b and abs(_length(single[a]) - _length(single[b])) >=
             max(3.0, 0.3 * max(_length(single[a]), _length(single[b])))]
    if pairs:
        _d, a, b = max(pairs)
        out.append(ForcePlant("swap", label, i, force=a, other=b))
    return out


def names_of(ref, label: str, i: int) -> set[str]:
    return set(_named(ref.analysis.force_plans(ref.index(label))[i]))


def _key(f) -> tuple:
    return (f.position, f.quantity, f.kind)


def found(clean, planted, ref, plant: ForcePlant) -> bool:
    """Whether a wrong finding the clean drawing has not is in the planted plan: at its
    position, on one of its forces (or its polygon, or its Kp)."""
    before = {_key(f) for f in clean.wrong}
    names = names_of(ref, plant.position, plant.plan)
    for f in planted.wrong:
        if _key(f) in before or f.position != plant.position:
            continue
        q = f.quantity.lstrip("∠")
        q = q[:-3] if q.endswith("_mm") else q
        if q in names or q in ("force polygon", "Kp") or q.replace("Fи", "Pи") in names:
            return True
    return False
