"""The loads of the lean full cycle: weights, inertia, the variant's loads and the neglect
rule generated from :mod:`graphplan.forces.loads` (see :mod:`graphplan.forces.lean`)."""

from __future__ import annotations

import math

import numpy as np

from ..kinematics import Cycle
from .lean_code import NotCompiled, Value, count_nonzero, interp_complex
from .lean_kinematics import KinematicsCode
from .loads import JUMP_TOL, diagram_value, resistance_names


def interp_diagram(xs, ys, nodes, d, signed: bool, clip: bool, lo: float, hi: float):
    """The diagram ``d`` as ``np.interp`` (see LoadsCode._diagram); x is clipped to [lo, hi]
    only where the general function is called (np.interp holds its end values beyond the
    ends, and x leaves [0, 1] by round-off only).

    One complex ``np.interp`` gives both the value (real part) and whether x is within
    2·:data:`JUMP_TOL` of a node (imaginary part: a step 1 near each node, 0 elsewhere,
    on a grid that merges the diagram's abscissae with the steps' corners)."""
    tol = 2 * JUMP_TOL
    # zero beyond an end inside [lo, hi]; an end at or beyond lo or hi holds its value
    left = 0.0 if xs[0] > lo else float(ys[0])
    right = 0.0 if xs[-1] < hi else float(ys[-1])
    gx = np.array([v for n in nodes for v in (n - 2 * tol, n - tol, n + tol, n + 2 * tol)])
    gy = np.array([v for _ in nodes for v in (0.0, 1.0, 1.0, 0.0)])
    grid = np.sort(np.concatenate((xs, gx)))  # xs strictly increasing (no jump); without
    grid = grid[np.concatenate(([True], np.diff(grid) > 0))]  # np.unique (it imports np.ma)
    table = np.interp(grid, xs, ys, left, right) + 1j * (
        np.interp(grid, gx, gy, 0.0, 0.0) if gx.size else 0.0)
    # at the diagram's own abscissae the value is its ordinate, exactly
    table.real[np.searchsorted(grid, xs)] = ys
    lr = (complex(left), complex(right))
    maximum = np.maximum

    def value(x):
        z = interp_complex(x, grid, table, *lr)
        if count_nonzero(z.imag):
            return diagram_value(d, np.clip(x, lo, hi), signed=signed)
        return maximum(z.real, 0.0) if clip else z.real

    return value


