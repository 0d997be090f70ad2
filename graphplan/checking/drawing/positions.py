"""The scheme of the mechanism at a position on a drawing, against the exact position at
the student's Kl.

A **scheme** is found by its caption (``План положений, пол. 2``, ``Схема, пол. 4``: the
caption kinds of :func:`~.plans.caption_kind`, a position named) and the crank's pivot
lettered below it (``O``, ``O1``; the centre of the small circle it is drawn as); its
scale is the ``Kl`` written in the caption, else the sheet's. Its joints lettered with the
mechanism's capitals (``A``, ``B``, ``C``) are laid against the exact position from the
pivot, ``(r_X − r_O)/Kl`` in mm: a joint off its place is a ``point`` finding (ok within
the reading precision, inaccurate within max(0,5 % of its distance from the pivot, twice
the reading), else wrong: a scheme is drawn with a compass from exact lengths); each link with both
joints lettered (and the crank from the pivot) drawn at another length is a ``model``
finding (``AB``, mm), at another angle a ``direction`` finding (``∠AB``).

A plan of positions drawing every position at once (its caption names no position) is
read by :mod:`.position_plan`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..units import fold
from .plans import caption_kind, caption_position, stated_scales
from .primitives import Text
from .scene import Scene


class PivotPlaced:
    """A figure placed by the crank's pivot on the sheet: its box and where it is."""

    __slots__ = ()
    pivot: tuple[float, float]

    def _points(self) -> list[tuple[float, float]]:
        return [self.pivot]

    @property
    def bbox(self) -> tuple[float, float, float, float]:
        pts = self._points()
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        return (min(xs), min(ys), max(xs), max(ys))

    @property
    def where(self) -> str:
        return f"at x = {self.pivot[0]:.0f}, y = {self.pivot[1]:.0f} mm"

    @property
    def where_ru(self) -> str:
        return f"x = {self.pivot[0]:.0f}, y = {self.pivot[1]:.0f} мм"


@dataclass(slots=True)
class DrawnScheme(PivotPlaced):
    """A scheme found on the drawing: its caption, Kl, position, the crank's pivot, the
    joints found, ``(position, joint) → (x, y)`` mm, and the links with both ends known,
    ``(position, "A|B") → (start, end)``."""

    caption: Text
    kl: float | None
    position: str
    pivot: tuple[float, float]
    joints: dict[tuple[str, str], tuple[float, float]] = field(default_factory=dict)
    links: dict[tuple[str, str], tuple[tuple[float, float], tuple[float, float]]] = field(
        default_factory=dict)
    kind: str = "scheme"

    def _points(self) -> list[tuple[float, float]]:
        return [self.pivot, *self.joints.values()]


def find_schemes(scene: Scene, ref) -> list[DrawnScheme]:
    """The schemes of a drawing (module docstring): each caption of a scheme or a plan of
    positions with the crank's pivot lettered below it, in its column."""
    mech = ref.mech
    pivot_name = mech.crank.pivot
    joints = set(ref.kin.pos.points)
    labels = set(ref.labels)
    scales = stated_scales(scene.drawing.texts)
    sheet_kl = next((s.value for s in scales if s.symbol == "Kl" and
                     caption_kind(s.text.text) is None), None)
    pivots = [L for L in scene.letters if L.node is not None and fold(L.name) == pivot_name]
    out = []
    used: set[int] = set()
    caps = [t for t in scene.drawing.texts if caption_kind(t.text) == "scheme"]
    for cap in sorted(caps, key=lambda t: (-t.y, t.x)):
        below = [L for L in pivots if L.node not in used and L.text.y < cap.y and
                 abs(L.text.x - cap.x) <= 150.0 and cap.y - L.text.y <= 300.0]
        if not below:
            continue
        piv = min(below, key=lambda L: math.hypot(L.text.x - cap.x, L.text.y - cap.y))
        used.add(piv.node)  # type: ignore[arg-type]
        at = _joint_at(scene, piv)
        kl = next((s.value for s in scales if s.symbol == "Kl" and s.text is cap), sheet_kl)
        pos = caption_position(cap.text)
        if pos is None:
            continue  # a plan of every position at once: not read yet
        if pos not in labels:
            alt = pos.strip("()")
            pos = next((lab for lab in ref.labels if lab.strip("()") == alt), pos)
        if pos not in labels:
            continue
        sc = DrawnScheme(cap, kl, pos, at)
        # the scheme's joints: lettered within its reach of the pivot (links drawn from
        # circle to circle do not touch: the scheme is not one group of lines)
        if not kl:
            continue
        k = ref.index(pos)
        P = ref.kin.pos.points
        size = max(float(np.hypot(*(np.asarray(P[n][k]) - np.asarray(P[pivot_name][k]))))
                   for n in P) / kl
        for L in sorted(scene.letters, key=lambda L: math.hypot(L.text.x - at[0],
                                                                L.text.y - at[1])):
            name = fold(L.name)
            if L.node is None or name not in joints or name == pivot_name:
                continue
            if math.hypot(L.text.x - at[0], L.text.y - at[1]) > 1.2 * size + 20.0:
                continue
            sc.joints.setdefault((pos, name), _joint_at(scene, L))
        # each link with two joints lettered: its line, joint to joint
        for link in [mech.crank.link, *mech.links]:
            try:
                pts = [q for q in mech.points_of(link) if not q.startswith("S")]
            except (KeyError, ValueError):
                continue
            for a_i, a in enumerate(pts):
                for b in pts[a_i + 1:]:
                    if (pos, a) in sc.joints and (pos, b) in sc.joints:
                        sc.links[(pos, a + "|" + b)] = (sc.joints[(pos, a)],
                                                        sc.joints[(pos, b)])
                    elif a == pivot_name and (pos, b) in sc.joints:
                        sc.links[(pos, a + "|" + b)] = (at, sc.joints[(pos, b)])
        if sc.joints:
            out.append(sc)
    return out


