"""The checks of a student's work: arithmetic, consistency, against the model, geometry.

:func:`check_work` reads the work (:class:`~graphplan.checking.engine.Work`), compares
every figure with graphplan (:class:`~graphplan.checking.reference.Reference`) and says,
figure by figure, whether it is ok, inaccurate or wrong — and for a wrong one *why*
(:mod:`graphplan.checking.diagnosis`):

* **arithmetic** — every written chain is re-evaluated with the student's own numbers;
* **consistency** — one quantity (a mass, a scale, a force) written with different values
  in different places, a unit that does not fit the quantity;
* **against the model** — each figure beside graphplan's exact value at the student's
  scales, with the tolerances of :class:`~graphplan.checking.engine.Tolerances`;
* **geometry** — an arm longer than the mechanism allows.

A finding that only follows from an earlier wrong figure (right working from a wrong
number) says so (``follows_from``): it is reported, but it is not a fault of its own.
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

from .diagnosis import Diag, Diagnoser, Fig
from .engine import Occurrence, Tolerances, Work, _close, where_text
from .expressions import decimals, show
from .findings import FigureCheck, Finding, LineCheck, Report
from .quantities import SCALE_OF_DIMENSION, Quantity
from .reference import Reference
from .student import StudentWork, load_student
from .words import num, qty, scale_text, unit_text


@dataclass(frozen=True, slots=True)
class _Say:
    en: str
    ru: str

    def __call__(self, lang: str) -> str:
        return self.ru if lang == "ru" else self.en


class Checker:
    """Checks one student's work against a reference (see the module docstring)."""

    def __init__(self, work: StudentWork, ref: Reference, tol: Tolerances,
                 neighbours: tuple[tuple[str, Reference], ...] = (), lang: str | None = None):
        self.student = work
        self.ref = ref
        self.tol = tol
        self.lang = lang or work.lang
        self.w = Work(work, ref, tol)
        self.neighbours = neighbours
        self._mag: dict[tuple, float] = {}

    # --- bands and verdicts -----------------------------------------------------------

    def magnitude(self, q: Quantity) -> float:
        """The largest |value| of a quantity over the variant's positions (for floors)."""
        if q.key not in self._mag:
            vals = []
            for k in range(len(self.ref.labels)):
                try:
                    v = self.ref.value(q.key if q.kind != "segment" else q.key[1:], k)
                except (KeyError, ValueError, IndexError):
                    v = None
                if v is not None:
                    vals.append(abs(v))
            self._mag[q.key] = max(vals, default=0.0)
        return self._mag[q.key]

    def band(self, q: Quantity, e: float, scales: dict[str, float],
             written: str = "") -> tuple[float, float, float]:
        """(ok, tolerance, relative tolerance) around the expected value ``e``.

        A length read off a drawing is allowed the reading precision plus half a unit of
        the last digit it is written with (``25,0`` read at ±0,5 mm may be 0,55 mm off).
        """
        t = self.tol
        if q.tolerance == "segment":
            digit = 0.5 * 10.0 ** (-decimals(written)) if written and t.reading_mm else 0.0
            return (max(t.segment_ok * abs(e), t.reading_mm / 2 + digit),
                    max(t.segment * abs(e), t.reading_mm + digit), t.segment)
        if q.tolerance == "exact":
            return (max(t.datum_ok * abs(e), 1e-12), max(t.datum * abs(e), 1e-12), t.datum)
        floor = 0.0
        plan = SCALE_OF_DIMENSION.get(q.dimension)
        if plan and plan in scales and q.kind in ("reaction", "kinematic"):
            floor = t.reading_mm * scales[plan]
        if q.dimension in ("N·m", "rad/s", "rad/s²"):
            # a value near zero (Mур at a dead centre) read from arms of a few tenths of a
            # mm: a floor of a quarter of the derived ok band of its largest value
            floor = max(floor, t.derived_ok / 4 * self.magnitude(q))
        return (max(t.derived_ok * abs(e), floor / 2, 1e-12),
                max(t.derived * abs(e), floor, 1e-12), t.derived)

    def verdict(self, s: float, e: float, ok: float, tol: float) -> str:
        d = abs(s - e)
        return "ok" if d <= ok else ("inaccurate" if d <= tol else "wrong")

    # --- figures ----------------------------------------------------------------------

    def evaluate(self, scope: str, occs: list[Occurrence]) -> Fig:
        """A figure beside graphplan: the scale it is read at, the model, the verdict."""
        o = occs[0]
        q = o.q
        s = o.value if q.signed else abs(o.value)
        base = self.w.stated_scales(o.position, o.line)
        cands: list[dict[str, float]] = [base]
        if q.on_paper and q.scale:
            cands = []
            ks: list[float | None] = [*(self.w.scale_candidates(q, o.position, occs) or [])]
            for k in ks or [None]:
                sc = dict(base)
                if k is not None:
                    sc[q.scale] = k
                cands.append(sc)
        best = None
        rank = {"ok": 0, "inaccurate": 1, "wrong": 2}
        for i, sc in enumerate(cands):
            for model in ("rule", "full"):
                e = self.w.expected(q, scope, o, model, sc)
                if e is None:
                    continue
                e = e if q.signed else abs(e)
                ok, tol, _ = self.band(q, e, sc, o.text)
                v = rank[self.verdict(s, e, ok, tol)]
                # another scale or the full model only when they make the verdict better
                score = (v, i, model != "rule") if v < 2 else (v, 0 if i == 0 else 1,
                                                                 model != "rule", i)
                if best is None or score < best[0]:
                    best = (score, e, model, sc)
        if best is None:
            return Fig(scope, q.key, occs, q, s, None, "rule", base, "", 0, 0, 0,
                       "not compared")
        _, e, model, sc = best
        note = ""
        if q.on_paper and q.scale and sc.get(q.scale) != base.get(q.scale):
            note = scale_text(q.scale, sc[q.scale], "en")
        ok, tol, rel = self.band(q, e, sc, o.text)
        return Fig(scope, q.key, occs, q, s, e, model, sc, note, ok, tol, rel,
                   self.verdict(s, e, ok, tol))

    def _discrepancies(self, figs: dict[tuple, Fig]) -> None:
        """δ, the discrepancy of the two balancing moments of a position (Zhukovsky's
        lever and the force plans), is the student's own: it is compared with the value
        their own Мур and Мур.ж give — by the line's formula when it names the two
        (``δ = (Мур.ж − Мур)/Мур.ж∙100``) when it names the two, and by
        ``|Мур.ж − Мур|/|Мур.ж|·100`` (or over Мур, or the larger): judged within 0,1
        percentage point or 5 % of itself (ok), 0,3 point or 10 % (inaccurate). A formula
        of the line that gives none of these is the fault (``formula``)."""
        from .expressions import value as evaluate_node

        for (scope, key), f in figs.items():
            if key != ("mbal_discrepancy",):
                continue
            o = f.occs[0]
            if o.position is None:  # in the general lines: the coefficient of fluctuation
                self._fluctuation(f)
                continue
            m = figs.get((scope, ("M_bal",)))
            mz = figs.get((scope, ("M_bal", "lever")))
            if m is None or mz is None:
                continue
            a, b = abs(mz.s), abs(m.s)
            d = abs(mz.s - m.s)
            cands = [100.0 * d / x for x in (a, b, max(a, b)) if x > 0]
            lw = o.work
            own = None
            if lw is not None and lw.template is not None and o.role == "result":
                env = {}
                for name in {x.name for x in lw.occs if x.role == "operand"}:
                    x = next(y for y in lw.occs if y.name == name and y.role == "operand")
                    if x.q.key == ("M_bal",):
                        env[name] = m.s
                    elif x.q.key == ("M_bal", "lever"):
                        env[name] = mz.s
                try:
                    own = abs(evaluate_node(lw.template, env)) if len(env) == 2 else None
                except Exception:  # a formula that cannot be evaluated
                    own = None
                if own is not None and own < 1.0 and any(
                        abs(own * 100 - c) <= 0.1 * c + 1e-9 for c in cands):
                    own *= 100.0  # the formula as a fraction, the result in %
            # the discrepancy by any of the usual denominators; a formula of the line's own
            # that gives none of them is a fault of the formula (see Diagnoser._delta)
            e = min(cands, key=lambda c: abs(c - f.s))
            f.e, f.model, f.scale_note = e, "rule", ""
            f.ok, f.tol, f.rel = max(0.05 * e, 0.1), max(0.1 * e, 0.3), 0.05
            f.verdict = self.verdict(f.s, e, f.ok, f.tol)
            f.extra["delta"] = (m, mz, cands, own)

    def _fluctuation(self, f: Fig) -> None:
        """δ in the general lines is the coefficient of speed fluctuation (коэффициент
        неравномерности хода), compared with the variant's ``dynamics.delta`` as a datum:
        a fraction (``δ = 1/80 = 0,0125``) or in per cent (``δ = 1,25 %``)."""
        from ..dynamics import DynamicsSettings

        d = DynamicsSettings.of(self.ref.mech).delta
        if d is None:
            return
        from dataclasses import replace

        o = f.occs[0]
        e = float(d) * (100.0 if o.explicit == "%" else 1.0)
        if o.explicit != "%":  # a fraction: no unit to show
            f.q = replace(f.q, unit="1")
        f.e, f.model, f.scale_note = e, "rule", ""
        f.ok, f.tol, f.rel = max(self.tol.datum_ok * e, 1e-12), max(self.tol.datum * e,
                                                                    1e-12), self.tol.datum
        f.verdict = self.verdict(f.s, e, f.ok, f.tol)
        f.extra["fluctuation"] = float(d)

    def _diagnose_at_scales(self, f: Fig, dg: Diagnoser) -> tuple[Fig, Diag]:
        """A length on paper wrong at every scale the student used there: the scale whose
        diagnosis is the most specific (the stated one on a tie)."""
        d = dg.diagnose(f)
        o = f.occs[0]
        if not (f.q.on_paper and f.q.scale):
            return f, d
        best = (d.rank, f, d)
        base = self.w.stated_scales(o.position, o.line)
        for k in self.w.scale_candidates(f.q, o.position, f.occs)[1:]:
            sc = {**base, f.q.scale: k}
            e = self.w.expected(f.q, f.scope, o, f.model, sc)
            if e is None:
                continue
            e = abs(e)
            ok, tol, rel = self.band(f.q, e, sc, o.text)
            g = Fig(f.scope, f.key, f.occs, f.q, f.s, e, f.model, sc,
                    scale_text(f.q.scale, k, "en"), ok, tol, rel, self.verdict(f.s, e, ok, tol))
            if g.verdict != "wrong":
                continue
            dd = dg.diagnose(g)
            if dd.rank < best[0]:
                best = (dd.rank, g, dd)
        return best[1], best[2]

    # --- the run ----------------------------------------------------------------------

    def run(self) -> Report:
        w = self.w
        figs: dict[tuple, Fig] = {}
        for (scope, key), occs in w.figures.items():
            if occs[0].q.kind == "scale":
                continue
            figs[(scope, key)] = self.evaluate(scope, occs)
        dg = Diagnoser(self, figs)
        self._discrepancies(figs)
        changed = True
        while changed:  # down the student's chain: a reading, its value, the load from it
            changed = False
            for f in figs.values():
                if f.verdict == "wrong" and (dg.own_chain(f) or dg.own_forces_chain(f) or
                                             dg.own_plan_chain(f)):
                    f.verdict = "inaccurate"
                    f.own_chain = changed = True
        consistency = self._consistency(figs, dg)  # first: it adds notes to the figures
        findings: list[Finding] = []
        for key, f in list(figs.items()):
            if f.verdict != "ok" and f.e is not None:
                if f.verdict == "wrong":
                    f, d = self._diagnose_at_scales(f, dg)
                    figs[key] = f
                else:
                    d = dg.inaccurate(f)
                f.diag = d
                findings.append(self._finding(f, d))
        findings += consistency
        findings += self._scales(figs)
        findings += self._lines(figs)
        findings += self._unreadable()
        findings = _merge_same_line(findings)
        self._reconcile(figs, findings)
        order = {p.label: i for i, p in enumerate(self.student.positions)}
        findings.sort(key=lambda x: (x.file_line or 10**9, order.get(x.position or "", -1)))
        return Report(
            source=str(self.student.source), variant=str(self.student.variant),
            student=self.student.student, title=self.student.title, lang=self.lang,
            tolerances=self.tol.as_dict(), findings=tuple(findings),
            figures=tuple(self._figure_rows(figs)), lines=tuple(self._line_rows()),
            positions=tuple(self._positions()), group=self.student.group,
            notes=tuple(self._notes()))

    def _reconcile(self, figs: dict[tuple, Fig], findings: list[Finding]) -> None:
        """A figure is never shown right under a finding of its own line that calls its
        written value wrong (an Mур with a wrong sum is not "ok" because its value is)."""
        # by position too: lines without a file line (a drawing's) are told apart by it
        wrong = {(f.position, f.file_line, f.quantity) for f in findings
                 if f.verdict == "wrong"}
        for f in figs.values():
            o = f.occs[0]
            if f.verdict in ("ok", "inaccurate") and (o.position, o.line.file_line,
                                                      o.name) in wrong:
                f.verdict = "wrong"

    def _unreadable(self) -> list[Finding]:
        """A line (or a member of one) that cannot be read is a finding, never a silence."""
        out = []
        for lw in self.w.lines:
            bad = next((m for m in lw.members if m.kind == "bad" or (
                m.kind == "text" and any(c.isdigit() or c in "()[]+-*/=^" for c in m.text))),
                None)
            if bad is None:
                continue
            why = bad.error or lw.note
            en = f"the line cannot be read ({bad.text!r}: {why}); nothing of it is checked."
            ru = (f"строку не удалось прочитать ({bad.text!r}: {why}); ничего из неё не "
                  "проверено.")
            lw.arithmetic = "unread"
            out.append(Finding(where_text(lw.position, lw.line, self.lang),
                               lw.result_name or bad.text, None, None, "", "unreadable",
                               "wrong", ru if self.lang == "ru" else en, lw.position,
                               lw.line.text, lw.line.file_line, explanation_en=en,
                               explanation_ru=ru))
        return out

    def _positions(self):
        import numpy as np

        for p in self.student.positions:
            k = self.ref.index(p.label)
            phi = float(np.degrees(self.ref.kin.phi[k]) % 360.0) if k is not None else None
            yield p.label, phi

    # --- findings ---------------------------------------------------------------------

    def _finding(self, f: Fig, d: Diag, verdict: str | None = None) -> Finding:
        o = f.occs[0]
        notes = list(dict.fromkeys([*d.notes, *f.extra_notes]))
        if f.scale_note and f.q.scale:
            sc = scale_text(f.q.scale, f.scales[f.q.scale], self.lang)
            notes.append(_Say(f"compared at {sc}, the scale used at this position",
                              f"сравнено при {sc}, масштабе этого положения")(self.lang))
        if f.model == "full":
            notes.append(_Say("compared with every load kept (the variant neglects some)",
                              "сравнено с учётом всех нагрузок (вариант часть отбрасывает)")(
                                  self.lang))
        return Finding(
            where=where_text(o.position, o.line, self.lang), quantity=o.name, stated=f.s,
            expected=f.e,
            unit=f.q.unit, kind=d.kind, verdict=verdict or f.verdict,
            explanation=d.ru if self.lang == "ru" else d.en,
            position=o.position, line=o.line.text, file_line=o.line.file_line,
            follows_from=d.follows, notes=tuple(notes), explanation_en=d.en,
            explanation_ru=d.ru)

    def _consistency(self, figs: dict[tuple, Fig], dg: Diagnoser) -> list[Finding]:
        """One quantity written with different values (beyond rounding)."""
        out = []
        for (scope, _key), f in figs.items():
            s0 = f.occs[0]
            groups: dict[float, list[Occurrence]] = defaultdict(list)
            for o in f.occs[1:]:
                a, b = abs(o.value), abs(s0.value)
                if _close(a, b, max(self.tol.arithmetic, 0.002), 1e-12):
                    continue
                if o.q.on_paper and _close(a, b, 0, self.tol.reading_mm):
                    continue
                if o.q.on_paper and o.q.scale:  # one segment on two plans at two scales
                    ka = self.w.stated_scales(o.position, o.line).get(o.q.scale)
                    kb = self.w.stated_scales(s0.position, s0.line).get(o.q.scale)
                    if ka and kb and not _close(ka, kb, 1e-6) and _close(
                            a * ka, b * kb, max(self.tol.arithmetic, 0.002),
                            self.tol.reading_mm * max(ka, kb)):
                        continue
                key_v = next((v for v in groups if _close(v, o.value, 1e-6)), o.value)
                groups[key_v].append(o)
            for occs in groups.values():
                o = occs[0]
                wh_en = ", ".join(dict.fromkeys(x.where_in("en") for x in occs))
                wh_ru = ", ".join(dict.fromkeys(x.where_in("ru") for x in occs))
                said = _Say(f"also used as {o.name} = {num(o.raw)} in {wh_en}",
                            f"также {o.name} = {num(o.raw, 'ru')} ({wh_ru})")
                if f.verdict == "wrong" or f.e is None:
                    f.extra_notes.append(said(self.lang))
                    continue
                g = self.evaluate(scope, [o, *occs[1:]])
                if g.verdict == "ok":
                    continue
                d = self._segment_for_force(f, o, g) or dg.diagnose(g)
                if d.kind in ("model",):
                    d = Diag("consistency",
                             f"{o.name} = {qty(g.s, g.q.unit)} here, but "
                             f"{qty(f.s, f.q.unit)} in {s0.where_in('en')}; graphplan: "
                             f"{qty(g.e, g.q.unit)}.",
                             f"{o.name} = {qty(g.s, g.q.unit, 'ru')} здесь, но "
                             f"{qty(f.s, f.q.unit, 'ru')} ({s0.where_in('ru')}); по расчёту "
                             f"{qty(g.e, g.q.unit, 'ru')}.", d.follows, d.notes)
                g.extra_notes.append(_Say(
                    f"stated as {qty(f.s, f.q.unit)} in {s0.where_in('en')}",
                    f"записано {qty(f.s, f.q.unit, 'ru')} ({s0.where_in('ru')})")(self.lang))
                out.append(self._finding(g, d, "wrong"))
        return out

    def _segment_for_force(self, f: Fig, o: Occurrence, g: Fig) -> Diag | None:
        """A force written as its segment on the force plan where the force is meant
        (``Мур = R21∙h21∙Кl`` with R21 = 60,02 mm of the plan at Kp = 2 N/mm)."""
        plan = SCALE_OF_DIMENSION.get(f.q.dimension)
        # the force's own plan: the Kp stated where the force is read off it, or here
        s0 = f.occs[0]
        ks = [self.w.stated_scales(x.position, x.line).get(plan or "") for x in (s0, o)]
        k = next((x for x in ks if x and abs(x - 1) >= 0.05 and _close(
            abs(o.raw) * x, abs(f.s), 0.01)), None)
        if not k or f.q.on_paper:
            return None
        sc = scale_text(plan, k, "en")  # type: ignore[arg-type]
        en = (f"{o.name} = {num(o.raw)} is its segment on the force plan (mm), not the "
              f"force: {num(o.raw)} mm × {sc} = {qty(f.s, f.q.unit)}, as stated in "
              f"{f.occs[0].where_in('en')} — {plan} is left out.")
        ru = (f"{o.name} = {num(o.raw, 'ru')} — это отрезок на плане сил (мм), а не сила: "
              f"{num(o.raw, 'ru')} мм × {scale_text(plan, k, 'ru')} = "  # type: ignore[arg-type]
              f"{qty(f.s, f.q.unit, 'ru')} ({f.occs[0].where_in('ru')}) — пропущен {plan}.")
        return Diag("scale", en, ru)

    def _scales(self, figs: dict[tuple, Fig]) -> list[Finding]:
        """A scale stated with one value and used with another."""
        w = self.w
        out = []
        for (scope, key), occs in w.figures.items():
            if key[0] != "scale":
                continue
            sym = key[1]
            k0 = w._stated_scale(sym, scope)
            if k0 is None:
                continue
            stated = next(o for o in occs if _close(o.value, k0, 1e-9))
            groups: dict[float, list[Occurrence]] = defaultdict(list)
            several = sym == "Kp" and len(w.kp_stated(scope)) > 1
            for o in occs:
                if several:  # a force plan per group: each use against the Kp in force
                    if o.role != "operand" or _close(o.value, w.kp_at(scope, o.line, k0),
                                                     self.tol.arithmetic):
                        continue
                    kv = next((v for v in groups if _close(v, o.value, 1e-9)), o.value)
                    groups[kv].append(o)
                    continue
                if o.role != "operand" and o.work is not None and \
                        o.work.arithmetic == "wrong" and _close(w._effective(o), k0, 1e-9):
                    continue  # the slip of the scale's own line: said there, once
                if not _close(o.value, k0, self.tol.arithmetic):
                    kv = next((v for v in groups if _close(v, o.value, 1e-9)), o.value)
                    groups[kv].append(o)
            for kv, uses in groups.items():
                o = uses[0]
                positions = sorted({u.position for u in uses if u.position}, key=str)
                where_en = ", ".join(dict.fromkeys(u.where_in("en") for u in uses))
                where_ru = ", ".join(dict.fromkeys(u.where_in("ru") for u in uses))
                other = self._same_as_other_scale(sym, kv, o.position)
                fits = self._paper_fits(sym, kv, k0, positions, figs)
                ks, k0s = scale_text(sym, kv), scale_text(sym, k0)
                ks_ru, k0s_ru = scale_text(sym, kv, "ru"), scale_text(sym, k0, "ru")
                if other:
                    en = (f"{ks} is used in {where_en}, but {sym} is stated as {k0s}: "
                          f"{num(kv)} is the scale {other} — {other} was used in place of "
                          f"{sym}.")
                    ru = (f"{ks_ru} использован ({where_ru}), а {sym} принят {k0s_ru}: "
                          f"{num(kv, 'ru')} — это масштаб {other}, он подставлен вместо "
                          f"{sym}.")
                elif fits:
                    en = (f"{ks} is used in {where_en}, but {sym} is stated as {k0s}; the "
                          f"lengths measured there ({fits}) fit {num(kv)}: the drawing is at "
                          f"{ks}, the stated scale is not the drawing's.")
                    ru = (f"{ks_ru} использован ({where_ru}), а {sym} принят {k0s_ru}; "
                          f"измеренные там отрезки ({fits}) соответствуют {num(kv, 'ru')}: "
                          f"чертёж выполнен в масштабе {ks_ru}, указанный масштаб не тот.")
                else:
                    en = f"{ks} is used in {where_en}, but {sym} is stated as {k0s}."
                    ru = f"{ks_ru} использован ({where_ru}), а {sym} принят {k0s_ru}."
                out.append(Finding(
                    where=o.where_in(self.lang), quantity=o.name, stated=kv, expected=k0,
                    unit=stated.q.unit, kind="scale", verdict="wrong",
                    explanation=ru if self.lang == "ru" else en, position=o.position,
                    line=o.line.text, file_line=o.line.file_line,
                    notes=tuple(f"{u.where_in(self.lang)}: {u.line.text}" for u in uses[1:]),
                    explanation_en=en, explanation_ru=ru))
        return out

    def _same_as_other_scale(self, sym: str, kv: float, position: str | None) -> str | None:
        for other, v in self.w.stated_scales(position).items():
            if other != sym and _close(v, kv, 1e-6):
                return other
        return None

    def _paper_fits(self, sym: str, kv: float, k0: float, positions, figs) -> str:
        """Names of lengths on paper at ``positions`` that fit the scale ``kv`` better than
        the stated ``k0`` (comma-separated, empty if none)."""
        names = []
        for f in figs.values():
            o = f.occs[0]
            if not (f.q.on_paper and f.q.scale == sym and o.position in positions):
                continue
            if f.scale_note and _close(f.scales.get(sym, 0.0), kv, 1e-9) and \
                    f.verdict != "wrong":
                names.append(f"{o.name} ({o.position})")
        return ", ".join(names)

    def _lines(self, figs: dict[tuple, Fig]) -> list[Finding]:
        """Findings of lines that are not a figure's: arithmetic of a line without a
        compared result, signs of a formula against its numbers, unit problems."""
        out = []
        lang = self.lang
        figured = {id(f.occs[0].work) for f in figs.values()
                   if f.occs[0].role == "result" and f.verdict == "wrong" and
                   f.e is not None}
        for lw in self.w.lines:
            pos = lw.position
            wh = where_text(pos, lw.line, self.lang)
            if lw.arithmetic in ("wrong", "sign") and id(lw) not in figured:
                a, b = lw.bad  # type: ignore[misc]
                res_fig = next((f for f in figs.values() if f.occs[0].work is lw and
                                f.occs[0].role == "result"), None)
                if lw.arithmetic == "sign" and res_fig is not None and res_fig.verdict == "ok":
                    continue  # the sign of a product set by the sense of rotation, rightly
                en = (f"the written numbers give {a.text} = {num(a.value)}, not {b.text}.")
                ru = (f"записанные числа дают {a.text} = {num(a.value, 'ru')}, а не "
                      f"{b.text}.")
                kind = "sign" if lw.arithmetic == "sign" else "arithmetic"
                out.append(Finding(wh, lw.result_name or lw.members[0].text, b.value, a.value,
                                   "", kind, "wrong", ru if lang == "ru" else en, pos,
                                   lw.line.text, lw.line.file_line, explanation_en=en,
                                   explanation_ru=ru))
            if lw.matched is not None and lw.matched.signs and not lw.line.symbols:
                for t, n, st, sn in lw.matched.signs:
                    term = show(t)
                    try:
                        from .expressions import value as _v

                        nv = _v(n)
                    except Exception:
                        nv = None
                    written = ("+" if sn > 0 else "−") + show(n)
                    en = (f"the formula has {'+' if st > 0 else '−'}{term}, but the numbers "
                          f"{'add' if sn > 0 else 'subtract'} it ({written}).")
                    ru = (f"в формуле {'+' if st > 0 else '−'}{term}, а в числах это "
                          f"слагаемое {'прибавлено' if sn > 0 else 'вычтено'} ({written}).")
                    out.append(Finding(wh, term, None if nv is None else sn * nv,
                                       None if nv is None else st * nv, "", "sign", "wrong",
                                       ru if lang == "ru" else en, pos, lw.line.text,
                                       lw.line.file_line, explanation_en=en,
                                       explanation_ru=ru))
            if lw.unit_problem and lw.result_q is not None:
                q = lw.result_q
                en = (f"{lw.result_name} is measured in {q.unit}, but is written in "
                      f"{lw.unit_problem}.")
                ru = (f"{lw.result_name} измеряется в {unit_text(q.unit, 'ru')}, а записано в "
                      f"{lw.unit_problem}.")
                out.append(Finding(wh, lw.result_name, None, None, q.unit, "unit", "wrong",
                                   ru if lang == "ru" else en, pos, lw.line.text,
                                   lw.line.file_line, explanation_en=en, explanation_ru=ru))
        return out

    # --- rows of the report -----------------------------------------------------------

    def _figure_rows(self, figs: dict[tuple, Fig]):
        self._compared: set = set()
        for f in figs.values():
            o = f.occs[0]
            d = f.diag
            why = (d.ru if self.lang == "ru" else d.en) if d else ""
            if f.verdict == "not compared":
                why = (_NOT_COMPARED["delta"] if f.key == ("mbal_discrepancy",) else
                       _NOT_COMPARED["figure"])(self.lang)
            else:
                self._compared.update(id(x.work) for x in f.occs)
            yield FigureCheck(o.position, o.name, f.q.unit, f.s, f.e, f.verdict,
                              where_text(o.position, o.line, self.lang), o.line.text,
                              d.kind if d else "", why, f.scale_note, len(f.occs))
        for (_scope, key), occs in self.w.figures.items():
            if key[0] == "scale":
                o = occs[0]
                yield FigureCheck(o.position, o.name, o.q.unit, o.value, None,
                                  "not compared", where_text(o.position, o.line, self.lang),
                                  o.line.text, explanation=_NOT_COMPARED["scale"](self.lang),
                                  uses=len(occs))

    def _not_compared(self, lw) -> str:
        """Why nothing of a line was compared with graphplan ("" if something was)."""
        if id(lw) in self._compared:
            return ""
        if lw.arithmetic == "unread":
            return _NOT_COMPARED["unread"](self.lang)
        if lw.occs and all(o.q.kind == "scale" for o in lw.occs):
            return _NOT_COMPARED["scale"](self.lang)
        if lw.result_name and lw.result_q is None:
            return _NOT_COMPARED["name"](self.lang).format(name=lw.result_name)
        if lw.result is None and any(m.kind == "formula" for m in lw.members):
            return ""  # a formula alone: it is compared through the numbers of the next line
        if not lw.occs:
            return _NOT_COMPARED["nothing"](self.lang)
        return _NOT_COMPARED["figure"](self.lang)

    def _line_rows(self):
        for lw in self.w.lines:
            names = tuple((o.name, o.text) for o in lw.occs if o.role == "operand")
            yield LineCheck(where_text(lw.position, lw.line, self.lang), lw.position,
                            lw.line.text,
                            lw.result_name or None, lw.evaluated,
                            None if lw.result is None else lw.result.value, lw.arithmetic,
                            names, lw.note or lw.line.note, self._not_compared(lw))

    def _notes(self):
        for lw in self.w.lines:
            if lw.note and lw.arithmetic != "unread":
                yield f"{where_text(lw.position, lw.line, self.lang)}: {lw.note}"