class LoadsCode:
    """The loads of every moving link as Value: forces ``(name, vector, at)`` and couples."""

    def __init__(self, st: KinematicsCode, cycle: Cycle, inertia: bool, frac: float):
        self.st = st
        mech, g = st.mech, st.g
        self.forces: dict[str, list] = {ln: [] for ln in mech.moving_links}
        self.moments: dict[str, list] = {ln: [] for ln in mech.moving_links}
        gvec = complex(*mech.gravity)
        w1sq = float(mech.crank.omega) ** 2
        for ln in mech.moving_links:
            props = mech.links.get(ln)
            if props is None or props.centre is None:
                continue
            S = st.P[props.centre]
            if props.mass > 0 and gvec != 0:
                self.forces[ln].append((f"G{ln}", g.K(props.mass * gvec), S))
            if inertia and props.mass > 0:
                self.forces[ln].append((f"Pи{ln}", g.mul(g.K(-props.mass), st.A[props.centre]),
                                        S))
            if inertia and props.inertia > 0:
                eps = st.E[ln]
                if eps.const is None:  # ε of round-off at a dead centre: no couple
                    keep = g.tmp(f"{g.ref(g.abs(eps))} > {g.lit(1e-12 * w1sq)}", "b", 1.0)
                    self.moments[ln].append((f"Mи{ln}",
                                             g.mul(g.mul(eps, keep), g.K(-props.inertia))))
                elif eps.const != 0:
                    self.moments[ln].append((f"Mи{ln}", g.K(-props.inertia * eps.const)))
        self._resistances(cycle)
        if frac > 0:
            self._neglect(frac)

    def _resistances(self, cycle: Cycle) -> None:
        st, g, mech = self.st, self.st.g, self.st.mech
        for n_res, (res, name) in enumerate(zip(mech.resistances, resistance_names(mech),
                                                strict=True)):
            tl = res.travel_link or mech.output.link
            q = g.K(0.0)
            if res.over == "stroke":
                q = self._coordinate(tl)
            size, dirn = self._values(res, n_res, cycle, q)
            s = -1.0 if res.sense == "resists" else 1.0
            w = float(res.working or mech.output.working)
            own = res.over == "stroke" and tl == res.link
            if res.kind == "force":
                assert res.point is not None  # a force has its point (the loader)
                at = st.P[res.point]
                key = f"{res.link}/{mech.frame_link}"
                u = st.guides[key][1] if key in st.guides else None
                if res.sense == "diagram":
                    if res.angle is not None:
                        e = g.K(g.unit(res.angle))
                    else:
                        assert u is not None
                        e = g.mul(u, g.K(w if own else 1.0))
                    vec = g.mul(e, size)
                elif u is not None:
                    motion = (g.mul(g.K(w), dirn()) if own
                              else g.fn("np.sign", st.sv(key), bound=1.0))
                    vec = g.mul(u, g.mul(g.K(s), g.mul(motion, size)))
                else:
                    v = self._point_velocity(res.link, at)
                    sp = g.abs(v)
                    safe = g.tmp(f"np.where({g.ref(sp)} > 0, {g.ref(sp)}, 1.0)", "r")
                    vec = g.mul(v, g.div(g.mul(g.K(s), size), safe))
                self.forces[res.link].append((name, vec, at))
            else:
                if res.sense == "diagram":
                    mom = size
                else:
                    motion = (g.mul(g.K(w), dirn()) if own
                              else g.fn("np.sign", st.W[res.link], bound=1.0))
                    mom = g.mul(g.K(s), g.mul(motion, size))
                self.moments[res.link].append((name, mom))

    def _values(self, res, n_res: int, cycle: Cycle, q: Value):
        """:func:`~graphplan.forces.load_values`: the signed size and the stroke's
        direction of motion (a function generating it when asked for)."""
        g, mech = self.st.g, self.st.mech
        period = cycle.period
        tau = g.mul(g.sub(Value("phi", kind="r"), g.K(cycle.origin)),
                    g.K(float(mech.crank.sense)))
        tau = g.fn("np.mod", tau, g.K(period), bound=period)
        if res.over == "crank":
            x = g.fn("np.mod", g.sub(tau, g.K(res.phase)), g.K(period), bound=period)
            val = self._diagram(res.strokes[0], x, True, (0.0, period), n_res, 0, clip_x=False)
            return g.sub(g.mul(val, g.K(res.maximum)), g.K(res.offset)), None
        lt = cycle.travels[(res.travel_link or mech.output.link,
                            res.working or mech.output.working)]
        from .loads import DEAD_CENTRE_TOL, _first_start

        two_pi = 2 * math.pi
        loaded = [m for m, d in enumerate(res.stroke_diagrams(round(period / math.pi)))
                  if d is not None]
        # u: the crank's travel from the load's first start dead centre (one reduction
        # modulo the period; loads.stroke_index takes τ modulo it first: the two differ by
        # round-off, 1e-15 rad, well inside DEAD_CENTRE_TOL that decides at a dead centre)
        u = g.fn("np.mod", g.add(g.mul(Value("phi", kind="r"), g.K(float(mech.crank.sense))),
                                 g.K(-cycle.origin * mech.crank.sense + DEAD_CENTRE_TOL
                                     - _first_start(res, mech, cycle, lt))), g.K(period),
                 bound=period)
        if period == two_pi and loaded == [0]:
            # one turn, one loaded stroke: stroke_index's k is 0 exactly where u < lt.turn
            # (its other turn starts where u/2π rounds to 1, after lt.turn)
            k = None
            sel0 = g.tmp(f"{g.ref(u)} < {g.lit(lt.turn)}", "b", 1.0)
        else:
            turn = g.fn("np.floor", g.tmp(f"{g.ref(u)} / {g.lit(two_pi)}", "r", u.bound / two_pi),
                        bound=u.bound / two_pi + 1)
            r = g.sub(u, g.mul(turn, g.K(two_pi)))
            k = g.add(g.mul(turn, g.K(2.0)), g.tmp(f"{g.ref(r)} >= {g.lit(lt.turn)}", "b", 1.0))
        if lt.kind == "rocker":
            mid = 0.5 * (lt.q_start + lt.q_end)
            q = g.add(q, g.mul(g.fn("np.round", g.mul(g.sub(g.K(mid), q), g.K(1 / two_pi)),
                                    bound=math.inf), g.K(two_pi)))
        xr = g.mul(g.sub(q, g.K(lt.q_start)), g.K(1.0 / (lt.q_end - lt.q_start)))
        x = xr  # in [0, 1] but for round-off: clipped where the general function reads it
        signed = res.sense == "diagram"
        size = g.K(0.0)
        for m in loaded:
            d = res.stroke_diagrams(round(period / math.pi))[m]
            sel = sel0 if k is None else g.tmp(f"{g.ref(k)} == {g.lit(float(m))}", "b", 1.0)
            val = self._diagram(d, x, signed, (0.0, 1.0), n_res, m)
            if res.offset == 0:  # the constant last: it folds into the force's direction
                size = g.add(size, g.mul(g.mul(val, sel), g.K(res.maximum)))
            else:
                size = g.add(size, g.mul(g.sub(g.mul(val, g.K(res.maximum)), g.K(res.offset)),
                                         sel))

        def dirn():
            """±1 on the strokes 0 → 1 and 1 → 0 (where the size is not 0)."""
            if len(loaded) == 1:
                return g.K(1.0 if loaded[0] % 2 == 0 else -1.0)
            assert k is not None
            return g.sub(g.K(1.0), g.mul(g.fn("np.mod", k, g.K(2.0), bound=2.0), g.K(2.0)))
        return size, dirn

    def _diagram(self, d, x: Value, signed: bool, span, n_res: int, m: int,
                 clip_x: bool = True) -> Value:
        """:func:`~graphplan.forces.diagram_value` of ``d`` at x: ``np.interp`` for a diagram
        without jumps, which is the same function except within :data:`JUMP_TOL` of a node
        where two pieces meet (or of an end inside ``span``); there, or for a diagram with
        jumps, the general function itself."""
        g = self.st.g
        xs = np.array([p[0] for p in d], float)
        ys = np.array([p[1] for p in d], float)
        top = float(np.max(np.abs(ys)))  # |value| ≤ the largest ordinate
        name = f"_{n_res}_{m}"
        if not np.all(np.diff(xs) > 10 * JUMP_TOL):
            fn = g.bind(f"diagram{name}", lambda x, d=d, s=signed: diagram_value(d, x, signed=s))
            if clip_x:
                x = g.fn("np.clip", x, g.K(float(span[0])), g.K(float(span[1])),
                         bound=max(abs(span[0]), abs(span[1])))
            return g.tmp(f"{fn}({g.ref(x)})", "r", top)
        nodes = [float(v) for v in xs[1:-1]]
        nodes += [float(v) for v in (xs[0], xs[-1]) if span[0] < v < span[1]]
        clip = not signed and ys.min() < 0
        fn = g.bind(f"diagram{name}",
                    interp_diagram(xs, ys, np.array(sorted(nodes)), d, signed, clip, *span))
        return g.tmp(f"{fn}({g.ref(x)})", "r", top)

    def _coordinate(self, link: str) -> Value:
        """The travel link's coordinate (:func:`~graphplan.kinematics.link_coordinate`)."""
        st, g, mech = self.st, self.st.g, self.st.mech
        for d in mech.dyads:
            if link not in d.links:
                continue
            for key, (G, u) in st.guides.items():
                slider, carrier = key.split("/")
                if slider == link and carrier == mech.frame_link:
                    point = d.new_points[0] if d.new_points else d.joints[0]
                    if d.kind == "RRP" and key in st.along:  # B = G + u·(B − G)·u
                        return st.along[key]
                    return g.dot(u, g.sub(st.P[point], G))
            break
        theta = st.theta_of(link)
        return g.fn("np.unwrap", theta)  # (no bound: it grows with the positions)

    def _point_velocity(self, link: str, at: Value) -> Value:
        st, g = self.st, self.st.g
        q = st.mech.points_of(link)[0]
        return g.add(st.V[q], g.mul(g.sub(at, st.P[q]), g.mul(g.K(1j), st.W[link])))

    def _neglect(self, frac: float) -> None:
        """Drop the loads below ``frac`` of the largest of their group (loads._neglect)."""
        g, mech = self.st.g, self.st.mech
        groups = [(mech.crank.link,), *(d.links for d in mech.dyads)]
        for links in groups:
            fl = [(ln, k) for ln in links for k in range(len(self.forces[ln]))]
            ml = [(ln, k) for ln in links for k in range(len(self.moments[ln]))]
            if not (fl or ml):
                continue
            names = [self.forces[ln][k][0] for ln, k in fl] + \
                [self.moments[ln][k][0] for ln, k in ml]
            if len(set(names)) < len(names):
                raise NotCompiled("two loads of one name in a group")
            ell = self._group_size(links) if ml else g.K(1.0)
            # the loads that vary (a force by its vector, a couple by M/ℓ) and the constants
            rows: list[tuple[str, tuple[str, int], Value]] = []
            consts: list[tuple[str, tuple[str, int], float]] = []
            for kind, keys in (("f", fl), ("m", ml)):
                for ln, k in keys:
                    v = self.forces[ln][k][1] if kind == "f" else \
                        g.div(self.moments[ln][k][1], ell)
                    if v.const is not None:
                        consts.append((kind, (ln, k), abs(v.const)))
                    else:
                        rows.append((kind, (ln, k), v))
            if not rows:  # constants only (the weights, without inertia): decided here
                limit_c = frac * max(c for _, _, c in consts)
                for kind, (ln, k), size in consts:
                    if size < limit_c:
                        if kind == "f":
                            nm, _, at = self.forces[ln][k]
                            self.forces[ln][k] = (nm, g.K(0.0), at)
                        else:
                            self.moments[ln][k] = (self.moments[ln][k][0], g.K(0.0))
                continue
            # the largest size, position by position (np.maximum of each: numpy's stack
            # and a reduction over its axis cost more at a course project's 36 positions)
            sizes = [g.abs(v) for _, _, v in rows]
            big = g.K(max(c for _, _, c in consts)) if consts else sizes[0]
            for sz in (sizes if consts else sizes[1:]):
                big = g.maximum(big, sz)
            limit = g.mul(big, g.K(frac))
            # where a size is 0 its load is 0: keeping the loads at or above the limit is
            # the general rule's drop of those below it and above 0
            for (kind, key, _), sz in zip(rows, sizes, strict=True):
                self._keep(kind, key, g.tmp(f"{g.ref(sz)} >= {g.ref(limit)}", "b", 1.0))
            for kind, key, size in consts:
                self._keep(kind, key, g.tmp(f"{g.ref(limit)} <= {g.lit(size)}", "b", 1.0))

    def _keep(self, kind: str, key: tuple[str, int], keep: Value) -> None:
        """A force (``kind`` "f") or couple kept where ``keep`` (0 elsewhere)."""
        g = self.st.g
        ln, k = key
        if kind == "f":
            nm, vec, at = self.forces[ln][k]
            self.forces[ln][k] = (nm, g.mul(vec, keep), at)
        else:
            nm, mom = self.moments[ln][k]
            self.moments[ln][k] = (nm, g.mul(mom, keep))

    def _group_size(self, links) -> Value:
        """ℓ of a group (loads.group_size): pairs on one rigid link are constants."""
        st, g, mech = self.st, self.st.g, self.st.mech
        names = list(dict.fromkeys(p for ln in links for p in mech.points_of(ln)))
        const = mech.crank.length
        arrays: list[Value] = []
        for k, a in enumerate(names):
            for b in names[k + 1:]:
                if st.on_one_link(a, b):
                    const = max(const, st.dist(a, b))
                else:
                    arrays.append(g.abs(g.sub(st.P[a], st.P[b])))
        size = g.K(const)
        for x in arrays:
            size = g.maximum(size, x)
        return size


__all__ = ["LoadsCode", "interp_diagram"]
