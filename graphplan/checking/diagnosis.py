"""Why a figure is wrong: the hypotheses tried, from the most specific to the least.

For a wrong figure (stated ``s``, graphplan's ``e``) :meth:`Diagnoser.diagnose` tries, in
order, and reports the first that explains ``s`` within the figure's tolerance:

1. **arithmetic** — its line's written numbers do not give its written result (×1000 or
   /1000 of them: a **unit** slip);
2. **follows** — the line's formula with graphplan's values of its names gives ``e``: the
   figure only *follows from* the names whose values are off (``propagated``);
3. **unit** — ``s/e`` is 1000, 10⁶ or g (or their inverses) with a unit written;
4. **sign** — ``s = −e`` for a signed figure (Mур);
5. **its formula** does not give ``e``: the Coriolis factor 2 left out (``coriolis``), a
   term of the wrong sign (``sign``), or the formula itself (``formula``);
6. **coriolis** — half the Coriolis acceleration; a segment of the acceleration plan drawn
   without the Coriolis term (the first of the position is the fault, the rest follow) or
   with the student's own wrong one (``propagated``);
7. **the student's own chain** — a segment from the student's force (``R43_mm =
   R43/Kp``), and, for a mechanism of one group, the crank's reaction closing the
   group's polygon with the student's loads and outer reaction, its arm h21 and Mур:
   right working from a wrong figure (``propagated``);
8. **lever arm** — the arm of the same force about another point, or another arm;
9. **geometry** — an arm longer than the distance from its centre to the force's point;
10. **scale** — a length measured at another scale the student used, or a value
    computed with another of the student's scales (Kv for Ka);
11. **other models** — the inertia forces reversed (``sign``), left out (``model``);
12. **the student's own value** of another position (``other-variant``) or of another
    figure of this position (``label``), to the written digit;
13. **another position** of the same mechanism, or a **neighbouring variant**
    (``other-variant``);
14. **label** — a given length or mass equal to another one (``lАВ = 0,08`` is l_OA);
15. a plain ratio of scales (×2, ×0.5, ×2.5 …) for a length on paper (``scale``);
16. otherwise ``model``: graphplan's exact value and the difference.

:meth:`Diagnoser.own_chain` runs before all of them: a figure computed by a right formula
and right arithmetic from the student's own figures, each within its tolerance, is at
worst inaccurate (the drafting error of the readings carried, not a fault).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .engine import LineWork, Occurrence, _close
from .errors import ExpressionError
from .expressions import decimals, show, value
from .matching import flip_term, sum_terms
from .quantities import SCALE_OF_DIMENSION, Quantity
from .units import fold
from .words import num, pct, qty, scale_text

UNIT_RATIOS = ((1e3, "1000 (N and kN, or mm and m)", "1000 (Н и кН, или мм и м)"),
               (1e6, "10⁶", "10⁶"), (9.81, "g (kg and N)", "g (кг и Н)"))
SERIES_RATIOS = (2.0, 0.5, 2.5, 0.4, 4.0, 0.25, 5.0, 0.2, 10.0, 0.1)
_LOAD_NAMES = {"inertia_force": "Pи", "inertia_moment": "Mи", "weight": "G"}


@dataclass(frozen=True, slots=True)
class Diag:
    """A diagnosis: the kind of finding, the explanation (en, ru), what it follows from."""

    kind: str
    en: str
    ru: str
    follows: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    rank: int = 99  # the hypothesis' place in the order of the module docstring


@dataclass(slots=True)
class Fig:
    """A figure beside graphplan (built by :meth:`Checker.evaluate`).

    ``s`` is the stated value (a magnitude unless the quantity is signed), ``e``
    graphplan's, ``scales`` the scales ``e`` was computed at, ``ok``/``tol`` the bands
    (absolute) and ``rel`` the relative tolerance.
    """

    scope: str
    key: tuple
    occs: list[Occurrence]
    q: Quantity
    s: float
    e: float | None
    model: str
    scales: dict[str, float]
    scale_note: str
    ok: float
    tol: float
    rel: float
    verdict: str
    diag: Diag | None = None
    extra_notes: list[str] = field(default_factory=list)
    own_chain: bool = False  # off only as far as the student's readings carry it
    extra: dict = field(default_factory=dict)  # what a special check found (δ)

    @property
    def name(self) -> str:
        o = self.occs[0]
        if o.position is None or "@" in o.name or self.q.scope == "global":
            return o.name
        return f"{o.name} ({o.position})"


class Diagnoser:
    """Runs the hypotheses of the module docstring for the figures of one check."""

    def __init__(self, checker, figs: dict[tuple, Fig]):
        self.c = checker
        self.w = checker.w
        self.ref = checker.ref
        self.figs = figs
        self._left_out: dict[str | None, str] = {}  # position → the first segment without aᵏ

    # --- helpers ----------------------------------------------------------------------

    def near(self, f: Fig, x: float | None, y: float | None = None) -> bool:
        """``x`` within the figure's tolerance of ``y`` (default: of its stated value)."""
        if x is None:
            return False
        y = f.s if y is None else y
        floor = max(f.tol - f.rel * abs(f.e or 0.0), 0.0)
        return abs(x - y) <= max(f.rel * max(abs(x), abs(y)), floor, 1e-12)

    def near_rel(self, f: Fig, x: float, y: float) -> bool:
        """``x`` within the figure's relative tolerance of ``y`` (no absolute floor: for
        ratios such as 1000 or 2, which a floor for values near zero would blur)."""
        return abs(x - y) <= max(f.rel * max(abs(x), abs(y)), 1e-12)

    def _u(self, f: Fig, x: float | None, lang: str = "en") -> str:
        return qty(x, f.q.unit, lang)

    def model_text(self, f: Fig) -> Diag:
        rel = (f.s - f.e) / abs(f.e) if f.e else None  # type: ignore[operator]
        en = f"graphplan's exact construction gives {self._u(f, f.e)} ({pct(rel)})."
        ru = f"точный расчёт даёт {self._u(f, f.e, 'ru')} ({pct(rel, 'ru')})."
        if f.scale_note:
            en = en[:-1] + f" at {f.scale_note}."
            ru = ru[:-1] + f" при {f.scale_note}."
        return Diag("model", en, ru)

    def inaccurate(self, f: Fig) -> Diag:
        rel = (f.s - f.e) / abs(f.e) if f.e else None  # type: ignore[operator]
        if f.own_chain:
            en = (f"off by {pct(rel)} of graphplan's {self._u(f, f.e)}, but it follows by a "
                  "right formula from the student's own readings, each within drafting "
                  "accuracy: their error carried, not a fault.")
            ru = (f"отличается на {pct(rel, 'ru')} от точного {self._u(f, f.e, 'ru')}, но "
                  "получено по верной формуле из собственных отсчётов, каждый в пределах "
                  "точности построения: это перенесённая погрешность, не ошибка.")
            return Diag("model", en, ru)
        tol = f"{f.rel * 100:g} %"
        en = (f"off by {pct(rel)} of graphplan's {self._u(f, f.e)}: beyond the drafting "
              f"reading accuracy, within the {tol} the method allows.")
        ru = (f"отличается на {pct(rel, 'ru')} от точного {self._u(f, f.e, 'ru')}: больше "
              f"точности отсчёта, но в пределах допуска {tol.replace('.', ',')}.")
        return Diag("model", en, ru)

    # --- the hypotheses ---------------------------------------------------------------

    def diagnose(self, f: Fig) -> Diag:
        """The first hypothesis of the module docstring that explains the figure."""
        from dataclasses import replace

        for rank, h in enumerate((self._arithmetic, self._delta, self._cycle, self._follows,
                                  self._unit,
                                  self._sign, self._lever,
                                  self._formula,
                                  self._coriolis, self._coriolis_plan, self._normal_plan,
                                  self._segment, self._own_forces, self._polygon,
                                  self._lever_arm, self._geometry, self._scale,
                                  self._models, self._own_reading, self._other_position,
                                  self._neighbours, self._label, self._series)):
            d = h(f)
            if d is not None:
                if d.kind == "arithmetic":
                    alt = self._models(f)
                    if alt is not None:
                        d = replace(d, notes=(*d.notes, alt.ru if self.c.lang == "ru"
                                              else alt.en))
                return replace(d, rank=rank)
        return self.model_text(f)

    def near_copy(self, f: Fig, x: float | None) -> bool:
        """``x`` within the figure's *ok* band of its stated value: a copied number."""
        if x is None:
            return False
        floor = max(f.ok - self.c.tol.segment_ok * abs(f.e or 0.0), 0.0) if \
            f.q.tolerance == "segment" else 0.0
        rel = self.c.tol.segment_ok if f.q.tolerance == "segment" else self.c.tol.derived_ok
        return abs(x - f.s) <= max(rel * max(abs(x), abs(f.s)), floor, 1e-12)

    def _arithmetic(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        lw = o.work
        if o.role != "result" or lw is None or lw.arithmetic not in ("wrong", "sign"):
            return None
        a, b = lw.bad  # type: ignore[misc]
        if lw.arithmetic == "sign":
            en = (f"the written numbers give {num(a.value)}; the result {b.text} has the "
                  f"opposite sign (graphplan: {self._u(f, f.e)}).")
            ru = (f"записанные числа дают {num(a.value, 'ru')}; у результата {b.text} "
                  f"обратный знак (по расчёту {self._u(f, f.e, 'ru')}).")
            return Diag("sign", en, ru)
        assert a.value is not None and b.value is not None  # the numbers the line wrote
        unit = self._unit_slip(f, float(a.value), float(b.value), b.text)
        if unit is not None:
            return unit
        en = f"the written numbers give {a.text} = {num(a.value)}, not {b.text}"
        ru = f"записанные числа дают {a.text} = {num(a.value, 'ru')}, а не {b.text}"
        re_c = self._canonical(lw, o, float(a.value))
        if re_c is not None and self.near(f, re_c, f.e):
            en += f"; {num(a.value)} is right (graphplan: {self._u(f, f.e)})."
            ru += f"; {num(a.value, 'ru')} — верно (по расчёту {self._u(f, f.e, 'ru')})."
        else:
            en += f" (graphplan: {self._u(f, f.e)})."
            ru += f" (по расчёту {self._u(f, f.e, 'ru')})."
        return Diag("arithmetic", en, ru)

    def _delta(self, f: Fig) -> Diag | None:
        """δ, the discrepancy of Мур and Мур.ж, that the student's own two moments do not
        give: written as a fraction (``unit``), by a formula of its own (``formula``), or
        not from the moments they wrote (``consistency``)."""
        if "fluctuation" in f.extra and f.e is not None:
            d = f.extra["fluctuation"]
            en = (f"the variant's coefficient of speed fluctuation is δ = {num(d)} "
                  f"(1/{num(1 / d, digits=4)}); {num(f.s)} is not it.")
            ru = (f"коэффициент неравномерности хода варианта δ = {num(d, 'ru')} "
                  f"(1/{num(1 / d, 'ru', 4)}); {num(f.s, 'ru')} — не он.")
            return Diag("model", en, ru)
        got = f.extra.get("delta")
        if got is None or f.e is None:
            return None
        m, mz, cands, own = got
        o = f.occs[0]
        mine = (f"Мур = {self._u(m, m.s)} ({m.occs[0].where_in('en')}) and Мур.ж = "
                f"{self._u(mz, mz.s)} ({mz.occs[0].where_in('en')})")
        mine_ru = (f"Мур = {self._u(m, m.s, 'ru')} ({m.occs[0].where_in('ru')}) и Мур.ж = "
                   f"{self._u(mz, mz.s, 'ru')} ({mz.occs[0].where_in('ru')})")
        std = cands[0]
        if any(abs(f.s * 100 - c) <= max(0.05 * c, 0.1) for c in cands):
            en = (f"δ = {num(f.s)} is a fraction: in per cent the student's own {mine} give "
                  f"{num(std)} %.")
            ru = (f"δ = {num(f.s, 'ru')} — доля, а не проценты: собственные {mine_ru} дают "
                  f"{num(std, 'ru')} %.")
            return Diag("unit", en, ru)
        if own is not None and all(abs(own - c) > max(0.05 * c, 0.1) for c in cands) and \
                abs(f.s - own) <= f.tol:
            en = (f"the formula of δ does not give the discrepancy: with the student's own "
                  f"{mine}, |Мур.ж − Мур|/|Мур.ж|·100 = {num(std)} %.")
            ru = (f"формула δ неверна: для собственных {mine_ru} расхождение "
                  f"|Мур.ж − Мур|/|Мур.ж|·100 = {num(std, 'ru')} %.")
            return Diag("formula", en, ru)
        en = (f"δ = {num(f.s)} % does not follow from the student's own {mine}: "
              f"|Мур.ж − Мур|/|Мур.ж|·100 = {num(f.e)} %.")
        ru = (f"δ = {num(f.s, 'ru')} % не следует из собственных {mine_ru}: "
              f"|Мур.ж − Мур|/|Мур.ж|·100 = {num(f.e, 'ru')} %.")
        _ = o
        return Diag("consistency", en, ru)

    def _lever(self, f: Fig) -> Diag | None:
        """Мур.ж of Zhukovsky's lever that disagrees with the student's own Мур of the force
        plans, which is right: the lever is off (``consistency``, δ said)."""
        if f.key != ("M_bal", "lever") or f.e is None:
            return None
        m = self.figs.get((f.scope, ("M_bal",)))
        if m is None or m.verdict == "wrong" or not m.s:
            return None
        delta = abs(f.s - m.s) / max(abs(f.s), 1e-12) * 100
        en = (f"Мур.ж = {self._u(f, f.s)} of Zhukovsky's lever differs from the student's own "
              f"Мур = {self._u(m, m.s)} of the force plans ({m.occs[0].where_in('en')}) by "
              f"δ = {num(delta, digits=3)} %; Мур is right (graphplan: {self._u(f, f.e)}): the "
              "lever is off.")
        ru = (f"Мур.ж = {self._u(f, f.s, 'ru')} по рычагу Жуковского расходится с собственным "
              f"Мур = {self._u(m, m.s, 'ru')} по планам сил ({m.occs[0].where_in('ru')}) на "
              f"δ = {num(delta, 'ru', 3)} %; Мур верен (по расчёту {self._u(f, f.e, 'ru')}): "
              "ошибка в рычаге.")
        return Diag("consistency", en, ru)

    def _cycle(self, f: Fig) -> Diag | None:
        """K written the other way up (φ_idle/φ_working, ``(180° − θ)/(180° + θ)``)."""
        if f.key != ("time_ratio",) or not f.e or not f.s or abs(f.e - 1) < 1e-6 or \
                not self.near(f, 1.0 / f.s, f.e):
            return None
        en = (f"K = {num(f.s)} is the inverse ratio: K = φ_working/φ_idle = (180° + θ)/"
              f"(180° − θ) = {num(f.e)}, the slower (working) stroke's crank angle over the "
              "faster one's.")
        ru = (f"K = {num(f.s, 'ru')} — обратное отношение: K = φр.х/φх.х = (180° + θ)/"
              f"(180° − θ) = {num(f.e, 'ru')} (угол поворота кривошипа за рабочий ход к углу "
              "за холостой).")
        return Diag("formula", en, ru)

    def _unit_slip(self, f: Fig, computed: float, written: float, text: str) -> Diag | None:
        """The numbers give ``computed``, the result says ``written`` = computed/1000 (the
        kN written with the unit N) or ×1000: a unit slip, not arithmetic."""
        if not computed or not written:
            return None
        for r in (1e3, 1e-3, 1e6, 1e-6):
            if abs(computed / written / r - 1) <= 0.01:
                big = r > 1
                slip = ("kilo-units written with the base unit" if big
                        else "base units written with the kilo-unit")
                en = (f"the numbers give {num(computed)}, the result {text} is "
                      f"{'1/' if big else ''}{num(r if big else 1 / r)} of it"
                      f"{'' if big else ' times more'}: a unit slip (the number of "
                      f"{slip}"
                      f"; graphplan: {self._u(f, f.e)}).")
                slip_ru = ("число в кН записано с единицей Н" if big
                           else "число в Н записано с единицей кН")
                ru = (f"числа дают {num(computed, 'ru')}, а результат {text} — в "
                      f"{num(r if r > 1 else 1 / r, 'ru')} раз {'меньше' if big else 'больше'}: "
                      f"перепутаны единицы ({slip_ru}"
                      f"; по расчёту {self._u(f, f.e, 'ru')}).")
                return Diag("unit", en, ru)
        return None

    def _canonical(self, lw: LineWork, o: Occurrence, raw: float) -> float | None:
        """A raw number of the line in the unit of its result's quantity."""
        q = o.q
        if o.explicit is not None and lw.result is not None and lw.result.unit is not None:
            v = raw * lw.result.unit.factor / q.factor
        else:
            v = raw * 1000.0 ** o.prefix
        return v if q.signed else abs(v)

    def _unit(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        if o.explicit is None or not f.e or not f.s:
            return None
        for r, en_r, ru_r in UNIT_RATIOS:
            if r == 9.81 and f.q.dimension not in ("N", "kg", "N·m"):
                continue
            for ratio in (r, 1.0 / r):
                # a small force read at ±0,5 mm of its plan keeps its reading allowance
                if self.near_rel(f, f.s, f.e * ratio) or (
                        r != 9.81 and not f.q.on_paper and abs(f.s / ratio - f.e) <= f.tol):
                    times = f"{num(ratio)} times" if ratio > 1 else f"1/{num(1 / ratio)} of"
                    en = (f"{o.name} = {o.text} is {times} graphplan's "
                          f"{self._u(f, f.e)}: a unit mix-up (a factor of {en_r}).")
                    times = (f"в {num(ratio, 'ru')} раз больше" if ratio > 1 else
                             f"в {num(1 / ratio, 'ru')} раз меньше")
                    ru = (f"{o.name} = {o.text} — {times} точного "
                          f"{self._u(f, f.e, 'ru')}: перепутаны единицы (множитель {ru_r}).")
                    return Diag("unit", en, ru)
        return None

    def _sign(self, f: Fig) -> Diag | None:
        if not f.q.signed or not f.e or not self.near(f, f.s, -f.e):
            return None
        en = (f"the size is right but the sign is not: graphplan gives {self._u(f, f.e)} "
              "(counter-clockwise positive).")
        ru = (f"величина верна, знак — нет: по расчёту {self._u(f, f.e, 'ru')} (против "
              "часовой стрелки — плюс).")
        return Diag("sign", en, ru)

    # the line's formula with graphplan's values

    def line_scales(self, lw: LineWork) -> dict[str, float]:
        """For each scale named in a line: the value graphplan's figures are read at —
        the stated one, or the one used in the line when the line's lengths on paper fit
        it better (the drawing was made at it)."""
        out: dict[str, float] = {}
        stated = self.w.stated_scales(lw.position, lw.line)
        for o in lw.occs:
            if o.role != "operand" or o.q.kind != "scale":
                continue
            sym = o.q.name
            k0 = stated.get(sym)
            if k0 is None or _close(o.value, k0, 1e-6):
                out[sym] = o.value if k0 is None else k0
                continue
            papers = [p for p in lw.occs if p.role == "operand" and p.q.on_paper and
                      p.q.scale == sym]
            votes = 0
            for p in papers:
                e_used = self.w.expected(p.q, p.scope, p, "rule", {**stated, sym: o.value})
                e_st = self.w.expected(p.q, p.scope, p, "rule", stated)
                if e_used is None or e_st is None:
                    continue
                votes += 1 if abs(p.value - e_used) < abs(p.value - e_st) else -1
            out[sym] = o.value if votes > 0 else k0
        return out

    def model_env(self, lw: LineWork, model: str = "rule", band: int = 0,
                  plain: bool = False) -> tuple[dict[str, float] | None, list[str]]:
        """graphplan's values of the names of a line (in the student's units) and the
        names whose written values are off (beyond their *ok* band, or with ``band=1``
        beyond their tolerance: wrong)."""
        if lw.matched is None:
            return None, []
        scales = self.line_scales(lw)
        stated = self.w.stated_scales(lw.position, lw.line)
        env: dict[str, float] = {}
        offs: list[str] = []
        for name, node in lw.matched.bindings:
            o = next((x for x in lw.occs if x.name == name and x.role == "operand"), None)
            if o is None:
                # a name the variant does not know (lO3A, a length measured on the
                # drawing): the student's own number, taken as written
                if lw.vocab.lookup(name) is not None:
                    return None, []
                try:
                    env[name] = value(node)
                except ExpressionError:
                    return None, []
                continue
            q = o.q
            if q.kind == "scale":
                right = scales.get(q.name, o.value)
            else:
                sc = {**stated, **scales}
                right = self.w.expected(q, o.scope, o, model, sc)
                if right is None:
                    return None, []
            prefix = 0 if plain else o.prefix
            env[name] = right / 1000.0 ** prefix * (math.copysign(1.0, o.raw) if
                                                    not q.signed else 1.0)
            val = o.raw * 1000.0 ** prefix if plain else o.value
            val = val if q.signed else abs(val)
            right_c = right if q.signed else abs(right)
            allowed = self.c.band(q, right_c, {**stated, **scales}, o.text)[band]
            if abs(val - right_c) > allowed:
                label = o.name if o.position is None or q.scope == "global" or \
                    "@" in o.name else f"{o.name} ({o.position})"
                if label not in offs:
                    offs.append(label)
        return env, offs

    def own_chain(self, f: Fig) -> bool:
        """The figure follows, by its own right arithmetic and a right formula, from the
        student's figures that are all within their tolerances: its error is the drafting
        error of those readings carried through the formula, not a fault (it is at worst
        inaccurate)."""
        o = f.occs[0]
        lw = o.work
        if o.role != "result" or lw is None or lw.arithmetic != "ok" or \
                lw.template is None or lw.matched is None or f.e is None:
            return False
        if lw.matched.signs and not lw.line.symbols:  # the numbers are not its formula's
            return False
        env, offs = self.model_env(lw, band=1)
        if env is None:
            return False
        scales = {x.name for x in lw.occs if x.role == "operand" and x.q.kind == "scale"}
        if scales & set(offs):  # computed with another scale (Kv for Ka): not drafting
            return False
        if offs:  # off beyond their band, but each may be right by its own chain
            for name, _node in lw.matched.bindings:
                x = next((y for y in lw.occs if y.name == name and y.role == "operand"), None)
                if x is None or x.q.kind == "scale":
                    continue
                g = self.figs.get((x.scope, x.q.key))
                # right by its own chain only as the figure it is (the same value)
                bad = g is None or g.e is None or g.verdict == "wrong" or g is f or \
                    not _close(abs(x.value), abs(g.s), 0.005,
                               0.5 * 10.0 ** -decimals(x.text))
                label = x.name if x.position is None or x.q.scope == "global" or \
                    "@" in x.name else f"{x.name} ({x.position})"
                if bad and label in offs:
                    return False
        try:
            F = self._canonical(lw, o, value(lw.template, env))
        except ExpressionError:
            return False
        return F is not None and self.near(f, F, f.e)

    def _follows(self, f: Fig) -> Diag | None:
        """Only the consequence of the student's own wrong figures before it (checked
        before the other hypotheses: a ratio of 9,81 or 1000 met by chance in a carried
        value is no slip of its own)."""
        d = self._formula(f)
        return d if d is not None and d.kind == "propagated" else None

    def _formula(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        lw = o.work
        if o.role != "result" or lw is None or lw.template is None or f.e is None:
            return None
        env, offs = self.model_env(lw)
        if env is None:
            return None
        try:
            F = self._canonical(lw, o, value(lw.template, env))
        except ExpressionError:
            return None
        if F is not None and not self.near(f, F, f.e):
            # the numbers may all be in the result's unit: an operand read as kN because
            # its number looked like kN (a segment written for a force) is not
            alt = self.model_env(lw, plain=True)
            try:
                F2 = self._canonical(lw, o, value(lw.template, alt[0])) if alt[0] else None
            except ExpressionError:
                F2 = None
            if F2 is not None and self.near(f, F2, f.e) and alt[1]:
                F, offs = F2, alt[1]
        if F is not None and self.near(f, F, f.e):
            if not offs:
                return None
            en = (f"follows from {', '.join(offs)}: with graphplan's values this formula gives "
                  f"{self._u(f, f.e)}.")
            ru = (f"следует из {', '.join(offs)}: с точными значениями эта формула даёт "
                  f"{self._u(f, f.e, 'ru')}.")
            return Diag("propagated", en, ru, tuple(offs))
        cor = self._coriolis_factor(f, F)
        if cor is not None:
            return cor
        for i, (_sg, term) in enumerate(sum_terms(lw.template)):
            t2 = flip_term(lw.template, i)
            if t2 is None:
                continue
            try:
                F2 = self._canonical(lw, o, value(t2, env))
            except ExpressionError:
                continue
            if F2 is not None and self.near(f, F2, f.e):
                why = self._sign_reason(f, term)
                en = (f"a term of the formula has the wrong sign: with {show(term)} taken with "
                      f"the opposite sign it gives graphplan's {self._u(f, f.e)}{why[0]}.")
                ru = (f"слагаемое формулы взято с неверным знаком: если {show(term)} взять с "
                      f"обратным знаком, получится точное {self._u(f, f.e, 'ru')}{why[1]}.")
                return Diag("sign", en, ru)
        swapped = self._swapped_scale(f, lw, o, env)
        if swapped is not None:
            return swapped
        if F is None:
            return None
        en = (f"the formula does not hold: with graphplan's values it gives {self._u(f, F)}, "
              f"but the exact value is {self._u(f, f.e)}.")
        ru = (f"формула неверна: с точными значениями она даёт {self._u(f, F, 'ru')}, а точное "
              f"значение {self._u(f, f.e, 'ru')}.")
        return Diag("formula", en, ru)

    def _swapped_scale(self, f: Fig, lw: LineWork, o: Occurrence, env: dict[str, float]
                       ) -> Diag | None:
        """The formula names one plan's scale where another's belongs (``VS2 = ps2∙μa``):
        with the right scale's value in its place it gives graphplan's value."""
        if lw.template is None or lw.matched is None:
            return None
        stated = self.w.stated_scales(o.position, o.line)
        for name, _node in lw.matched.bindings:
            x = next((y for y in lw.occs if y.name == name and y.role == "operand"), None)
            if x is None or x.q.kind != "scale":
                continue
            for other, k2 in stated.items():
                if other == x.q.name or not k2 or other == "Kp":
                    continue
                try:
                    F2 = self._canonical(lw, o, value(lw.template, {**env, name: k2}))
                except ExpressionError:
                    continue
                if F2 is not None and self.near(f, F2, f.e):
                    en = (f"{x.name} = {num(x.value)} is the scale {x.q.name}, but this value "
                          f"is read at {other} = {num(k2)}: with it the line gives "
                          f"graphplan's {self._u(f, f.e)} — a scale used in place of another.")
                    ru = (f"{x.name} = {num(x.value, 'ru')} — масштаб {x.q.name}, а эту величину "
                          f"читают в масштабе {other} = {num(k2, 'ru')}: с ним получается "
                          f"точное {self._u(f, f.e, 'ru')} — перепутан масштаб.")
                    return Diag("scale", en, ru)
        return None

    @staticmethod
    def is_coriolis(f: Fig) -> bool:
        return f.key[0] in ("reading", "segment") and any(
            isinstance(x, str) and x.startswith("aᵏ") for x in f.key)

    def _coriolis_factor(self, f: Fig, formula_value: float | None = None) -> Diag | None:
        """The Coriolis acceleration without its factor 2 (aᵏ = ω·v_r): half the value."""
        if not self.is_coriolis(f) or not f.e:
            return None
        half = f.e / 2
        if not (self.near_rel(f, f.s, half) or (formula_value is not None and
                                                 self.near_rel(f, formula_value, half))):
            return None
        en = (f"the Coriolis acceleration is aᵏ = 2·ω·v_r: {self._u(f, f.s)} is half of "
              f"graphplan's {self._u(f, f.e)} — the factor 2 is left out.")
        ru = (f"кориолисово ускорение aᵏ = 2·ω·v_r: {self._u(f, f.s, 'ru')} — половина "
              f"точного {self._u(f, f.e, 'ru')}, пропущен множитель 2.")
        return Diag("coriolis", en, ru)

    def _coriolis(self, f: Fig) -> Diag | None:
        return self._coriolis_factor(f)

    def _coriolis_plan(self, f: Fig) -> Diag | None:
        """A segment of the acceleration plan drawn with the student's own Coriolis
        acceleration (a wrong one: it follows from it), or with none where there is one
        (left out of the vector equation: the first such segment of the position is the
        fault, the others follow from it)."""
        q, o = f.q, f.occs[0]
        if q.kind != "segment" or q.scale != "Ka" or o.position not in self.ref.labels or \
                f.e is None or self.is_coriolis(f):
            return None
        k = self.ref.index(o.position)
        names = self.ref.coriolis_names(k)
        if not names:
            return None
        sc = f.scales
        if not (sc.get("Kv") and sc.get("Ka")):
            return None
        mine = [g for g in self.figs.values() if self.is_coriolis(g) and
                g.occs[0].position == o.position and g.e]
        if len(names) > 1:  # each component with the student's own factor
            pairs = self.ref.coriolis_pairs(k)
            each: dict[str, tuple[float, Fig]] = {}
            for g in sorted(mine, key=lambda x: x.q.kind == "segment"):
                cname = next((n for n in names if n in g.key), None)
                if cname is not None and cname in pairs and g.verdict == "wrong" and g.e:
                    each[cname] = (g.s / g.e, g)  # (g.e is set: mine holds no other)
            if not each:
                return None
            spec = tuple(sorted((n, round(x, 6)) for n, (x, _g) in each.items()))
            v = self.ref.reading_mm_coriolis(q.name, k, sc.get("Kl", 1e-3), sc["Kv"],
                                             sc["Ka"], 1.0, (), spec)
            if not self.explains(f, v):
                return None
            g = next(iter(each.values()))[1]
        else:
            if mine:
                g = min(mine, key=lambda x: x.q.kind != "segment")
                if g.verdict != "wrong":
                    return None
                assert g.e  # mine holds only figures with an expected value
                factor = g.s / g.e
            else:
                g, factor = None, 0.0
            v = self.ref.reading_mm_coriolis(q.name, k, sc.get("Kl", 1e-3), sc["Kv"],
                                             sc["Ka"], round(factor, 6))
            if not (self.explains(f, v) if g is not None else (
                    v is not None and self.near(f, v) and not self.near(f, v, f.e))):
                return None
        if g is not None:
            en = (f"follows from {g.name}: the plan drawn with that Coriolis acceleration "
                  f"gives {num(v)} mm (graphplan: {num(f.e)} mm).")
            ru = (f"следует из {g.name}: план, построенный с этим кориолисовым ускорением, "
                  f"даёт {num(v, 'ru')} мм (по расчёту {num(f.e, 'ru')} мм).")
            return Diag("propagated", en, ru, (g.name,))
        first = self._left_out.setdefault(o.position, f.name)
        if first != f.name:
            en = (f"follows from the Coriolis acceleration left out (see {first}): "
                  f"{num(v)} mm without it (graphplan: {num(f.e)} mm).")
            ru = (f"следует из пропущенного кориолисова ускорения (см. {first}): "
                  f"{num(v, 'ru')} мм без него (по расчёту {num(f.e, 'ru')} мм).")
            return Diag("propagated", en, ru, (first,))
        en = (f"the plan is drawn without the Coriolis acceleration aᵏ = 2·ω·v_r: without it "
              f"{q.name} is {num(v)} mm, as stated; with it {num(f.e)} mm.")
        ru = (f"план построен без кориолисова ускорения aᵏ = 2·ω·v_r: без него {q.name} = "
              f"{num(v, 'ru')} мм, как записано; с ним {num(f.e, 'ru')} мм.")
        return Diag("coriolis", en, ru)

    def explains(self, f: Fig, v: float | None) -> bool:
        """The student's own chain's value ``v`` explains the stated figure: within its
        tolerance, nearer to it than graphplan's value, and moved from graphplan's by
        more than half the *ok* band (a small effect that drafting error carries over
        the band is still the effect)."""
        if v is None or f.e is None:
            return False
        if not self.near(f, v):
            # the band around the chain's own value (a small segment keeps its reading
            # allowance), widened by half: the chain carries the drafting of its inputs
            tol = max(self.c.band(f.q, abs(v), f.scales, f.occs[0].text)[1], f.tol)
            if abs(f.s - v) > 1.5 * tol:
                return False
        if not self.near(f, v, f.e):
            return True
        return abs(v - f.e) >= 0.5 * f.ok and abs(f.s - v) < abs(f.s - f.e)

    def normal_plan_value(self, f: Fig) -> tuple[float, tuple[str, ...]] | None:
        """A segment of the acceleration plan rebuilt with the student's own wrong normal
        components (and Coriolis ones, if wrong too): (its length, the wrong names)."""
        q, o = f.q, f.occs[0]
        if q.kind != "segment" or q.scale != "Ka" or o.position not in self.ref.labels or \
                f.e is None or q.key[1] == "a_n" or self.is_coriolis(f):
            return None
        k = self.ref.index(o.position)
        normals: dict[str, tuple[float, Fig]] = {}
        slipped: set[str] = set()
        for g in self.figs.values():
            key = g.key[1:] if g.key[0] == "segment" else g.key
            if key[0] != "a_n" or g.occs[0].position != o.position or not g.e or \
                    g.verdict in ("ok", "not compared"):
                continue
            link = self.ref.normal_link(key[1], key[2])
            if link is None:
                continue
            # a normal component off its value: wrong, or inaccurate with a slip in it
            w = g.occs[0].work
            if g.verdict == "wrong" or (w is not None and w.arithmetic in ("wrong", "sign")):
                slipped.add(link)
            # the segment is what is drawn: it wins over the value it was laid off from
            if link not in normals or g.q.kind == "segment":
                normals[link] = (g.s / g.e, g)
        normals = {ln: x for ln, x in normals.items() if ln in slipped}
        if not normals:
            return None
        each: dict[str, float] = {}
        names = self.ref.coriolis_names(k)
        for g in sorted(self.figs.values(), key=lambda x: x.q.kind == "segment"):
            cname = next((n for n in names if n in g.key), None)
            if cname and self.is_coriolis(g) and g.occs[0].position == o.position and \
                    g.e and g.verdict == "wrong":
                each[cname] = round(g.s / g.e, 6)
        sc = f.scales
        if not (sc.get("Kv") and sc.get("Ka")):
            return None
        spec = tuple(sorted((ln, round(x, 6)) for ln, (x, _g) in normals.items()))
        v = self.ref.reading_mm_coriolis(q.name, k, sc.get("Kl", 1e-3), sc["Kv"], sc["Ka"],
                                         1.0, spec, tuple(sorted(each.items())))
        if v is None:
            return None
        return v, tuple(dict.fromkeys(g.name for _x, g in normals.values()))

    def within_chain(self, f: Fig, v: float | None) -> bool:
        """The stated figure is within its reading band of its own chain's value ``v``
        and nearer to it than to graphplan's: a reading off the student's own plan."""
        if v is None or f.e is None or abs(f.s - v) >= abs(f.s - f.e):
            return False
        return abs(f.s - v) <= self.c.band(f.q, abs(v), f.scales, f.occs[0].text)[1]

    def own_plan_chain(self, f: Fig) -> bool:
        """A segment of the student's own acceleration plan (drawn from a wrong normal
        component) that the chain moves too little to call it a consequence: at worst
        inaccurate."""
        got = self.normal_plan_value(f)
        return got is not None and not self.explains(f, got[0]) and \
            self.within_chain(f, got[0])

    def _normal_plan(self, f: Fig) -> Diag | None:
        """A segment of the acceleration plan drawn from the student's own wrong normal
        component (``n_BA = anBA/Ka`` from a wrong ``anBA``): the plan rebuilt with it
        (and with the student's Coriolis acceleration, if that is wrong too) gives the
        segment — it follows from the normal component (``propagated``)."""
        got = self.normal_plan_value(f)
        if got is None or not self.explains(f, got[0]):
            return None
        v, names = got
        en = (f"follows from {', '.join(names)}: the plan drawn with that normal component "
              f"gives {num(v)} mm (graphplan: {num(f.e)} mm).")
        ru = (f"следует из {', '.join(names)}: план, построенный с этой нормальной "
              f"составляющей, даёт {num(v, 'ru')} мм (по расчёту {num(f.e, 'ru')} мм).")
        return Diag("propagated", en, ru, names)

    # the student's own force analysis

    def _outer_pair(self, i: str, j: str) -> tuple[str, str] | None:
        """(by, on) of a reaction between two groups: by the group solved first (the
        later one in the structure) on the group it passes to; ``None`` otherwise."""
        mech = self.ref.mech
        where = {ln: n for n, d in enumerate(mech.dyads) for ln in d.links}
        if i not in where or j not in where or where[i] == where[j]:
            return None
        return (i, j) if where[i] > where[j] else (j, i)

    def own_force_inputs(self, position: str, skip: tuple = ()):
        """The student's own figures a force plan of ``position`` is drawn from: loads
        (name → size), tangential reactions, reactions passed from one group to the
        next, and which of them are wrong (name → the input's place)."""
        sizes: dict[str, float] = {}
        tang: dict[str, float] = {}
        outer: dict[tuple[str, str], float] = {}
        wrong: dict[str, tuple[str, object]] = {}
        for g in self.figs.values():
            if g.e is None or g.key == skip or g.scope not in (position, "global"):
                continue
            key = g.key
            if g.q.kind == "load":
                name = _LOAD_NAMES.get(key[0])
                name = f"{name}{key[1]}" if name else (key[1] if key[0] == "resistance"
                                                       else None)
                if name is None:
                    continue
                slot: tuple[str, object] = ("size", fold(name))
                sizes[fold(name)] = g.s
            elif key[0] == "reaction_t" and g.scope == position:
                slot = ("tang", f"Rτ{key[1]}{key[2]}")
                tang[f"Rτ{key[1]}{key[2]}"] = g.s
            elif key[0] == "reaction" and g.scope == position:
                pair = self._outer_pair(key[1], key[2])
                if pair is None:
                    continue
                slot = ("outer", pair)
                outer[pair] = g.s
            else:
                continue
            if g.verdict == "wrong":
                wrong[g.name] = slot
        return sizes, tang, outer, wrong

    def own_force_value(self, f: Fig, k: int, own) -> float | None:
        """The figure's value (in its unit, at its scales) in an own force analysis."""
        key = f.key[1:] if f.key[0] == "segment" else f.key
        v = self.ref.own_value(key, k, own)
        if v is None:
            return None
        if f.q.on_paper:
            s = f.scales.get(f.q.scale or "")
            return abs(v) / s if s else None
        return v if f.q.signed else abs(v)

    def own_forces_chain(self, f: Fig) -> bool:
        """A figure of the force plans (a reaction, its segment, an arm of a reaction,
        h21, Mур) that the student's own force analysis gives, from their own loads and
        reactions each within its tolerance: their drafting error carried (at worst
        inaccurate), as :meth:`own_chain` for a line's formula."""
        o = f.occs[0]
        key = f.key[1:] if f.key[0] == "segment" else f.key
        if o.position is None or o.position not in self.ref.labels or f.e is None:
            return False
        if not (key[0] in ("reaction", "reaction_n", "crank_arm", "M_bal") or (
                key[0] == "arm" and fold(str(key[1]))[:1] == "R")):
            return False
        if o.work is not None and o.work.arithmetic in ("wrong", "sign", "unread"):
            return False
        k = self.ref.index(o.position)
        sizes, tang, outer, wrong = self.own_force_inputs(
            o.position, skip=("reaction", *key[1:]) if key[0] == "reaction" else ())
        model = f.model if f.model in ("rule", "full") else "rule"
        own = self.ref.own_forces(k, sizes, tang, model, outer)
        v = None if own is None else self.own_force_value(f, k, own)
        if wrong and self.explains(f, v):
            return False  # a consequence of a wrong figure: "follows from" it
        return self.within_chain(f, v)

    def _own_forces(self, f: Fig) -> Diag | None:
        """A reaction, its segment, an arm of a reaction, h21 or Mур of the force plans
        drawn from the student's own loads, tangential reactions and the reactions one
        group passes to the next (:meth:`Reference.own_forces`): right working from a
        wrong figure (``propagated``), in a mechanism of any number of groups."""
        o = f.occs[0]
        key = f.key[1:] if f.key[0] == "segment" else f.key
        if o.position is None or o.position not in self.ref.labels or f.e is None:
            return None
        if not (key[0] in ("reaction", "reaction_n", "crank_arm", "M_bal") or (
                key[0] == "arm" and fold(str(key[1]))[:1] == "R")):
            return None
        k = self.ref.index(o.position)
        sizes, tang, outer, wrong = self.own_force_inputs(
            o.position, skip=("reaction", *key[1:]) if key[0] == "reaction" else ())
        if not wrong:
            return None
        model = f.model if f.model in ("rule", "full") else "rule"
        own = self.ref.own_forces(k, sizes, tang, model, outer)
        v = None if own is None else self.own_force_value(f, k, own)
        if v is None or not self.explains(f, v):
            return None
        causes = []
        for name, (what, slot) in wrong.items():  # the wrong inputs that move this figure
            s2, t2, o2 = dict(sizes), dict(tang), dict(outer)
            {"size": s2, "tang": t2, "outer": o2}[what].pop(slot, None)  # type: ignore
            alt = self.ref.own_forces(k, s2, t2, model, o2)
            w = None if alt is None else self.own_force_value(f, k, alt)
            if w is None or abs(w - v) > 0.25 * max(f.tol, 1e-12):
                causes.append(name)
        causes = causes or list(wrong)
        en = (f"follows from {', '.join(causes)}: the force plans drawn with these values "
              f"give {self._u(f, v)} (graphplan: {self._u(f, f.e)}).")
        ru = (f"следует из {', '.join(causes)}: планы сил, построенные с этими значениями, "
              f"дают {self._u(f, v, 'ru')} (по расчёту {self._u(f, f.e, 'ru')}).")
        return Diag("propagated", en, ru, tuple(causes))

    def _own_reading(self, f: Fig) -> Diag | None:
        """The student's own value of the same figure at another position, or of another
        figure at this position, written again here (a reading reused)."""
        o = f.occs[0]
        if o.position is None or f.q.scope == "global":
            return None
        half = 0.5 * 10.0 ** (-decimals(o.text)) * 1.01 if o.text else 0.0
        for g in self.figs.values():
            if g is f or g.e is None or g.verdict == "not compared":
                continue
            go = g.occs[0]
            if go.position is None or go.work is o.work:
                continue
            same_q = g.key == f.key and go.position != o.position
            other_q = (go.position == o.position and g.key != f.key and
                       g.q.unit == f.q.unit and g.q.scale == f.q.scale)
            if not (same_q or other_q) or abs(g.s - f.s) > max(half, 1e-12):
                continue
            if self.near(f, g.s, f.e) or (other_q and g.verdict == "wrong"):
                continue
            if same_q:
                en = (f"{self._u(f, f.s)} is the student's own {go.name} of position "
                      f"{go.position} ({go.where_in('en')}), not of {o.position} "
                      f"(graphplan: {self._u(f, f.e)}).")
                ru = (f"{self._u(f, f.s, 'ru')} — собственное значение {go.name} для "
                      f"положения {go.position} ({go.where_in('ru')}), а не для "
                      f"{o.position} (по расчёту {self._u(f, f.e, 'ru')}).")
                return Diag("other-variant", en, ru)
            en = (f"{self._u(f, f.s)} is the student's own {go.name} ({go.where_in('en')}), "
                  f"not {o.name} ({self._u(f, f.e)}): a right number under a wrong name.")
            ru = (f"{self._u(f, f.s, 'ru')} — это {go.name} ({go.where_in('ru')}), а не "
                  f"{o.name} ({self._u(f, f.e, 'ru')}): верное число под чужим "
                  "обозначением.")
            return Diag("label", en, ru)
        return None

    def _sign_reason(self, f: Fig, term) -> tuple[str, str]:
        names = {n for n in _names(term)}
        if any(n.startswith(("Pи", "Ри", "Фи", "Ф", "Mи", "Ми")) for n in names):
            return ((" — the inertia force points against the acceleration (Pи = −m·a); "
                     "at this position it opposes the weight"),
                    (" — сила инерции направлена против ускорения (Pи = −m·a); в этом "
                     "положении она противоположна силе тяжести"))
        return "", ""

    # the student's own chain

    def _segment(self, f: Fig) -> Diag | None:
        q, o = f.q, f.occs[0]
        if q.kind != "segment" or not q.scale or o.position is None:
            return None
        base_key = q.key[1:]
        base = self.figs.get((f.scope, base_key))
        if base is None or base.occs[0].work is None:
            return None
        bw = base.occs[0].work
        if base.occs[0].role == "result" and any(x.q.key == q.key for x in bw.occs
                                                  if x.role == "operand"):
            return None  # the value was computed from this segment, not the other way
        k = f.scales.get(q.scale)
        if not k or not self.near(f, base.s / k):
            return None
        if base.verdict == "ok":
            return None
        en = (f"follows from {base.name} = {self._u(base, base.s)}: {num(base.s)}/{num(k)} = "
              f"{num(base.s / k)} mm, right for that value (graphplan: {self._u(f, f.e)}).")
        ru = (f"следует из {base.name} = {self._u(base, base.s, 'ru')}: "
              f"{num(base.s, 'ru')}/{num(k, 'ru')} = {num(base.s / k, 'ru')} мм — верно для "
              f"этого значения (по расчёту {self._u(f, f.e, 'ru')}).")
        return Diag("propagated", en, ru, (base.name,))

    def student_polygon(self, position: str) -> tuple[np.ndarray, list[str]] | None:
        """The crank's reaction on the group (R12) from the group's polygon drawn with the
        student's loads and outer reaction (graphplan's directions): ``R12 = −(ΣF + R43)``.
        Only for a mechanism of one group; ``None`` when the student gives no R43."""
        from ..forces import dyad_pairs, reaction_name

        mech, ref = self.ref.mech, self.ref
        k = ref.index(position)
        if len(mech.dyads) != 1 or k is None:
            return None
        d = mech.dyads[0]
        pairs = dyad_pairs(mech, d)
        outer = pairs[2]
        i, j = outer.by, outer.on
        fig = self.figs.get((position, ("reaction", i, j)))
        scales = self.w.stated_scales(position)
        if fig is not None:
            mag = fig.s
        else:
            seg = self.figs.get((position, ("segment", "reaction", i, j)))
            if seg is None or "Kp" not in scales:
                return None
            fig, mag = seg, seg.s * scales["Kp"]
        vec = None
        for model in ("rule", "full"):
            fs = ref.forces[model]
            name = reaction_name(i, j)
            if name in fs.reactions and np.hypot(*fs.reactions[name].vector[k]) > 0:
                vec = np.asarray(fs.reactions[name].vector[k], float)
                break
        if vec is None:
            return None
        off = [] if fig.verdict != "wrong" else [fig.name]
        total = mag * vec / float(np.hypot(*vec))
        rule = ref.loads["rule"]
        for f in ref.loads["full"].all_forces():
            if f.link not in d.links:
                continue
            v = np.asarray(f.vector[k], float)
            size = float(np.hypot(*v))
            if size == 0:
                continue
            lf = self._load_fig(f.name, position)
            kept = any(x.name == f.name and np.hypot(*x.vector[k]) > 0
                       for x in rule.all_forces())
            if lf is None and not kept:
                continue
            m = lf.s if lf is not None else size
            if lf is not None and lf.verdict == "wrong":
                off.append(lf.name)
            total = total + m * v / size
        return -total, off

    def _load_fig(self, name: str, position: str) -> Fig | None:
        for f in self.figs.values():
            if f.q.kind == "load" and f.q.name == name and f.scope in (position, "global"):
                return f
        return None

    def _polygon(self, f: Fig) -> Diag | None:
        mech = self.ref.mech
        o = f.occs[0]
        if o.position is None or o.position not in self.ref.labels or len(mech.dyads) != 1:
            return None
        from ..forces import dyad_pairs

        first = dyad_pairs(mech, mech.dyads[0])[0]
        key = f.key
        rkey = ("reaction", first.by, first.on)
        keys = [rkey, ("segment", *rkey), ("crank_arm", first.on), ("M_bal",)]
        crank_loads = any(np.any(x.vector) for x in self.ref.loads["full"].forces.get(
            mech.crank.link, ()))
        if crank_loads:  # Mур = rA × R12 only for a crank without loads of its own
            keys.remove(("M_bal",))
        else:  # and R41 = R21
            fkey = ("reaction", mech.frame_link, mech.crank.link)
            keys += [fkey, ("segment", *fkey)]
        if key not in keys:
            return None
        got = self.student_polygon(o.position)
        if got is None:
            return None
        r12, off = got
        if not off:
            return None
        k = self.ref.index(o.position)
        pin = self.ref.kin.pos.points[mech.crank.pin][k] - self.ref.kin.pos.points[
            mech.crank.pivot][k]
        size = float(np.hypot(*r12))
        if key[0] == "reaction":
            v = size
        elif key[0] == "segment":
            kp = f.scales.get("Kp")
            if not kp:
                return None
            v = size / kp
        elif key[0] == "crank_arm":
            kl = f.scales.get("Kl")
            if not kl or size == 0:
                return None
            v = abs(float(pin[0] * r12[1] - pin[1] * r12[0])) / size / kl
        else:
            v = float(pin[0] * r12[1] - pin[1] * r12[0])
        if not self.near(f, v) or self.near(f, v, f.e):
            return None
        en = (f"follows from {', '.join(off)}: the group's polygon closed with these values "
              f"gives {self._u(f, v)} (graphplan: {self._u(f, f.e)}).")
        ru = (f"следует из {', '.join(off)}: план сил группы, замкнутый с этими значениями, "
              f"даёт {self._u(f, v, 'ru')} (по расчёту {self._u(f, f.e, 'ru')}).")
        return Diag("propagated", en, ru, tuple(off))

    # geometry, scales, arms

    def _arm(self, f: Fig):
        """An arm read at a known position with Kl stated: (quantity, occurrence, k, Kl)."""
        q, o = f.q, f.occs[0]
        if q.kind != "arm" or o.position not in self.ref.labels:
            return None
        kl = f.scales.get("Kl")
        return (q, o, self.ref.index(o.position), kl) if kl else None

    def _geometry(self, f: Fig) -> Diag | None:
        arm = self._arm(f)
        if arm is None:
            return None
        q, _, k, kl = arm
        mech = self.ref.mech
        if q.key[0] == "crank_arm":
            limit, force, about, at = mech.crank.length, f"R{q.key[1]}{mech.crank.link}", \
                mech.crank.pivot, mech.crank.pin
        else:
            force, about = q.key[1], q.key[2]
            limit = self.ref.arm_limit(force, about, k)
            line = self.ref.force_line(force, k)
            at = "its point"
            if line is not None:
                pts = self.ref.kin.pos.points
                at = next((p for p in pts if np.allclose(pts[p][k], line[0], atol=1e-9)),
                          "its point")
        if limit is None:
            return None
        lim_mm = limit / kl
        if f.s <= lim_mm + max(f.tol - f.rel * abs(f.e or 0.0), self.c.tol.reading_mm):
            return None
        en = (f"impossible: an arm of {force} about {about} cannot exceed {about}{at} = "
              f"{num(lim_mm)} mm at {scale_text('Kl', kl)} (graphplan: {self._u(f, f.e)}).")
        ru = (f"невозможно: плечо {force} относительно {about} не может быть больше "
              f"{about}{at} = {num(lim_mm, 'ru')} мм при {scale_text('Kl', kl, 'ru')} (по "
              f"расчёту {self._u(f, f.e, 'ru')}).")
        return Diag("geometry", en, ru)

    def _scale(self, f: Fig) -> Diag | None:
        q, o = f.q, f.occs[0]
        if not f.e:
            return None
        if q.on_paper and q.scale:
            k_now = f.scales.get(q.scale)
            used = {x.value for x in self.w.occs if x.q.key == ("scale", q.scale)}
            for k2 in sorted(used):
                if not k_now or _close(k2, k_now, 1e-6):
                    continue
                e2 = f.e * k_now / k2
                if self.near(f, e2):
                    en = (f"{num(f.s)} mm is graphplan's length at {scale_text(q.scale, k2)} "
                          f"({num(e2)} mm), not at {scale_text(q.scale, k_now)} "
                          f"({num(f.e)} mm): measured at another scale.")
                    ru = (f"{num(f.s, 'ru')} мм — точная длина при "
                          f"{scale_text(q.scale, k2, 'ru')} ({num(e2, 'ru')} мм), а не при "
                          f"{scale_text(q.scale, k_now, 'ru')} ({num(f.e, 'ru')} мм): "
                          "измерено в другом масштабе.")
                    return Diag("scale", en, ru)
            return None
        right = SCALE_OF_DIMENSION.get(q.dimension)
        st = self.w.stated_scales(o.position)
        if right is None or right not in st:
            return None
        for other, k2 in st.items():
            if other == right or not k2:
                continue
            e2 = f.e * k2 / st[right]
            if self.near(f, e2):
                en = (f"{self._u(f, f.s)} is graphplan's value computed with {other} = "
                      f"{num(k2)} in place of {right} = {num(st[right])}: a swapped scale "
                      f"(graphplan: {self._u(f, f.e)}).")
                ru = (f"{self._u(f, f.s, 'ru')} получается, если вместо {right} = "
                      f"{num(st[right], 'ru')} взять {other} = {num(k2, 'ru')}: перепутан "
                      f"масштаб (по расчёту {self._u(f, f.e, 'ru')}).")
                return Diag("scale", en, ru)
        return None

    def _lever_arm(self, f: Fig) -> Diag | None:
        arm = self._arm(f)
        if arm is None:
            return None
        q, o, k, kl = arm
        mech = self.ref.mech
        cands: list[tuple[str, str, float]] = []
        if q.key[0] == "arm":
            force, about = q.key[1], q.key[2]
            for p in self.ref.kin.pos.points:
                if self.ref.point(about) == p:
                    continue
                v = self.ref.value(("arm", force, p), k)
                if v is not None:
                    cands.append((f"the arm of {force} about {p}", f"плечо {force} "
                                  f"относительно {p}", v / kl))
        v = self.ref.value(("crank_arm", mech.dyads[0].links[0]), k) if mech.dyads else None
        if v is not None and q.key[0] != "crank_arm":
            cands.append(("h21, the arm of R21 about the crank's pivot",
                          "h21, плечо R21 относительно оси кривошипа", v / kl))
        arms: dict = next((p.arms for p in self.w.work.positions if p.label == o.position), {})
        for spec in arms.values():
            if ("arm", spec.force, spec.about) == q.key:
                continue
            v = self.ref.value(("arm", spec.force, spec.about), k)
            if v is not None:
                cands.append((f"{spec.name}, the arm of {spec.force} about {spec.about}",
                              f"{spec.name}, плечо {spec.force} относительно {spec.about}",
                              v / kl))
        best = None
        for en_c, ru_c, v in cands:
            if self.near(f, v) and not self.near(f, v, f.e) and (
                    best is None or abs(v - f.s) < abs(best[2] - f.s)):
                best = (en_c, ru_c, v)
        if best is None:
            return None
        en = (f"{num(f.s)} mm is {best[0]} ({num(best[2])} mm); {o.name} should be "
              f"{num(f.e)} mm.")
        ru = (f"{num(f.s, 'ru')} мм — это {best[1]} ({num(best[2], 'ru')} мм); {o.name} "
              f"должно быть {num(f.e, 'ru')} мм.")
        return Diag("lever-arm", en, ru)

    def _models(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        if f.e is None:
            return None
        for model, kind, en_m, ru_m in (
                ("reversed", "sign", "the inertia forces reversed (Pи = +m·a instead of "
                 "−m·a)", "с силами инерции обратного направления (Pи = +m·a вместо −m·a)"),
                ("no-inertia", "model", "the inertia forces left out",
                 "без сил инерции")):
            e_m = self.w.expected(f.q, f.scope, o, model, f.scales)
            if e_m is None:
                continue
            e_m = e_m if f.q.signed else abs(e_m)
            if self.near(f, e_m) and not self.near(f, e_m, f.e):
                en = (f"matches graphplan's analysis with {en_m}: {self._u(f, e_m)}; the right "
                      f"value is {self._u(f, f.e)}.")
                ru = (f"совпадает с расчётом {ru_m}: {self._u(f, e_m, 'ru')}; верное значение "
                      f"{self._u(f, f.e, 'ru')}.")
                return Diag(kind, en, ru)
        return None

    def _other_position(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        if f.q.scope == "global" or o.position is None:
            return None
        best = None
        for label in self.ref.labels:
            if label == o.position:
                continue
            e_k = self.ref.expected(f.q, label, f.scales)
            if e_k is None:
                continue
            e_k = e_k if f.q.signed else abs(e_k)
            if self.near_copy(f, e_k) and not self.near(f, e_k, f.e) and (
                    best is None or abs(e_k - f.s) < abs(best[1] - f.s)):
                best = (label, e_k)
        if best is None:
            return None
        en = (f"{self._u(f, f.s)} is graphplan's value at position {best[0]} "
              f"({self._u(f, best[1])}), not at {o.position} ({self._u(f, f.e)}).")
        ru = (f"{self._u(f, f.s, 'ru')} — точное значение для положения {best[0]} "
              f"({self._u(f, best[1], 'ru')}), а не {o.position} ({self._u(f, f.e, 'ru')}).")
        return Diag("other-variant", en, ru)

    def _neighbours(self, f: Fig) -> Diag | None:
        o = f.occs[0]
        for name, nb in self.c.neighbours:
            where = o.position if f.q.scope != "global" else 0
            if where is not None and where not in nb.labels and where != 0:
                continue
            try:
                e_n = nb.expected(f.q, where if where is not None else 0, f.scales)
            except (KeyError, ValueError, IndexError):
                continue
            if e_n is None:
                continue
            e_n = e_n if f.q.signed else abs(e_n)
            if self.near_copy(f, e_n) and not self.near(f, e_n, f.e):
                en = (f"{self._u(f, f.s)} is the value of variant {name!r} "
                      f"({self._u(f, e_n)}), not of this one ({self._u(f, f.e)}).")
                ru = (f"{self._u(f, f.s, 'ru')} — значение из варианта {name!r} "
                      f"({self._u(f, e_n, 'ru')}), а не из этого ({self._u(f, f.e, 'ru')}).")
                return Diag("other-variant", en, ru)
        return None

    def _label(self, f: Fig) -> Diag | None:
        q, o = f.q, f.occs[0]
        if q.kind not in ("given", "drawn"):
            return None
        vocab = o.work.vocab if o.work is not None else self.w.vocab_general
        seen = set()
        for other in vocab.names.values():
            if other.key in seen or other.key == q.key or other.kind != q.kind or \
                    other.unit != q.unit:
                continue
            seen.add(other.key)
            e2 = self.w.expected(other, "global", o, "rule", f.scales)
            if e2 is not None and self.near(f, abs(e2)) and not self.near(f, abs(e2), f.e):
                en = (f"{num(f.s)} is {other.name} ({self._u(f, abs(e2))}), not {o.name} "
                      f"({self._u(f, f.e)}): a right number under a wrong name.")
                ru = (f"{num(f.s, 'ru')} — это {other.name} ({self._u(f, abs(e2), 'ru')}), а "
                      f"не {o.name} ({self._u(f, f.e, 'ru')}): верное число под чужим "
                      "обозначением.")
                return Diag("label", en, ru)
        return None

    def _series(self, f: Fig) -> Diag | None:
        if not f.q.on_paper or not f.e:
            return None
        for r in SERIES_RATIOS:
            if self.near_copy(f, f.e * r):
                sym = f.q.scale or ""
                en = (f"{num(f.s)} mm is {num(r)}× graphplan's {num(f.e)} mm: measured at "
                      f"another scale than {scale_text(sym, f.scales.get(sym, 0.0))}.")
                ru = (f"{num(f.s, 'ru')} мм — в {num(r, 'ru')} раза от точных "
                      f"{num(f.e, 'ru')} мм: измерено в другом масштабе.")
                return Diag("scale", en, ru)
        return None


def _names(node) -> list[str]:
    from .expressions import Bin, Call, Neg, Sym

    if isinstance(node, Sym):
        return [node.name]
    if isinstance(node, Neg):
        return _names(node.x)
    if isinstance(node, Bin):
        return _names(node.a) + _names(node.b)
    if isinstance(node, Call):
        return _names(node.arg)
    return []


__all__ = ["Diag", "Diagnoser", "Fig"]
