"""Judging a force plan and the arm h21 found on a drawing (see :mod:`.forces`).

A force plan's position is its caption's, else the position whose forces (at the plan's
Kp) its lines fit best (the least root mean square of the relative differences). Each
force's line becomes a figure of the calculation checker (``R43_mm = 14,5 мм`` at the
position, with ``Kp``): the same verdicts and causes. Besides, each force's direction
against graphplan's vector (degrees; its sense where the line's own arrowhead shows it),
and a polygon whose forces leave a gap (``closure``): the plan does not close.
"""

from __future__ import annotations

import math

import numpy as np

from ..engine import Tolerances
from ..findings import Finding
from ..words import num
from .forces import DrawnArm, DrawnForce, FoundForcePlan, _closure
from .judged import Judged


def _finding(where: str, position, quantity, kind, stated, expected, unit, en, ru, lang,
             verdict="wrong", line="") -> Finding:
    pos = (f"положение {position}" if lang == "ru" else f"position {position}") \
        if position else ("положение ?" if lang == "ru" else "position ?")
    return Finding(where=f"{pos}, {where}", quantity=quantity, stated=stated,
                   expected=expected, unit=unit, kind=kind, verdict=verdict,
                   explanation=ru if lang == "ru" else en, position=position, line=line,
                   explanation_en=en, explanation_ru=ru)


def _expected_mm(ref, vocab, name: str, k: int, kp: float) -> float | None:
    q = vocab.lookup(f"{name}_mm")
    if q is None:
        return None
    try:
        v = ref.value(q.key[1:], k)
    except (KeyError, ValueError, IndexError):
        return None
    return None if v is None else abs(v) / kp


def force_vector(ref, name: str, k: int):
    """graphplan's vector of a force at position k (N): the load's or the reaction's,
    else the side of graphplan's force plan that draws it (a reaction's components
    ``Rτ12``, ``Rn12`` are drawn, not loads or reactions of their own); ``None`` if
    graphplan draws no such force."""
    line = ref.force_line(name, k)
    if line is not None:
        return line[1]
    for p in ref.analysis.force_plans(k):
        for poly in p.polygons.values():
            for q, a, b in poly:
                if q == name:
                    return (np.asarray(p.points[b], float) - np.asarray(p.points[a], float)
                            ) * p.scale.per_mm
    return None


def _angle_error(f, vec) -> float:
    """The drawn force's direction less graphplan's, degrees (−180…180); the line's
    direction only (−90…90) when no arrowhead of its own shows its sense."""
    am = math.degrees(math.atan2(f.end[1] - f.start[1], f.end[0] - f.start[0]))
    ae = math.degrees(math.atan2(vec[1], vec[0]))
    err = (am - ae + 180.0) % 360.0 - 180.0
    if not f.sense:
        err = (err + 90.0) % 180.0 - 90.0
    return err


