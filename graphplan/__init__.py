"""graphplan: the graphical method of the Theory of Machines and Mechanisms.

Pipeline: :func:`load` a variant file → :func:`analyse_structure` →
:func:`analyse_cycle` (dead centres, positions) → :func:`solve` the exact
kinematics of the positions (vectorised over crank angles).
"""

from .errors import (
    AssemblyError,
    GraphplanError,
    InputError,
    LayoutError,
    SingularPoseError,
    StructureError,
)
from .kinematics import Cycle, Kinematics, analyse_cycle, solve, sweep
from .model import Mechanism, Structure, load, loads
from .model import analyse as analyse_structure

__version__ = "0.1.0"

__all__ = [
    "AssemblyError",
    "Cycle",
    "GraphplanError",
    "InputError",
    "Kinematics",
    "LayoutError",
    "Mechanism",
    "SingularPoseError",
    "Structure",
    "StructureError",
    "__version__",
    "analyse_cycle",
    "analyse_structure",
    "load",
    "loads",
    "solve",
    "sweep",
]
