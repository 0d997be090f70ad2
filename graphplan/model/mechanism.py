"""The mechanism as a value: structure and dimensions, in SI units, no solved state.

A class-II planar mechanism is described as the textbook builds it: the frame
(стойка) with its fixed points, the crank (начальный механизм, link 1 + frame),
then Assur dyads attached one after another, each adding two links and three
lower pairs.

Sign conventions (said once here and in ``docs/variant-format.md``):

* coordinates in the variant's own frame, x right, y up, metres;
* every angle in radians, measured from +x, counter-clockwise positive; the crank
  angle φ is the absolute angle of O→A; ω and ε are counter-clockwise positive;
* each link has a *reference axis* that defines its angle θ:

  ====  ===================  =====================================
  kind  link i               link j
  ====  ===================  =====================================
  crank O→A                  —
  RRR   A→B                  C→B
  RRP   A→B                  along its guide (slider)
  RPR   along the slot       along the slot (rocker, origin C)
  PRP   along guide 1        along guide 2
  RPP   along the slot       along its guide
  ====  ===================  =====================================

* a guide is a line carried by a link (the frame or a moving one); its direction
  is the positive sense of the sliding coordinate along it.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

from ..errors import InputError
from .settings import (
    FORMATS,
    DrawingSettings,
    KinetostaticsSettings,
    TitleBlockSettings,
    description_of,
)

DYAD_KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")
"""The five kinds (виды) of class-II Assur dyads, outer–inner–outer pair."""

JOINT_COUNT = {"RRR": 3, "RRP": 2, "RPR": 2, "PRP": 1, "RPP": 2}
"""How many named joints each kind lists in ``joints``."""

NEW_JOINTS = {"RRR": (1,), "RRP": (1,), "RPR": (), "PRP": (0,), "RPP": (1,)}
"""Indices in ``joints`` of the joints a dyad places (the others must exist)."""

DYAD_KIND_NUMBER = {"RRR": 1, "RRP": 2, "RPR": 3, "PRP": 4, "RPP": 5}
"""The kind number of each dyad as Russian textbooks number them (вид 1…5)."""


@dataclass(frozen=True, slots=True)
class Guide:
    """A straight guide carried by a link: the path line of a sliding pair.

    Attributes
    ----------
    link : str
        Link that carries the guide (the frame or a moving link).
    through : str | None
        Named point of that link the line passes through.
    xy : tuple[float, float] | None
        Or, for a guide on the frame only, fixed coordinates (m) of a point of it.
    angle : float
        Direction (rad): absolute for the frame, relative to the carrying link's
        reference axis for a moving link. Ignored when ``toward`` is given.
    toward : str | None
        Alternatively the direction from ``through`` toward another point of the link.
    """

    link: str
    through: str | None = None
    xy: tuple[float, float] | None = None
    angle: float = 0.0
    toward: str | None = None


@dataclass(frozen=True, slots=True)
class Dyad:
    """One Assur group of class II (a dyad): two links, three lower pairs.

    Attributes
    ----------
    kind : str
        One of ``RRR``, ``RRP``, ``RPR``, ``PRP``, ``RPP`` (outer, inner, outer pair).
    links : tuple[str, str]
        Link numbers ``(i, j)``; link i carries the first outer pair.
    joints : tuple[str, ...]
        Named joints, in order: RRR ``(A, B, C)`` with B new; RRP ``(A, B)`` with B
        new; RPR ``(A, C)`` (block pin, rocker pivot); PRP ``(B,)`` new; RPP
        ``(A, D)`` with D new (the reference point of link j on its guide).
    lengths : tuple[float, ...]
        RRR ``(l_AB, l_CB)``; RRP ``(l_AB,)``; other kinds ``()`` (m).
    guides : tuple[Guide, ...]
        RRP and RPP: the guide of link j; PRP: the guides of links i and j.
    offset : float
        RPR only: signed distance (m) of the slot axis from the pivot C, to the
        left of the slot direction.
    slot_angle : float
        RPP only: angle (rad) of the slot of link j to its guide.
    branch : int
        Assembly branch, +1 or −1 (see ``docs/variant-format.md``).
    """

    kind: str
    links: tuple[str, str]
    joints: tuple[str, ...]
    lengths: tuple[float, ...] = ()
    guides: tuple[Guide, ...] = ()
    offset: float = 0.0
    slot_angle: float = 0.0
    branch: int = 1

    @property
    def name(self) -> str:
        """Label as the textbook writes it, e.g. ``RRP(2-3)``."""
        return f"{self.kind}({self.links[0]}-{self.links[1]})"

    @property
    def new_points(self) -> tuple[str, ...]:
        """Joints this dyad places (the others exist before it)."""
        return {
            "RRR": self.joints[1:2],
            "RRP": self.joints[1:2],
            "RPR": (),
            "PRP": self.joints[0:1],
            "RPP": self.joints[1:2],
        }[self.kind]

    @property
    def points_on_links(self) -> tuple[tuple[str, ...], tuple[str, ...]]:
        """Joints of this dyad that lie on link i and on link j."""
        jt = self.joints
        if self.kind == "RRR":
            return (jt[0], jt[1]), (jt[1], jt[2])
        if self.kind == "RRP":
            return (jt[0], jt[1]), (jt[1],)
        if self.kind == "PRP":
            return (jt[0],), (jt[0],)
        return (jt[0],), (jt[1],)  # RPR: pin A on the block, pivot C on the rocker; RPP

    @property
    def anchor_points(self) -> tuple[str, ...]:
        """Existing joints this dyad attaches to (outer revolute pairs)."""
        return {
            "RRR": (self.joints[0], self.joints[2]),
            "RRP": (self.joints[0],),
            "RPR": (self.joints[0], self.joints[1]),
            "PRP": (),
            "RPP": (self.joints[0],),
        }[self.kind]


@dataclass(frozen=True, slots=True)
class Crank:
    """The driving link: pivot on the frame, pin, length and constant speed.

    ``omega`` is the constant angular velocity ω1 = ±π·n/30 (rad/s), positive
    counter-clockwise.
    """

    link: str
    pivot: str
    pin: str
    length: float
    rpm: float
    omega: float

    @property
    def n1(self) -> float:
        """The crank's speed n1, rpm (> 0), as the variant gives it (or 30·|ω1|/π)."""
        return self.rpm

    @property
    def sense(self) -> float:
        """+1 for a counter-clockwise crank, −1 for a clockwise one: the sign of ω1 (never 0).

        The crank's travel in its sense of rotation is ``sense·(φ − φ_first)``."""
        return 1.0 if self.omega > 0 else -1.0