def judge_force_plan(fp: FoundForcePlan, ref, tol: Tolerances, lang: str):
    j = Judged(fp, fp.kp, "plan")  # type: ignore[arg-type]
    where_en = f"force plan {fp.where}"
    where_ru = f"план сил, {fp.where_ru}"
    j.key = where_ru if lang == "ru" else where_en
    vocab = ref.vocabulary()
    if not fp.kp:
        j.findings.append(_finding(j.key, fp.position, "Kp", "scale", None, None, "",
                                   "Kp is not written at the force plan: it is not checked.",
                                   "у плана сил не указан Kp: он не проверяется.", lang,
                                   verdict="inaccurate"))
        return j
    labels = list(ref.labels)
    pos = fp.position if fp.position in labels else None
    if pos is None:
        def misfit(k: int) -> float:
            errs, angles = [], []
            for name, f in fp.forces.items():
                e = _expected_mm(ref, vocab, name, k, fp.kp)  # type: ignore[arg-type]
                if e is not None and e > 0.5:
                    errs.append((f.length - e) / e)
                vec = force_vector(ref, name, k)
                if vec is not None and f.length >= 2.0 and float(np.hypot(*vec)) > 0:
                    angles.append(_angle_error(f, vec) / 30.0)
            # medians: a force or two read off a neighbouring line do not decide it
            if not errs:
                return math.inf
            return float(np.median(np.abs(errs))) + (float(np.median(np.abs(angles)))
                                                       if angles else 0.0)

        k_best = min(range(len(labels)), key=misfit)
        pos = labels[k_best]
        j.findings.append(_finding(
            j.key, pos, "Kp", "label", None, None, "",
            f"the force plan has no caption naming its position: it is taken as position "
            f"{pos}, whose forces it fits best.",
            f"у плана сил нет подписи с номером положения: он отнесён к положению {pos}, "
            f"с силами которого совпадает лучше всего.", lang, verdict="ok"))
    j.pos = pos
    j.scales = {"Kp": float(fp.kp)}
    k = labels.index(pos)
    _choose_lines(fp, ref, vocab, k, tol)
    for name, f in fp.forces.items():
        e = _expected_mm(ref, vocab, name, k, fp.kp)  # type: ignore[arg-type]
        if e is not None and e < SHORT_MM and f.length >= SHORT_MM:
            # a force too short to draw to scale, its name read off a neighbour's line
            j.findings.append(_finding(
                j.key, pos, f"{name}_mm", "label", None, e, "mm",
                f"{name} is {num(e, 'en', 2)} mm at this Kp, too short to draw: its name "
                f"stands at a line of {num(f.length, 'en', 3)} mm, not judged.",
                f"{name} при этом Kp — {num(e, 'ru', 2)} мм, слишком мала для чертежа: её "
                f"название стоит у линии {num(f.length, 'ru', 3)} мм, не проверяется.",
                lang, verdict="ok"))
            continue
        if vocab.lookup(f"{name}_mm") is not None:
            j.figures[f"{name}_mm"] = f.length
        vec = force_vector(ref, name, k)
        if vec is None or f.length < 2.0 or float(np.hypot(*vec)) <= 0:
            continue
        am = math.degrees(math.atan2(f.end[1] - f.start[1], f.end[0] - f.start[0]))
        ae = math.degrees(math.atan2(vec[1], vec[0]))
        err = _angle_error(f, vec)
        okd = max(1.0, math.degrees(math.atan(tol.reading_mm / f.length)))
        told = max(2.0, math.degrees(math.atan(2 * tol.reading_mm / f.length)))
        if abs(err) <= okd:
            continue
        verdict = "inaccurate" if abs(err) <= told else "wrong"
        rev = abs(abs(err) - 180.0) < 5.0
        en = (f"{name} is drawn in the opposite sense." if rev else
              f"{name} is drawn at {num(am % 360, 'en', 4)}°, graphplan's at "
              f"{num(ae % 360, 'en', 4)}° ({num(err, 'en', 3)}°).")
        ru = (f"{name} направлена в обратную сторону." if rev else
              f"{name} проведена под углом {num(am % 360, 'ru', 4)}°, по расчёту "
              f"{num(ae % 360, 'ru', 4)}° ({num(err, 'ru', 3)}°).")
        j.findings.append(_finding(j.key, pos, f"∠{name}", "direction", err, 0.0, "°", en, ru,
                                   lang, verdict))
    j.findings += _missing(fp, ref, vocab, k, pos, j.key, lang)
    size = max((f.length for f in fp.forces.values()), default=0.0)
    distinct = {f.segments for f in fp.forces.values()}
    if fp.closure_mm is not None and len(distinct) >= 3 and \
            fp.closure_mm > max(tol.reading_mm, tol.segment * size):
        j.findings.append(_finding(
            j.key, pos, "force polygon", "closure", fp.closure_mm, 0.0, "mm",
            f"the force polygon does not close: its ends are {num(fp.closure_mm, 'en', 3)} mm "
            "apart (the sum of the forces of a group in equilibrium is zero).",
            f"многоугольник сил не замкнут: его концы в {num(fp.closure_mm, 'ru', 3)} мм "
            "друг от друга (сумма сил группы в равновесии равна нулю).", lang))
    return j


MISSING_MM = 3.0
"""A force of the group's polygon at least this long (mm at the plan's Kp) must be drawn."""


