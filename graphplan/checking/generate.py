"""A student's calculation written by graphplan itself, and faults put into it.

:func:`generate` writes, for a variant, the calculation a careful student would write —
scales, ω1, the velocities and accelerations read off the plans (``vB = pb∙Kv = …``),
weights and inertia forces, each group's moment equation for its tangential reaction
with the arms measured on the position plan, the reactions read off the force plans
(``R12 = R12_mm∙Kp = …``), h21 and ``Мур = R21∙h21∙Кl = …`` — from graphplan's own
constructions (:mod:`graphplan.plans.constructions`, :mod:`graphplan.plans.forces`) at
graphplan's scales, every segment rounded to 0,01 mm and every result computed from the
written numbers, as a student computes it. It must pass the checker clean.

:func:`inject` then puts faults into it, each on its own line and position:

==============  ==================================================================
``arithmetic``  a result that its numbers do not give (×1,2 … ×1,9)
``scale``       Ka written in place of Kv, or Kv in place of Ka, in a product
``other``       a segment of another position's plan (``other-variant``)
``sign``        Mур with the wrong sign
``unit``        a reaction in кН with the number of newtons
``lever-arm``   the arm of the same force about another point
``normal``      a slip in a normal component ``aⁿ = v²/l``
``load``        a slip in an inertia force or moment (``Pи = m∙a``)
…               (and the others of :data:`FAULT_KINDS`)
==============  ==================================================================

A student draws on from their own figures: every later line that uses a wrong value
takes it (:func:`_carry`), the acceleration plan is built again from a wrong normal or
Coriolis component, and the force plans from wrong loads, tangential reactions and the
reactions one group passes to the next (:func:`_redraw`, with
:meth:`~graphplan.checking.reference.Reference.own_forces`): the readings off them
change, and the checker must call them consequences, not faults.

Each injected fault is returned with the finding the checker must report for it
(position, quantity, kind).
"""

from __future__ import annotations

import math
import random
import re
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..numbers import written as _fmt  # numbers as a student writes them
from .expressions import evaluate
from .reference import Reference
from .units import fold

FAULT_KINDS = ("arithmetic", "scale", "other", "sign", "unit", "lever-arm", "unit-down",
               "coriolis", "reuse", "label", "segment-for-force", "coriolis-left-out",
               "normal", "load")
KIND_OF_FAULT = {"arithmetic": "arithmetic", "scale": "scale", "other": "other-variant",
                 "sign": "sign", "unit": "unit", "lever-arm": "lever-arm",
                 "unit-down": "unit", "coriolis": "coriolis", "reuse": "other-variant",
                 "label": "label", "segment-for-force": "scale",
                 "coriolis-left-out": "coriolis", "normal": "arithmetic",
                 "load": "arithmetic"}


class Drafting:
    """How a student reads lengths off a drawing: exactly (to 0,01 mm), or with the noise
    of drafting — each length off by up to ``noise_mm`` (uniform) and written with 3 or 4
    significant figures, results with 4.

    Parameters
    ----------
    noise_mm : float
        The largest reading error (mm); 0 reads exactly.
    rng : random.Random, optional
        The source of the noise (default: seeded with 0).
    """

    def __init__(self, noise_mm: float = 0.0, rng: random.Random | None = None):
        self.noise_mm = noise_mm
        self.rng = rng or random.Random(0)

    @property
    def digits(self) -> int:
        """Significant figures of a computed result."""
        return 4 if self.noise_mm else 5

    def __call__(self, mm: float) -> str:
        """A length measured on a drawing (mm), as written."""
        if not self.noise_mm:
            return _fmt(mm, decimals=2)
        x = abs(mm + self.rng.uniform(-self.noise_mm, self.noise_mm)) if mm > \
            self.noise_mm else mm
        if x == 0:
            return "0"
        digits = self.rng.choice((3, 4))
        mag = math.floor(math.log10(abs(x)))
        return _fmt(x, decimals=min(2, max(0, digits - 1 - mag)))


EXACT = Drafting()


@dataclass(frozen=True, slots=True)
class Operand:
    """A name of a formula and the number written for it."""

    name: str
    text: str


@dataclass(frozen=True, slots=True)
class GenLine:
    """One written line: ``lhs = formula = numbers = result unit``.

    ``formula`` names its operands in braces (``"{πb}∙{Ka}"``); the numbers are the
    formula with each operand's text. ``tags`` say what the line is (for the faults).
    """

    lhs: str
    formula: str
    operands: tuple[Operand, ...]
    unit: str
    digits: int = 5
    sign: int = 1
    tags: tuple[str, ...] = ()
    result_text: str | None = None

    @property
    def numbers(self) -> str:
        out = self.formula
        for op in self.operands:
            out = out.replace("{" + op.name + "}", op.text)
        return out

    @property
    def template(self) -> str:
        return re.sub(r"\{([^}]+)\}", r"\1", self.formula)

    @property
    def result(self) -> float:
        if not self.operands:
            return evaluate(self.result_text or "0").number
        return evaluate(self.numbers).number

    def text(self) -> str:
        if not self.operands:
            return f"{self.lhs} = {self.result_text} {self.unit}".strip()
        res = self.result_text if self.result_text is not None else _fmt(self.result,
                                                                         self.digits)
        return f"{self.lhs} = {self.template} = {self.numbers} = {res} {self.unit}".strip()


@dataclass(frozen=True, slots=True)
class GenPosition:
    label: str
    lines: tuple[GenLine, ...]
    arms: tuple[tuple[str, str, str], ...] = ()  # name, force, about


@dataclass(frozen=True, slots=True)
class Generated:
    """A generated work: general lines and positions, and the variant's path as written."""

    variant: str
    general: tuple[GenLine, ...]
    positions: tuple[GenPosition, ...]
    student: str = "graphplan"

    def toml(self) -> str:
        """The student file (``docs/check-format.md``)."""
        out = ["[work]", f"variant = {_q(self.variant)}", f"student = {_q(self.student)}",
               'lang = "ru"', "", "[general]", "lines = ["]
        out += [f"  {_q(ln.text())}," for ln in self.general]
        out.append("]")
        for p in self.positions:
            out += ["", "[[positions]]", f"label = {_q(p.label)}"]
            if p.arms:
                arms = ", ".join(f"{_q(n)} = {{ force = {_q(f)}, about = {_q(a)} }}"
                                 for n, f, a in p.arms)
                out.append(f"arms = {{ {arms} }}")
            out.append("lines = [")
            out += [f"  {_q(ln.text())}," for ln in p.lines]
            out.append("]")
        return "\n".join(out) + "\n"