@dataclass(frozen=True, slots=True)
class PointOnLink:
    """A point fixed on a link (centre of mass, force point, anchor of a later dyad).

    Position: ``P = F + along·d + across·(k×d)``, where F is the point ``origin``
    of the same link and ``d`` the unit vector toward ``toward`` or, when that is
    ``None``, along the link's reference axis.
    """

    name: str
    link: str
    origin: str
    toward: str | None = None
    along: float = 0.0
    across: float = 0.0
    fraction: float | None = None


@dataclass(frozen=True, slots=True)
class LinkProps:
    """Mass (kg), moment of inertia about the centre of mass (kg·m²), centre point."""

    mass: float = 0.0
    inertia: float = 0.0
    centre: str | None = None


@dataclass(frozen=True, slots=True)
class Resistance:
    """A known external load of the variant: a force on a point of a link or a couple on a
    link (the technological resistance of a press, the gas force on a piston, the moment on
    a crusher's jaw …), given by its diagram.

    The defaults are the classical technological resistance: on the output link, over the
    output's working stroke, always opposing the motion.

    Attributes
    ----------
    kind : str
        ``"force"`` or ``"moment"``.
    link : str
        The loaded (moving) link.
    point : str | None
        Point of application of a force.
    maximum : float
        Scale of the diagram's values: the load is ``value·maximum − offset`` (N or N·m).
        Negative for the rod's side of a double-acting cylinder (``rod``), whose pressure
        pushes the piston toward the head, against its x.
    diagram : tuple of (x, value) pairs
        The diagram of the first loaded stroke (kept for the readers of one diagram).
    name : str | None
        Its name on the sheets (``Q``, ``Fг``, ``Mс`` … by default).
    sense : str
        ``"resists"`` — the value is a size and the load opposes the motion (of the
        slider along its frame guide, of the point, or the link's rotation);
        ``"drives"`` — a size along the motion; ``"diagram"`` — the value's sign gives
        the direction: along ``angle`` (or the travel's direction for a force on a
        slider), CCW for a moment.
    over : str
        ``"stroke"``: x is the position of ``travel_link`` as a fraction of its stroke, 0 at
        its start dead centre, 1 at the end one; ``"crank"``: x is the crank's travel
        (rad) from the cycle's origin.
    strokes : tuple
        ``"stroke"``: one diagram (a tuple of pairs) or ``None`` (no load) per stroke of
        the cycle, in order from ``travel_link``'s first start dead centre at or after
        ``phase`` (2 strokes per turn: 0→1, 1→0, …). ``"crank"``: one diagram over
        0 … the cycle (rad).
    angle : float | None
        Absolute direction (rad) of a force in the ``"diagram"`` sense; None: the
        direction of the travel (x growing) of the slider it acts on.
    travel_link : str | None
        The link whose travel is the abscissa (None: the output link).
    working : int
        +1: x grows with the travel link's coordinate; −1: x falls.
    phase : float
        Crank travel (rad) from the cycle's origin before which the stroke list does not
        start (the firing interval of a second cylinder).
    offset : float
        Subtracted from ``value·maximum``: the ambient pressure times the piston area of
        an indicator diagram (N).
    gas : bool
        Given as pressures on a piston (``bore``): x = 0 is its ВМТ.
    """

    kind: str  # "force" | "moment"
    link: str
    point: str | None
    maximum: float
    diagram: tuple[tuple[float, float], ...]
    name: str | None = None
    sense: str = "resists"
    over: str = "stroke"
    strokes: tuple = ()
    angle: float | None = None
    travel_link: str | None = None
    working: int = 0
    phase: float = 0.0
    offset: float = 0.0
    gas: bool = False  # given as pressures on a piston (``bore``): an indicator diagram

    def stroke_diagrams(self, n_strokes: int) -> tuple:
        """The diagram (or None) of each of ``n_strokes`` strokes of the cycle."""
        if self.strokes:
            return tuple(self.strokes)
        return (self.diagram,) + (None,) * (n_strokes - 1)