def _missing(fp: FoundForcePlan, ref, vocab, k: int, pos: str, key: str, lang: str):
    """A force left out of the polygon: graphplan's plan of the group the drawn forces
    belong to (the one sharing most of their names) has a force of its polygon of
    :data:`MISSING_MM` or more at the plan's Kp that is neither named on the drawing nor
    drawn as an arrow of its length whose name was not read."""
    def qkey(name: str):
        q = vocab.lookup(f"{name}_mm")
        return q.key if q is not None else name

    drawn = {qkey(n) for n in fp.forces}
    best = max(ref.analysis.force_plans(k), key=lambda p: len(drawn & {qkey(q) for q, _a, _b in
                                                p.polygons["group"]}), default=None)
    if best is None:
        return []
    out = []
    for name, _a, _b in best.polygons["group"]:
        if qkey(name) in drawn:
            continue
        e = _expected_mm(ref, vocab, name, k, fp.kp)  # type: ignore[arg-type]
        if e is None or e < MISSING_MM or any(abs(u.length - e) <= max(0.3, 0.03 * e)
                                              for u in fp.unnamed):
            continue
        out.append(_finding(
            key, pos, f"{name}_mm", "missing", 0.0, e, "mm",
            f"{name} ({num(e, 'en', 3)} mm at this Kp) is not in the force polygon: a force "
            "of the group left out (the polygon then closes with wrong reactions).",
            f"{name} ({num(e, 'ru', 3)} мм при этом Kp) нет в многоугольнике сил: сила "
            "группы пропущена (многоугольник замыкают неверные реакции).", lang))
    return out


SHORT_MM = 2.0
"""A force shorter than this on its plan (mm) cannot be drawn to scale (the sheets say so
and draw it as a dot or a stub): a name of one at a longer line is not judged."""


def _mismatch(f: DrawnForce, length: float | None, vec) -> float:
    """How far a drawn force is from graphplan's (mm): the difference of the lengths plus
    the length times the angle between them (radians; the line's only without a sense)."""
    if length is None:
        return math.inf
    out = abs(f.length - length)
    if vec is not None and float(np.hypot(*vec)) > 0 and f.length > 0:
        out += length * abs(math.radians(_angle_error(f, vec)))
    return out


