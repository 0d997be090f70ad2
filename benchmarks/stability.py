"""Where the methods fail: a four-bar swept toward its toggle, the press at its dead centres.

The variant ``fourbar-toggle`` is the example four-bar with the frame lengthened from
400 to 549.8 mm, so that ``d + a = 649.8`` mm comes within 0.2 mm of ``b + c = 650`` mm:
once a turn the coupler and the rocker are nearly collinear, the two lines of the
velocity plan (⟂ AB, ⟂ CB) and the closing lines of the force plan (∥ AB, ∥ CB) meet at
about 2°. Every method is run over the turn and its error is measured against the
50-digit reference at every crank angle; the drafting emulation also gets the bound
:mod:`graphplan.plans.conditioning` states, and the positions where it marks its plans.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from . import methods as M
from . import newton
from . import reference as R

ROOT = Path(__file__).resolve().parent.parent
TOGGLE_FRAME_MM = 549.8


def fourbar_toggle():
    """The example four-bar with its frame at :data:`TOGGLE_FRAME_MM` (a near-toggle)."""
    import graphplan as g

    text = (ROOT / "examples" / "fourbar.toml").read_text(encoding="utf-8")
    text, n = re.subn(r"C = \[400, 0\]", f"C = [{TOGGLE_FRAME_MM}, 0]", text)
    assert n == 1, "examples/fourbar.toml changed: the frame point C is not where expected"
    text = text.replace('name = "fourbar"', 'name = "fourbar-toggle"')
    return g.loads(text, source="fourbar-toggle.toml")


def sweep(mech, phi, precision: float = 0.5, bound_every: int = 3, pylinkage=None):
    """Per crank angle, the error of every method (relative to the cycle's largest value).

    Returns a dict: ``phi_deg``; per method ``{"velocities": [...], "M_bal": [...]}``;
    ``bound`` (the drafting's stated bounds, at every ``bound_every``-th angle) and
    ``marked`` (where its plans are marked), and the smallest intersection angle.
    """
    import graphplan as g
    from graphplan.plans import force_conditioning, kinematic_conditioning

    cycle = g.analyse_cycle(mech)
    ref = M.reference_arrays(R.reference(mech, phi, cycle.dead_centres))
    out: dict = {"phi_deg": np.degrees(phi).tolist(), "methods": {}}

    def record(name, res):
        entry = {"velocities": M.errors_per_position(res, ref, "velocities").tolist()}
        if res.M_bal is not None:
            entry["M_bal"] = M.errors_per_position(res, ref, "M_bal").tolist()
        out["methods"][name] = entry

    record("graphplan analytic", M.analytic(mech, cycle, phi))
    cons = M.Constructions(mech, cycle, phi)
    record("graphplan constructions, exact", cons.run(M.Drafting()))
    record(f"drafting {precision:g} mm", cons.run(M.Drafting(precision, 1.0)))
    model = newton.LoopModel(mech)
    nk = newton.kinematics(model, phi, newton.initial_guess(model, cons.kin, 0))
    nr, nm = newton.forces(model, nk, cycle, phi)
    res = M.Result(np.asarray(phi), velocities={n: v for n, v in nk["velocities"].items()
                                                if n not in mech.frame_points},
                   reactions=nr, M_bal=nm)
    record("newton (generic, loop equations)", res)
    if pylinkage is not None:
        from .peers import PylinkageModel

        pm = PylinkageModel(mech, cons.kin, 0, float(phi[0]), len(phi))
        got = pm.result(pm.sweep_default())
        if np.allclose(np.unwrap(got["phi"]), np.unwrap(phi), atol=1e-9):
            res = M.Result(np.asarray(phi), velocities={n: v for n, v in got["velocities"].items()
                                                        if n not in mech.frame_points})
            record("pylinkage step_with_derivatives", res)
    # the stated bounds of the drafting (velocities relative to the same scale as above)
    vscale = max(float(np.max(np.hypot(*v.T))) for v in ref["velocities"].values())
    mscale = float(np.max(np.abs(ref["M_bal"])))
    kl, kv, ka = cons.scales_for(1.0)
    idx, vb, mb, marked, angles = [], [], [], [], []
    for k in range(0, len(phi), bound_every):
        kc = kinematic_conditioning(mech, cons.kin, k, kl, kv, ka, precision)
        fc = force_conditioning(mech, cons.kin, cons.forces, cons.loads, k, kl, kv, precision)
        pts = [f.bound for (plan, name), f in kc.figures.items()
               if plan == "velocity" and name.startswith("point ")
               and name[6:].upper() in {n.upper() for n in ref["velocities"]}]
        idx.append(k)
        vb.append(max(pts) / vscale)
        mb.append(fc.figures[("force", "Mур")].bound / mscale)
        marked.append(bool(kc.flagged or fc.flagged))
        angles.append(min([x.angle_deg for x in kc.intersections + fc.intersections] or [90.0]))
    out["bound"] = {"index": idx, "phi_deg": [float(np.degrees(phi[k])) for k in idx],
                    "velocities": vb, "M_bal": mb, "marked": marked, "min_angle_deg": angles}
    out["min_angle_deg"] = float(min(angles))
    return out


__all__ = ["TOGGLE_FRAME_MM", "fourbar_toggle", "sweep"]
