"""Figures of sheet 3 drawn with matplotlib (imported lazily), at their scales.

Every construction figure is drawn in millimetres of the sheet: the data of an axes box
are drawing mm (``x = τ/Kφ``, ``y = Mс/KM``, ``y = A/KA``, ``x = I/KI`` …) and the box is
exactly as many mm wide and tall as its data span, so the figure placed on the sheet at
its size (:class:`graphplan.sheet.Figure`) reads back at the printed scales:

* :func:`work_svg` — Mс(φ) with the mean ordinates of the intervals, the pole P at H mm
  and its rays; Aс(φ) by chords parallel to the rays, and Aд(φ); ΔT(φ) = Aд + Aс; the
  exact curves thin, the graphical ones main;
* :func:`energy_mass_svg` — Wittenbauer's diagram ΔT(Iп) with the tangents at ψmax and
  ψmin, the points k, l they cut on the ΔT axis and the segment kl; below it Iп(φ)
  turned 90° (φ downwards), at the same KI;
* :func:`omega_svg` — the check: ω(φ) of the steady motion with the flywheel, ωmax,
  ωmin, ωср and δ (an ordinary plot, not a construction).

Each function returns ``(svg_text, width_mm, height_mm)``.
"""

from __future__ import annotations

import io
import math

import numpy as np

from ..units import fmt
from .figures import HASH_SALT, MM, _font

THIN, MAIN = 0.25, 0.5  #: line widths, mm
TEXT_H, SMALL_H = 3.5, 2.5
PAD = 6.0  #: room around an axes box for letters, mm
WORDS = {
    "ru": {"J": "Дж", "Nm": "Н·м", "mm": "мм", "rad": "рад", "kgm2": "кг·м²", "s": "с",
           "flat": "ψ < 20°: kl по отрезкам на оси ΔT",
           "omega": "Проверка: ω(φ) с маховиком", "target": "цель"},
    "en": {"J": "J", "Nm": "N·m", "mm": "mm", "rad": "rad", "kgm2": "kg·m²", "s": "s",
           "flat": "ψ < 20°: kl from the intercepts",
           "omega": "Check: ω(φ) with the flywheel", "target": "target"},
}


def _rc():
    return {"svg.fonttype": "path", "svg.hashsalt": HASH_SALT, "axes.unicode_minus": False,
            "lines.solid_capstyle": "round", "lines.solid_joinstyle": "round"}


def _box(fig, W, H, x0, y0, w, h, xlim, ylim):
    """An axes box at (x0, y0) mm from the figure's bottom-left, w×h mm, data in mm."""
    ax = fig.add_axes((x0 / W, y0 / H, w / W, h / H))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_axis_off()
    ax.patch.set_visible(False)
    return ax


def _axis_lines(ax, xlo, xhi, ylo, yhi, xlabel, ylabel):
    """The two axes of a diagram with arrows and their letters (mm data)."""
    ax.plot([xlo, xhi], [0, 0], "-k", lw=THIN * MM)
    ax.plot([0, 0], [ylo, yhi], "-k", lw=THIN * MM)
    arrow = {"clip_on": False, "color": "black", "markersize": 2.2 * MM, "lw": 0}
    ax.plot([xhi], [0], ">", **arrow)
    ax.plot([0], [yhi], "^", **arrow)
    ax.text(xhi + 1.0, 1.0, xlabel, ha="left", va="bottom", **_font(xlabel, TEXT_H))
    ax.text(2.0, yhi, ylabel, ha="left", va="center", **_font(ylabel, TEXT_H))


def _ticks(ax, xs, labels, below: float = 0.0):
    for x, lab in zip(xs, labels, strict=True):
        ax.plot([x, x], [-1.0, 1.0], "-k", lw=THIN * MM)
        if lab:
            ax.text(x, below - 1.5, lab, ha="center", va="top", **_font(lab, SMALL_H))


def _save(fig) -> str:
    buf = io.StringIO()
    fig.savefig(buf, format="svg", metadata={"Date": None})
    return buf.getvalue()