def _joint_at(scene: Scene, L) -> tuple[float, float]:
    """Where a lettered joint is: the centre of the small circle it is drawn as nearest its
    letter (lines end on a circle's rim or at its centre), else the letter's node."""
    t = L.text
    nd = scene.nodes[L.node]
    rings = [c for c in scene.drawing.circles if c.r <= 3.0 and
             math.hypot(c.x - nd.x, c.y - nd.y) <= c.r + 0.5 and
             math.hypot(c.x - t.x, c.y - t.y) <= 3.0 * t.height + 3.0]
    if rings:
        c = min(rings, key=lambda c: math.hypot(c.x - nd.x, c.y - nd.y))
        return (c.x, c.y)
    return (nd.x, nd.y)


def judge_scheme(sc: DrawnScheme, ref, tol, lang: str):
    """A scheme's joints and links against the exact positions (module docstring)."""
    from ..findings import Finding
    from ..words import num
    from .judged import Judged

    j = Judged(sc, sc.kl, "plan")  # type: ignore[arg-type]
    j.key = (f"схема, {sc.where_ru}" if lang == "ru" else f"scheme {sc.where}")
    j.pos = sc.position
    if not sc.kl:
        return j
    P = ref.kin.pos.points
    pivot = ref.mech.crank.pivot
    o = np.asarray(sc.pivot, float)

    def finding(pos, quantity, kind, stated, expected, unit, en, ru, verdict):
        where = (f"положение {pos}, {j.key}" if lang == "ru" else f"position {pos}, {j.key}")
        return Finding(where=where, quantity=quantity, stated=stated, expected=expected,
                       unit=unit, kind=kind, verdict=verdict,
                       explanation=ru if lang == "ru" else en, position=pos,
                       line=sc.caption.text, explanation_en=en, explanation_ru=ru)

    def verdict(err: float, length: float, ok_frac: float, frac: float, ok_mm: float,
                mm: float) -> str:
        if err <= max(ok_frac * length, ok_mm):
            return "ok"
        return "inaccurate" if err <= max(frac * length, mm) else "wrong"

    for (pos, name), xy in sorted(sc.joints.items()):
        if pos not in ref.labels:
            continue
        k = ref.index(pos)
        e = (np.asarray(P[name][k]) - np.asarray(P[pivot][k])) / sc.kl
        m = np.asarray(xy, float) - o
        err = float(np.hypot(*(m - e)))
        length = float(np.hypot(*e))
        # a scheme is drawn with a compass from exact lengths: a joint's place is as
        # good as the reading, whatever its distance from the pivot
        v = verdict(err, length, 0.0, tol.segment_ok, tol.reading_mm, 2 * tol.reading_mm)
        if v == "ok":
            continue
        j.findings.append(finding(
            pos, f"•{name}", "point", err, 0.0, "mm",
            f"the joint {name} of position {pos} is {num(err, 'en', 3)} mm from its exact "
            f"place at Kl = {num(sc.kl)} ({num(length, 'en', 4)} mm from {pivot}).",
            f"шарнир {name} положения {pos} в {num(err, 'ru', 3)} мм от точного места при "
            f"Kl = {num(sc.kl, 'ru')} ({num(length, 'ru', 4)} мм от {pivot}).", v))
    for (pos, link), (a, b) in sorted(sc.links.items()):
        if pos not in ref.labels:
            continue
        k = ref.index(pos)
        pa, pb = link.split("|")
        link = pa + pb
        e = (np.asarray(P[pb][k]) - np.asarray(P[pa][k])) / sc.kl
        m = np.asarray(b, float) - np.asarray(a, float)
        le, lm = float(np.hypot(*e)), float(np.hypot(*m))
        v = verdict(abs(lm - le), le, tol.segment_ok, tol.segment, 0.5 * tol.reading_mm,
                    tol.reading_mm)
        if v != "ok":
            j.findings.append(finding(
                pos, link, "model", lm, le, "mm",
                f"the link {link} of position {pos} is drawn {num(lm, 'en', 4)} mm long, "
                f"l_{link}/Kl = {num(le, 'en', 4)} mm.",
                f"звено {link} положения {pos} длиной {num(lm, 'ru', 4)} мм, а "
                f"l_{link}/Kl = {num(le, 'ru', 4)} мм.", v))
        err = (math.degrees(math.atan2(m[1], m[0]) - math.atan2(e[1], e[0])) + 180.0) \
            % 360.0 - 180.0
        ok = max(1.0, math.degrees(math.atan(tol.reading_mm / le)))
        band = max(2.0, math.degrees(math.atan(2 * tol.reading_mm / le)))
        if abs(err) > ok:
            j.findings.append(finding(
                pos, f"∠{link}", "direction", err, 0.0, "°",
                f"the link {link} of position {pos} is drawn at "
                f"{num(math.degrees(math.atan2(m[1], m[0])) % 360, 'en', 4)}°, the exact "
                f"position's at {num(math.degrees(math.atan2(e[1], e[0])) % 360, 'en', 4)}° "
                f"({num(err, 'en', 3)}°).",
                f"звено {link} положения {pos} проведено под углом "
                f"{num(math.degrees(math.atan2(m[1], m[0])) % 360, 'ru', 4)}°, в точном "
                f"положении {num(math.degrees(math.atan2(e[1], e[0])) % 360, 'ru', 4)}° "
                f"({num(err, 'ru', 3)}°).", "inaccurate" if abs(err) <= band else "wrong"))
    return j


__all__ = ["DrawnScheme", "PivotPlaced", "find_schemes", "judge_scheme"]
