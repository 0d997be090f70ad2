"""The lesson of the force plans of one position: every Assur group from the last to
the first, then the crank (:func:`graphplan.plans.forces.force_plans`, as on sheet 2).

Each plan has two panels: the **scheme** of the group (its links on the position plan
at Kl, with the known forces and their arms) for the moment equations, and the
**force plan** at Kp for the polygon. A moment equation ``ΣM_B(link 2): Rτ12·AB +
G2·h_G2 + … = 0`` draws each known force (direction only, a fixed length: its size is
in the caption), its line of action and the arm ``h`` from the moment centre, read by
the construction (:attr:`graphplan.plans.forces.ForcePlan.arms_mm`); the caption
converts each arm into the force's moment, ``M = F·h`` (N·mm of the drawing, as the
equation is written). The unknown's line is drawn too: a tangential component is
perpendicular to the line from the centre to its joint, so its arm is that distance.
The polygon's steps draw the construction's own elements: each known force laid off
at Kp (``ab = Q/Kp``), the two closing lines of known direction, the reactions read.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import replace

import numpy as np

from ..forces import reaction_name
from ..plans import ForcePlan, Step, position_mm, unit_vector
from .captions import WORDS, group_name, num, shown
from .model import Lesson, LessonStep, Mark, Panel, Result, Term

ARROW_MM = 15.0  #: shortest arrow of a force on a scheme (direction only), mm
ARROW_SHARE = 0.12  #: … or this share of the scheme's size, if longer
_MOMENT = re.compile(r"ΣM_(?P<c>[^(\s]+)\(link (?P<links>[^)]+)\): (?P<rest>.*?) = 0")


def forces_lesson(analysis, k: int) -> Lesson:
    """The force plans of position k as a lesson (module docstring)."""
    mech, kin = analysis.mech, analysis.kin
    s2, loads = analysis.sheet2, analysis.loads
    plans = analysis.force_plans(k)  # sheet 2's own plans of position k
    label = kin.labels[k]
    origin = np.asarray(kin.pos.points[mech.crank.pivot][k], float)
    panels: list[Panel] = []
    steps: list[LessonStep] = []
    known: dict = {}
    for i, fp in enumerate(plans):
        links = _plan_links(mech, fp)
        crank = fp.group.startswith("crank")
        kl = s2.figure_kl(i)  # as sheet 2 draws the group or the crank
        P = position_mm(kin, k, kl.per_mm, mech.crank.pivot)
        name = {"ru": f"кривошип {mech.crank.link}" if crank else group_name(fp.group, "ru"),
                "en": f"crank {mech.crank.link}" if crank else group_name(fp.group, "en")}
        scheme = len(panels)
        panels.append(Panel(f"scheme-{fp.group}", {
            "ru": f"Схема: {name['ru']}, {WORDS['ru']['position']} {label}",
            "en": f"Scheme: {name['en']}, {WORDS['en']['position']} {label}"}, kl.basis))
        plan_panel = len(panels)
        panels.append(Panel(f"plan-{fp.group}", {
            "ru": f"План сил: {name['ru']}, {WORDS['ru']['position']} {label}",
            "en": f"Force plan: {name['en']}, {WORDS['en']['position']} {label}"},
            fp.scale.basis))
        forces_on = _forces_on(mech, loads, k, links, known, origin, kl.per_mm)
        pts = np.array([P[p] for ln in links for p in mech.points_of(ln) if p in P])
        arrow = max(ARROW_MM, ARROW_SHARE * float(np.max(np.ptp(pts, axis=0))))
        context_done = False
        labelled: set[str] = set()
        for s in fp.steps:
            m = _MOMENT.match(s.equation)
            if m:
                marks = [] if context_done else _scheme_context(mech, kin, k, P, links)
                context_done = True
                marks += _moment_marks(fp, m, forces_on, P, origin, kl.per_mm, arrow)
                steps.append(_moment_step(len(steps) + 1, scheme, fp, s, m, forces_on, marks))
            else:
                steps.append(_plan_step(len(steps) + 1, plan_panel, fp, s, labelled))
        known.update(fp.reactions)
    used = sorted({s.panel for s in steps})
    remap = {p: i for i, p in enumerate(used)}
    panels = [panels[p] for p in used]
    steps = [replace(s, panel=remap[s.panel]) for s in steps]
    title = {lang: f"{WORDS[lang]['forces']} — {mech.name}, {WORDS[lang]['position']} {label}"
             for lang in ("ru", "en")}
    kls = (s2.kl.basis,) if s2.kl_crank is None or s2.kl_crank == s2.kl else (
        s2.kl.basis, s2.kl_crank.basis.replace("Kl", f"Kl({mech.crank.link})", 1))
    scales = (*kls, *dict.fromkeys(fp.scale.basis for fp in plans))
    return Lesson("forces", mech.name, mech.source, label, title, tuple(panels), tuple(steps),
                  scales)


def _plan_links(mech, fp: ForcePlan) -> tuple[str, ...]:
    if fp.group.startswith("crank"):
        return (mech.crank.link,)
    return next(d.links for d in mech.dyads if d.name == fp.group)


def _forces_on(mech, loads, k, links, known, origin, kl) -> dict[str, tuple]:
    """Known forces on the links: name → (vector N, point of application mm), as the
    force plans take them (the loads, and the reactions of the groups drawn before)."""
    out: dict[str, tuple] = {}
    for ln in links:
        for f in loads.forces.get(ln, ()):
            if np.any(f.vector[k]):
                out[f.name] = (np.asarray(f.vector[k], float), (f.at[k] - origin) / kl)
    for r in known.values():
        if r.by in links and r.on not in links:
            out[reaction_name(r.on, r.by)] = (-np.asarray(r.vector, float), (r.at - origin) / kl)
    return out


def _xy(v) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def _scheme_context(mech, kin, k, P, links) -> list[Mark]:
    """The links of the group on the position plan, their joints and guides (black)."""
    centres = {lp.centre for lp in mech.links.values() if lp.centre}
    marks: list[Mark] = []
    names: list[str] = []
    for ln in links:
        pts = [p for p in mech.points_of(ln) if p in P and p not in centres]
        for a, b in itertools.pairwise(pts):
            marks.append(Mark("curve", f"link-{ln}-{a}{b}", (_xy(P[a]), _xy(P[b])), "context"))
        names += [p for p in mech.points_of(ln) if p in P]
    for key, (_, u) in kin.pos.guides.items():
        slider = key.split("/")[0]
        if slider in links:
            pts = [p for p in mech.points_of(slider) if p in P]
            if pts:
                c, d = P[pts[0]], np.asarray(u[k], float)
                marks.append(Mark("curve", f"guide-{key}", (_xy(c - 25 * d), _xy(c + 25 * d)),
                                  "context", dashed=True))
    for n in dict.fromkeys(names):
        marks.append(Mark("point", n, (_xy(P[n]),), "context"))
        marks.append(Mark("label", n, (_xy(P[n]),), "context", text=n))
    return marks


def _foot(c, x, d):
    u = unit_vector(d)
    return x + float(np.dot(c - x, u)) * u


def _names(rest: str) -> list[str]:
    """The forces and couples of an equation's terms: ``G2·h_G2`` → G2, ``Mи2/Kl`` → Mи2."""
    return [t.split("·")[0].split("/")[0].lstrip("−") for _, t in _terms(rest)]


