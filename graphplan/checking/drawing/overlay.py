"""The overlay: graphplan's construction drawn over the student's plans.

One SVG of the whole sheet and one close-up of every plan with a wrong finding (force
plans too: graphplan's force from the student's start, the wrong ones in red; schemes of
a position: the exact position from the student's pivot, a joint off its place in red): the
student's lines in their own colour, graphplan's construction of the plan's position at
the student's scale (pole laid on the student's pole) in blue, and in red each segment
whose length or direction is wrong, with the measured and the expected length
(``pb: 40,12 ≠ 42,19 мм``) and a ring where the construction puts the point.
"""

from __future__ import annotations

import html

import numpy as np

from ..words import num
from .judge_forces import force_vector

BLUE = "#00a060"  # graphplan's construction: a green no CAD layer colour is by default
RED = "#d01010"


def _e(s: str) -> str:
    return html.escape(str(s), quote=True)


def drawing_overlay(dc, lang: str | None = None) -> list[str]:
    """The overlay sheets (SVG texts) of a :class:`~.check.DrawingCheck`."""
    lang = lang or dc.report.lang
    d = dc.drawing
    x0, y0, x1, y1 = d.bounds()
    H = y1 + y0  # y is flipped about the middle of the drawing's extent

    def P(x: float, y: float) -> str:
        return f"{x:.2f},{H - y:.2f}"

    body = []
    for s in d.segments:
        body.append(f"<line x1='{s.x1:.2f}' y1='{H - s.y1:.2f}' x2='{s.x2:.2f}' "
                    f"y2='{H - s.y2:.2f}' stroke='{_e(s.colour)}' stroke-width='0.18'/>")
    for f in d.fills:
        body.append("<polygon points='" + " ".join(P(x, y) for x, y in f.points) +
                    f"' fill='{_e(f.colour)}' stroke='none'/>")
    for t in d.texts:
        if len(t.text) > 40:
            continue
        body.append(f"<text x='{t.x:.2f}' y='{H - t.y + 0.35 * t.height:.2f}' "
                    f"font-size='{t.height * 1.3:.2f}' text-anchor='middle' "
                    f"fill='{_e(t.colour)}' font-family='sans-serif' "
                    f"transform='rotate({-t.angle:.1f} {t.x:.2f} {H - t.y:.2f})'>"
                    f"{_e(t.text)}</text>")
    wrong_fig: dict[str, list] = {}
    for f in dc.report.findings:
        if f.verdict == "wrong":
            wrong_fig.setdefault(f.where, []).append(f)
    crops = []
    for j in dc.plans:
        L = j.laid
        if L is None or L.plan is None or j.found.kind == "force":
            continue
        p0 = np.asarray(L.pole_at)
        plan = L.plan
        for sg in L.segments:
            a = p0 + plan.points[sg.start]
            b = p0 + plan.points[sg.end]
            body.append(f"<line x1='{a[0]:.2f}' y1='{H - a[1]:.2f}' x2='{b[0]:.2f}' "
                        f"y2='{H - b[1]:.2f}' stroke='{BLUE}' stroke-width='0.3' "
                        "stroke-opacity='0.75' stroke-dasharray='1.2,0.6'/>")
        inv = {c: s for s, c in L.match.items()}
        bad = [f for f in dc.report.findings if f.verdict == "wrong" and j.key and
               j.key in f.where]
        names = {f.quantity.lstrip("∠") for f in bad}
        placed: dict[tuple[int, int], int] = {}
        for sg in L.segments:
            if sg.name not in names or sg.start not in inv or sg.end not in inv:
                continue
            a = p0 + L.measured[sg.start]
            b = p0 + L.measured[sg.end]
            ea = p0 + plan.points[sg.start]
            eb = p0 + plan.points[sg.end]
            lm = float(np.hypot(*(b - a)))
            le = float(np.hypot(*(eb - ea)))
            body.append(f"<line x1='{a[0]:.2f}' y1='{H - a[1]:.2f}' x2='{b[0]:.2f}' "
                        f"y2='{H - b[1]:.2f}' stroke='{RED}' stroke-width='0.45'/>")
            body.append(f"<circle cx='{eb[0]:.2f}' cy='{H - eb[1]:.2f}' r='0.9' fill='none' "
                        f"stroke='{RED}' stroke-width='0.25'/>")
            mid = (a + b) / 2
            # labels of lines drawn over each other stand one under another
            key = (round(mid[0]), round(mid[1]))
            mid = mid - np.array([0.0, 2.8 * placed.get(key, 0)])
            placed[key] = placed.get(key, 0) + 1
            unit = "мм" if lang == "ru" else "mm"
            body.append(f"<text x='{mid[0] + 1:.2f}' y='{H - mid[1] - 1:.2f}' font-size='2.2' "
                        f"fill='{RED}' font-family='sans-serif'>{_e(sg.name)}: "
                        f"{_e(num(lm, lang, 4))} ≠ {_e(num(le, lang, 4))} {unit}</text>")
        if any(f.primary for f in bad):
            bx0, by0, bx1, by1 = j.found.bbox
            pts = [p0 + plan.points[c] for c in plan.points]
            bx0 = min([bx0] + [q[0] for q in pts])
            bx1 = max([bx1] + [q[0] for q in pts])
            by0 = min([by0] + [q[1] for q in pts])
            by1 = max([by1] + [q[1] for q in pts])
            m = 12.0
            crops.append((bx0 - m, H - by1 - m, bx1 - bx0 + 2 * m, by1 - by0 + 2 * m,
                          j.key))
    for j in dc.plans:
        if j.found.kind == "force" and j.pos is not None and j.scale:
            _force_overlay(dc, j, body, crops, H, lang)
        elif j.found.kind == "scheme" and j.found.kl and dc.ref is not None:
            _scheme_overlay(dc, j, body, crops, H, lang)
        elif j.found.kind == "positions" and j.found.kl_used and dc.ref is not None:
            _positions_overlay(dc, j, body, crops, H, lang)
    legend = ("graphplan's construction (green, dashed), wrong segments (red) with the measured ≠ "
              "expected length, rings where the construction puts the point" if lang != "ru"
              else "построение graphplan (зелёным пунктиром), неверные отрезки (красным): "
              "измерено ≠ по построению, кружки — где точка по построению")
    content = "\n".join(body)
    out = [_svg(x0 - 5, H - y1 - 5, x1 - x0 + 10, y1 - y0 + 10, content, legend)]
    for vx, vy, vw, vh, title in crops:
        out.append(_svg(vx, vy, vw, vh, content, title))
    return out