_NOT_COMPARED = {
    "figure": _Say("graphplan has no value of this figure here to compare it with",
                   "в расчёте graphplan нет этой величины для сравнения"),
    "scale": _Say("a scale is the student's choice: only its arithmetic and its use are "
                  "checked", "масштаб выбирает студент: проверены только его арифметика и "
                  "применение"),
    "name": _Say("the name {name!r} is not known for this variant (see docs/check-format.md, "
                 "Names)", "обозначение {name!r} неизвестно для этого варианта (см. "
                 "docs/check-format.md, «Names»)"),
    "nothing": _Say("the line names no figure (give `quantity` or `symbols`)",
                    "строка не называет величину (укажите `quantity` или `symbols`)"),
    "unread": _Say("the line cannot be read", "строку не удалось прочитать"),
    "delta": _Say("δ compares the position's Мур of the force plans with Мур.ж of "
                  "Zhukovsky's lever: write both at this position to compare it; in the "
                  "general lines δ is the coefficient of speed fluctuation, and the "
                  "variant gives none (dynamics.delta)",
                  "δ сравнивает Мур планов сил и Мур.ж рычага Жуковского: запишите оба "
                  "в этом положении, чтобы его проверить; в общих строках δ — "
                  "коэффициент неравномерности хода, а вариант его не задаёт "
                  "(dynamics.delta)"),
}