def work_svg(unit, lang: str = "ru") -> tuple[str, float, float]:
    """Mс(φ), Aс(φ) and Aд(φ), ΔT(φ) by graphical integration, at Kφ, KM, KA = KT."""
    import matplotlib
    from matplotlib.figure import Figure

    w = WORDS[lang]
    wd, m = unit.flywheel.work, unit.model
    L, H, Kphi, KM, KA = wd.length_mm, wd.H, wd.Kphi, wd.KM, wd.KA
    x_tau = m.tau / Kphi
    xn = wd.node_tau / Kphi
    y_M = m.moment.M / KM
    yMd = wd.M_d / KM
    panels = []
    lo, hi = min(y_M.min(), wd.yM_mm.min(), 0.0), max(y_M.max(), yMd, 0.0)
    panels.append(("M", lo, hi))
    yA, yAd = wd.A_c / KA, wd.A_d / KA
    panels.append(("A", min(yA.min(), wd.yA_mm.min(), 0.0), max(yAd.max(), 0.0)))
    yT = wd.dT / KA
    panels.append(("T", min(yT.min(), (wd.dT_graph / KA).min(), 0.0),
                   max(yT.max(), (wd.dT_graph / KA).max(), 0.0)))
    xlo, xhi = -H - 10.0, L + 14.0
    box_w = xhi - xlo
    heights = [(hi - lo) + 2 * PAD + 4.0 for _, lo, hi in panels]
    W = box_w + 2 * PAD
    Hfig = sum(heights) + 10.0
    pos_x = m.moment.pos_tau / Kphi
    with matplotlib.rc_context(_rc()):
        fig = Figure(figsize=(W / 25.4, Hfig / 25.4))
        top = Hfig - 6.0
        title = f"Kφ = 2π/L = 2π/{fmt(L)} = {fmt(Kphi, 4)} {w['rad']}/{w['mm']}"
        fig.text(PAD / W, 1 - 1.0 / Hfig, title, ha="left", va="top", **_font(title, SMALL_H))
        for (kind, lo, hi), h in zip(panels, heights, strict=True):
            top -= h
            ylo, yhi = lo - PAD - 2.0, hi + PAD + 2.0
            ax = _box(fig, W, Hfig, PAD, top, box_w, h, (xlo, xhi), (ylo, yhi))
            if kind == "M":
                _axis_lines(ax, -H - 4.0, L + 6.0, lo - 2.0, hi + PAD - 1.0, "φ",
                            f"Mс, Mд, {w['Nm']}")
                ax.plot(x_tau, y_M, "-k", lw=THIN * MM)
                ax.stairs(wd.yM_mm, xn, color="black", lw=MAIN * MM, baseline=None)
                ax.plot([0, L], [yMd, yMd], "--k", lw=THIN * MM)
                ax.text(L - 2.0, yMd + 1.0, "Mд", ha="right", va="bottom", **_font("Mд", TEXT_H))
                for y in wd.yM_mm:  # the rays of the pole to the projected mean ordinates
                    ax.plot([-H, 0.0], [0.0, y], "-", color="0.45", lw=0.7 * THIN * MM)
                ax.plot([-H], [0.0], "o", color="black", markersize=1.2 * MM)
                ax.text(-H, 1.5, "P", ha="center", va="bottom", **_font("P", TEXT_H))
                s = (f"KM = {fmt(KM, 4)} {w['Nm']}/{w['mm']},  H = {fmt(H)} {w['mm']}")
                ax.text(L * 0.35, hi + PAD - 1.0, s, ha="left", va="center",
                        **_font(s, SMALL_H))
                _ticks(ax, xn, [""] * len(xn))
            elif kind == "A":
                _axis_lines(ax, -4.0, L + 6.0, lo - 2.0, hi + PAD - 1.0, "φ",
                            f"Aс, Aд, {w['J']}")
                ax.plot(x_tau, yA, "-k", lw=THIN * MM)
                ax.plot(x_tau, yAd, "-k", lw=THIN * MM)
                ax.plot(xn, wd.yA_mm, "-ok", lw=MAIN * MM, markersize=1.0 * MM)
                ax.plot([0, L], [0, -wd.yA_mm[-1]], "-k", lw=MAIN * MM)
                ax.text(L + 1.0, -wd.yA_mm[-1], "Aд", ha="left", va="center",
                        **_font("Aд", TEXT_H))
                ax.text(L + 1.0, wd.yA_mm[-1], "Aс", ha="left", va="center",
                        **_font("Aс", TEXT_H))
                s = (f"KA = Kφ·KM·H = {fmt(KA, 4)} {w['J']}/{w['mm']}")
                ax.text(L * 0.35, hi + PAD - 1.0, s, ha="left", va="center",
                        **_font(s, SMALL_H))
                _ticks(ax, xn, [""] * len(xn))
            else:
                _axis_lines(ax, -4.0, L + 6.0, lo - 2.0, hi + PAD - 1.0, "φ",
                            f"ΔT, {w['J']}")
                ax.plot(x_tau, yT, "-k", lw=THIN * MM)
                ax.plot(xn, wd.dT_graph / KA, "-ok", lw=MAIN * MM, markersize=1.0 * MM)
                s = f"KT = KA = {fmt(KA, 4)} {w['J']}/{w['mm']}"
                ax.text(L * 0.35, hi + PAD - 1.0, s, ha="left", va="center",
                        **_font(s, SMALL_H))
                _ticks(ax, pos_x, list(m.moment.labels), below=min(lo, 0.0))
        return _save(fig), W, Hfig


