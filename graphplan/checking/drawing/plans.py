"""Finding the plans on a sheet by their letters, and what the student wrote about them.

A **velocity plan** is a group of lines (:class:`~.scene.Scene`) with a node lettered
``p`` (the pole); an **acceleration plan** one lettered ``π`` (also ``п``, ``pi``). A
plan whose other letters are primed (``a'``, ``b'``) is Zhukovsky's lever, not a plan. A
plan's **position** is read from its caption — the nearest text such as ``План
скоростей, пол. 2`` or ``положение (2)`` — and its **scale** from the nearest text such as
``Kv = 0,01 (м/с)/мм`` or ``μv = …`` (a plan without one of its own takes the sheet's).
Force plans are found by the names of their forces written along their lines
(:mod:`.forces`), the plan of positions by its capital letters (:mod:`.positions`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

from ..units import fold
from .primitives import Text
from .scene import Letter, Scene

VELOCITY_POLES = {"p"}
ACCELERATION_POLES = {"π", "п", "pi", "Π"}
KINDS = {"velocity": "Kv", "acceleration": "Ka"}

_POSITION = re.compile(
    r"(?:пол(?:ожени[еяию]|\.)?|pos(?:ition)?\.?|№)\s*№?\s*"
    r"(\(\s*(?:\d{1,2}|[a-zа-я])\s*\)['′ʹ’]?|\d{1,2}['′ʹ’]?|[a-zа-я]['′ʹ’]?)(?![\dA-Za-zА-Яа-я])",
    re.IGNORECASE)
_KIND_WORDS = {"lever": ("рычаг", "жуковск", "lever", "zhukovsk"),
               "velocity": ("скорост", "velocit"), "acceleration": ("ускорен", "accelerat"),
               "force": ("сил", "force", "кривошип", "crank", "групп", "group"),
               "scheme": ("схема", "scheme", "diagram of", "план положени")}
_SCALE = re.compile(r"(?<![A-Za-zА-Яа-я])(?:[KК]|μ|µ|m(?=u))\s*u?\s*_?\s*\{?\s*"
                    r"([lLvapPFfлр])(?![A-Za-zА-Яа-я])\s*\}?\s*=")
_RATIO = re.compile(r"(\d+(?:[.,]\d+)?)\s*:\s*(\d+(?:[.,]\d+)?)(?![\d:])")
_RATIO_M = re.compile(r"(?<![A-Za-zА-Яа-я])(?:[MМ]|Масштаб|[Ss]cale)\s*"
                      r"(\d+(?:[.,]\d+)?)\s*:\s*(\d+(?:[.,]\d+)?)(?![\d:])")
_NUMBER = re.compile(r"[-+]?\d+(?:[.,]\d+)?(?:\s*[·*x×]\s*10\s*\^?\s*[-−]?\d+|[eE][-+]?\d+)?")
_SCALE_OF = {"l": "Kl", "L": "Kl", "л": "Kl", "v": "Kv", "a": "Ka", "p": "Kp", "P": "Kp",
             "F": "Kp", "f": "Kp", "р": "Kp"}


@dataclass(frozen=True, slots=True)
class StatedScale:
    """A scale written on the sheet: its symbol (Kl, Kv, Ka, Kp), value (SI per mm) and
    the text it was read from."""

    symbol: str
    value: float
    text: Text


class Boxed:
    """A figure found on a sheet by its box ``bbox`` (x0, y0, x1, y1, mm): where it is, as
    the findings say it (the box's centre)."""

    __slots__ = ()
    bbox: tuple[float, float, float, float]

    @property
    def where(self) -> str:
        x0, y0, x1, y1 = self.bbox
        return f"at x = {(x0 + x1) / 2:.0f}, y = {(y0 + y1) / 2:.0f} mm"

    @property
    def where_ru(self) -> str:
        x0, y0, x1, y1 = self.bbox
        return f"x = {(x0 + x1) / 2:.0f}, y = {(y0 + y1) / 2:.0f} мм"


@dataclass(slots=True)
class FoundPlan(Boxed):
    """A plan found on the drawing.

    ``points`` maps each name as the student wrote it to the node's place (mm of the
    sheet); ``letters`` are the letters read; ``caption`` and ``position`` what its
    caption says; ``scale`` the scale written for it (``None``: the sheet's, or none).
    """

    kind: str
    group: int
    pole: str
    points: dict[str, tuple[float, float]]
    letters: list[Letter]
    bbox: tuple[float, float, float, float]
    caption: Text | None = None
    position: str | None = None
    scale: StatedScale | None = None
    segments: list[int] = field(default_factory=list)
    options: dict[str, list[tuple[float, float]]] = field(default_factory=dict)


def pole_kind(name: str) -> str | None:
    f = fold(name)
    if f in VELOCITY_POLES:
        return "velocity"
    if f in ACCELERATION_POLES or f.lower() == "pi":
        return "acceleration"
    return None


def read_number(text: str) -> float | None:
    m = _NUMBER.search(text)
    if not m:
        return None
    s = m.group(0).replace(",", ".").replace(" ", "").replace("−", "-")
    mm = re.match(r"([-+]?\d+(?:\.\d+)?)[·*x×]10\^?([-]?\d+)", s)
    try:
        return float(mm.group(1)) * 10.0 ** int(mm.group(2)) if mm else float(s)
    except ValueError:
        return None


def stated_scales(texts) -> list[StatedScale]:
    """Every scale written on the sheet (``Kv = vA/pa = 0,46/46 = 0,01 (м/с)/мм``: the value
    is the last member's number). Scales of the kinematic diagrams (a text that also names
    a pole distance ``H1``) are left out."""
    out = []
    for t in texts:
        s = t.text
        m = _SCALE.search(s)
        # a drawing's scale by ГОСТ 2.302 (``М 1:2``, ``Масштаб 2:1``, ``μl = 1:2``): 1 mm
        # of paper is b/a mm of the mechanism; a ratio is no velocity's or force's scale
        ratio = _RATIO.search(s[m.end():]) if m else _RATIO_M.search(s)
        if ratio and m and ratio.start() > 0 and s[m.end():][:ratio.start()].strip():
            ratio = None  # "Kl = lOA/OA = …": not a ratio right after the sign
        if ratio:
            a, b = (float(g.replace(",", ".")) for g in ratio.group(1, 2))
            if a > 0 and b > 0 and (not m or _SCALE_OF.get(m.group(1)) == "Kl"):
                out.append(StatedScale("Kl", b / a / 1000.0, t))
            continue
        if not m or re.search(r"\bH\s*\d?\s*=", s):
            continue
        sym = _SCALE_OF.get(m.group(1))
        if sym is None:
            continue
        rest = s[m.end():]
        # the scale's own formula ends where another scale begins (", Ka = …")
        nxt = _SCALE.search(rest)
        if nxt:
            rest = rest[:nxt.start()]
        last = rest.split("=")[-1]
        v = read_number(last)
        if v is None or not (v > 0 and math.isfinite(v)):
            continue
        unit = fold(last.lower())
        if re.search(r"мм\s*/|mm\s*/", unit) and not re.search(r"/\s*мм|/\s*mm", unit):
            v = 1.0 / v  # written as mm per unit
        if sym == "Kp" and re.search(r"kн|kn|кн", unit.replace("k", "k")):
            v *= 1000.0
        if sym == "Kp" and re.search(r"мн/|mn/", unit):
            v *= 1e6
        out.append(StatedScale(sym, v, t))
    return out


def caption_position(text: str) -> str | None:
    m = _POSITION.search(text)
    if not m:
        return None
    g = m.group(1).replace(" ", "")
    return g


def caption_kind(text: str) -> str | None:
    low = text.lower()
    for kind, words in _KIND_WORDS.items():
        if any(w in low for w in words):
            return kind
    return None


def bbox_distance(t: Text, bbox) -> float:
    x0, y0, x1, y1 = bbox
    dx = max(x0 - t.x, 0.0, t.x - x1)
    dy = max(y0 - t.y, 0.0, t.y - y1)
    return math.hypot(dx, dy)


def find_plans(scene: Scene) -> list[FoundPlan]:
    """The velocity and acceleration plans of a drawing (see the module docstring)."""
    by_group: dict[int, list[Letter]] = {}
    for L in scene.letters:
        if L.node is None:
            continue
        by_group.setdefault(scene.node_group(L.node), []).append(L)
    # a letter by the loose end of a construction line that lies apart from every plan
    # (a line drawn through a point but stopped short of it) is read with the plan of
    # the next node it is nearly as near
    poled = {g for g, ls in by_group.items() if any(pole_kind(L.name) for L in ls)}
    for g in [g for g in by_group if g not in poled]:
        for L in list(by_group[g]):
            nd = scene.nodes[L.node]  # type: ignore[index]
            to = next((n for n in L.options[1:] if scene.node_group(n) in poled), None)
            if to is None or nd.tip or nd.ends != 1 or nd.passes:
                continue
            by_group[g].remove(L)
            by_group[scene.node_group(to)].append(
                replace(L, node=to, options=(to, *(n for n in L.options if n != to))))
    plans = []
    for g, letters in by_group.items():
        poles = [L for L in letters if pole_kind(L.name)]
        kinds = {k for L in poles if (k := pole_kind(L.name))}
        if len(kinds) != 1:
            continue
        kind = kinds.pop()
        others = [L for L in letters if L not in poles]
        if not others:
            continue
        primed = sum(1 for L in others if any(c in L.name for c in "'′ʹ’"))
        if primed > len(others) / 2:
            continue  # Zhukovsky's lever
        if any(L.name[:1].isupper() and not pole_kind(L.name) for L in others) and \
                sum(L.name[:1].isupper() for L in others) > len(others) / 2:
            continue  # capitals: a plan of positions or a scheme
        segs = [i for i, gg in enumerate(scene.group_of) if gg == g]
        xs = [c for i in segs for c in (scene.segments[i].x1, scene.segments[i].x2)]
        ys = [c for i in segs for c in (scene.segments[i].y1, scene.segments[i].y2)]
        bbox = (min(xs), min(ys), max(xs), max(ys))
        points: dict[str, tuple[float, float]] = {}
        options: dict[str, list[tuple[float, float]]] = {}
        for L in letters:
            nd = scene.nodes[L.node]  # type: ignore[index]
            if L.name not in points:
                points[L.name] = (nd.x, nd.y)
                # the other nodes the letter is nearly as near (not where two pieces of
                # one line meet: no point is there unless the letter is nearest it)
                options[L.name] = [(scene.nodes[n].x, scene.nodes[n].y)
                                   for i, n in enumerate(L.options)
                                   if scene.node_group(n) == g and
                                   (i == 0 or not scene.is_join(n))]
        _unnamed_arrows(scene, g, letters, options)
        plans.append(FoundPlan(kind, g, poles[0].name, points, letters, bbox, segments=segs,
                               options=options))
    _captions(scene, plans)
    return [p for p in plans if not _is_lever(scene, p)]


def _unnamed_arrows(scene: Scene, g: int, letters: list[Letter],
                    options: dict[str, list[tuple[float, float]]]) -> None:
    """An arrow of the plan whose head no letter names is the vector of one of the letters
    that stand at no arrowhead of their own — by a loose line end, or at a point another
    text names too (two letters at one point only where the construction puts two points
    at one place) — as a teacher reads a letter set off its point: that arrowhead is
    added to each such letter's options, and the construction tells which it names
    (:func:`.measure.lay` takes of a letter's options the one nearest its point)."""
    named = {L.node for L in letters}
    texts_at: dict[int, set[int]] = {}
    for L in letters:
        texts_at.setdefault(L.node, set()).add(id(L.text))  # type: ignore[arg-type]
    adrift = [L for L in letters if not pole_kind(L.name) and L.name in options and
              (not scene.nodes[L.node].tip or len(texts_at[L.node]) > 1)]  # type: ignore[index]
    for n, nd in enumerate(scene.nodes):
        if not nd.tip or n in named or scene.node_group(n) != g:
            continue
        for L in adrift:
            if (nd.x, nd.y) not in options[L.name]:
                options[L.name].append((nd.x, nd.y))


def _is_lever(scene: Scene, p: FoundPlan) -> bool:
    """A plan captioned as Zhukovsky's lever (letters unprimed): nearer its lever caption
    than any caption of a plan."""
    x0, y0, x1, y1 = p.bbox
    reach = 0.5 * math.hypot(x1 - x0, y1 - y0) + 40.0
    own = bbox_distance(p.caption, p.bbox) if p.caption is not None else math.inf
    for t in scene.drawing.texts:
        if caption_kind(t.text) == "lever":
            d = bbox_distance(t, p.bbox)
            if d <= reach and d < own:
                return True
    return False


def _captions(scene: Scene, plans: list[FoundPlan]) -> None:
    texts = scene.drawing.texts
    caps = [(t, caption_position(t.text), caption_kind(t.text)) for t in texts]
    caps = [c for c in caps if c[1] is not None]
    pairs = []
    for i, p in enumerate(plans):
        x0, y0, x1, y1 = p.bbox
        reach = 0.5 * math.hypot(x1 - x0, y1 - y0) + 40.0
        for j, (t, _pos, kind) in enumerate(caps):
            if kind not in (None, p.kind):
                continue
            d = bbox_distance(t, p.bbox)
            if t.y < y0:  # a caption stands above its plan: one below is a weaker claim
                d *= 3.0
            if d <= reach:
                pairs.append((d, i, j))
    # nearest pairs first, each plan and each caption once
    done_p, done_c = set(), set()
    for _d, i, j in sorted(pairs):
        if i in done_p or j in done_c:
            continue
        done_p.add(i)
        done_c.add(j)
        plans[i].caption, plans[i].position = caps[j][0], caps[j][1]


def assign_scales(plans: list[FoundPlan], scales: list[StatedScale]) -> dict[str, float]:
    """Give each plan the scale written nearest to it (within reach); return the sheet's
    scales (those not next to a plan of theirs: a derivation ``Kv = vA/pa = …`` first)."""
    sheet: dict[str, float] = {}
    used: set[int] = set()
    pairs = []
    for k, p in enumerate(plans):
        sym = KINDS.get(p.kind)
        reach = 12.0  # a plan's own scale is written at it (or in its caption)
        for i, s in enumerate(scales):
            if s.symbol != sym:
                continue
            d = bbox_distance(s.text, p.bbox)
            if p.caption is not None and s.text is p.caption:
                d = 0.0
            if d <= reach:
                pairs.append((d, k, i))
    done: set[int] = set()
    for _d, k, i in sorted(pairs):
        if k in done or i in used:
            continue
        done.add(k)
        used.add(i)
        plans[k].scale = scales[i]
    for prefer in (True, False):
        for i, s in enumerate(scales):
            if s.symbol in sheet or i in used:
                continue
            derivation = s.text.text.count("=") >= 2
            if derivation == prefer:
                sheet[s.symbol] = s.value
    return sheet


__all__ = ["FoundPlan", "StatedScale", "assign_scales", "caption_kind", "caption_position",
           "find_plans", "pole_kind", "read_number", "stated_scales"]