def _moment_marks(fp: ForcePlan, m, forces_on, P, origin, kl, arrow) -> list[Mark]:
    """Each known force of the equation with its line of action and arm; the unknown's
    line."""
    c_name = m.group("c")
    c = P.get(c_name)
    marks: list[Mark] = []
    if c is None:
        return marks
    named = set(_names(m.group("rest"))[1:])
    for name, (vec, at) in forces_on.items():
        if name not in named or f"h_{name}@{c_name}" not in fp.arms_mm:
            continue
        u = unit_vector(vec)
        marks.append(Mark("vector", name, (_xy(at), _xy(at + arrow * u)),
                          "reaction" if name.startswith("R") else "load", text=name))
        foot = _foot(c, at, vec)
        ends = sorted([0.0, float(np.dot(foot - at, u)), arrow])
        marks.append(Mark("line", f"action-{name}", (_xy(at + (ends[0] - 4) * u),
                                                      _xy(at + (ends[-1] + 4) * u)), "line",
                          dashed=True))
        if float(np.hypot(*(foot - c))) > 1e-6:
            marks.append(Mark("vector", f"h_{name}", (_xy(c), _xy(foot)), "arm",
                              text=f"h{name}"))
    unknown = _terms(m.group("rest"))[0][1]
    q = unknown.split("·")[0].split("/")[0].lstrip("−")
    r = fp.reactions.get(re.sub(r"^R[τn]", "R", q))
    if r is not None:
        at = (np.asarray(r.at, float) - origin) / kl
        if q.startswith("Rτ"):
            d = np.array([-(at - c)[1], (at - c)[0]])
        else:
            d = np.asarray(r.vector, float)
        if np.hypot(*d) > 0:
            u = unit_vector(d)
            marks.append(Mark("line", q, (_xy(at - arrow * u), _xy(at + arrow * u)), "line",
                              text=q))
            marks.append(Mark("point", f"{q}@", (_xy(at),), "point"))
    return marks