def _force_overlay(dc, j, body: list[str], crops: list, H: float, lang: str) -> None:
    """A force plan: graphplan's force (green, dashed) from where the student's starts,
    and in red each force with a wrong finding, measured ≠ expected."""
    fp = j.found
    ref = dc.ref
    k = list(ref.labels).index(j.pos) if ref is not None and j.pos in ref.labels else None
    bad = [f for f in dc.report.findings if f.verdict == "wrong" and j.key and
           j.key in f.where]
    expected = {f.quantity[:-3]: f.expected for f in bad
                if f.quantity.endswith("_mm") and f.expected is not None}
    names = {f.quantity.lstrip("∠").removesuffix("_mm") for f in bad}
    unit = "мм" if lang == "ru" else "mm"
    for name, f in fp.forces.items():
        a = np.asarray(f.start, float)
        b = np.asarray(f.end, float)
        line = force_vector(ref, name, k) if k is not None else None
        if line is not None and float(np.hypot(*line)) > 0:
            vec = np.asarray(line, float) / float(j.scale)
            d = b - a
            if not f.sense and float(np.dot(vec, d)) < 0:
                vec = -vec  # the line's direction only: laid along the student's
            e = a + vec
            body.append(f"<line x1='{a[0]:.2f}' y1='{H - a[1]:.2f}' x2='{e[0]:.2f}' "
                        f"y2='{H - e[1]:.2f}' stroke='{BLUE}' stroke-width='0.3' "
                        "stroke-opacity='0.75' stroke-dasharray='1.2,0.6'/>")
        if name not in names:
            continue
        body.append(f"<line x1='{a[0]:.2f}' y1='{H - a[1]:.2f}' x2='{b[0]:.2f}' "
                    f"y2='{H - b[1]:.2f}' stroke='{RED}' stroke-width='0.45'/>")
        mid = (a + b) / 2
        text = f"{name}: {num(f.length, lang, 4)}"
        if name in expected:
            text += f" ≠ {num(expected[name], lang, 4)}"
        body.append(f"<text x='{mid[0] + 1:.2f}' y='{H - mid[1] - 1:.2f}' font-size='2.2' "
                    f"fill='{RED}' font-family='sans-serif'>{_e(text)} {unit}</text>")
    if any(f.primary for f in bad):
        bx0, by0, bx1, by1 = fp.bbox
        m = 12.0
        crops.append((bx0 - m, H - by1 - m, bx1 - bx0 + 2 * m, by1 - by0 + 2 * m, j.key))