def energy_mass_svg(unit, lang: str = "ru", phi_len: float = 100.0
                    ) -> tuple[str, float, float]:
    """Wittenbauer's diagram ΔT(Iп) with its tangents; Iп(φ) turned 90° below it."""
    import matplotlib
    from matplotlib.figure import Figure

    w = WORDS[lang]
    fw, m = unit.flywheel, unit.model
    KI, KT = fw.KI, fw.KT
    xI = m.inertia.I_var / KI
    yT = fw.work.dT / KT
    xmax = float(xI.max()) + 25.0
    ylo = min(float(yT.min()), fw.l_mm, 0.0)
    yhi = max(float(yT.max()), fw.k_mm, 0.0)
    h1 = yhi - ylo + 2 * PAD + 14.0
    Kphi2 = 2 * math.pi / phi_len
    h2 = phi_len + 2 * PAD
    box_w = max(xmax + 30.0, 75.0)
    W, Hfig = box_w + 2 * PAD, h1 + h2 + 12.0
    pos_I = np.interp(m.moment.pos_tau, m.tau, m.inertia.I_var) / KI
    pos_T = np.interp(m.moment.pos_tau, m.tau, fw.work.dT) / KT
    with matplotlib.rc_context(_rc()):
        fig = Figure(figsize=(W / 25.4, Hfig / 25.4))
        ax = _box(fig, W, Hfig, PAD, h2 + 6.0, box_w, h1, (-20.0, box_w - 20.0),
                  (ylo - PAD - 3.0, yhi + PAD + 11.0))
        _axis_lines(ax, -4.0, xmax, ylo - 3.0, yhi + PAD, "Iп", f"ΔT, {w['J']}")
        ax.plot(xI, yT, "-k", lw=MAIN * MM)
        ax.plot(pos_I, pos_T, "o", color="black", markersize=1.0 * MM)
        for x, y, lab in zip(pos_I, pos_T, m.moment.labels, strict=True):
            ax.text(x + 1.0, y + 1.0, lab, ha="left", va="bottom", **_font(lab, SMALL_H))
        xs = np.array([0.0, xmax])
        ax.plot(xs, fw.k_mm + fw.tan_max * xs, "-k", lw=THIN * MM)
        ax.plot(xs, fw.l_mm + fw.tan_min * xs, "-k", lw=THIN * MM)
        for y, name in ((fw.k_mm, "k"), (fw.l_mm, "l")):
            ax.plot([0.0], [y], "o", color="black", markersize=1.2 * MM)
            ax.text(-1.5, y, name, ha="right", va="center", **_font(name, TEXT_H))
        ax.annotate("", xy=(-8.0, fw.k_mm), xytext=(-8.0, fw.l_mm),
                    arrowprops={"arrowstyle": "<->", "lw": THIN * MM, "shrinkA": 0,
                                "shrinkB": 0})
        kl = f"kl = {fmt(fw.segment_mm, 4)} {w['mm']}"
        ax.text(-9.5, 0.5 * (fw.k_mm + fw.l_mm), kl, ha="right", va="center", rotation=90,
                **_font(kl, SMALL_H))
        psi = f"ψmax = {fw.psi_max:.2f}°, ψmin = {fw.psi_min:.2f}°"
        ks = f"KI = {fmt(KI, 4)} {w['kgm2']}/{w['mm']}, KT = {fmt(KT, 4)} {w['J']}/{w['mm']}"
        ax.text(-18.0, yhi + PAD + 6.5, psi, ha="left", va="bottom", **_font(psi, SMALL_H))
        ax.text(-18.0, yhi + PAD + 2.5, ks, ha="left", va="bottom", **_font(ks, SMALL_H))
        if fw.tangents_flat:
            ax.text(2.0, ylo - PAD, w["flat"], ha="left", va="top",
                    **_font(w["flat"], SMALL_H))
        ax2 = _box(fig, W, Hfig, PAD, 4.0, box_w, h2, (-20.0, box_w - 20.0),
                   (-phi_len - PAD, PAD))
        ax2.plot([-4.0, xmax], [0, 0], "-k", lw=THIN * MM)
        ax2.plot([0, 0], [2.0, -phi_len - 3.0], "-k", lw=THIN * MM)
        ax2.plot([0], [-phi_len - 3.0], "v", clip_on=False, color="black",
                 markersize=2.2 * MM, lw=0)
        ax2.text(1.5, -phi_len - 3.0, "φ", ha="left", va="center", **_font("φ", TEXT_H))
        ax2.plot(xI, -m.tau / Kphi2, "-k", lw=MAIN * MM)
        py = -m.moment.pos_tau / Kphi2
        for x, y, lab in zip(pos_I, py, m.moment.labels, strict=True):
            ax2.plot([0.0, x], [y, y], "-", color="0.45", lw=0.6 * THIN * MM)
            ax2.text(-1.5, y, lab, ha="right", va="center", **_font(lab, SMALL_H))
        cap = (f"Iп(φ), Kφ = {fmt(Kphi2, 4)} {w['rad']}/{w['mm']}")
        ax2.text(xmax * 0.4, -phi_len * 0.5, cap, ha="left", va="center",
                 **_font(cap, SMALL_H))
        return _save(fig), W, Hfig


