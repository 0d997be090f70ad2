"""graphplan: the graphical method of the Theory of Machines and Mechanisms.

Pipeline: :func:`load` a variant file → :func:`analyse_structure` →
:func:`analyse_cycle` (dead centres, positions) → :func:`solve` the exact
kinematics of the positions (vectorised over crank angles).
"""

from .cycle import Cycle, analyse_cycle, sweep
from .errors import (
    AssemblyError,
    GraphplanError,
    InputError,
    LayoutError,
    SingularPoseError,
    StructureError,
)
from .kinematics import Kinematics, solve
from .loader import load, loads
from .model import Mechanism
from .structure import Structure
from .structure import analyse as analyse_structure

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