def _scheme_overlay(dc, j, body: list[str], crops: list, H: float, lang: str) -> None:
    """A scheme of a position: the exact position at the scheme's Kl laid from the
    student's pivot (green, dashed: the links, a ring at each joint), and in red each
    joint off its place (a line from where it is drawn to the exact place, the distance)
    and each link drawn at another length (measured ≠ expected)."""
    sc = j.found
    ref = dc.ref
    P = ref.kin.pos.points
    pivot = ref.mech.crank.pivot
    o = np.asarray(sc.pivot, float)
    unit = "мм" if lang == "ru" else "mm"

    def exact(pos: str, name: str) -> np.ndarray:
        k = ref.index(pos)
        return o + (np.asarray(P[name][k]) - np.asarray(P[pivot][k])) / sc.kl

    def line(a, b, colour: str, width: float, dash: bool) -> None:
        _line(body, H, a, b, colour, width, dash)

    def label(at, text: str) -> None:
        _label(body, H, at, text)

    for (pos, link) in sc.links:
        if pos in ref.labels:
            a, b = link.split("|")
            line(exact(pos, a), exact(pos, b), BLUE, 0.3, True)
    for (pos, name) in sc.joints:
        if pos in ref.labels:
            e = exact(pos, name)
            body.append(f"<circle cx='{e[0]:.2f}' cy='{H - e[1]:.2f}' r='0.9' fill='none' "
                        f"stroke='{BLUE}' stroke-width='0.25'/>")
    bad = [f for f in dc.report.findings if f.verdict == "wrong" and j.key and
           j.key in f.where]
    for f in bad:
        if f.position not in ref.labels:
            continue
        if f.kind == "point" and (f.position, f.quantity[1:]) in sc.joints:
            name = f.quantity[1:]
            m = np.asarray(sc.joints[(f.position, name)], float)
            e = exact(f.position, name)
            line(m, e, RED, 0.45, False)
            body.append(f"<circle cx='{e[0]:.2f}' cy='{H - e[1]:.2f}' r='0.9' fill='none' "
                        f"stroke='{RED}' stroke-width='0.25'/>")
            label(m, f"{name}: {num(float(f.stated), lang, 3)} {unit}")
        elif f.kind == "model":
            key = next((lk for (p, lk) in sc.links if p == f.position and
                        lk.replace("|", "") == f.quantity), None)
            if key is not None:
                a, b = sc.links[(f.position, key)]
                line(a, b, RED, 0.45, False)
                mid = (np.asarray(a, float) + np.asarray(b, float)) / 2
                label(mid, f"{f.quantity}: {num(float(f.stated), lang, 4)} ≠ "
                      f"{num(float(f.expected), lang, 4)} {unit}")
    if any(f.primary for f in bad):
        bx0, by0, bx1, by1 = sc.bbox
        pad = 15.0
        crops.append((bx0 - pad, H - by1 - pad, bx1 - bx0 + 2 * pad, by1 - by0 + 2 * pad, j.key))


