"""One plan (or arm) of a drawing and what was decided about it (:mod:`.check`)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..findings import Finding
from .measure import Laid
from .plans import FoundPlan


@dataclass(slots=True)
class Judged:
    """One plan of the drawing and what was decided about it."""

    found: FoundPlan
    scale: float | None
    scale_source: str  # "plan" | "sheet" | "inferred"
    laid: Laid | None = None  # against the construction it is checked at
    best: Laid | None = None  # the position that fits it best
    findings: list[Finding] = field(default_factory=list)
    figures: dict[str, float] = field(default_factory=dict)
    key: str = ""
    pos: str | None = None  # a force plan's or an arm's position
    scales: dict[str, float] = field(default_factory=dict)  # its own (Kp, a scheme's Kl)
    causes: dict[str, str] = field(default_factory=dict)  # a figure → the finding it follows

    @property
    def position(self) -> str | None:
        return self.laid.position if self.laid else self.pos


__all__ = ["Judged"]