def _merge_same_line(findings: list[Finding]) -> list[Finding]:
    """Findings of one line with the same kind and the same stated value are one finding
    (``R41 = R12 = 424 Н``: one unit slip, two names)."""
    out: list[Finding] = []
    for f in findings:
        twin = next((g for g in out if g.line == f.line and g.where == f.where and
                     g.kind == f.kind and g.stated is not None and f.stated is not None and
                     math.isclose(g.stated, f.stated, rel_tol=1e-9)), None)
        if twin is None:
            out.append(f)
            continue
        i = out.index(twin)
        from dataclasses import replace

        out[i] = replace(twin, quantity=f"{twin.quantity} = {f.quantity}",
                         notes=tuple(dict.fromkeys(twin.notes + f.notes)))
    return out


# --- entry points ----------------------------------------------------------------------------


_REFERENCES: dict[tuple, Reference] = {}


def reference_for(variant: Path, extra: dict[str, float] | None = None) -> Reference:
    """A cached :class:`Reference` of a variant file (by path, mtime and extra positions)."""
    p = Path(variant).resolve()
    key = (str(p), p.stat().st_mtime_ns, tuple(sorted((extra or {}).items())))
    if key not in _REFERENCES:
        if len(_REFERENCES) > 16:
            _REFERENCES.clear()
        _REFERENCES[key] = Reference.of(p, extra)
    return _REFERENCES[key]