def _q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _name(quantity: str) -> str:
    """graphplan's reading quantity (``"v_B"``, ``"aⁿ_BA"``) → a student's name."""
    return quantity.replace("ⁿ_", "n").replace("τ_", "τ").replace("_", "")


def generate(variant: str | Path, *, positions: tuple[str, ...] | None = None,
             variant_ref: str | None = None, student: str = "graphplan",
             drafting: Drafting = EXACT, ref: Reference | None = None) -> Generated:
    """The calculation of a variant as a careful student writes it (module docstring).

    Parameters
    ----------
    variant : path
        The variant file.
    positions : tuple of str, optional
        Labels to write (default: every position of the variant where the force plans
        can be drawn).
    variant_ref : str, optional
        How the student file names the variant (default: its absolute path).
    drafting : Drafting, optional
        How lengths are read off the drawings (default: exactly, to 0,01 mm).
    """
    measure = drafting
    dg = drafting.digits
    from ..plans import force_plans
    ref = ref or Reference.of(variant)
    mech, kin = ref.mech, ref.kin
    sc = ref.sheet1
    kl, kv, ka = sc.kl.per_mm, sc.kv.per_mm, sc.ka.per_mm
    cr = mech.crank
    piv, A = cr.pivot, cr.pin
    oa_mm = cr.length / kl
    general = [
        GenLine("Кl", f"{{l{piv}{A}}}/{{{piv}{A}}}",
                (Operand(f"l{piv}{A}", _fmt(cr.length, 6)),
                 Operand(f"{piv}{A}", _fmt(oa_mm, 6))),
                "м/мм", 6, tags=("scale",)),
        GenLine("ω1", "π∙{n1}/30",
                (Operand("n1", _fmt(cr.rpm, 6)),), "рад/с", 5),
    ]
    w1 = general[-1].result
    va = w1 * cr.length
    aa = w1 ** 2 * cr.length
    general += [
        GenLine(f"v{A}", f"{{ω1}}∙{{l{piv}{A}}}", (Operand("ω1", _fmt(w1, 5)),
                                                Operand(f"l{piv}{A}", _fmt(cr.length, 6))),
                "м/с", 5),
        GenLine("Kv", f"{{v{A}}}/{{p{A.lower()}}}", (Operand(f"v{A}", _fmt(va, 5)),
                                                     Operand(f"p{A.lower()}",
                                                             _fmt(va / kv, decimals=2))),
                "(м/с)/мм", 4, tags=("scale",), result_text=_fmt(kv, 6)),
        GenLine(f"a{A}", f"{{ω1}}^2∙{{l{piv}{A}}}", (Operand("ω1", _fmt(w1, 5)),
                                                  Operand(f"l{piv}{A}", _fmt(cr.length, 6))),
                "м/с²", 5),
        GenLine("Ka", f"{{a{A}}}/{{π{A.lower()}}}", (Operand(f"a{A}", _fmt(aa, 5)),
                                                     Operand(f"π{A.lower()}",
                                                             _fmt(aa / ka, decimals=2))),
                "(м/с²)/мм", 4, tags=("scale",), result_text=_fmt(ka, 6)),
    ]
    g = float(np.hypot(*mech.gravity))
    for ln, props in mech.links.items():
        if props.mass > 0 and g > 0:
            general.append(GenLine(f"G{ln}", f"{{m{ln}}}∙{{g}}",
                                   (Operand(f"m{ln}", _fmt(props.mass, 6)),
                                    Operand("g", _fmt(g, 4))), "Н", 6))
    weights = {ln.lhs: ln.result for ln in general if ln.lhs.startswith("G")}
    loads, forces = ref.loads["rule"], ref.forces["rule"]
    kl_s = sc.kl
    out_positions = []
    labels = positions or kin.labels
    for label in labels:
        k = ref.index(label)
        if k is None:
            raise ValueError(f"the variant has no position {label!r}")
        try:
            plans = force_plans(mech, kin, forces, loads, k, kl_s)
        except Exception:
            if positions:
                raise
            continue
        lines: list[GenLine] = []
        vals: dict[str, float] = {}
        written_omegas: set[str] = set()
        for seg, quantity, scale_name, unit in _readings(ref, k, kl, kv, ka):
            name = _name(quantity)
            if seg in (f"p{A.lower()}", f"π{A.lower()}"):
                continue
            scale_txt = _fmt(kv if scale_name == "Kv" else ka, 6)
            known = _known_component(ref, k, quantity, seg, vals, written_omegas, lines, dg)
            if known is not None:  # aⁿ = v²/l, aᵏ = 2·ω·v_r computed, then drawn
                lines.append(known)
                vals[name] = float(_fmt(known.result, dg).replace(",", "."))
                lines.append(GenLine(seg, f"{{{name}}}/{{{scale_name}}}",
                                     (Operand(name, _fmt(vals[name], dg)),
                                      Operand(scale_name, scale_txt)), "мм", 3,
                                     tags=("drawn", name)))
                continue
            mm = measure(ref.reading_mm(seg, k, kl, kv, ka) or 0.0)
            gl = GenLine(name, f"{{{seg}}}∙{{{scale_name}}}",
                         (Operand(seg, mm), Operand(scale_name, scale_txt)), unit, dg,
                         tags=("reading", scale_name))
            lines.append(gl)
            vals[name] = float(_fmt(gl.result, dg).replace(",", "."))
        for ln, props in mech.links.items():
            if props.mass <= 0 or props.centre is None:
                continue
            a_name = f"a{props.centre}"
            if a_name not in vals:
                continue
            lines.append(GenLine(f"Pи{ln}", f"{{m{ln}}}∙{{{a_name}}}",
                                 (Operand(f"m{ln}", _fmt(props.mass, 6)),
                                  Operand(a_name, _fmt(vals[a_name], dg))), "Н", dg,
                                 tags=("load",)))
        for ln, props in mech.links.items():
            eps = ref.value(("eps", ln), k)
            mi = ref.value(("inertia_moment", ln), k)
            if props.inertia > 0 and eps and mi:
                lines.append(GenLine(f"Mи{ln}", f"{{IS{ln}}}∙{{ε{ln}}}",
                                     (Operand(f"IS{ln}", _fmt(props.inertia, 6)),
                                      Operand(f"ε{ln}", _fmt(eps, 5))), "Нм", 5,
                                     tags=("load",)))
        for f in loads.all_forces():
            if f.kind == "resistance" and np.hypot(*f.vector[k]) > 0:
                lines.append(GenLine(f.name, "", (), "Н", tags=("load",),
                                     result_text=_fmt(float(np.hypot(*f.vector[k])), 6)))
        for mm_ in loads.all_moments():
            if mm_.kind == "resistance" and mm_.moment[k] != 0:
                lines.append(GenLine(mm_.name, "", (), "Нм", tags=("load",),
                                     result_text=_fmt(abs(float(mm_.moment[k])), 6)))
        arms: list[tuple[str, str, str]] = []
        written = {ln.lhs: ln.result for ln in lines}
        written.update(weights)
        # a force plan per group, each at its own Kp stated before it (graphplan's own
        # answer key draws them so); one Kp for all when they agree
        kp, kp_t = 0.0, ""

        def state_kp(fp) -> None:
            nonlocal kp, kp_t
            scale = fp.scale.per_mm
            basis = fp.scale.quantity
            if kp and (_close_rel(scale, kp) or basis not in fp.readings):
                return
            kp, kp_t = scale, _fmt(scale, 6)
            size = fp.readings[basis].value
            lines.append(GenLine("Кр", f"{{{basis}}}/{{{basis}_mm}}",  # noqa: B023 (this k)
                                 (Operand(basis, _fmt(size, 6)),
                                  Operand(f"{basis}_mm", _fmt(size / kp, decimals=2))),
                                 "Н/мм", 4, tags=("scale",), result_text=kp_t))

        for fp in plans:
            if fp.group.startswith("crank"):
                gl = _crank_line(fp, written, arms, kl, cr, measure)
                if gl is not None:
                    lines.extend(gl)
                continue
            state_kp(fp)
            for eq in fp.equations:
                tl = _tangential(eq, fp, written, arms, kl, measure)
                if tl is not None:
                    lines.append(tl)
            for q, r in fp.readings.items():
                if not re.fullmatch(r"R\d\d", q) or q in written or f"R{q[2]}{q[1]}" in \
                        written:
                    continue
                gl = GenLine(q, f"{{{q}_mm}}∙{{Кр}}", (Operand(f"{q}_mm",
                                                              measure(r.value / kp)),
                                                      Operand("Кр", kp_t)), "Н", dg + 1,
                             tags=("reaction",))
                lines.append(gl)
                written[q] = float(_fmt(gl.result, dg + 1).replace(",", "."))
        out_positions.append(GenPosition(label, tuple(lines), tuple(arms)))
    return Generated(variant_ref or str(Path(variant).resolve()), tuple(general),
                     tuple(out_positions), student)