def _terms(rest: str) -> list[tuple[str, str]]:
    """``Rτ12·AB − G2·h_G2 + Mи2/Kl`` → [("+", "Rτ12·AB"), ("−", "G2·h_G2"), …]."""
    out, sign = [], "+"
    for tok in re.split(r"\s+", rest.strip()):
        if tok in ("+", "−", "-"):
            sign = "−" if tok != "+" else "+"
        elif tok:
            out.append((sign, tok))
            sign = "+"
    return out


def _moment_step(number, panel, fp: ForcePlan, s: Step, m, forces_on, marks) -> LessonStep:
    c_name = m.group("c")
    terms_ = _terms(m.group("rest"))
    unknown = terms_[0][1]
    q = unknown.split("·")[0].split("/")[0].lstrip("−")
    direction = None
    if q.startswith("Rτ"):
        direction = f"⟂ {unknown.split('·')[1]}" if "·" in unknown else None
    if "·x_" in unknown:  # the offset of a slide's reaction along its guide
        terms = [Term(unknown.split("·")[1], "∥ guide", None), Term(q, "✓", "✓")]
    else:
        terms = [Term(q, direction, None)]
    results = []
    for _sign, t in terms_[1:]:
        name = t.split("·")[0].split("/")[0]
        terms.append(Term(name, "✓", "✓"))
        h = fp.arms_mm.get(f"h_{name}@{c_name}")
        if h is not None and name in forces_on:
            f = float(np.hypot(*forces_on[name][0]))
            results.append(Result(f"h_{name}", f"M_{c_name}({name})", h, f * h, "N·mm",
                                  name, f))
    return LessonStep(number, panel, "couple" if "x_" in unknown else "moment", s.equation,
                      {"en": s.text, "ru": s.text_ru}, tuple(terms), tuple(results),
                      tuple(marks))


def _plan_step(number, panel, fp: ForcePlan, s: Step, labelled: set[str]) -> LessonStep:
    marks: list[Mark] = []
    lines = []
    for e in s.elements:
        if e.kind == "segment":
            marks.append(Mark("vector", e.name, (e.start, e.end), e.role, text=e.name))
        elif e.kind == "line":
            marks.append(Mark("line", e.name, (e.start, e.end), "line"))
            lines.append(e.name)
        else:
            marks.append(Mark("point", e.name, (e.start,), "point"))
    for n, xy in fp.points.items():
        if n in labelled:
            continue
        if any(np.allclose(xy, p) for e in s.elements for p in (e.start, e.end)):
            labelled.add(n)
            marks.append(Mark("label", n, (_xy(xy),), "label", text=n))
    results, terms = [], []
    if s.readings:
        laid = not lines and len(s.readings) == 1 and s.text.startswith("Lay")
        for q in s.readings:
            rd = fp.readings[q]
            results.append(Result(rd.name, q, rd.mm, rd.value, "N", "Kp", fp.scale.per_mm, laid))
        kind = "lay" if laid else "read"
        if laid:
            terms = [Term(s.readings[0], f"∥ {s.readings[0]}", f"{num(shown(results[0]))} N")]
    elif lines:
        kind = "intersect"
        dirs = {n.split(" ", 1)[0]: n.split(" ", 1)[1] for n in lines if " " in n}
        rest = s.equation.split("=")[0]
        for t in (x.strip() for x in rest.split("+")):
            terms.append(Term(t, dirs[t], None) if t in dirs else Term(t, "✓", "✓"))
    else:  # a projection on a guide (·u), else an equation of moments
        kind = "projection" if "·u" in s.equation else "moment"
    return LessonStep(number, panel, kind, s.equation, {"en": s.text, "ru": s.text_ru},
                      tuple(terms), tuple(results), tuple(marks))


__all__ = ["forces_lesson"]
