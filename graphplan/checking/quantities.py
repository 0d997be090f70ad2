"""The names of a student's figures and what each one is.

A :class:`Quantity` says what a name such as ``R12``, ``πb``, ``h21`` or ``Mур`` stands
for: its *key* (what graphplan computes for it, see :mod:`graphplan.checking.reference`),
its unit, whether it is one value for the whole mechanism (a mass, a scale, a length) or
one per position, and which tolerance applies to it (a segment measured on a plan, or a
value derived from measurements).

Names are compared after :func:`~graphplan.checking.units.fold` (``Мур`` = ``Mур``,
``Кр`` = ``Kp``), and, where that is unambiguous, without regard to case (``as2`` =
``aS2``). The vocabulary of a variant (:class:`Vocabulary`) lists every name it knows:

==================  ===========================================================  ======
name                meaning                                                      unit
==================  ===========================================================  ======
``Kl Kv Ka Kp``     scales (also ``μl μv μa μF``)                                SI/mm
``m2`` ``G2``       mass and weight of link 2; ``g``                             kg, N
``n1`` ``ω1``       crank speed                                                  rpm, 1/s
``lOA`` ``OA``      a length of a link, and the same drawn on the position plan  m, mm
``vB vBA ω2``       velocities (magnitudes)                                      m/s, 1/s
``aB aBA anBA aτBA ε2``  accelerations (magnitudes)                              m/s², 1/s²
``pb ab πb n_BA``   segments of the velocity and acceleration plans              mm
``G2 Pи3 Mи2 Q Q0`` loads: weight, inertia force and moment, resistance, its max N, N·m
``R12 Rτ12 Rn12``   reactions (magnitudes; ``R21`` = ``R12``)                    N
``X_mm``            the segment of force or velocity X on its plan (``R12_mm``)   mm
``h21``             the arm of R21 about the crank's pivot, on the position plan mm
``h3`` …            an arm declared in the student file (force, about a point)    mm
``Mур``             the balancing moment, counter-clockwise positive              N·m
``Мур.ж``           the same from Zhukovsky's lever                               N·m
``δ``               their discrepancy, ``|Мур.ж − Мур|/Мур.ж·100``               %
``K`` ``θ``         coefficient of change of average speed, and its angle θ      —, °
``X@4``             the figure X of position 4 (in templates)                    —
==================  ===========================================================  ======

A force written with a length unit (``R12 = 90,47 мм``) is the force's segment.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from itertools import combinations

from .units import fold

Key = tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Quantity:
    """What a name stands for.

    Attributes
    ----------
    name : str
        The canonical name (``"R12"``, ``"πb"``, ``"Mур"``).
    key : tuple of str
        What to compute for it (``("reaction", "1", "2")``, ``("reading", "πb")``).
    kind : str
        ``scale``, ``given`` (masses, g, lengths, speeds of the variant), ``drawn``
        (lengths on the position plan), ``kinematic``, ``segment`` (on a plan),
        ``load``, ``reaction``, ``arm``, ``moment``.
    unit : str
        The unit of its values: SI, or ``mm`` on paper.
    dimension : str
        The dimension of :mod:`graphplan.checking.units` its written units must have.
    factor : float
        SI value of one ``unit`` (``mm`` → 0.001).
    scope : str
        ``global`` (one value) or ``position``.
    signed : bool
        Whether its sign is meaningful (Mур); other values are magnitudes.
    tolerance : str
        ``segment`` (measured), ``derived`` or ``exact`` (a given datum).
    scale : str | None
        For a length on paper: the scale it is drawn at (``Kl``, ``Kv``, ``Ka``, ``Kp``).
    prefixes : tuple of int
        Powers of 1000 an unlabelled number of it may carry (``kN`` for a force: 1).
    """

    name: str
    key: Key
    kind: str
    unit: str
    dimension: str
    factor: float = 1.0
    scope: str = "position"
    signed: bool = False
    tolerance: str = "derived"
    scale: str | None = None
    prefixes: tuple[int, ...] = (0,)

    @property
    def on_paper(self) -> bool:
        """Measured in millimetres of a drawing."""
        return self.unit == "mm"


SCALE_DIMENSIONS = {"Kl": "m/mm", "Kv": "(m/s)/mm", "Ka": "(m/s²)/mm", "Kp": "N/mm"}
SCALE_OF_DIMENSION = {"m": "Kl", "m/s": "Kv", "m/s²": "Ka", "N": "Kp"}

_SCALE_ALIASES = {"Kl": "Kl", "μl": "Kl", "Kv": "Kv", "μv": "Kv", "Ka": "Ka", "μa": "Ka",
                  "Kp": "Kp", "KP": "Kp", "KF": "Kp", "Kf": "Kp", "μF": "Kp", "μp": "Kp",
                  "μP": "Kp"}
_MBAL_ALIASES = ("Mур", "Mуp", "M_ур", "Mур1", "Mbal", "M_bal", "Mb")
# the same moment from Zhukovsky's lever (Мур.ж is read as Мур_ж): a figure of its own,
# compared with graphplan's Mур and with the force plans' Мур by δ
_LEVER_ALIASES = ("Mурж", "Mур_ж", "MурЖ", "Mур_Ж", "Mур_рыч", "Mур_р", "Mж", "M_ж",
                  "Mурл", "Mур_л")
# δ = |Мур.ж − Мур|/Мур.ж·100 %, the discrepancy of the two
_DELTA_ALIASES = ("δМур", "δM", "δ_Мур", "δMур", "Δ", "ΔМур", "δ%", "delta")
_INERTIA_FORCE = ("Pи", "Фи", "Ф", "Φ", "Fи", "Pin")
_INERTIA_MOMENT = ("Mи", "MФ", "MΦ", "Min")


def _q(name, key, kind, unit, dim, **kw) -> Quantity:
    return Quantity(name, key, kind, unit, dim, **kw)


def _segment(base: Quantity, name: str | None = None) -> Quantity:
    scale = SCALE_OF_DIMENSION[base.dimension]
    return Quantity(name or f"{base.name}_mm", ("segment", *base.key), "segment", "mm", "m",
                    0.001, base.scope, False, "segment", scale)


@dataclass(frozen=True, slots=True)
class ArmSpec:
    """An arm declared in the student file: the perpendicular from ``about`` to the line
    of action of ``force``, in mm on the position plan."""

    name: str
    force: str
    about: str


class Vocabulary:
    """Every name a student may use for a variant, and what it stands for.

    Parameters
    ----------
    mech : Mechanism
    readings : dict[str, str]
        Segment names of the velocity and acceleration plans → the quantity they
        stand for as graphplan names it (``"πb"`` → ``"a_B"``).
    reactions : iterable of str
        Reaction names of the kinetostatics (``"R12"``, ``"R43"`` …).
    loads : iterable of str
        Names of the loads (``"G2"``, ``"Pи3"``, ``"Q"``).
    arms : dict[str, ArmSpec]
        Arms declared in the student file (for one position).
    """

    def __init__(self, mech, readings: dict[str, str], reactions, loads, arms=None):
        self.mech = mech
        self.names: dict[str, Quantity] = {}
        crank = mech.crank
        add = self._add
        for alias, canon in _SCALE_ALIASES.items():
            add(_q(canon, ("scale", canon), "scale", SCALE_DIMENSIONS[canon],
                   SCALE_DIMENSIONS[canon], scope="position" if canon == "Kp" else "global",
                   tolerance="exact", prefixes=(0, 1) if canon == "Kp" else (0,)), alias)
        add(_q("g", ("g",), "given", "m/s²", "m/s²", scope="global", tolerance="exact"))
        add(_q("n1", ("rpm",), "given", "rpm", "rpm", scope="global", tolerance="exact"))
        add(_q(f"ω{crank.link}", ("omega1",), "given", "rad/s", "rad/s", scope="global"))
        add(_q(f"ε{crank.link}", ("eps1",), "given", "rad/s²", "rad/s²", scope="global",
               tolerance="exact"))
        for ln, props in mech.links.items():
            if props.mass > 0:
                add(_q(f"m{ln}", ("mass", ln), "given", "kg", "kg", scope="global",
                       tolerance="exact"))
                g = _q(f"G{ln}", ("weight", ln), "load", "N", "N", scope="global",
                       prefixes=(0, 1))
                add(g)
                self._add(_segment(g))
            if props.inertia > 0:
                add(_q(f"IS{ln}", ("inertia", ln), "given", "kg·m²", "kg·m²", scope="global",
                       tolerance="exact"), f"JS{ln}", f"Is{ln}", f"Js{ln}")
        for name in loads:
            m = re.fullmatch(r"Pи(\d+)", name)
            if m:
                q = _q(name, ("inertia_force", m.group(1)), "load", "N", "N", prefixes=(0, 1))
                add(q, *(f"{a}{m.group(1)}" for a in _INERTIA_FORCE))
                add(_segment(q))
            m = re.fullmatch(r"Mи(\d+)", name)
            if m:
                add(_q(name, ("inertia_moment", m.group(1)), "load", "N·m", "N·m",
                       prefixes=(0, 1)), *(f"{a}{m.group(1)}" for a in _INERTIA_MOMENT))
            if name.startswith("Q") or name.startswith("Mс"):
                unit = "N" if name.startswith("Q") else "N·m"
                q = _q(name, ("resistance", name), "load", unit, unit, prefixes=(0, 1))
                add(q, *(("Fпс", "Pпс", "F") if name == "Q" else ()))
                if unit == "N":
                    add(_segment(q))
            elif not re.fullmatch(r"(G|Pи|Mи)\d+", name):
                # any other load of the variant by its own name (gas force Fг1, the
                # liquid's Fж, a drive moment): a moment if its name says M
                unit = "N·m" if fold(name)[:1] == "M" else "N"
                q = _q(name, ("resistance", name), "load", unit, unit, prefixes=(0, 1))
                add(q)
                if unit == "N":
                    add(_segment(q))
        if mech.resistances:
            r = mech.resistances[0]
            unit = "N" if r.kind == "force" else "N·m"
            add(_q("Q0", ("resistance_max",), "given", unit, unit, scope="global",
                   prefixes=(0, 1)), "Qmax", "Fmax", "Pmax", "Fпс.max")
        for name in reactions:
            m = re.fullmatch(r"R(\d)(\d)", name)
            if not m:
                continue
            i, j = m.groups()
            for a, b in ((i, j), (j, i)):
                q = _q(f"R{a}{b}", ("reaction", i, j), "reaction", "N", "N", prefixes=(0, 1))
                add(q)
                add(_segment(q))
                for comp, aliases in (("t", ("Rτ", "Rt", "R^τ")), ("n", ("Rn", "Rⁿ", "R^n"))):
                    cq = _q(f"{aliases[0]}{a}{b}", (f"reaction_{comp}", i, j), "reaction", "N",
                            "N", prefixes=(0, 1))
                    add(cq, *(f"{al}{a}{b}" for al in aliases[1:]))
                    add(_segment(cq))
            if crank.link in (i, j) and mech.frame_link not in (i, j):
                other = j if i == crank.link else i
                add(_q(f"h{other}{crank.link}", ("crank_arm", other), "arm", "mm", "m",
                       factor=0.001, tolerance="segment", scale="Kl"))
        add(_q("Mур", ("M_bal",), "moment", "N·m", "N·m", signed=True, prefixes=(0, 1)),
            *_MBAL_ALIASES)
        add(_q("Mур.ж", ("M_bal", "lever"), "moment", "N·m", "N·m", signed=True,
               prefixes=(0, 1)), *_LEVER_ALIASES)
        add(_q("δ", ("mbal_discrepancy",), "cycle", "%", "1", factor=0.01), *_DELTA_ALIASES)
        # the coefficient of change of the output's average speed, and the angle between
        # the crank's positions at the output's dead centres: K = (180° + θ)/(180° − θ)
        add(_q("K", ("time_ratio",), "cycle", "1", "1", scope="global"), "Kср")
        add(_q("θ", ("overlap_angle",), "cycle", "deg", "deg", scope="global"), "Θ", "θ°")
        # lengths of the links and the same lengths drawn on the position plan
        points_by_link = {ln: mech.points_of(ln) for ln in (mech.frame_link, *mech.moving_links)}
        for ln, pts in points_by_link.items():
            if ln == mech.frame_link:
                continue
            for p, q in combinations(pts, 2):
                for a, b in ((p, q), (q, p)):
                    add(_q(f"l{a}{b}", ("length", a, b), "given", "m", "m", scope="global",
                           tolerance="exact", prefixes=(0, -1)))
                    add(_q(f"{a}{b}", ("drawn", a, b), "drawn", "mm", "m", factor=0.001,
                           scope="global", tolerance="segment", scale="Kl"))
        # kinematics of points and of pairs of points of one link
        all_points = []
        for ln in mech.moving_links:
            for p in points_by_link[ln]:
                if p not in all_points:
                    all_points.append(p)
            add(_q(f"ω{ln}", ("omega", ln), "kinematic", "rad/s", "rad/s"))
            add(_q(f"ε{ln}", ("eps", ln), "kinematic", "rad/s²", "rad/s²"))
        for p in all_points:
            v = _q(f"v{p}", ("v", p), "kinematic", "m/s", "m/s")
            a = _q(f"a{p}", ("a", p), "kinematic", "m/s²", "m/s²")
            add(v)
            add(a)
            add(_segment(v))
            add(_segment(a))
        for ln in mech.moving_links:
            for p, q in combinations(points_by_link[ln], 2):
                for a_, b_ in ((p, q), (q, p)):
                    for q_ in (_q(f"v{a_}{b_}", ("v_rel", a_, b_), "kinematic", "m/s", "m/s"),
                               _q(f"a{a_}{b_}", ("a_rel", a_, b_), "kinematic", "m/s²", "m/s²")):
                        add(q_)
                        add(_segment(q_))
                    an = _q(f"an{a_}{b_}", ("a_n", a_, b_), "kinematic", "m/s²", "m/s²")
                    at = _q(f"aτ{a_}{b_}", ("a_t", a_, b_), "kinematic", "m/s²", "m/s²")
                    add(an, f"aⁿ{a_}{b_}", f"an_{a_}{b_}", f"aⁿ_{a_}{b_}")
                    add(at, f"at{a_}{b_}", f"aτ_{a_}{b_}", f"at_{a_}{b_}")
                    add(_segment(an))
                    add(_segment(at))
        for seg, what in readings.items():
            base = self.lookup(_reading_name(what))
            scale = "Kv" if what.startswith("v") else "Ka"
            if base is None:
                # a value only the plan names (Coriolis aᵏ_A3, relative aʳ_AA3, v_A3 of a
                # point of a slider pair): compared with the plan's own reading
                dim = "m/s" if scale == "Kv" else "m/s²"
                base = _q(_reading_name(what), ("reading", seg, what), "kinematic", dim, dim)
                add(base, *_reading_aliases(what))
            key = base.key
            add(Quantity(seg, ("segment", *key), "segment", "mm", "m", 0.001, "position",
                         False, "segment", scale))
        for arm in (arms or {}).values():
            add(_q(arm.name, ("arm", arm.force, arm.about), "arm", "mm", "m", factor=0.001,
                   tolerance="segment", scale="Kl"))

    def _add(self, q: Quantity, *aliases: str) -> None:
        for n in (q.name, *aliases):
            self.names.setdefault(fold(n), q)
        self._lower: dict[str, list[tuple[str, Quantity]]] | None = None

    def lookup(self, name: str) -> Quantity | None:
        """The quantity a name stands for (``None`` if unknown); ``X@4`` names X."""
        base = name.split("@", 1)[0]
        q = self.names.get(fold(base))
        if q is not None:
            return q
        folded = fold(base)
        lower = getattr(self, "_lower", None)
        if lower is None:  # an index, not a scan per unknown name
            lower = {}
            for k, v in self.names.items():
                lower.setdefault(k.lower(), []).append((k, v))
            self._lower = lower
        cands = lower.get(folded.lower(), [])
        hits = {id(v): v for _k, v in cands}
        if len(hits) > 1:  # "as2": prefer the names whose first letter has the same case
            hits = {id(v): v for k, v in cands if k[:1] == folded[:1]}
        return next(iter(hits.values())) if len(hits) == 1 else None

    def segment_of(self, q: Quantity) -> Quantity | None:
        """The segment of a force or kinematic value on its plan (``R12`` → ``R12_mm``)."""
        if q.dimension not in SCALE_OF_DIMENSION or q.on_paper:
            return None
        return self.lookup(f"{q.name}_mm") or _segment(q)

    def split(self, name: str) -> tuple[str, ...] | None:
        """A name written without signs between its parts, split into known names with
        the fewest parts (``"Pи2h2"`` → ``("Pи2", "h2")``); ``None`` if it cannot be."""
        if "@" in name:
            base = name.split("@", 1)[0]
            return (name,) if self.lookup(base) else None
        if self.lookup(name) is not None:
            return (name,)
        n = len(name)
        best: list[tuple[str, ...] | None] = [None] * (n + 1)
        best[0] = ()
        for i in range(n):
            done = best[i]
            if done is None:
                continue
            for j in range(i + 1, n + 1):
                piece = name[i:j]
                if self.lookup(piece) is None:
                    continue
                cand = (*done, piece)
                have = best[j]
                if have is None or len(cand) < len(have):
                    best[j] = cand
        return best[n]


def _reading_aliases(what: str) -> tuple[str, ...]:
    """Other spellings of a plan's value: ``aᵏ_A3`` is also ``akA3``, ``aкA3``, ``aкорA3``;
    ``aʳ_AA3`` is ``arAA3``, ``aотнAA3``."""
    m = re.fullmatch(r"([va])([ᵏʳⁿτ])?_(\w+)", what)
    if m is None:
        return ()
    v, sup, pts = m.groups()
    sups = {"ᵏ": ("k", "к", "кор", "K", "_k", "_к", "^k"), "ʳ": ("r", "отн", "_r", "^r"),
            "ⁿ": ("n", "_n"), "τ": ("t", "_t", "τ")}.get(sup or "", ("",))
    out = [f"{v}{s}{pts}" for s in sups] + [f"{v}{s}_{pts}" for s in sups]
    return tuple(dict.fromkeys(out))


def _reading_name(what: str) -> str:
    """graphplan's reading quantity (``"a_B"``, ``"aⁿ_BA"``, ``"aτ_BA"``) → a name."""
    return what.replace("ⁿ_", "n").replace("τ_", "τ").replace("_", "")


__all__ = ["SCALE_DIMENSIONS", "SCALE_OF_DIMENSION", "ArmSpec", "Quantity", "Vocabulary"]