@dataclass(frozen=True, slots=True)
class ExtraPosition:
    """A named position: by absolute crank angle, by turn from a dead centre, or by stroke."""

    label: str
    phi: float | None = None  # absolute crank angle (rad)
    from_dead_centre: str | None = None  # "start" | "end" (of the working stroke)
    turn: float = 0.0  # crank turn from that dead centre, in the sense of rotation (rad)
    stroke: float | None = None  # travel fraction of the working stroke


@dataclass(frozen=True, slots=True)
class Positions:
    """How the cycle is divided: N equal steps from the first position, plus named ones."""

    count: int = 8
    first: str | float = "start"  # "start" | "end" dead centre, or an absolute angle (rad)
    number_from: int = 1
    extra: tuple[ExtraPosition, ...] = ()
    cycle: int = 360  # degrees of crank per cycle: 360, or 720 (a four-stroke process)

    @property
    def period(self) -> float:
        """The cycle in radians of crank travel (2π or 4π)."""
        return math.radians(self.cycle)

@dataclass(frozen=True, slots=True)
class Output:
    """The output link whose motion defines the stroke and the dead centres."""

    link: str
    working: int = 1  # +1: the working stroke moves the output coordinate forward


@dataclass(frozen=True, slots=True)
class Mechanism:
    """A validated class-II mechanism in SI units.

    Holds structure and dimensions only; solving returns new objects
    (:func:`graphplan.kinematics.exact.solve`).
    """

    name: str
    source: str
    frame_link: str
    frame_points: dict[str, tuple[float, float]]
    crank: Crank
    dyads: tuple[Dyad, ...]
    points: tuple[PointOnLink, ...]
    links: dict[str, LinkProps]
    gravity: tuple[float, float]
    resistances: tuple[Resistance, ...]
    positions: Positions
    output: Output
    length_unit: str = "m"
    settings: dict = field(default_factory=dict)

    # --- the settings, typed (:mod:`graphplan.model.settings`: every default there) -----

    @property
    def drawing(self) -> DrawingSettings:
        """``[drawing]``: format, language, reading step, fixed scales and positions."""
        return DrawingSettings.of(self.settings)

    @property
    def kinetostatics(self) -> KinetostaticsSettings:
        """``[kinetostatics]``: the neglect rule, inertia, the shifted inertia force."""
        return KinetostaticsSettings.of(self.settings)

    @property
    def title_block(self) -> TitleBlockSettings:
        """``[title_block]``: what the sheets' title block is filled with."""
        return TitleBlockSettings.of(self.settings)

    @property
    def description(self) -> str | None:
        """``[variant] description`` (None: not given)."""
        return description_of(self.settings)

    def with_drawing(self, **changes: Any) -> Mechanism:
        """This variant with fields of its ``[drawing]`` settings changed (names and types
        of :class:`DrawingSettings`; None removes a key)."""
        d = dataclasses.replace(self.drawing, **changes)
        return dataclasses.replace(self, settings={**self.settings, "drawing": d.table()})

    def on_format(self, fmt: str) -> Mechanism:
        """This variant drawn on format ``fmt`` ("A1", "A2", "A3"): the format decides the
        scales, so the scales Kl, Kv, Ka the variant fixed for its own format are dropped
        (chosen again to fill the new one); the same variant when ``fmt`` is its own."""
        if fmt not in FORMATS:
            raise InputError(f"a sheet format is one of {', '.join(FORMATS)} (got {fmt!r})")
        if fmt == self.drawing.format:
            return self
        return self.with_drawing(format=fmt, Kl=None, Kv=None, Ka=None)

    @property
    def moving_links(self) -> tuple[str, ...]:
        """Moving links in the order they are attached: the crank, then each dyad's two."""
        out = [self.crank.link]
        for d in self.dyads:
            out.extend(d.links)
        return tuple(out)

    def points_of(self, link: str) -> tuple[str, ...]:
        """Names of the points fixed on ``link`` (joints and extra points), in order."""
        names: list[str] = []

        def add(*ps: str) -> None:
            for p in ps:
                if p not in names:
                    names.append(p)

        if link == self.frame_link:
            add(*self.frame_points)
            add(self.crank.pivot)
        if link == self.crank.link:
            add(self.crank.pivot, self.crank.pin)
        for d in self.dyads:
            i, j = d.links
            if link not in (i, j):
                continue
            on_i, on_j = d.points_on_links
            add(*(on_i if link == i else on_j))
        for p in self.points:
            if p.link == link:
                add(p.name)
        return tuple(names)

    def home_link(self, point: str) -> str:
        """The link on which ``point`` was first defined (for an anchor: the known link)."""
        if point in self.frame_points or point == self.crank.pivot:
            return self.frame_link
        if point == self.crank.pin:
            return self.crank.link
        for p in self.points:
            if p.name == point:
                return p.link
        for d in self.dyads:
            if point in d.new_points:
                return d.links[1] if d.kind in ("RPP",) else d.links[0]
        raise KeyError(point)