def check_work(work: StudentWork, tolerances: dict[str, float] | None = None,
               neighbours: tuple[Path, ...] = (), lang: str | None = None) -> Report:
    return checker_for(work, tolerances, neighbours, lang).run()


def checker_for(work: StudentWork, tolerances: dict[str, float] | None = None,
                neighbours: tuple[Path, ...] = (), lang: str | None = None) -> Checker:
    """The checker of a student's work read by
    :func:`~graphplan.checking.student.load_student` (:func:`check_work` runs it).

    Parameters
    ----------
    work : StudentWork
    tolerances : dict, optional
        Overrides of :class:`Tolerances` (the student file's ``[tolerances]`` come first,
        these win).
    neighbours : tuple of Path
        Further variant files whose values a figure may have been copied from (the
        student file's ``work.neighbours`` are added).
    lang : str, optional
        ``"ru"`` or ``"en"`` for the explanations (default: the file's ``work.lang``).

    Raises
    ------
    GraphplanError
        If the variant cannot be loaded or solved, or a position label is unknown.
    """
    from .errors import StudentFileError

    extra = {p.label: p.phi_deg for p in work.positions if p.phi_deg is not None}
    ref = reference_for(work.variant, extra)
    for i, p in enumerate(work.positions):
        if p.label not in ref.labels and p.label != "max":
            raise StudentFileError(
                f"{work.source}: positions[{i}].label: the variant has no position "
                f"{p.label!r} (expected one of {', '.join(ref.labels)}, 'max', or give phi)")
    tol = Tolerances.of({**work.tolerances, **(tolerances or {})})
    nbs = []
    for n in (*work.neighbours, *neighbours):
        nbs.append((Path(n).stem, reference_for(Path(n), extra)))
    return Checker(work, ref, tol, tuple(nbs), lang)


def check_file(path: str | Path, **kw) -> Report:
    """Load a student file and check it (see :func:`check_work`)."""
    return check_work(load_student(path), **kw)


def overlays(checker: Checker, report: Report) -> list[str]:
    """The overlay sheets (SVG texts) of a finished check."""
    from .overlay import overlay_sheets

    return overlay_sheets(report, checker.ref, checker.w)


__all__ = ["Checker", "check_file", "check_work", "checker_for", "overlays", "reference_for"]
