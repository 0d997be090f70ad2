"""Drawings of the plans made the way students make them, for trying the drawing checker.

:func:`student_sheet` draws the velocity and acceleration plans of some positions of a
variant — not with graphplan's sheet code, but as a CAD user draws: each vector a line
split into pieces or a polyline through several points, arrowheads as INSERTs of a block
holding a SOLID (DXF) or as filled patches (PDF), letters as MTEXT set off diagonally
from their points, captions such as «Положение 2. План скоростей» and scales written
``μv = 0,01 (м/с)/мм`` with a decimal comma, the whole placed far from the origin and,
optionally, in inches. :class:`Plant` puts one error of a student into it: a point
moved, a scale written wrong, a normal component left out (its end unlettered and the
point drawn where the plan goes without it), or the plan of another position under the
caption.

The tests check these drawings with ``graphplan check --drawing``: the correct ones must
give no wrong finding, each planted error its own.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ...plans import acceleration_plan, velocity_plan


@dataclass(frozen=True, slots=True)
class Plant:
    """One error to put into a drawing.

    ``kind``: ``moved`` (the point ``point`` of the plan moved by ``offset`` mm),
    ``scale`` (the plan's scale written ``factor`` times the one it is drawn at),
    ``omit`` (the normal component ending at ``point`` — e.g. ``n_BA`` — left out), or
    ``position`` (the plan of position ``other`` drawn under the caption).
    """

    kind: str
    plan: str  # "velocity" | "acceleration"
    position: str
    point: str = ""
    offset: tuple[float, float] = (2.5, 2.0)
    factor: float = 2.0
    other: str = ""


def _plans(ref, label: str, kl, kv, ka):
    k = ref.index(label)
    vp = velocity_plan(ref.mech, ref.kin, k, kl, kv)
    ap = acceleration_plan(ref.mech, ref.kin, k, kl, ka, vp)
    return vp, ap


def _without_normal(plan, normal: str):
    """The points of an acceleration plan drawn with the normal component ``normal``
    (ending at ``n_XY``) left out: X where the line of its tangential component, drawn
    from the component's start instead, meets the other line through X."""
    pts = {k: np.asarray(v, float).copy() for k, v in plan.points.items()}
    segs = []
    for st in plan.steps:
        for e in st.elements:
            if e.kind == "segment":
                segs.append(e)
    nseg = next(e for e in segs if e.role == "normal" and
                np.allclose(e.end, plan.points[normal]))
    start = np.asarray(nseg.start)
    tseg = next((e for e in segs if e.role == "tangential" and
                 np.allclose(e.start, nseg.end)), None)
    if tseg is None:
        raise ValueError(f"no tangential component after {normal}")
    tip = np.asarray(tseg.end)
    d1 = tip - np.asarray(tseg.start)
    if np.hypot(*d1) < 1e-9:
        raise ValueError("a zero tangential component")
    other = next((e for e in segs if np.allclose(e.end, tip) and e is not tseg and
                  e.role == "tangential"), None) or next(
        e for e in segs if np.allclose(e.end, tip) and e.role == "absolute")
    d2 = tip - np.asarray(other.start)
    A = np.array([d1, -d2]).T
    t = np.linalg.solve(A, tip - start)
    new = start + t[0] * d1
    point = next(k for k, v in plan.points.items() if np.allclose(v, tip))
    moved = pts[point].copy()
    for k, v in plan.points.items():
        if np.allclose(v, moved):
            pts[k] = new
    del pts[normal]
    return pts, [e for e in segs if e is not nseg]


def _layout(ref, labels, plant: Plant | None, scales: float = 1.0):
    """Each plan to draw: (kind, caption label, scale symbol, scale written, points,
    segments, letters) in plan mm, at ``scales`` times graphplan's Kv and Ka."""
    from dataclasses import replace

    sc = ref.sheet1  # with the student's extra positions
    kl = sc.kl
    kv, ka = (replace(k, per_mm=k.per_mm * scales) for k in (sc.kv, sc.ka))
    out = []
    for lab in labels:
        for kind in ("velocity", "acceleration"):
            src = lab
            written = kv.per_mm if kind == "velocity" else ka.per_mm
            if plant and plant.kind == "position" and plant.plan == kind and \
                    plant.position == lab:
                src = plant.other
            vp, ap = _plans(ref, src, kl, kv, ka)
            plan = vp if kind == "velocity" else ap
            pts = {k: np.asarray(v, float) for k, v in plan.points.items()}
            segs = [e for st in plan.steps for e in st.elements if e.kind == "segment"]
            lines = [e for st in plan.steps for e in st.elements if e.kind == "line"]
            if plant and plant.plan == kind and plant.position == lab:
                if plant.kind == "moved":
                    old = pts[plant.point].copy()
                    for k2, v in list(pts.items()):
                        if np.allclose(v, old):
                            pts[k2] = old + np.asarray(plant.offset)
                elif plant.kind == "scale":
                    written *= plant.factor
                elif plant.kind == "omit":
                    pts, segs = _without_normal(plan, plant.point)
                    lines = []
            # segments by their ends' names, on the (possibly changed) points
            names = list(plan.points)

            def at(xy, names=names, plan=plan):
                return min(names, key=lambda n: float(np.hypot(*(np.asarray(xy) -
                                                                 plan.points[n]))))

            seg_names = [(at(e.start), at(e.end)) for e in segs]
            seg_names = [(a, b) for a, b in seg_names if a in pts and b in pts]
            ln = [(np.asarray(e.start), np.asarray(e.end)) for e in lines]
            out.append((kind, lab, "Kv" if kind == "velocity" else "Ka", written, pts,
                        seg_names, ln))
    return out


def _letters(pts: dict, merge: float = 0.3) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """One text per place (names of points closer than ``merge`` mm joined by commas),
    with the direction to set it off in: away from the middle of the plan."""
    groups: list[tuple[list[str], np.ndarray]] = []
    for name, xy in pts.items():
        for g in groups:
            if np.hypot(*(g[1] - xy)) < merge:
                g[0].append(name)
                break
        else:
            groups.append(([name], xy))
    mid = np.mean([xy for _n, xy in groups], axis=0) if groups else np.zeros(2)
    out = []
    for names, xy in groups:
        d = xy - mid
        L = float(np.hypot(*d))
        u = d / L if L > 1e-6 else np.array([0.7071, 0.7071])
        out.append((", ".join(n.replace("_", "") for n in names), xy, u))
    return out


def student_sheet(variant, path: str | Path, labels, fmt: str = "dxf",
                  plant: Plant | None = None, origin=(5000.0, -3000.0),
                  inches: bool = False, leaders: float = 0.0,
                  outlines: bool = False, scales: float = 1.0,
                  units: str = "(м/с)/мм") -> Path:
    """Draw the plans of ``labels`` of a variant as a student's DXF or PDF (module doc).

    ``leaders`` (DXF): every letter set this many mm farther out than usual and joined
    to its point by a thin leader line that stops 1.5 mm short of the point (выноска);
    the pole's letters (with those of every point at the pole) set below the pole, under
    two short direction lines drawn through it. ``outlines`` (PDF): every letter drawn as
    its glyphs' outlines, no text (as a PDF printed from a viewer that turns text into
    curves). ``scales``: the plans drawn at this many times graphplan's Kv and Ka (a CAD
    user's own scales); ``units`` (DXF): the velocity scale's unit as written, ``(м/с)/мм``
    or ``м/(с·мм)`` (the acceleration's alike, ``с²``)."""
    from ..checks import reference_for

    ref = reference_for(Path(variant))
    plans = _layout(ref, labels, plant, scales)
    path = Path(path)
    if fmt == "pdf":
        _pdf(plans, path, outlines)
    else:
        _dxf(plans, path, np.asarray(origin, float), inches, leaders, units)
    return path


def _cells(plans):
    """Where each plan goes (its pole): a grid, velocity plans above acceleration plans,
    the cells as large as the largest plan and 40 mm between plans."""
    xs = [float(v[0]) for p in plans for v in p[4].values()]
    ys = [float(v[1]) for p in plans for v in p[4].values()]
    w = max(xs) - min(xs) + 40.0
    h = max(ys) - min(ys) + 50.0
    for i, p in enumerate(plans):
        col = i // 2
        row = i % 2
        yield p, np.array([20.0 - min(xs) + w * col, 20.0 - min(ys) + h * (1 - row)])


def _dxf(plans, path: Path, origin: np.ndarray, inches: bool, leaders: float = 0.0,
         units: str = "(м/с)/мм") -> None:
    import ezdxf

    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 1 if inches else 4
    k = 1 / 25.4 if inches else 1.0
    blk = doc.blocks.new("ARROWHEAD")
    # a 3 × 1 mm solid, the tip at the block's origin, pointing along +x
    blk.add_solid([(0, 0), (-3 * k, 0.5 * k), (-3 * k, -0.5 * k)])
    doc.layers.add("ПЛАНЫ", color=5)
    doc.layers.add("Построения", color=8)
    msp = doc.modelspace()

    def X(v) -> tuple[float, float]:
        return (float((v[0] + origin[0]) * k), float((v[1] + origin[1]) * k))

    for (kind, lab, _sym, written, pts, segs, lines), c in _cells(plans):
        pole = "p" if kind == "velocity" else "π"
        word = "скоростей" if kind == "velocity" else "ускорений"
        top = max(float(v[1]) for v in pts.values()) + 14.0
        cap = msp.add_mtext(f"Положение {lab}. План {word}",
                            dxfattribs={"char_height": 3.5 * k, "layer": "ПЛАНЫ"})
        cap.set_location(X(c + np.array([-30.0, top])))
        unit = units if kind == "velocity" else units.replace("с)", "с²)").replace(
            "(с·", "(с²·")
        mu = "μv" if kind == "velocity" else "μa"
        msp.add_text(f"{mu} = {written:.4g} {unit}".replace(".", ","),
                     dxfattribs={"height": 2.5 * k, "layer": "ПЛАНЫ"}).set_placement(
            X(c + np.array([-30.0, top - 7.0])))
        for a, b in lines:
            msp.add_line(X(c + a), X(c + b), dxfattribs={"layer": "Построения"})
        chain = []
        for i, (a, b) in enumerate(segs):
            A, B = c + pts[a], c + pts[b]
            L = float(np.hypot(*(B - A)))
            if L < 1e-6:
                continue
            if i % 3 == 0:
                # split in two pieces, as a line broken and joined again
                M = A + 0.4 * (B - A)
                msp.add_line(X(A), X(M), dxfattribs={"layer": "ПЛАНЫ"})
                msp.add_line(X(M), X(B), dxfattribs={"layer": "ПЛАНЫ"})
            elif i % 3 == 1:
                chain.append((A, B))
            else:
                msp.add_lwpolyline([X(A), X(B)], dxfattribs={"layer": "ПЛАНЫ"})
            ang = float(np.degrees(np.arctan2(*(B - A)[::-1])))
            if L > 3.5:
                msp.add_blockref("ARROWHEAD", X(B), dxfattribs={"rotation": ang,
                                                                "layer": "ПЛАНЫ"})
        for A, B in chain:
            msp.add_lwpolyline([X(A), X(A + 0.5 * (B - A)), X(B)],
                               dxfattribs={"layer": "ПЛАНЫ", "color": 1})
        boxes: list[tuple[float, float, float, float]] = []  # texts on leaders so far
        # the plan's lines as points 0.5 mm apart: a letter on a leader is set clear of them
        drawn = [pts[a] + t * (pts[b] - pts[a]) for a, b in segs
                 for t in np.linspace(0.0, 1.0, 2 + int(np.hypot(*(pts[b] - pts[a])) / 0.5))]
        drawn += [a + t * (b - a) for a, b in lines
                  for t in np.linspace(0.0, 1.0, 2 + int(np.hypot(*(b - a)) / 0.5))]
        drawn_xy = np.array(drawn) if drawn else np.zeros((0, 2))
        # on leaders, points closer than 1 mm take one group of letters (one leader)
        for text, xy, out in _letters(pts, 1.0 if leaders else 0.3):
            at_pole = pole in text.split(", ")
            far = 1.5
            # set off outwards from the plan's middle, as a draftsman keeps letters clear
            att = (7 if out[1] >= 0 else 1) if out[0] >= 0 else (9 if out[1] >= 0 else 3)
            if leaders and at_pole:
                out = np.array([0.0, -1.0])  # under the pole, below its direction lines
                for ang in (0.0, 70.0):
                    u = np.array([np.cos(np.radians(ang)), np.sin(np.radians(ang))])
                    msp.add_line(X(c + xy - 8.0 * u), X(c + xy + 8.0 * u),
                                 dxfattribs={"layer": "Построения"})
                far, att = 6.0, 8  # top centre
            elif leaders:
                # the text farther out, its middle on the leader's line, and no text over
                # another where points crowd (the leader made longer)
                hw, hh = 0.35 * 3.0 * len(text), 1.5

                def clear(o, lead, hw=hw, hh=hh, xy=xy, drawn_xy=drawn_xy, boxes=boxes):
                    edge = min(hw / max(abs(float(o[0])), 1e-9),
                               hh / max(abs(float(o[1])), 1e-9))
                    far = 1.0 + lead + 0.7 + edge
                    cx, cy = xy + far * o
                    line = [xy + t * o for t in np.linspace(1.5, 1.0 + lead, 12)]
                    ok = not any((abs(cx - bx) < hw + bw + 0.5 and abs(cy - by) < hh + bh + 0.5)
                                 or any(abs(q[0] - bx) < bw + 0.5 and abs(q[1] - by) < bh + 0.5
                                        for q in line) for bx, by, bw, bh in boxes)
                    ok = ok and not np.any((abs(drawn_xy[:, 0] - cx) < hw + 0.3) &
                                           (abs(drawn_xy[:, 1] - cy) < hh + 0.3))
                    return ok, far, float(cx), float(cy)

                tries = [(turn, leaders + 2.0 * j) for j in range(6)
                         for turn in (0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0)]
                for turn, lead in tries:
                    r = np.radians(turn)
                    o = np.array([out[0] * np.cos(r) - out[1] * np.sin(r),
                                  out[0] * np.sin(r) + out[1] * np.cos(r)])
                    ok, far, cx, cy = clear(o, lead)
                    if ok:
                        break
                if not ok:
                    o, lead = out, leaders
                    _ok, far, cx, cy = clear(o, lead)
                out = o
                boxes.append((float(cx), float(cy), hw, hh))
                att = 5
                # a leader from just off the point out to the text (GOST 2.316)
                msp.add_line(X(c + xy + 1.5 * out), X(c + xy + (1.0 + lead) * out),
                             dxfattribs={"layer": "Построения"})
            m = msp.add_mtext(text, dxfattribs={"char_height": 3.0 * k, "layer": "ПЛАНЫ"})
            m.set_location(X(c + xy + far * out), attachment_point=att)
    doc.saveas(path)


def mpl_page(width: float, height: float):
    """A matplotlib figure of ``width`` × ``height`` mm whose one axes draws in page mm
    (no margin, no axis): the page of a student's PDF. Returns (figure, axes)."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(width / 25.4, height / 25.4))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, width)
    ax.set_ylim(0, height)
    ax.set_axis_off()
    return fig, ax


def _pdf(plans, path: Path, outlines: bool = False) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.patches import Polygon

    with matplotlib.rc_context({"pdf.fonttype": 42, "font.family": "DejaVu Sans"}):
        placed = [c + v for p, c in _cells(plans) for v in p[4].values()]
        # the page: A2 landscape (mm), or larger when the plans need it
        W = max(594.0, max(float(q[0]) for q in placed) + 60.0)
        H = max(420.0, max(float(q[1]) for q in placed) + 40.0)
        fig, ax = mpl_page(W, H)
        pt = 72 / 25.4
        for (kind, lab, sym, written, pts, segs, lines), c in _cells(plans):
            pole = "p" if kind == "velocity" else "π"
            word = "скоростей" if kind == "velocity" else "ускорений"
            top = max(float(v[1]) for v in pts.values()) + 14.0
            x, y = c + np.array([-30.0, top])
            ax.text(x, y, f"План {word}, пол. {lab}",
                    fontsize=3.5 * pt / 0.72)
            unit = "(м/с)/мм" if kind == "velocity" else "(м/с²)/мм"
            x, y = c + np.array([-30.0, top - 7.0])
            ax.text(x, y,
                    f"{sym} = {written:.4g} {unit}".replace(".", ","), fontsize=2.5 * pt / 0.72)
            for a, b in lines:
                ax.plot([c[0] + a[0], c[0] + b[0]], [c[1] + a[1], c[1] + b[1]], "-",
                        color="0.4", lw=0.25 * pt)
            for a, b in segs:
                A, B = c + pts[a], c + pts[b]
                L = float(np.hypot(*(B - A)))
                if L < 1e-6:
                    continue
                u = (B - A) / L
                n = np.array([-u[1], u[0]])
                if L > 3.5:
                    S = B - 3.0 * u
                    ax.plot([A[0], S[0]], [A[1], S[1]], "-", color="k", lw=0.5 * pt)
                    ax.add_patch(Polygon([B, S + 0.5 * n, S - 0.5 * n], closed=True,
                                         facecolor="k", edgecolor="none"))
                else:
                    ax.plot([A[0], B[0]], [A[1], B[1]], "-", color="k", lw=0.5 * pt)
            for text, xy, out in _letters(pts):
                lx, ly = c + xy + 1.5 * out
                ax.text(lx, ly, text, fontsize=3.0 * pt / 0.72,
                        ha="left" if out[0] >= 0 else "right",
                        va="bottom" if out[1] >= 0 else "top")
            del pole
        if outlines:  # the text as its glyphs' paths (SVG), the SVG printed to a PDF
            import io

            import cairosvg

            buf = io.BytesIO()
            with matplotlib.rc_context({"svg.fonttype": "path", "svg.hashsalt": "0"}):
                fig.savefig(buf, format="svg")
            path.write_bytes(cairosvg.svg2pdf(bytestring=buf.getvalue()))
        else:
            with PdfPages(path, metadata={"CreationDate": None}) as pdf:
                pdf.savefig(fig)
        plt.close(fig)


def kompas_like(src: str | Path, dst: str | Path, units: str = "mm") -> Path:
    """The DXF ``src`` (:func:`student_sheet`'s) written again as КОМПАС-3D and older
    AutoCAD write one: ``units="mm"`` gives an R12 file (no ``$INSUNITS``: the header of
    R12 has none) with every polyline a POLYLINE, every MTEXT a TEXT of width factor 0,8
    and oblique angle 15° (ГОСТ 2.304 lettering) aligned as the MTEXT was attached; the
    blocks (the arrowheads' SOLIDs) kept as INSERTs. ``units="cm"``: the same in an R2000
    file whose ``$INSUNITS`` is 5 (centimetres), every coordinate and height in cm."""
    import ezdxf
    from ezdxf.enums import TextEntityAlignment as TA

    old = ezdxf.readfile(str(src))
    # to the new file's units, from the old's (mm, or inches)
    k = (0.1 if units == "cm" else 1.0) * (25.4 if old.header.get("$INSUNITS") == 1 else 1.0)
    doc = ezdxf.new("R2000" if units == "cm" else "R12")
    if units == "cm":
        doc.header["$INSUNITS"] = 5
    for layer in old.layers:
        if layer.dxf.name not in doc.layers:
            doc.layers.add(layer.dxf.name, color=layer.color)
    for blk in old.blocks:
        if blk.name.startswith("*") or blk.name in doc.blocks:
            continue
        new = doc.blocks.new(blk.name)
        for part in blk:
            if part.dxftype() == "SOLID":
                new.add_solid([(v.x * k, v.y * k) for v in
                               (part.dxf.vtx0, part.dxf.vtx1, part.dxf.vtx2, part.dxf.vtx3)])
    align = {1: TA.TOP_LEFT, 2: TA.TOP_CENTER, 3: TA.TOP_RIGHT, 4: TA.MIDDLE_LEFT,
             5: TA.MIDDLE_CENTER, 6: TA.MIDDLE_RIGHT, 7: TA.BOTTOM_LEFT,
             8: TA.BOTTOM_CENTER, 9: TA.BOTTOM_RIGHT}
    msp = doc.modelspace()
    for ent in old.modelspace():
        e: Any = ent
        t = e.dxftype()
        at = {"layer": e.dxf.get("layer", "0")}
        if e.dxf.hasattr("color"):
            at["color"] = e.dxf.color
        if t == "LINE":
            msp.add_line((e.dxf.start.x * k, e.dxf.start.y * k),
                         (e.dxf.end.x * k, e.dxf.end.y * k), dxfattribs=at)
        elif t == "LWPOLYLINE":
            msp.add_polyline2d([(x * k, y * k) for x, y, *_ in e.get_points()],
                               close=e.closed, dxfattribs=at)
        elif t == "INSERT":
            msp.add_blockref(e.dxf.name, (e.dxf.insert.x * k, e.dxf.insert.y * k),
                             dxfattribs={**at, "rotation": e.dxf.get("rotation", 0.0)})
        elif t in ("MTEXT", "TEXT"):
            text = e.plain_text() if t == "MTEXT" else e.dxf.text
            h = (e.dxf.char_height if t == "MTEXT" else e.dxf.height) * k
            how = align.get(e.dxf.get("attachment_point", 1), TA.TOP_LEFT) if t == "MTEXT" \
                else TA.LEFT
            msp.add_text(text, dxfattribs={**at, "height": h, "width": 0.8,
                                           "oblique": 15.0}).set_placement(
                (e.dxf.insert.x * k, e.dxf.insert.y * k), align=how)
    dst = Path(dst)
    doc.saveas(dst)
    return dst


__all__ = ["Plant", "kompas_like", "mpl_page", "student_sheet"]