def _choose_lines(fp: FoundForcePlan, ref, vocab, k: int, tol: Tolerances) -> None:
    """A name written nearer a neighbour's line than its own (a crowded polygon): when
    the line nearest the name is not the force graphplan draws and another line the
    name is nearly as near is, within the segment tolerance, that line is the force —
    one text to a line: a line whose own name fits it stays that name's, and of the
    names that do not fit their nearest line the best fitting choose first."""
    # the names of one text share their line and options: they choose together
    units: dict[tuple, list[str]] = {}
    for name, f in fp.forces.items():
        units.setdefault((f.segments, tuple(o.segments for o in f.options)), []).append(name)

    def misfit(names: list[str], line: DrawnForce) -> float:
        """The worst of the names' mismatches, in bands (≤ 1: within the tolerance)."""
        worst = 0.0
        for name in names:
            length = _expected_mm(ref, vocab, name, k, fp.kp)  # type: ignore[arg-type]
            if length is None:
                continue
            band = max(tol.segment * length, tol.reading_mm)
            worst = max(worst, _mismatch(line, length, force_vector(ref, name, k)) / band)
        return worst

    held: set[tuple[int, ...]] = set()
    loose = []
    for names in units.values():
        f = fp.forces[names[0]]
        if not f.options or (len(names) == 1 and misfit(names, f) <= 1.0):
            held.add(f.segments)
            continue
        # a text naming forces drawn on nearly one line (``Rn12, R12, R23`` beside three
        # lines converging, ``Rn63, R63`` by two lines 1° apart): a name keeps the line
        # when it fits it and no line the text is nearly as near fits it clearly better;
        # the others choose
        stay = [n for n in names if misfit([n], f) <= 1.0 and
                all(misfit([n], o) >= misfit([n], f) - 0.5 for o in f.options)]
        if stay:
            held.add(f.segments)
            loose += [[n] for n in names if n not in stay]
        elif len(names) > 1 and misfit(names, f) <= 1.0:
            held.add(f.segments)
        else:
            loose.append(names)
    # each name of a loose text takes the line that fits it best, the best fits first;
    # the names of one text may share a line (``Rn12, R12`` drawn on one line) or take
    # lines of their own (``Rn34, R34`` by a fan of lines from one point)
    choices = []
    for names in loose:
        f = fp.forces[names[0]]
        for n in names:
            choices += [(m, n, id(names), o) for o in f.options
                        if (m := misfit([n], o)) <= 1.0]
    changed = False
    done: set[str] = set()
    owner: dict[tuple[int, ...], int] = {}
    for _m, name, key, o in sorted(choices, key=lambda c: c[0]):
        if name in done or (o.segments in held and owner.get(o.segments) != key):
            continue
        done.add(name)
        held.add(o.segments)
        owner[o.segments] = key
        f = fp.forces[name]
        fp.forces[name] = DrawnForce(name, o.start, o.end, o.sense, o.segments,
                                     (f, *[x for x in f.options if x is not o]))
        changed = True
    # two names each nearer the other's line (a crowded polygon): exchanged when each then
    # fits its line and together they fit better — the pair's best, not one name's
    for names in loose:
        f = fp.forces[names[0]]
        if misfit(names, f) <= 1.0 or any(fp.forces[n].segments != f.segments
                                          for n in names):
            continue
        for o in f.options:
            other = [n for n, g in fp.forces.items() if g.segments == o.segments and
                     n not in names]
            if not other or any(fp.forces[n].segments != o.segments for n in other):
                continue
            # only lines their lengths do not tell apart (converging, a few degrees
            # apart): names swapped between lines of other lengths are the student's
            band = max(tol.segment * min(f.length, o.length), tol.reading_mm)
            turn = abs(_angle_error(f, np.subtract(o.end, o.start)))
            if abs(f.length - o.length) > band or min(turn, abs(180.0 - turn)) > 15.0:
                continue
            if misfit(names, o) <= 1.0 and misfit(other, f) <= 1.0 and \
                    misfit(names, o) + misfit(other, f) < misfit(names, f) + misfit(other, o):
                for n in names:
                    g = fp.forces[n]
                    fp.forces[n] = DrawnForce(n, o.start, o.end, o.sense, o.segments,
                                              (g, *[x for x in g.options if x is not o]))
                for n in other:
                    g = fp.forces[n]
                    fp.forces[n] = DrawnForce(n, f.start, f.end, f.sense, f.segments,
                                              (g, *[x for x in g.options
                                                    if x.segments != f.segments]))
                changed = True
                break
    # a name standing by a line another name owns and fits (a name set off a crowded
    # cluster, by a long neighbour's line; 'Rn43' written with 'R43' by R43's line): it
    # names an arrow of the plan drawn without a name — the one that fits it, as a
    # teacher looks for the short arrow of G5's length and direction when 'G5' stands by
    # R65's line
    for names in units.values():
        f = fp.forces[names[0]]
        go = [n for n in names if fp.forces[n].segments == f.segments and
              misfit([n], f) > 1.0]
        owners = [n for n, g in fp.forces.items() if g.segments == f.segments and
                  n not in go and misfit([n], f) <= 1.0]
        if not go or not owners:
            continue
        fits = [(misfit(go, u), u) for u in fp.unnamed if u.segments not in held]
        m, u = min(fits, key=lambda c: c[0], default=(math.inf, None))
        if u is None or m > 1.0:
            continue
        held.add(u.segments)
        fp.unnamed = [x for x in fp.unnamed if x is not u]
        for name in go:
            g = fp.forces[name]
            fp.forces[name] = DrawnForce(name, u.start, u.end, u.sense, u.segments,
                                         (g, *g.options))
        changed = True
    if changed:
        fp.closure_mm = _closure(fp.forces, fp.unnamed)


def judge_arm(a: DrawnArm, ref, sheet: dict[str, float], lang: str):
    class _Arm:
        kind = "arm"
        where = f"h21 at x = {a.x:.0f}, y = {a.y:.0f} mm"
        where_ru = f"h21, x = {a.x:.0f}, y = {a.y:.0f} мм"
        caption = None
        bbox = (a.x, a.y, a.x, a.y)

    j = Judged(_Arm(), a.kl, "plan")  # type: ignore[arg-type]
    j.key = f"h21 x = {a.x:.0f}, y = {a.y:.0f} мм" if lang == "ru" else \
        f"h21 at x = {a.x:.0f}, y = {a.y:.0f} mm"
    kl = a.kl or sheet.get("Kl")
    pos = a.position
    if pos not in ref.labels:
        alt = (pos or "").strip("()")
        pos = next((lab for lab in ref.labels if lab.strip("()") == alt), None)
    if pos is None or not kl:
        return j
    j.pos = pos
    j.scales = {"Kl": float(kl)}
    j.figures["h21"] = a.length
    return j


__all__ = ["force_vector", "judge_arm", "judge_force_plan"]
