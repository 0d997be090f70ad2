"""The two charts of the benchmark (matplotlib), written as SVG and PNG.

* ``bench-speed-accuracy`` — error against time, log–log, one point per method and
  setting on each example: the kinematics (left) and the force analysis (right);
* ``bench-stability`` — the error of each method against the crank angle on the
  four-bar swept toward its toggle, with the bound graphplan states for the drafting and
  the angles where it marks its plans.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

COLOURS = {
    "graphplan analytic": "#1f77b4",
    "graphplan constructions, exact": "#2ca02c",
    "drafting": "#ff7f0e",
    "newton (generic, loop equations)": "#9467bd",
    "pylinkage step_with_derivatives": "#d62728",
    "pylinkage step_fast_with_kinematics (numba)": "#8c1c13",
}
MARKERS = {"press": "o", "fourbar": "s", "shaper": "^"}
FLOOR = 1e-17
"""Errors below this (exact zeros) are drawn at it."""



#: Vertical offsets (points) of the names of the drafting precisions on the chart.
LABEL_DY = {0.1: -13.0, 0.25: -4.5, 0.5: 4.5, 1.0: 13.0}

def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update({"font.size": 9, "svg.fonttype": "none", "svg.hashsalt": "graphplan"})
    return plt


def _colour(name: str) -> str:
    return COLOURS["drafting"] if name.startswith("drafting") else COLOURS.get(name, "#7f7f7f")


def _save(fig, folder: Path, stem: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    svg = folder / f"{stem}.svg"
    fig.savefig(svg, metadata={"Date": None})
    fig.savefig(folder / f"{stem}.png", dpi=110)
    return svg


def speed_accuracy_chart(results: dict, folder: Path) -> Path:
    """Error against time of a whole turn (360 positions), log–log."""
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), constrained_layout=True)
    panels = (("kinematics_cycle", "accelerations", "Kinematics (accelerations)"),
              ("full_cycle", "M_bal", "Kinematics + kinetostatics (Mур)"))
    seen = set()
    n = None
    for ax, (tkey, ekey, title) in zip(axes, panels, strict=True):
        for mname, m in results["mechanisms"].items():
            n = m["positions"]
            scale = 360.0 / n  # the charts are per turn of 360 positions
            for meth, e in m["methods"].items():
                t = e.get("time", {}).get(tkey, {}).get("median_s")
                err = e.get("errors", {}).get(ekey)
                if t is None or err is None:
                    continue
                label = "drafting (0.1–1 mm, scale ×0.5–2)" if meth.startswith("drafting") \
                    else meth
                size = 30 if not meth.startswith("drafting") else 12 + 10 * e["magnify"]
                ax.scatter(t * 1e3 * scale, max(err, FLOOR), s=size, marker=MARKERS.get(mname, "o"),
                           color=_colour(meth), edgecolors="black", linewidths=0.4, zorder=3,
                           label=label if (label, ax) not in seen else None)
                seen.add((label, ax))
                if meth.startswith("drafting") and e["magnify"] == 1.0 and mname == "press":
                    # the four precisions lie close together: their names fan out
                    dy = LABEL_DY.get(e["precision_mm"], 0.0)
                    ax.annotate(f"{e['precision_mm']:g} mm", (t * 1e3 * scale, err), fontsize=6,
                                xytext=(-38, dy), textcoords="offset points", va="center",
                                ha="right", color="#a04000",
                                arrowprops={"arrowstyle": "-", "color": "#a04000", "lw": 0.4})
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("time of one turn, 360 positions, ms (median)")
        ax.set_ylabel("relative error against the 50-digit reference")
        ax.set_title(title)
        ax.grid(True, which="major", alpha=0.3)
        ax.axhline(1e-9, color="grey", ls=":", lw=0.8)
        ax.text(0.01, 1.4e-9, "1e-9 (the target of the exact mode)", fontsize=7, color="grey",
                transform=ax.get_yaxis_transform())
    axes[1].axvline(1.0, color="grey", ls="--", lw=0.8)
    axes[1].text(1.05, 0.02, "1 ms (target, press)", fontsize=7, color="grey",
                 transform=axes[1].get_xaxis_transform())
    handles, labels = [], []
    for ax in axes:
        h, lab = ax.get_legend_handles_labels()
        for hh, ll in zip(h, lab, strict=True):
            if ll not in labels:
                handles.append(hh)
                labels.append(ll)
    for mname, mk in MARKERS.items():
        if mname in results["mechanisms"]:
            handles.append(plt.Line2D([], [], marker=mk, ls="", color="white",
                                      markeredgecolor="black"))
            labels.append(mname)
    fig.legend(handles, labels, loc="outside lower center", ncol=4, fontsize=8, frameon=False)
    fig.suptitle(f"graphplan against its peers, same process and run ({n} positions per turn, "
                 "times scaled to 360)", fontsize=10)
    path = _save(fig, folder, "bench-speed-accuracy")
    plt.close(fig)
    return path


def stability_chart(results: dict, folder: Path) -> Path:
    """Error against crank angle near the toggle of a four-bar, every method."""
    plt = _pyplot()
    st = results["stability"]
    phi = np.asarray(st["phi_deg"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), constrained_layout=True)
    b = st["bound"]
    bphi = np.asarray(b["phi_deg"])
    marked = np.asarray(b["marked"], bool)
    for ax, key, title in ((axes[0], "velocities", "Velocities of every point"),
                           (axes[1], "M_bal", "Balancing moment Mур")):
        for name, e in st["methods"].items():
            if key not in e:
                continue
            y = np.maximum(np.asarray(e[key], float), FLOOR)
            ax.plot(phi, y, lw=1.0, color=_colour(name), label=name)
        ax.plot(bphi, np.maximum(np.asarray(b[key]), FLOOR), ls="--", lw=1.0,
                color=COLOURS["drafting"], label="bound stated for the drafting")
        step = float(np.median(np.diff(bphi))) if len(bphi) > 1 else 1.0
        for x in bphi[marked]:
            ax.axvspan(x - step / 2, x + step / 2, color="#ffd8b0", alpha=0.6, lw=0)
        ax.set_yscale("log")
        ax.set_xlim(0, 360)
        ax.set_xlabel("crank angle φ, °")
        ax.set_ylabel("error / largest value of the turn")
        ax.set_title(title)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, loc="lower left")
    k = int(np.argmin(b["min_angle_deg"]))
    fig.suptitle(f"Four-bar near its toggle (frame 549.8 mm): the lines of the plans meet at "
                 f"{min(b['min_angle_deg']):.1f}° at φ = {bphi[k]:.0f}°; shaded: plans marked "
                 "ill-conditioned", fontsize=10)
    path = _save(fig, folder, "bench-stability")
    plt.close(fig)
    return path


SWEEP_STYLE = {
    "graphplan full cycle": ("#1f77b4", "-", "o"),
    "graphplan full cycle, general objects": ("#9467bd", "-", "D"),
    "graphplan kinematics": ("#1f77b4", "--", "o"),
    "closed form: full cycle": ("#2ca02c", "-", "s"),
    "closed form: kinematics": ("#2ca02c", "--", "s"),
    "pylinkage numba (kinematics)": ("#8c1c13", "--", "^"),
    "pylinkage default (kinematics)": ("#d62728", "--", "v"),
}


def _sweep_axes(ax, ylabel: str, title: str, legend: str) -> None:
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("positions per turn N")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, loc=legend)


def sweep_chart(results: dict, folder: Path) -> Path:
    """Time per turn against the number of positions N, every method (left); the full
    cycle's time over each other method's (right: below 1 graphplan is faster)."""
    plt = _pyplot()
    sw = results["sweep"]
    sizes = np.asarray(sw["sizes"], float)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    ax = axes[0]
    for name, ts in sw["median_s"].items():
        pts = [(n, t) for n, t in zip(sizes, ts, strict=True) if t is not None]
        if not pts:
            continue
        colour, ls, mk = SWEEP_STYLE.get(name, ("#7f7f7f", "-", "o"))
        ax.plot(*zip(*[(n, t * 1e3) for n, t in pts], strict=True), ls=ls, marker=mk,
                color=colour, lw=1.2, ms=4, label=name)
    _sweep_axes(ax, "time of one turn, ms (median)",
                "Every method at every N (solid: with the forces)", "upper left")
    ax = axes[1]
    full = sw["median_s"]["graphplan full cycle"]
    for name in ("closed form: full cycle", "pylinkage numba (kinematics)",
                 "pylinkage default (kinematics)"):
        ts = sw["median_s"].get(name) or []
        pts = [(n, f / t) for n, f, t in zip(sizes, full, ts, strict=False)
               if f is not None and t is not None]
        if not pts:
            continue
        colour, _, mk = SWEEP_STYLE[name]
        ax.plot(*zip(*pts, strict=True), marker=mk, color=colour, lw=1.2, ms=4,
                label=f"graphplan full cycle / {name}")
    ax.axhline(1.0, color="grey", lw=0.8)
    ax.axhline(1 / 20, color="#d62728", ls=":", lw=0.8)
    ax.text(sizes[0], 1 / 20 * 1.15, "target against the default path: 1/20", fontsize=7,
            color="#d62728")
    ax.axhline(4.0, color="#2ca02c", ls=":", lw=0.8)
    ax.text(sizes[0], 4.0 * 1.15, "target against the closed form at N = 360: 4", fontsize=7,
            color="#2ca02c")
    _sweep_axes(ax, "time ratio (below 1: graphplan faster)",
                "graphplan's full cycle against the others", "best")
    env = results.get("environment", {})
    fig.suptitle(f"The N sweep on the press ({env.get('cpus', '?')} CPUs, "
                 f"{env.get('machine', '')}; same process, methods in turns)", fontsize=10)
    path = _save(fig, folder, "bench-sweep")
    plt.close(fig)
    return path


__all__ = ["speed_accuracy_chart", "stability_chart", "sweep_chart"]
