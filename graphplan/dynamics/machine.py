"""The machine unit (машинный агрегат): motor, drive and mechanism with its flywheel.

Puts the steps of sheet 3 together in the order of the hand calculation (method B.4, B.5):

1. Mс(φ), Iп(φ) reduced to the crank (:func:`graphplan.dynamics.reduction.dynamic_model`);
2. Aс, Aд, ΔT by graphical integration and exactly; Mд from equal work over the cycle;
3. the power the motor must give ``Pдв.тр = Pс/η = Mд·ω1/η`` and the motor, the smallest
   of its series at the chosen synchronous speed with ``P_ном ≥ Pдв.тр``
   (:mod:`graphplan.dynamics.motor`); the gear ratio
   ``u = n_ном/n1``;
4. the flywheel by Wittenbauer's energy–mass diagram for δ, less the rotor's inertia
   reduced to the crank ``J_рот·u²`` (when the catalogue gives J_рот), by Merkalov for
   comparison; its rim or disc on the crank shaft or, ``u²`` times lighter, on the motor
   shaft;
5. the check by simulation: the steady ω(φ) of the crank with ``Iп + J_рот·u² + Iм``.

Settings, ``[dynamics]`` of the variant: ``delta`` (required), ``efficiency`` (η, default
1), ``crank_inertia``, ``grid``, ``intervals`` (of the graphical integration, default
24), ``motor_series`` (default :data:`graphplan.dynamics.motor.DEFAULT_SERIES`), ``motor_speed``
(synchronous rpm, default 1500), ``flywheel = {shape = "rim"|"disc",
shaft = "crank"|"motor", b_ratio, h_ratio, density}``.
All quantities SI (N·m, J, W, kg·m², rad/s); moments positive in the crank's sense of
rotation, as in :mod:`graphplan.dynamics.reduction`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..paper import TITLE_BLOCK_SIZE
from ..units import nice_ceil
from .flywheel import Flywheel, FlywheelSize, flywheel, flywheel_size
from .motor import MotorChoice, choose_motor, required_power
from .reduction import MAX_POLE_MM, DynamicModel, Solved, dynamic_model
from .settings import DynamicsSettings
from .simulation import Simulation, simulate
from .work import work_diagrams

DIAGRAM_LENGTH = 288.0  #: abscissa L of the work diagrams on an A1 sheet 3, mm (48 × 6)
DIAGRAM_HEIGHT = 120.0  #: drawn span of Mс and of Aс with Aд on A1, mm (fixes KM, H, KA)
ENERGY_HEIGHT = 220.0  #: default largest drawn span of ΔT (energy–mass diagram), mm
#: The drawn spans of Mс(φ), Aс/Aд(φ) and ΔT(φ) stacked on an A1 sheet 3 together, mm
#: (the frame's 584 mm less the room of their axes, letters and numbers): ΔT(φ) and the
#: energy–mass diagram beside it get what Mс and Aс leave.
SPANS_HEIGHT = 500.0
ENERGY_WIDTH = 90.0  #: largest drawn span of JII on the energy–mass diagram, mm
#: Room for H and JII beside the work diagrams, left of the title block, on A1 (see
#: :meth:`DiagramSize.for_frame`): 816 − 185 − 2 − 26 − 288 − 34 mm.
BESIDE_A1 = 281.0
PSI_MIN_DEG = 20.0  #: the lower tangent's angle ψmin at least this (method D.3: 20…70°)
#: Scales of sheet 3's ΔT and JII (value per mm): 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k.
SCALE_SERIES = (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)


def round_scale(value: float) -> float:
    """The smallest member of :data:`SCALE_SERIES` × 10^k that is ≥ ``value`` (> 0)."""
    return nice_ceil(value, SCALE_SERIES)


def _room_for_dT(wd, M, spans: float = SPANS_HEIGHT) -> float:
    """What ``spans`` (:data:`SPANS_HEIGHT` on A1) leaves to ΔT after the drawn Mс (with Mд)
    and Aс, Aд."""
    yM, yMd = np.concatenate((wd.yM_mm, M / wd.KM)), wd.M_d / wd.KM
    m_mm = max(float(yM.max()), yMd, 0.0) - min(float(yM.min()), 0.0)
    every = np.concatenate((wd.A_c / wd.KA, wd.A_d / wd.KA, wd.yA_mm, [-wd.yA_mm[-1], 0.0]))
    a_mm = float(every.max() - every.min())
    return max(spans - m_mm - a_mm, 0.2 * spans)


PSI_MAX_DEG = 70.0  #: the upper tangent's angle ψmax at most this


def energy_mass_scales(dT_span: float, I_span: float, omega: float, delta: float,
                       height_mm: float = ENERGY_HEIGHT, width_mm: float = ENERGY_WIDTH
                       ) -> tuple[float, float]:
    """Scales ``(KT, KJ)`` of ΔT(φ) and of the energy–mass diagram (J/mm, kg·m²/mm).

    KT draws ``dT_span`` (ΔT's span with the tangents' intercepts k, l on the ΔT axis)
    at most ``height_mm`` tall. The tangents stand at ``tg ψ = KJ·ω²·(1 ± δ)/(2·KT)``,
    so KJ is the finest round scale that makes ``ψmin ≥ PSI_MIN_DEG`` (ψ of tens of
    degrees: the tangents and their points of contact can be drawn and read), made
    coarser only if JII would be wider than ``width_mm``; and where that makes ψmax
    steeper than :data:`PSI_MAX_DEG` (JII's energy comparable with ΔT: an engine, a
    compressor), KT is made coarser instead. The diagram is tall and narrow when JII
    varies little against ΔT (a press: JII·ω²/2 is a few % of ΔT), which is the honest
    picture of it.
    """
    KT = round_scale(dT_span / height_mm)
    KJ = round_scale(2.0 * KT * math.tan(math.radians(PSI_MIN_DEG)) / (omega**2 * (1 - delta)))
    if I_span > 0 and I_span / KJ > width_mm:
        KJ = round_scale(I_span / width_mm)
        steepest = KJ * omega**2 * (1 + delta) / (2.0 * KT)
        if steepest > math.tan(math.radians(PSI_MAX_DEG)):
            KT = round_scale(KJ * omega**2 * (1 + delta)
                             / (2.0 * math.tan(math.radians(PSI_MAX_DEG - 5.0))))
    return KT, KJ


def _sheet3_scales(m, intervals: int, size: dict, diagrams: DiagramSize
                   ) -> tuple[dict, float, float]:
    """The height of Mс(φ) and Aс(φ) (``size``), KT and KJ that fill sheet 3's column of
    diagrams best: the drawn Mс, Aс and ΔT together as near ``diagrams.spans_mm``
    (:data:`SPANS_HEIGHT` on A1) as the round scales allow (KM, H and KT are rounded, so a
    taller Mс and Aс may leave ΔT and the energy–mass diagram more or less), ΔT at least
    two fifths of the spans tall (200 mm on A1)."""
    best = None
    spans = diagrams.spans_mm
    step = max(1, round(10 * diagrams.height_mm / DIAGRAM_HEIGHT))  # 10 mm on A1
    for h in range(int(size["height_mm"]), int(size["height_mm"]) + 6 * step + 1, step):
        trial = {**size, "height_mm": float(h)}
        wd = work_diagrams(m, intervals, **trial)
        extent = _extent_with_intercepts(wd.dT, m.inertia.I_var, m.omega1, m.delta)
        room = _room_for_dT(wd, m.moment.M, spans)
        KT, KJ = energy_mass_scales(extent, float(np.ptp(np.append(m.inertia.I_var, 0.0))),
                                    m.omega1, m.delta, height_mm=room,
                                    width_mm=min(diagrams.energy_width_mm,
                                                 max(diagrams.beside_mm - wd.H, 10.0)))
        drawn = spans - room + extent / KT
        if best is None or (extent / KT >= 0.4 * spans and drawn > best[0] + 1.0):
            best = (drawn, trial, KT, KJ)
    assert best is not None  # seven heights tried
    return best[1], best[2], best[3]


def _extent_with_intercepts(dT, I_var, omega: float, delta: float) -> float:
    """The drawn extent of ΔT with the lower tangent's intercept l below it, J: the
    tangent ΔT = b + k·JII (k = ω²(1 − δ)/2) through the curve's lowest reach cuts the ΔT
    axis at ``b = min(ΔT − k·JII)`` (≤ min ΔT since JII ≥ 0); k = ω²(1 + δ)/2 at the top
    cuts it at or under max ΔT."""
    b_min = float(np.min(dT - 0.5 * omega**2 * (1 - delta) * I_var))
    return float(np.max(dT)) - min(float(np.min(dT)), b_min)


@dataclass(frozen=True, slots=True)
class DiagramSize:
    """The abscissa L of the work diagrams, the drawn span of Mс and of Aс with Aд, the
    drawn spans of Mс, Aс and ΔT stacked together, the widest JII of the energy–mass
    diagram and the farthest pole distance H, mm (A1's by default); ``beside_mm`` the room
    left of the title block for H and JII together beside the work diagrams (the
    energy–mass diagram stands level with ΔT(φ), down to the frame: JII ≤ beside − H)."""

    length_mm: float = DIAGRAM_LENGTH
    height_mm: float = DIAGRAM_HEIGHT
    spans_mm: float = SPANS_HEIGHT
    energy_width_mm: float = ENERGY_WIDTH
    max_pole_mm: float = MAX_POLE_MM
    beside_mm: float = BESIDE_A1

    @classmethod
    def for_frame(cls, frame_width_mm: float, frame_height_mm: float = 584.0) -> DiagramSize:
        """A1's in proportion to a sheet's frame (A1's frame: 816×584 mm), never larger:
        L a multiple of 48 mm (whole-mm intervals for 24 and 48 of them), the stacked
        spans the frame's height less the room of the three diagrams' axes and letters
        (84 mm), JII and H as wide as the frame's width allows (H a multiple of 5 mm)."""
        k = min(1.0, frame_width_mm / 816.0)
        length = 48.0 * math.floor(DIAGRAM_LENGTH / 48.0 * k)
        # beside: the frame left of the 185 mm title block, less 2 mm, the 26 mm of the
        # work diagrams' margins and letters, L, and the 34 mm of the energy–mass
        # diagram's own (its k, l, kl 20 mm, the tangents past the curve 14 mm)
        return cls(length,
                   float(math.floor(DIAGRAM_HEIGHT * min(1.0, frame_height_mm / 584.0))),
                   min(SPANS_HEIGHT, frame_height_mm - 84.0),
                   float(math.floor(ENERGY_WIDTH * k)),
                   5.0 * math.floor(MAX_POLE_MM * k / 5.0),
                   min(BESIDE_A1, frame_width_mm - TITLE_BLOCK_SIZE[0] - 2.0 - 26.0 - length
                       - 34.0))


SHEET3_DIAGRAMS = DiagramSize.for_frame(816.0)  #: sheet 3 on A1


@dataclass(frozen=True, slots=True)
class MachineUnit:
    """Sheet 3's results: the model, the flywheel, the motor, the mounted flywheel and the
    simulation that checks them.

    Attributes
    ----------
    model : DynamicModel
    flywheel : Flywheel
        On the crank shaft (``I_m``), the rotor already counted (``flywheel.I_rotor``).
    motor : MotorChoice
    power_W : float
        The power the motor must give, Pдв.тр = Pс/η = Mд·ω1/η, W.
    efficiency : float
        η of the drive (``dynamics.efficiency``, default 1).
    mounted : FlywheelSize
        The flywheel's rim or disc on the shaft it is mounted on (``shaft``).
    shaft : str
        ``"crank"`` or ``"motor"``.
    simulation : Simulation
        Of ``Iп + I_rotor + I_m`` with constant Mд (energy form) and, in RK4, the motor's
        linear characteristic of its rated slip.

    A machine whose loads drive it — an engine, the gas doing positive work over the cycle
    — has no motor (``motor`` is None): its constant moment ``flywheel.M_d`` is then the
    consumer's resistance Mс < 0, and ``power_W`` the engine's mean power |Mс|·ω1·η.
    """

    @property
    def driven_by_loads(self) -> bool:
        """The loads drive the crank (an engine): the constant moment resists."""
        return self.motor is None

    model: DynamicModel
    flywheel: Flywheel
    motor: MotorChoice | None
    power_W: float
    mounted: FlywheelSize
    shaft: str
    simulation: Simulation
    efficiency: float = 1.0

    @property
    def flywheel_needed(self) -> bool:
        """False when the crank (``dynamics.crank_inertia``) and the rotor ``Jрот·u²``
        already hold ω within δ: Jм = 0, ``mounted`` is a flywheel of size 0 and the
        simulation runs without one (its δ at or under the target)."""
        return self.flywheel.needed

    @property
    def delta_error_pct(self) -> float:
        """(δ simulated − δ target)/δ target·100."""
        return (self.simulation.delta_actual / self.flywheel.delta - 1.0) * 100.0

    def _repr_markdown_(self) -> str:
        """Jupyter: the hand calculation of sheet 3 (``dynamics.en.md``)."""
        from ..reports import dynamics_markdown

        return dynamics_markdown(self, "en")

    def to_json(self) -> dict:
        """The ``"dynamics"`` entry of the JSON report (SI units)."""
        fw, mc = self.flywheel, self.motor
        motor = None if mc is None else {
            "type": mc.motor.type, "series": mc.series,
            "power_W": mc.motor.power_w, "sync_rpm": mc.motor.sync_rpm,
            "rated_rpm": mc.motor.rated_rpm,
            "start_torque_ratio": mc.motor.start_torque_ratio,
            "max_torque_ratio": mc.motor.max_torque_ratio,
            "rotor_inertia": mc.motor.inertia_kg_m2, "reserve": mc.reserve,
        }
        return {
            "driven_by": "loads" if mc is None else "motor",
            "cycle_deg": math.degrees(self.model.period),
            "delta_target": fw.delta,
            "delta_simulated": self.simulation.delta_actual,
            "delta_simulated_motor": float(self.simulation.cycle_delta[-1]),
            "flywheel_needed": fw.needed,
            "I_flywheel": fw.I_m,
            "I_flywheel_approx": fw.I_m_approx,
            "I_flywheel_graphical": fw.I_m_graph,
            "I_rotor_reduced": fw.I_rotor,
            "I_const": fw.I_const,
            "J_I": fw.J_I,
            "dT_max": fw.dT_max,
            "M_drive": fw.M_d,
            "M_drive_graphical": fw.work.M_d_graph,
            "work_graphical_error": fw.work.error,
            "power_W": self.power_W,
            "omega1": fw.omega,
            "scales": {"Kphi": fw.work.Kphi, "KM": fw.work.KM, "H_mm": fw.work.H,
                       "KA": fw.work.KA, "KT": fw.KT, "KI": fw.KI},
            "tangents": {"psi_max_deg": fw.psi_max, "psi_min_deg": fw.psi_min,
                         "k_mm": fw.k_mm, "l_mm": fw.l_mm, "kl_mm": fw.segment_mm,
                         "flat": fw.tangents_flat},
            "motor": motor,
            "gear_ratio": None if mc is None else mc.u,
            "flywheel": None if not fw.needed else {  # documented: null when not needed
                         "shaft": self.shaft, "shape": self.mounted.shape,
                         "inertia": self.mounted.inertia, "D": self.mounted.D,
                         "b": self.mounted.b, "h": self.mounted.h,
                         "mass": self.mounted.mass, "rim_speed": self.mounted.speed,
                         "rim_speed_ok": self.mounted.speed_ok},
        }


def machine_unit(analysis: Solved, *, model: DynamicModel | None = None,
                 diagrams: DiagramSize = SHEET3_DIAGRAMS) -> MachineUnit:
    """Motor, gear ratio, flywheel and its check for the variant of ``analysis``.

    ``analysis`` gives the mechanism, its kinematics and its ``[dynamics]`` settings
    (:class:`~graphplan.dynamics.settings.DynamicsSettings`); ``diagrams`` the size of the
    work diagrams the graphical integration is drawn at (sheet 3's on A1 by default;
    :meth:`DiagramSize.for_frame` for another format).

    Raises
    ------
    InputError
        ``dynamics.delta`` missing (from :func:`graphplan.dynamics.reduction.flywheel`).
    MotorSelectionError
        No motor of the series at that speed is large enough.
    DynamicsError
        The resistance does no work, or the motion is impossible.
    """
    mech = analysis.mech
    s = DynamicsSettings.of(mech)
    m = model or dynamic_model(analysis)
    if m.delta is None:
        raise InputError(f"{mech.source}: dynamics.delta is missing (the coefficient of speed "
                         "non-uniformity δ, e.g. delta = 0.1): sheet 3 needs it")
    intervals = s.intervals_for(m.period)
    size = {"length_mm": diagrams.length_mm, "height_mm": diagrams.height_mm,
            "max_pole_mm": diagrams.max_pole_mm}
    eta = s.eta
    # Mд = −Aс(2π)/2π does not depend on the flywheel: the motor is chosen before it
    M_const = work_diagrams(m, intervals, **size).M_d
    choice = None
    if M_const > 0:  # a motor drives the machine
        power = required_power(M_const, m.omega1, eta)
        n1 = mech.crank.n1  # as the variant gives it (ω1·30/π picked up round-off)
        choice = choose_motor(power, n1, series=s.motor_series, sync_rpm=s.motor_speed)
    else:  # the loads drive it (an engine): its mean effective power, no motor
        power = -M_const * m.omega1 * eta
    I_rotor = 0.0 if choice is None else (choice.J_reduced or 0.0)
    fws = s.flywheel
    shaft, shape = fws.shaft, fws.shape
    b_ratio, h_ratio, density = fws.b_ratio, fws.h_ratio, fws.density
    size, KT, KJ = _sheet3_scales(m, intervals, size, diagrams)
    fw = flywheel(m, intervals=intervals, shape=shape, b_ratio=b_ratio, h_ratio=h_ratio,
                  density=density, I_rotor=I_rotor, KI=KJ, KT=KT, **size)
    u = choice.u if (shaft == "motor" and choice is not None) else 1.0
    mounted = flywheel_size(fw.I_m, m.omega1, shape=shape, ratio=u, b_ratio=b_ratio,
                            h_ratio=h_ratio, density=density)
    slip = 0.0 if choice is None else 1.0 - choice.motor.rated_rpm / choice.motor.sync_rpm
    sim = simulate(m, fw.I_m + I_rotor, slip=slip if slip > 0 else None, delta=fw.delta)
    return MachineUnit(m, fw, choice, power, mounted, shaft if choice else "crank", sim, eta)


__all__ = ["SHEET3_DIAGRAMS", "DiagramSize", "MachineUnit", "machine_unit"]
