"""The step model of a lesson: what each step draws and what its caption says.

A :class:`Lesson` is one construction (a velocity or acceleration plan, the force plans
of a position, Zhukovsky's lever, the flywheel) cut into the steps a lecturer draws on
the blackboard. Every step belongs to one :class:`Panel` (a figure with its own scale:
the plan, the scheme of a group at Kl, the work diagrams …) and carries

* the marks it adds (:class:`Mark`, in the panel's millimetres, **y up** like the
  constructions; the drawing flips y once, see :mod:`graphplan.teaching.drawing`);
* its caption: the vector equation, the known and unknown parts of it
  (:class:`Term`: direction and magnitude, ``None`` where unknown), what is drawn,
  and the results (:class:`Result`): a segment read off the drawing and converted at
  its scale, ``pb = 42.19 mm → v_B = pb·Kv = 42.19·0.01 = 0.4219 m/s``, or a known
  value laid off, ``v_A = 0.4608 m/s → pa = v_A/Kv = 46.08 mm``.

Every number of a caption is taken from the construction's own readings (nothing is
measured again here), so the page teaches exactly the plan the sheets draw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

Pt = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Mark:
    """One thing drawn by a step, in panel mm (y up).

    ``kind``: ``vector`` (arrow from ``points[0]`` to ``points[-1]``), ``line`` (a
    construction line), ``curve`` (an open polyline), ``point`` (a dot),
    ``label`` (the letter ``text`` next to ``points[0]``) or ``text`` (a note written at
    ``points[0]``, left-aligned). ``role`` chooses the colour (absolute, relative,
    normal, tangential, coriolis, sliding, line, load, reaction, force, arm, curve,
    context …); ``context`` marks are the background of a panel (the links of a
    scheme, the axes of a diagram), drawn from its first step on in black.
    ``text`` of a vector or line, when given, is written at its middle.
    """

    kind: str
    name: str
    points: tuple[Pt, ...]
    role: str
    text: str = ""
    dashed: bool = False


@dataclass(frozen=True, slots=True)
class Panel:
    """A figure of a lesson: its title (ru/en) and the line saying its scale."""

    key: str
    title: dict[str, str]
    scale: str = ""


@dataclass(frozen=True, slots=True)
class Term:
    """A term of the step's vector equation: its direction and magnitude, None if unknown."""

    name: str
    direction: str | None
    magnitude: str | None


@dataclass(frozen=True, slots=True)
class Result:
    """A length on the drawing and the physical value it stands for: ``value = mm·per_mm``.

    ``laid`` is True when the value is known and the length is laid off
    (``pa = v_A/Kv``), False when the length is measured and converted
    (``v_B = pb·Kv``). ``factor`` is how the scale is written (``Kv``,
    ``KT/(ω²·δ)``); ``unit`` is SI (m/s, m/s², N, J, kg·m², m).
    """

    segment: str
    quantity: str
    mm: float
    value: float
    unit: str
    factor: str
    per_mm: float
    laid: bool = False

    def __post_init__(self) -> None:
        for name in ("mm", "value", "per_mm"):
            v = getattr(self, name)
            if not math.isfinite(v):
                raise ValueError(f"result {self.segment}: {name} is not finite ({v!r})")
        if not math.isclose(self.value, self.mm * self.per_mm, rel_tol=1e-9, abs_tol=1e-12):
            raise ValueError(f"result {self.segment}: {self.value!r} is not "
                             f"{self.mm!r} mm × {self.per_mm!r}")


@dataclass(frozen=True, slots=True)
class LessonStep:
    """One step of a lesson (numbered from 1, in drawing order).

    ``kind`` names what the step does (``pole``, ``lay``, ``intersect``, ``read``,
    ``similar``, ``point``, ``moment``, ``turn``, ``force``, ``balance``, ``diagram``,
    ``tangent`` …) and picks its heading. ``text`` is the construction's own sentence
    (ru/en); ``notes`` are derived lines (the angular velocity of a link from the step's
    reading, …) that, like the results, a student works out in the try-it-yourself mode.
    """

    number: int
    panel: int
    kind: str
    equation: str
    text: dict[str, str]
    terms: tuple[Term, ...] = ()
    results: tuple[Result, ...] = ()
    marks: tuple[Mark, ...] = ()
    notes: tuple[dict[str, str], ...] = ()
    links: tuple[str, ...] = ()  #: the links the step is about, drawn in colour on the scheme


@dataclass(frozen=True, eq=False)
class Lesson:
    """A construction cut into steps, with its panels and scales (compared by identity).

    Attributes
    ----------
    plan : str
        ``velocity``, ``acceleration``, ``forces``, ``zhukovsky`` or ``flywheel``.
    variant : str
        The variant's name; ``source`` its file.
    position : str | None
        The position's label (None for the flywheel, which is of the whole cycle).
    title : dict[str, str]
        ``{"ru": …, "en": …}``.
    panels : tuple[Panel, ...]
    steps : tuple[LessonStep, ...]
    scales : tuple[str, ...]
        The scales as written on the sheet (``Kv = vA/pa = 0.4608/46.08 = 0.01 (m/s)/mm``).
    scheme : tuple
        The mechanism at the lesson's position (drawing items in mm,
        :func:`graphplan.drawing.mechanism_scheme`), shown beside the plan with each step's
        ``links`` in colour; empty for the flywheel (a lesson of the whole cycle).
    """

    plan: str
    variant: str
    source: str
    position: str | None
    title: dict[str, str]
    panels: tuple[Panel, ...]
    steps: tuple[LessonStep, ...]
    scales: tuple[str, ...] = ()
    scheme: tuple = ()

    def __post_init__(self) -> None:
        for n, s in enumerate(self.steps, start=1):
            if s.number != n or not 0 <= s.panel < len(self.panels):
                raise ValueError(f"lesson {self.plan}: step {n} is misnumbered or has no panel")

    @property
    def results(self) -> tuple[Result, ...]:
        """Every result of every step, in order."""
        return tuple(r for s in self.steps for r in s.results)

    def _repr_html_(self) -> str:  # Jupyter: the page in an isolated frame
        from .page import notebook_html

        return notebook_html(self)

    def _repr_svg_(self) -> str:  # Jupyter without HTML output: the last frame
        from .drawing import frame_svg

        return frame_svg(self, len(self.steps))


__all__ = ["Lesson", "LessonStep", "Mark", "Panel", "Result", "Term"]