def omega_svg(unit, width_mm: float, height_mm: float, lang: str = "ru") -> str:
    """ω(φ) of the steady motion with Iп + Iрот + Iм and constant Mд (energy form), with
    ωmax, ωmin, ωср and δ."""
    import matplotlib
    from matplotlib.figure import Figure

    w = WORDS[lang]
    s = unit.simulation
    deg = np.degrees(s.tau)
    with matplotlib.rc_context(_rc()):
        fig = Figure(figsize=(width_mm / 25.4, height_mm / 25.4))
        ax = fig.add_axes((22 / width_mm, 12 / height_mm, 1 - 28 / width_mm,
                           1 - 22 / height_mm))
        ax.plot(deg, s.omega, "-k", lw=MAIN * MM)
        for v in (s.omega_max, s.omega_min, s.omega_avg):
            ax.axhline(v, color="0.4", lw=0.6 * THIN * MM)
        ax.set_xlim(0, 360)
        ax.set_xticks(np.degrees(unit.model.moment.pos_tau))
        ax.set_xticklabels(unit.model.moment.labels, **_font("0123456789()", SMALL_H))
        for lab in ax.get_yticklabels():
            lab.set(**_font("0123456789.", SMALL_H))
        ax.tick_params(width=THIN * MM, length=1.5 * MM, labelsize=_font("0", SMALL_H)["fontsize"])
        for sp in ax.spines.values():
            sp.set_linewidth(THIN * MM)
        ax.set_ylabel(f"ω, {w['rad']}/{w['s']}", **_font("ω, рад/с", TEXT_H))
        title = (f"{w['omega']}: δ = {s.delta_actual:.4f} "
                 f"({w['target']} {s.delta_target:g})")
        fig.text(0.5, 1 - 1.5 / height_mm, title, ha="center", va="top", **_font(title, TEXT_H))
        return _save(fig)


__all__ = ["energy_mass_svg", "omega_svg", "work_svg"]
