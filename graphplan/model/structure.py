"""Structural analysis: kinematic pairs, mobility, and Assur groups.

Mobility by Chebyshev's formula for a planar mechanism::

    W = 3·n − 2·p5 − p4

with n the moving links, p5 the lower pairs (revolute R = В, prismatic P = П),
p4 the higher pairs (none here). The mechanism is then split, as the textbook
does, into the initial mechanism I(frame, crank) and class-II groups, found on
the pair graph itself (not copied from the file's list): a group is two unknown
links joined by one pair, each joined by exactly one more pair to the links
already known.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import StructureError
from .mechanism import DYAD_KIND_NUMBER, Mechanism


@dataclass(frozen=True, slots=True)
class Pair:
    """A lower kinematic pair between two links: ``kind`` 'R' or 'P', at ``joint`` if R."""

    kind: str
    links: tuple[str, str]
    joint: str | None = None

    @property
    def label(self) -> str:
        where = f" {self.joint}" if self.joint else ""
        return f"{self.kind}{where} ({self.links[0]}-{self.links[1]})"

    @property
    def label_ru(self) -> str:
        """The pair as Russian textbooks letter it: ``В O1 (6-1)`` (вращательная),
        ``П (2-3)`` (поступательная)."""
        where = f" {self.joint}" if self.joint else ""
        return f"{russian_kind(self.kind)}{where} ({self.links[0]}-{self.links[1]})"


_RU_PAIRS = str.maketrans("RP", "ВП")


def russian_kind(kind: str) -> str:
    """A dyad's kind as Russian textbooks write it: В for a revolute pair (вращательная),
    П for a prismatic one (поступательная), e.g. ``RRP`` → ``ВВП``."""
    return kind.translate(_RU_PAIRS)


@dataclass(frozen=True, slots=True)
class AssurGroup:
    """A class-II group (dyad) found on the pair graph: topology only, no lengths."""

    kind: str  # outer–inner–outer pair kinds, e.g. "RRP"
    links: tuple[str, str]
    pairs: tuple[Pair, Pair, Pair]  # outer of links[0], inner, outer of links[1]
    group_class: int = 2
    order: int = 2

    @property
    def kind_ru(self) -> str:
        """The kind as Russian textbooks write it (:func:`russian_kind`)."""
        return russian_kind(self.kind)

    @property
    def kind_number(self) -> int:
        """Kind (вид) 1…5 of the dyad."""
        return DYAD_KIND_NUMBER[self.kind]

    @property
    def formula(self) -> str:
        """Textbook notation, e.g. ``II₂(2,3)`` (class II, kind as the subscript)."""
        sub = "₀₁₂₃₄₅"[self.kind_number]
        return f"II{sub}({self.links[0]},{self.links[1]})"


@dataclass(frozen=True, slots=True)
class Structure:
    """Result of the structural analysis."""

    n_moving: int
    p5: int
    p4: int
    mobility: int
    pairs: tuple[Pair, ...]
    initial: tuple[str, str]  # (frame, crank)
    groups: tuple[AssurGroup, ...]

    @property
    def formula(self) -> str:
        """Formula of structure, e.g. ``I(4,1) → II₂(2,3)``."""
        parts = [f"I({self.initial[0]},{self.initial[1]})"] + [g.formula for g in self.groups]
        return " → ".join(parts)

    @property
    def mobility_equation(self) -> str:
        """Chebyshev's formula with this mechanism's numbers."""
        return (
            f"W = 3·n − 2·p5 − p4 = 3·{self.n_moving} − 2·{self.p5} − {self.p4} = {self.mobility}"
        )


def pairs_of(mech: Mechanism) -> tuple[Pair, ...]:
    """List the lower pairs of the mechanism, in the order they are attached."""
    pairs = [Pair("R", (mech.frame_link, mech.crank.link), mech.crank.pivot)]
    for d in mech.dyads:
        i, j = d.links
        jt = d.joints
        home = mech.home_link
        if d.kind == "RRR":
            pairs += [Pair("R", (home(jt[0]), i), jt[0]), Pair("R", (i, j), jt[1]),
                      Pair("R", (j, home(jt[2])), jt[2])]
        elif d.kind == "RRP":
            pairs += [Pair("R", (home(jt[0]), i), jt[0]), Pair("R", (i, j), jt[1]),
                      Pair("P", (j, d.guides[0].link))]
        elif d.kind == "RPR":
            pairs += [Pair("R", (home(jt[0]), i), jt[0]), Pair("P", (i, j)),
                      Pair("R", (j, home(jt[1])), jt[1])]
        elif d.kind == "PRP":
            pairs += [Pair("P", (d.guides[0].link, i)), Pair("R", (i, j), jt[0]),
                      Pair("P", (j, d.guides[1].link))]
        elif d.kind == "RPP":
            pairs += [Pair("R", (home(jt[0]), i), jt[0]), Pair("P", (i, j)),
                      Pair("P", (j, d.guides[0].link))]
    return tuple(pairs)


def analyse(mech: Mechanism) -> Structure:
    """Compute the mobility and decompose the mechanism into Assur groups.

    Raises
    ------
    StructureError
        If W ≠ 1, or if the links do not split into the crank and class-II dyads.
    """
    pairs = pairs_of(mech)
    moving = {ln for p in pairs for ln in p.links} - {mech.frame_link}
    n = len(moving)
    p5 = len(pairs)
    w = 3 * n - 2 * p5
    for p in pairs:
        if p.links[0] == p.links[1]:
            raise StructureError(
                f"{mech.source}: pair {p.label} joins link {p.links[0]!r} to itself"
            )
    if w != 1:
        raise StructureError(
            f"{mech.source}: mobility W = 3·n − 2·p5 − p4 = 3·{n} − 2·{p5} − 0 = {w}; "
            "a mechanism driven by one crank needs W = 1 (check the link numbers of the dyads)"
        )
    known = {mech.frame_link, mech.crank.link}
    remaining = [p for p in pairs if not set(p.links) <= known]
    groups: list[AssurGroup] = []
    unknown = set(moving) - known
    while unknown:
        found = _find_dyad(remaining, known, unknown)
        if found is None:
            raise StructureError(
                f"{mech.source}: links {', '.join(sorted(unknown))} do not form class-II groups "
                "attached to the frame and the crank"
            )
        groups.append(found)
        known |= set(found.links)
        unknown -= set(found.links)
        remaining = [p for p in remaining if p not in found.pairs]
    return Structure(n, p5, 0, w, pairs, (mech.frame_link, mech.crank.link), tuple(groups))


def _find_dyad(pairs: list[Pair], known: set[str], unknown: set[str]) -> AssurGroup | None:
    for inner in pairs:
        i, j = inner.links
        if i not in unknown or j not in unknown:
            continue
        # pairs to links still unknown belong to groups attached later
        outer_i = [p for p in pairs if i in p.links and p is not inner and _other(p, i) in known]
        outer_j = [p for p in pairs if j in p.links and p is not inner and _other(p, j) in known]
        if len(outer_i) == 1 and len(outer_j) == 1:
            oi, oj = outer_i[0], outer_j[0]
            kind = oi.kind + inner.kind + oj.kind
            if kind == "PRR":  # the same kind read from the other end
                kind, i, j, oi, oj = "RRP", j, i, oj, oi
            elif kind == "PPR":
                kind, i, j, oi, oj = "RPP", j, i, oj, oi
            if kind not in DYAD_KIND_NUMBER:
                continue
            return AssurGroup(kind, (i, j), (oi, inner, oj))
    return None


def _other(pair: Pair, link: str) -> str:
    return pair.links[1] if pair.links[0] == link else pair.links[0]