def _decimals(text: str) -> int:
    """Decimals a number is written with (a length read again keeps its precision)."""
    return len(text.split(",")[1]) if "," in text else 0


def _close_rel(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * max(abs(a), abs(b))


def _known_component(ref: Reference, k: int, quantity: str, seg: str,
                     vals: dict[str, float], omegas: set[str], lines: list[GenLine],
                     digits: int) -> GenLine | None:
    """A normal or Coriolis acceleration computed as a student computes it before laying
    it off: ``anBA = vBA^2/lBA`` (from the velocity read before) and ``aᵏA3 = 2∙ω3∙vAA3``
    (ω of the guide written on a line of its own); ``None`` when the line cannot be
    written that way (a zero component, a velocity not read)."""
    m = re.fullmatch(r"a([ⁿᵏ])_(\w+)", quantity)
    if m is None:
        return None
    value = ref.plan_value(seg, k)
    if not value:
        return None
    sup, pts = m.groups()
    name = _name(quantity)
    if sup == "ⁿ":
        v_name = f"v{pts}"
        if v_name not in vals or len(pts) != 2:
            return None
        length = ref.value(("length", pts[0], pts[1]), k)
        if not length:
            return None
        return GenLine(name, f"{{{v_name}}}^2/{{l{pts}}}",
                       (Operand(v_name, _fmt(vals[v_name], digits)),
                        Operand(f"l{pts}", _fmt(length, 4))), "м/с²", digits,
                       tags=("normal",))
    # the Coriolis acceleration: 2·ω of a link times a relative velocity read before
    w = ref.kin.vel.omega
    for v_name, v in vals.items():
        if not v_name.startswith("v") or v == 0:
            continue
        for link in ref.mech.moving_links:
            om = abs(float(w[link][k]))
            if om and abs(2 * om * v - value) <= 0.02 * value:
                o_name = f"ω{link}"
                if o_name not in omegas:
                    omegas.add(o_name)
                    lines.append(GenLine(o_name, "", (), "рад/с",
                                         result_text=_fmt(om, digits)))
                return GenLine(name, f"2∙{{{o_name}}}∙{{{v_name}}}",
                               (Operand(o_name, _fmt(om, digits)),
                                Operand(v_name, _fmt(v, digits))), "м/с²", digits,
                               tags=("coriolis",))
    return None


def _readings(ref: Reference, k: int, kl: float, kv: float, ka: float):
    ref.reading_mm("pa", k, kl, kv, ka)  # builds the plans at these scales
    vp, ap = ref._plans[(k, kl, kv, ka)]
    for r in vp.readings.values():
        yield r.name, r.quantity, "Kv", "м/с"
    for r in ap.readings.values():
        yield r.name, r.quantity, "Ka", "м/с²"


_TERM = re.compile(r"([+−-])\s*([^\s·/]+)(?:·(\S+)|/Kl)")


def _size(force: str, fp, written: dict[str, float]) -> float | None:
    if force in written:
        return written[force]
    rev = f"R{force[2]}{force[1]}" if re.fullmatch(r"R\d\d", force) else None
    if rev and rev in written:
        return written[rev]
    if force in fp.readings:
        return fp.readings[force].value
    return None


def _terms(rest: str, about: str, fp, written, arms, measure: Drafting = EXACT,
           skip: str = ""):
    """The known moments of an equation as formula terms and operands (signs moved to the
    other side), or None when a term cannot be written."""
    terms, ops = [], []
    for sgn, force, h_name in _TERM.findall(rest):
        s = "-" if sgn == "+" else "+"
        if not h_name:  # a couple M/Kl
            size = _size(force, fp, written)
            if size is None:
                return None
            terms.append(f"{s}{{{force}}}/{{Кl}}")
            ops += [Operand(force, _fmt(size, 6))]
            continue
        if force == skip:
            continue
        h = fp.arms_mm.get(f"h_{force}@{about}")
        size = _size(force, fp, written)
        if h is None or size is None:
            return None
        aname = f"h{force}{about}"
        if (aname, force, about) not in arms:
            arms.append((aname, force, about))
        terms.append(f"{s}{{{force}}}∙{{{aname}}}")
        ops += [Operand(force, _fmt(size, 6)), Operand(aname, measure(h))]
    return terms, ops


def _tangential(eq: str, fp, written: dict[str, float], arms: list, kl: float,
                measure: Drafting = EXACT) -> GenLine | None:
    """``ΣM_B(link 2): Rτ12·AB − G2·h_G2 = 0`` as ``Rτ12 = (G2∙hG2B)/AB = …``."""
    m = re.match(r"ΣM_(\w+)\(link [^)]*\): (Rτ\d\d)·(\w+)(.*) = 0$", eq)
    if m is None:
        return None
    about, unknown, arm_name, rest = m.groups()
    h_unknown = fp.arms_mm.get(f"h_{unknown}@{about}")
    got = _terms(rest, about, fp, written, arms, measure)
    if not h_unknown or got is None or not got[0]:
        return None
    terms, ops = got
    if any("/{Кl}" in t for t in terms):
        ops.append(Operand("Кl", _fmt(kl, 6)))
    body = "".join(terms)
    body = body[1:] if body.startswith("+") else body
    if arm_name.startswith("h_"):
        arm_name = f"h{unknown}{about}"
        arms.append((arm_name, unknown, about))
    return GenLine(unknown, f"({body})/{{{arm_name}}}",
                   (*_order(ops, body), Operand(arm_name, measure(h_unknown) if
                                                arm_name.startswith("h") else
                                                _fmt(h_unknown, decimals=2))), "Н",
                   measure.digits, tags=("tangential",))


def _order(ops: list[Operand], body: str) -> list[Operand]:
    """Operands in the order their names appear in the formula (Кl once, where it is)."""
    out, seen = [], set()
    for name in re.findall(r"\{([^}]+)\}", body):
        for o in ops:
            if o.name == name and name not in seen:
                out.append(o)
                seen.add(name)
                break
    return out


def _crank_line(fp, written: dict[str, float], arms: list, kl: float, cr,
                measure: Drafting = EXACT):
    """``ΣM_O(link 1): Mур/Kl − R21·h_R21 + G1·h_G1 = 0`` as h21 and
    ``Мур = (R21∙h21 − G1∙hG1O)∙Кl = …``."""
    eq = fp.equations[0]
    m = re.match(r"ΣM_(\w+)\(link [^)]*\): Mур/Kl(.*) = 0$", eq)
    if m is None:
        return None
    about, rest = m.groups()
    lines = []
    react = [f for _s, f, _h in _TERM.findall(rest) if re.fullmatch(r"R\d\d", f)]
    terms, ops = [], []
    for sgn, force, h_name in _TERM.findall(rest):
        s = "-" if sgn == "+" else "+"
        size = _size(force, fp, written)
        if size is None:
            return None
        if not h_name:
            terms.append(f"{s}{{{force}}}/{{Кl}}")
            ops.append(Operand(force, _fmt(size, 6)))
            continue
        h = fp.arms_mm.get(f"h_{force}@{about}")
        if h is None:
            return None
        h_txt = measure(h)
        if force in react:
            aname = f"h{force[1:]}"
            lines.append(GenLine(aname, "", (), "мм", result_text=h_txt,
                                 tags=("crank_arm",)))
        else:
            aname = f"h{force}{about}"
            arms.append((aname, force, about))
        terms.append(f"{s}{{{force}}}∙{{{aname}}}")
        ops += [Operand(force, _fmt(size, 6)), Operand(aname, h_txt)]
    if not terms:
        return None
    if len(terms) == 1:
        body = terms[0]
        formula = (body[1:] if body.startswith("+") else body) + "∙{Кl}"
    else:
        body = "".join(terms)
        formula = "(" + (body[1:] if body.startswith("+") else body) + ")∙{Кl}"
    ops.append(Operand("Кl", _fmt(kl, 6)))
    lines.append(GenLine("Мур", formula, tuple(_order(ops, formula)), "Нм", measure.digits,
                         tags=("M_bal",)))
    return lines


# --- faults ---------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Fault:
    """A fault put into a generated work, and the finding it must give."""

    kind: str  # one of FAULT_KINDS
    position: str
    quantity: str  # the name the finding must carry
    finding_kind: str
    line: str  # the faulty line as written
    carried: tuple[str, ...] = ()  # later lines that use the wrong value, as written
    redrawn: tuple[str, ...] = ()  # plans drawn again from it: "acceleration", "forces"


def inject(gen: Generated, kinds: tuple[str, ...], rng: random.Random,
           ref: Reference | None = None, only=None) -> tuple[Generated, tuple[Fault, ...]]:
    """Put one fault of each of ``kinds`` into ``gen``, each at a position of its own
    (``only``: a predicate on the lines a fault may go into, default any that fits).

    Raises
    ------
    ValueError
        If a fault cannot be placed (no suitable line is left).
    """
    ref = ref or Reference.of(gen.variant)
    positions = [list(p.lines) for p in gen.positions]
    used_pos: set[int] = set()
    faults = []
    for kind in kinds:
        now = replace(gen, positions=tuple(replace(p, lines=tuple(ls)) for p, ls in
                                           zip(gen.positions, positions, strict=True)))
        cands = [(i, j) for i, lines in enumerate(positions) for j, ln in enumerate(lines)
                 if i not in used_pos and (only is None or only(ln)) and
                 _fits(kind, ln, gen.positions[i].label, ref, now)]
        if not cands:
            raise ValueError(f"no line left for a fault of kind {kind!r}")
        i, j = rng.choice(cands)
        label = gen.positions[i].label
        old = positions[i][j]
        orig = list(positions[i])
        before = [ln.text() for ln in orig]
        if kind == "coriolis-left-out":
            used_pos.add(i)
            fault = _leave_out_coriolis(positions[i], j, label, ref, now)
        else:
            new, quantity = _apply(kind, old, label, ref, now, rng)
            positions[i][j] = new
            used_pos.add(i)
            if kind not in ("unit", "unit-down", "sign", "segment-for-force"):
                _carry(positions[i], j, old, new)
            fault = Fault(kind, label, quantity, KIND_OF_FAULT[kind], new.text())
        if kind not in ("unit", "unit-down", "sign", "segment-for-force"):
            # the student draws on with their own values: the acceleration plan from a
            # wrong normal or Coriolis component, the force plans from wrong loads
            redrawn = _redraw(positions[i], orig, label, ref, now)
        else:
            redrawn = ()
        was = set(before)
        carried = tuple(t for t in (ln.text() for ln in positions[i])
                        if t not in was and t != fault.line)
        faults.append(replace(fault, carried=carried, redrawn=redrawn))
    out = replace(gen, positions=tuple(replace(p, lines=tuple(ls)) for p, ls in
                                       zip(gen.positions, positions, strict=True)))
    return out, tuple(faults)


def _redraw(lines: list[GenLine], orig: list[GenLine], label: str, ref: Reference,
            gen: Generated) -> tuple[str, ...]:
    """A student draws on from their own figures: when a fault changed a normal or
    Coriolis component, the acceleration plan is rebuilt with it (every segment read
    again, with the same drafting error); when it changed a load, a tangential reaction
    or a reaction one group passes to the next, the force plans are solved again from
    the student's own values (:meth:`Reference.own_forces`) and every reaction, arm of a
    reaction and h21 the fault moves is read off them (with the drafting error it was
    read with). The changes are carried on (:func:`_carry`).
    ``orig`` are the position's lines before the fault. Returns the plans redrawn
    (``"acceleration"``, ``"forces"``) where a reading changed."""
    sc = _scales(gen)
    kl, kv, ka = sc.get("Кl", 1e-3), sc.get("Kv"), sc.get("Ka")
    k = ref.index(label)
    done: list[str] = []
    if k is None or not kv or not ka:
        return ()
    was = {ln.text() for ln in orig}
    first = {ln.lhs: ln for ln in reversed(orig)}

    def written(ln: GenLine) -> float:
        return evaluate(_written_result(ln)).number

    def changed() -> list[GenLine]:
        return [ln for ln in lines if ln.text() not in was]

    # the acceleration plan from the student's own normal and Coriolis components
    moved = [ln for ln in changed() if {"normal", "coriolis"} & set(ln.tags) and
             ln.lhs in first and written(first[ln.lhs])]
    if moved:
        normals, each = [], []
        for ln in moved:  # the student's component over graphplan's (as the checker has it)
            if "normal" in ln.tags and len(ln.lhs) == 4:
                link = ref.normal_link(ln.lhs[2], ln.lhs[3])
                exact = ref.value(("a_n", ln.lhs[2], ln.lhs[3]), k)
                if link is not None and exact:
                    normals.append((link, round(written(ln) / exact, 6)))
            elif "coriolis" in ln.tags:
                exact = ref.plan_value("k_" + ln.lhs[2:], k)
                if exact:
                    each.append(("k_" + ln.lhs[2:], round(written(ln) / exact, 6)))
        spec = tuple(sorted(normals))
        for m, ln in enumerate(lines):
            if "reading" not in ln.tags or ln.operands[1].name != "Ka":
                continue
            seg = ln.operands[0]
            e0 = ref.reading_mm(seg.name, k, kl, kv, ka)
            e1 = ref.reading_mm_coriolis(seg.name, k, kl, kv, ka, 1.0, spec,
                                         tuple(sorted(each)))
            if e0 is None or e1 is None or abs(e1 - e0) < 0.01:
                continue
            mine = float(seg.text.replace(",", ".")) + (e1 - e0)
            new = replace(ln, operands=(replace(seg, text=_fmt(abs(mine), decimals=_decimals(
                seg.text))),
                                        *ln.operands[1:]))
            lines[m] = new
            _carry(lines, m, ln, new)
            if "acceleration" not in done:
                done.append("acceleration")
    where = {ln_: n for n, d in enumerate(ref.mech.dyads) for ln_ in d.links}

    def outer_pair(name: str) -> tuple[str, str] | None:
        if not re.fullmatch(r"R\d\d", name):
            return None
        i_, j_ = name[1], name[2]
        if i_ in where and j_ in where and where[i_] != where[j_]:
            return (i_, j_) if where[i_] > where[j_] else (j_, i_)
        return None

    if not any({"load", "tangential"} & set(ln.tags) or ("reaction" in ln.tags and
                                                         outer_pair(ln.lhs))
               for ln in changed()):
        return tuple(done)
    # the force plans from the student's own loads, tangential and passed-on reactions

    def inputs(upto: list[GenLine]):
        sizes: dict[str, float] = {}
        tang: dict[str, float] = {}
        outer: dict[tuple[str, str], float] = {}
        for x in upto:
            if "load" in x.tags:
                sizes[fold(x.lhs)] = abs(written(x))
            elif "tangential" in x.tags:
                tang[x.lhs] = abs(written(x))
            elif "reaction" in x.tags and outer_pair(x.lhs):
                outer[outer_pair(x.lhs)] = abs(written(x))  # type: ignore[index]
        return sizes, tang, outer

    arms = {n: (f, a) for p in gen.positions if p.label == label for n, f, a in p.arms}
    kp = None
    for m in range(len(lines)):
        ln = lines[m]
        if ln.lhs == "Кр" and ln.result_text is not None:
            kp = evaluate(ln.result_text).number
        targets: list[tuple[int, tuple, float]] = []  # operand index (-1: result), key, scale
        if "reaction" in ln.tags and re.fullmatch(r"R\d\d", ln.lhs) and kp:
            targets.append((0, ("reaction", ln.lhs[1], ln.lhs[2]), kp))
        elif "crank_arm" in ln.tags:
            targets.append((-1, ("crank_arm", ln.lhs[1]), kl))
        elif {"tangential", "M_bal"} & set(ln.tags):
            for t, op in enumerate(ln.operands):
                spec_ = arms.get(op.name)
                if spec_ is not None and spec_[0].startswith("R"):
                    targets.append((t, ("arm", *spec_), kl))
        if not targets:
            continue
        n_before = next((i for i, x in enumerate(orig) if x.lhs == ln.lhs and
                         x.tags == ln.tags), None)
        if n_before is None:
            continue
        s1, t1, o1 = inputs(lines[:m])
        s0, t0, o0 = inputs(orig[:n_before])
        own = ref.own_forces(k, s1, t1, "rule", o1)
        base = ref.own_forces(k, s0, t0, "rule", o0)
        if own is None or base is None:
            continue
        new = ln
        for t, key, scale in targets:
            # read off the student's own plan, with the same drafting error; a figure
            # the fault does not move is left as it was read
            e0, e1 = ref.value(key, k), ref.own_value(key, k, own)
            e_before = ref.own_value(key, k, base)
            if e0 is None or e1 is None or e_before is None or \
                    abs(e1 - e_before) / scale < 0.01:
                continue
            if t < 0:
                mine = evaluate(new.result_text or "0").number + (e1 - e0) / scale
                new = replace(new, result_text=_fmt(abs(mine), decimals=_decimals(
                    new.result_text or "0")))
            else:
                op = new.operands[t]
                mine = float(op.text.replace(",", ".")) + (abs(e1) - abs(e0)) / scale
                ops = list(new.operands)
                ops[t] = replace(op, text=_fmt(abs(mine), decimals=_decimals(op.text)))
                new = replace(new, operands=tuple(ops))
        if new is not ln:
            lines[m] = new
            _carry(lines, m, ln, new)
            if "forces" not in done:
                done.append("forces")
    return tuple(done)


def _without_coriolis(lines: list[GenLine], label: str, ref: Reference, gen: Generated
                      ) -> list[tuple[int, str]]:
    """The acceleration readings of a position drawn without the Coriolis acceleration:
    (line index, segment as written) for each one that differs by 2 mm and 15 % or more."""
    sc = _scales(gen)
    kl, kv, ka = sc.get("Кl", 1e-3), sc.get("Kv"), sc.get("Ka")
    k = ref.index(label)
    if k is None or not kv or not ka or len(ref.coriolis_names(k)) != 1:
        return []
    out = []
    for m, ln in enumerate(lines):
        if "reading" not in ln.tags or ln.operands[1].name != "Ka":
            continue
        seg = ln.operands[0]
        v = ref.reading_mm_coriolis(seg.name, k, kl, kv, ka, 0.0)
        mine = float(seg.text.replace(",", "."))
        if v is not None and abs(v - mine) >= 2 and abs(v - mine) >= 0.15 * max(v, mine) \
                and _far(v, mine):
            out.append((m, _fmt(v, decimals=2)))
    return out


def _leave_out_coriolis(lines: list[GenLine], j: int, label: str, ref: Reference,
                        gen: Generated) -> Fault:
    """The Coriolis acceleration left out: its lines struck out, the acceleration plan
    drawn without it (every reading that changes), and the values carried on."""
    changes = _without_coriolis(lines, label, ref, gen)
    first = lines[changes[0][0]]
    carried: list[str] = []
    for m, text in changes:
        old = lines[m]
        lines[m] = replace(old, operands=(replace(old.operands[0], text=text),
                                          *old.operands[1:]))
        if m != changes[0][0]:
            carried.append(lines[m].text())
        carried += _carry(lines, m, old, lines[m])
    cor = lines[j]
    drop = {j} | {m for m, ln in enumerate(lines) if "drawn" in ln.tags and cor.lhs in ln.tags}
    for m in sorted(drop, reverse=True):
        del lines[m]
    first_now = next(ln for ln in lines if ln.lhs == first.lhs and "reading" in ln.tags)
    return Fault("coriolis-left-out", label, first.operands[0].name, "coriolis",
                 first_now.text(), tuple(carried))


def _written_result(ln: GenLine) -> str:
    return ln.result_text if ln.result_text is not None else _fmt(ln.result, ln.digits)


def _reversed(name: str) -> str:
    m = re.fullmatch(r"(R[τn]?)(\d)(\d)", name)
    return f"{m.group(1)}{m.group(3)}{m.group(2)}" if m else name


def _carry(lines: list[GenLine], j: int, old: GenLine, new: GenLine) -> tuple[str, ...]:
    """A student carries a wrong result on: every later line of the position that uses
    it takes the wrong number (and its own result changes with it). Returns the carried
    lines as written."""
    changed = {old.lhs: _written_result(new)} if _written_result(old) != _written_result(
        new) else {}
    out = []
    for m in range(j + 1, len(lines)):
        ln = lines[m]
        ops = list(ln.operands)
        hit = False
        for t, op in enumerate(ops):
            for name, text in changed.items():
                if op.name in (name, _reversed(name)):
                    ops[t] = replace(op, text=text)
                    hit = True
        if hit:
            before = _written_result(ln)
            if "scale" in ln.tags and ln.result_text is not None and len(ops) == 2:
                # Кр = Q/Q_mm: the scale is chosen, the segment drawn from the force
                kp = float(ln.result_text.replace(",", "."))
                size = float(ops[0].text.replace(",", "."))
                ops[1] = replace(ops[1], text=_fmt(size / kp, 4))
            lines[m] = replace(ln, operands=tuple(ops))
            out.append(lines[m].text())
            if _written_result(lines[m]) != before:
                changed[ln.lhs] = _written_result(lines[m])
    return tuple(out)


def _scales(gen: Generated) -> dict[str, float]:
    return {ln.lhs: (evaluate(ln.result_text).number if ln.result_text else ln.result)
            for ln in gen.general if "scale" in ln.tags}


def _segment_elsewhere(ln: GenLine, label: str, ref: Reference, gen: Generated):
    """Another position whose segment differs by 15 % or more (and is no plain ratio)."""
    seg = ln.operands[0]
    sc = _scales(gen)
    kl, kv, ka = sc.get("Кl", 1e-3), sc.get("Kv"), sc.get("Ka")
    mine = float(seg.text.replace(",", "."))
    out = []
    for other in ref.labels:
        if other == label:
            continue
        v = ref.reading_mm(seg.name, ref.labels.index(other), kl, kv, ka)
        if v is None or v < 5 or mine < 5:
            continue
        r = v / mine
        if abs(r - 1) < 0.15 or any(abs(r / s - 1) < 0.03 for s in
                                    (2, 0.5, 2.5, 0.4, 4, 0.25, 5, 0.2, 10, 0.1)):
            continue
        out.append((other, v))
    return out


def _fits(kind: str, ln: GenLine, label: str, ref: Reference, gen: Generated) -> bool:
    if kind == "arithmetic":
        return bool(ln.operands) and "scale" not in ln.tags and abs(ln.result) > 1e-6 \
            and "M_bal" not in ln.tags
    if kind == "normal":  # a slip in aⁿ = v²/l, and the acceleration plan drawn from it
        return "normal" in ln.tags and abs(ln.result) > 1e-6
    if kind == "load":  # a slip in Pи = m∙a or Mи = IS∙ε, and the force plans drawn on
        return "load" in ln.tags and bool(ln.operands) and abs(ln.result) > 1e-6
    if kind == "scale":
        return "reading" in ln.tags and abs(ln.result) > 1e-3 and float(
            ln.operands[0].text.replace(",", ".")) >= 5
    if kind == "other":
        return "reading" in ln.tags and bool(_segment_elsewhere(ln, label, ref, gen))
    if kind == "sign":
        return "M_bal" in ln.tags and abs(ln.result) > 0.05 * max(
            abs(x) for x in ref.forces["rule"].M_bal)
    if kind == "unit":
        return ("reaction" in ln.tags or ("load" in ln.tags and not ln.operands)) and \
            ln.result > 1.0
    if kind == "unit-down":
        return ("reaction" in ln.tags or "load" in ln.tags) and ln.result > 100.0
    if kind == "coriolis":
        return "coriolis" in ln.tags and ln.result > 0.05
    if kind == "coriolis-left-out":
        if "coriolis" not in ln.tags or ln.result <= 0.05:
            return False
        lines = next(p.lines for p in gen.positions if p.label == label)
        return bool(_without_coriolis(list(lines), label, ref, gen))
    if kind == "reuse":
        return "reading" in ln.tags and bool(_own_elsewhere(ln, label, gen))
    if kind == "label":
        return "reading" in ln.tags and bool(_other_name(ln, label, ref, gen))
    if kind == "segment-for-force":
        return "M_bal" in ln.tags and _segment_of_force(ln, label, gen) is not None
    if kind == "lever-arm":
        if "tangential" not in ln.tags:
            return False
        return bool(_other_arms(ln, label, ref, gen))
    raise ValueError(f"unknown fault kind {kind!r} (expected one of {', '.join(FAULT_KINDS)})")


_RATIOS = (2, 0.5, 2.5, 0.4, 4, 0.25, 5, 0.2, 10, 0.1)


def _far(a: float, b: float) -> bool:
    """Two lengths a slip can tell apart: 15 % or more, and no plain ratio."""
    if a < 5 or b < 5:
        return False
    r = a / b
    return abs(r - 1) >= 0.15 and all(abs(r / x - 1) >= 0.03 for x in _RATIOS)


def _own_elsewhere(ln: GenLine, label: str, gen: Generated) -> list[str]:
    """The student's own reading of the same segment at other positions (as written)."""
    seg = ln.operands[0]
    mine = float(seg.text.replace(",", "."))
    out = []
    for p in gen.positions:
        if p.label == label:
            continue
        for other in p.lines:
            if "reading" in other.tags and other.operands[0].name == seg.name:
                v = float(other.operands[0].text.replace(",", "."))
                if _far(v, mine):
                    out.append(other.operands[0].text)
    return out


def _other_name(ln: GenLine, label: str, ref: Reference, gen: Generated) -> list[str]:
    """Readings of another segment of the same plan at the same position, as the student
    wrote them, that differ from this one and from every value this segment has."""
    seg = ln.operands[0]
    mine = float(seg.text.replace(",", "."))
    sc = _scales(gen)
    kl, kv, ka = sc.get("Кl", 1e-3), sc.get("Kv"), sc.get("Ka")
    elsewhere = [ref.reading_mm(seg.name, k, kl, kv, ka) for k in range(len(ref.labels))]
    out = []
    for p in gen.positions:
        if p.label != label:
            continue
        for other in p.lines:
            if "reading" not in other.tags or other.operands[0].name == seg.name or \
                    other.operands[1].name != ln.operands[1].name:
                continue
            v = float(other.operands[0].text.replace(",", "."))
            if _far(v, mine) and all(x is None or _far(v, x) or abs(v - x) > 3
                                     for x in elsewhere):
                out.append(other.operands[0].text)
    return out


def _segment_of_force(ln: GenLine, label: str, gen: Generated) -> tuple[str, str] | None:
    """In ``Мур = R21∙h21∙Кl``: the reaction's name and its segment as written."""
    for op in ln.operands:
        if not re.fullmatch(r"R\d\d", op.name):
            continue
        for p in gen.positions:
            if p.label != label:
                continue
            for other in p.lines:
                if other.lhs in (op.name, _reversed(op.name)) and "reaction" in other.tags:
                    mm = other.operands[0].text
                    kp = float(other.operands[1].text.replace(",", "."))
                    if float(mm.replace(",", ".")) > 3 and abs(kp - 1) > 0.15:
                        return op.name, mm
    return None


def _other_arms(ln: GenLine, label: str, ref: Reference, gen: Generated):
    kl = _scales(gen).get("Кl", 1e-3)
    out = []
    names = {p_[0]: (p_[1], p_[2]) for p in gen.positions if p.label == label for p_ in p.arms}
    for op in ln.operands:
        if op.name not in names:
            continue
        force, about = names[op.name]
        mine = float(op.text.replace(",", "."))
        if mine < 3:
            continue
        for pt in ref.kin.pos.points:
            if pt == about:
                continue
            v = ref.value(("arm", force, pt), label)
            if v is None:
                continue
            v /= kl
            if v > 3 and abs(v / mine - 1) > 0.15:
                out.append((op.name, v))
    return out


def _apply(kind: str, ln: GenLine, label: str, ref: Reference, gen: Generated,
           rng: random.Random) -> tuple[GenLine, str]:
    if kind in ("arithmetic", "normal", "load"):
        factor = rng.choice((1.2, 1.3, 1.45, 1.6, 1.75, 1.9))
        return replace(ln, result_text=_fmt(ln.result * factor, ln.digits)), ln.lhs
    if kind == "scale":
        sc = _scales(gen)
        name = ln.operands[1].name
        other = "Ka" if name == "Kv" else "Kv"
        ops: tuple[Operand, ...] = (ln.operands[0],
                                    replace(ln.operands[1], text=_fmt(sc[other], 6)))
        return replace(ln, operands=ops), name
    if kind == "other":
        other, v = rng.choice(_segment_elsewhere(ln, label, ref, gen))
        ops = (replace(ln.operands[0], text=_fmt(v, decimals=2)), *ln.operands[1:])
        return replace(ln, operands=ops), ln.operands[0].name
    if kind == "sign":
        return replace(ln, result_text=_fmt(-ln.result, ln.digits)), ln.lhs
    if kind == "unit":
        return replace(ln, unit={"Н": "кН", "Нм": "кНм"}.get(ln.unit, "кН")), ln.lhs
    if kind == "unit-down":  # the number of kN (kN·m) with the unit N (N·m)
        return replace(ln, result_text=_fmt(ln.result / 1000, ln.digits)), ln.lhs
    if kind == "coriolis":  # aᵏ = ω·v_r: the factor 2 left out
        return replace(ln, formula=ln.formula.replace("2∙", "", 1)), ln.lhs
    if kind == "reuse":
        text = rng.choice(_own_elsewhere(ln, label, gen))
        return replace(ln, operands=(replace(ln.operands[0], text=text),
                                     *ln.operands[1:])), ln.operands[0].name
    if kind == "label":
        text = rng.choice(_other_name(ln, label, ref, gen))
        return replace(ln, operands=(replace(ln.operands[0], text=text),
                                     *ln.operands[1:])), ln.operands[0].name
    if kind == "segment-for-force":
        name, mm = _segment_of_force(ln, label, gen)  # type: ignore[misc]
        ops = tuple(replace(op, text=mm) if op.name == name else op for op in ln.operands)
        return replace(ln, operands=ops), name
    name, v = rng.choice(_other_arms(ln, label, ref, gen))
    ops = tuple(replace(op, text=_fmt(v, decimals=2)) if op.name == name else op
                for op in ln.operands)
    return replace(ln, operands=ops), name


# --- measuring the checker on a class of synthetic students ---------------------------------


@dataclass(frozen=True, slots=True)
class Scores:
    """How the checker does on a class of generated works (:func:`score`).

    ``recall`` — planted faults found as a fault of their own at their position and
    name; ``cause_accuracy`` — of those, the share with the planted kind; ``root_attribution``
    — of the faults the checker reports (primary wrong findings) in faulty works, the share
    that are planted faults (a consequence charged as a fault lowers it); ``false_alarms`` —
    wrong findings on lines nothing was planted in or carried to, and anything wrong in a
    correct work.
    """

    works: int
    variants: int
    clean_works: int
    planted: int
    found: int
    cause_right: int
    reported: int
    reported_roots: int
    false_alarms: int
    redrawn: int = 0  # planted faults the student drew a plan on from (a chain to follow)
    misses: tuple[str, ...] = ()
    alarms: tuple[str, ...] = ()
    miscaused: tuple[str, ...] = ()
    not_roots: tuple[str, ...] = ()  # faults reported that are no planted fault

    @property
    def recall(self) -> float:
        return self.found / self.planted if self.planted else 1.0

    @property
    def cause_accuracy(self) -> float:
        return self.cause_right / self.found if self.found else 1.0

    @property
    def root_attribution(self) -> float:
        return self.reported_roots / self.reported if self.reported else 1.0

    def summary(self) -> str:
        return (f"{self.works} works over {self.variants} variants ({self.clean_works} "
                f"correct, {self.planted} planted faults): recall {self.recall:.3f}, false "
                f"alarms {self.false_alarms}, root attribution {self.root_attribution:.3f}, "
                f"cause named right {self.cause_accuracy:.3f}; {self.redrawn} faults with "
                "plans drawn on from them")


def _plan_class(variants, works: int, rng: random.Random):
    """(variant, kinds) for each work: every fault kind alone in every variant where it
    fits, then combinations of 2–3 kinds, and one correct work in six."""
    plan: list[tuple[Any, tuple[str, ...]]] = []
    for v in variants:
        plan.append((v, ()))
        plan += [(v, (k,)) for k in FAULT_KINDS]
    i = 0
    while len(plan) < works:
        v = variants[i % len(variants)]
        i += 1
        plan.append((v, () if i % 6 == 0 else tuple(rng.sample(FAULT_KINDS,
                                                              rng.choice((2, 3))))))
    return plan


def score(variants, works: int = 200, *, seed: int = 0, noise_mm: float = 0.5,
          positions: int = 3, dump: Path | None = None) -> Scores:
    """Generate ``works`` students over ``variants`` (paths), read with drafting noise of
    ``noise_mm``, each at ``positions`` positions, faults planted alone and in
    combination (:func:`inject`), check them and score the checker (:class:`Scores`). A
    fault kind that does not fit a work (no suitable line) is left out of it."""
    from .checks import check_work, reference_for
    from .student import loads_student

    rng = random.Random(seed)
    variants = [Path(v) for v in variants]
    labels = {}
    for v in variants:
        ref = reference_for(v)
        labels[v] = [p.label for p in generate(v, ref=ref).positions]
    planted = found = cause = reported = roots = alarms_n = clean = redrawn = 0
    misses, alarms, miscaused, not_roots = [], [], [], []
    plan = _plan_class(variants, works, rng)
    for n, (v, kinds) in enumerate(plan):
        ref = reference_for(v)
        labs = labels[v]
        pos = tuple(sorted(rng.sample(labs, min(positions, len(labs))), key=labs.index))
        gen = generate(v, positions=pos, variant_ref=str(v.resolve()), ref=ref,
                       drafting=Drafting(noise_mm, random.Random(seed * 7919 + n)),
                       student=f"student {n}")
        faults: tuple[Fault, ...] = ()
        fits: list[str] = []
        for k in kinds:
            try:
                inject(gen, (*fits, k), random.Random(n), ref)
                fits.append(k)
            except ValueError:
                continue
        if fits:
            gen, faults = inject(gen, tuple(fits), random.Random(n), ref)
        else:
            clean += 1
        report = check_work(loads_student(gen.toml(), f"<student {n}>.toml"))
        if dump is not None:  # the works, to look at a miss or an alarm
            Path(dump).mkdir(parents=True, exist_ok=True)
            (Path(dump) / f"{n:03d}-{v.stem}.toml").write_text(gen.toml(), encoding="utf-8")
        touched = {f.line for f in faults} | {t for f in faults for t in f.carried}
        wrong = [f for f in report.findings if f.verdict == "wrong"]
        primary = [f for f in wrong if f.primary]
        tag = f"{v.stem} #{n}"
        for fault in faults:
            planted += 1
            redrawn += bool(fault.redrawn)
            hit = [f for f in primary if f.position == fault.position and
                   fault.quantity in f.quantity.split(" = ")]
            if not hit:
                misses.append(f"{tag} {fault.kind} {fault.position} {fault.quantity}: "
                              f"{fault.line}")
                continue
            found += 1
            if any(f.kind == fault.finding_kind for f in hit):
                cause += 1
            else:
                miscaused.append(f"{tag} {fault.kind}→{hit[0].kind} {fault.position} "
                                 f"{fault.quantity}: {hit[0].explanation_en}")
        if faults:
            reported += len(primary)
            for f in primary:
                if any(f.position == x.position and x.quantity in f.quantity.split(" = ")
                       for x in faults):
                    roots += 1
                else:
                    not_roots.append(f"{tag} {f.kind} {f.where} {f.quantity}: {f.line} — "
                                     f"{f.explanation_en}")
        for f in wrong:
            if f.line not in touched:
                alarms_n += 1
                alarms.append(f"{tag} {f.kind} {f.where} {f.quantity}: {f.line} — "
                              f"{f.explanation_en}")
    return Scores(len(plan), len(variants), clean, planted, found, cause, reported, roots,
                  alarms_n, redrawn, tuple(misses), tuple(alarms), tuple(miscaused),
                  tuple(not_roots))


__all__ = ["FAULT_KINDS", "KIND_OF_FAULT", "Drafting", "Fault", "GenLine", "Generated",
           "Scores", "generate", "inject", "score"]