def _positions_overlay(dc, j, body: list[str], crops: list, H: float, lang: str) -> None:
    """A plan of all positions: each numbered position laid exactly from the student's
    pivot at the Kl used (green, dashed: the links, a ring at each joint), and in red each
    joint off its place (from where it is drawn to the exact place, the distance), each
    crank drawn at another angle than its number's (the drawn crank, a ring where its
    number puts the pin, the angle off), a trajectory off its path (the curve in red, the
    exact path dashed, the distance), a Kl, a numbering or a position left out."""
    pl = j.found
    ref = dc.ref
    mech = ref.mech
    o = np.asarray(pl.pivot, float)
    unit = "мм" if lang == "ru" else "mm"

    def line(a, b, colour: str, width: float, dash: bool) -> None:
        _line(body, H, a, b, colour, width, dash)

    def ring(at, colour: str) -> None:
        body.append(f"<circle cx='{at[0]:.2f}' cy='{H - at[1]:.2f}' r='0.9' fill='none' "
                    f"stroke='{colour}' stroke-width='0.25'/>")

    def label(at, text: str) -> None:
        _label(body, H, at, text)

    def exact(lab: str, name: str):
        if name == mech.crank.pivot:
            return o
        e = pl.expected.get((lab, name))
        return None if e is None else np.asarray(e, float)

    for (lab, link) in pl.links:
        a, b = (exact(lab, n) for n in link.split("|"))
        if a is not None and b is not None:
            line(a, b, BLUE, 0.3, True)
    for (lab, name), e in pl.expected.items():
        if (lab, name) in pl.joints or name == mech.crank.pin:
            ring(e, BLUE)
    bad = [f for f in dc.report.findings if f.verdict == "wrong" and j.key and
           j.key in f.where]
    r_exp = float(mech.crank.length) / pl.kl_used
    for f in bad:
        if f.kind == "point" and f.quantity.startswith("⌒"):
            # a trajectory off its path: the exact path dashed, the curves drawn in red
            name = f.quantity[1:]
            path = pl.exact_paths.get(name)
            if path is not None:
                pts = " ".join(f"{x:.2f},{H - y:.2f}" for x, y in path)
                body.append(f"<polyline points='{pts}' fill='none' stroke='{BLUE}' "
                            "stroke-width='0.3' stroke-dasharray='1.2,0.6'/>")
            for drawn in (p for p in pl.paths if p.point == name):
                pts = " ".join(f"{x:.2f},{H - y:.2f}" for x, y in drawn.points)
                body.append(f"<polyline points='{pts}' fill='none' stroke='{RED}' "
                            "stroke-width='0.45'/>")
                label(drawn.points[len(drawn.points) // 2],
                      f"⌒{name}: {num(float(f.stated), lang, 3)} {unit}")
        elif f.kind == "point" and (f.position, f.quantity[1:]) in pl.joints:
            name = f.quantity[1:]
            m = np.asarray(pl.joints[(f.position, name)], float)
            e = exact(f.position, name)
            if e is not None:
                line(m, e, RED, 0.45, False)
                ring(e, RED)
                label(m, f"{name}{f.position}: {num(float(f.stated), lang, 3)} {unit}")
        elif f.kind in ("extreme", "other-variant") and f.position in pl.pins:
            k = ref.index(f.position)
            phi = float(ref.kin.phi[k])
            m = np.asarray(pl.pins[f.position], float)
            e = o + r_exp * np.array([np.cos(phi), np.sin(phi)])
            line(o, m, RED, 0.45, False)
            line(o, e, BLUE, 0.3, True)
            ring(e, RED)
            label(m, f"φ{f.position}: {'+' if float(f.stated) > 0 else ''}"
                     f"{num(float(f.stated), lang, 3)}°")
        elif f.kind in ("scale", "label", "extreme", "missing"):
            label(o + np.array([3.0, -4.0 - 3.0 * bad.index(f)]),
                  f"{f.quantity}: {f.explanation.split(':')[0]}")
    if any(f.primary for f in bad):
        bx0, by0, bx1, by1 = pl.bbox
        pad = 15.0
        crops.append((bx0 - pad, H - by1 - pad, bx1 - bx0 + 2 * pad, by1 - by0 + 2 * pad, j.key))


def _line(body: list[str], H: float, a, b, colour: str, width: float, dash: bool) -> None:
    body.append(f"<line x1='{a[0]:.2f}' y1='{H - a[1]:.2f}' x2='{b[0]:.2f}' "
                f"y2='{H - b[1]:.2f}' stroke='{colour}' stroke-width='{width}'" +
                (" stroke-opacity='0.75' stroke-dasharray='1.2,0.6'/>" if dash else "/>"))


def _label(body: list[str], H: float, at, text: str) -> None:
    body.append(f"<text x='{at[0] + 1:.2f}' y='{H - at[1] - 1:.2f}' font-size='2.2' "
                f"fill='{RED}' font-family='sans-serif'>{_e(text)}</text>")


def _svg(x: float, y: float, w: float, h: float, content: str, title: str) -> str:
    w, h = max(w, 1.0), max(h, 1.0)
    width = 800 if w >= h else max(300, int(800 * w / h))
    return (f"<svg xmlns='http://www.w3.org/2000/svg' viewBox='{x:.2f} {y:.2f} {w:.2f} "
            f"{h:.2f}' width='{width}' height='{int(width * h / w)}'>"
            f"<title>{_e(title)}</title><rect x='{x:.2f}' y='{y:.2f}' width='{w:.2f}' "
            f"height='{h:.2f}' fill='white'/>{content}</svg>\n")


__all__ = ["drawing_overlay"]
