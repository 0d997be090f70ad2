"""Import layering: computing never imports rendering libraries; results are frozen."""

import dataclasses
import subprocess
import sys

import numpy as np
import pytest

import graphplan as g
from graphplan.files import bundled_example


def test_import_loads_no_rendering_library():
    code = (
        "import sys, graphplan, graphplan.project.analysis, graphplan.cli;"
        "bad = [m for m in ('svgwrite', 'matplotlib', 'shapely') if m in sys.modules];"
        "print(','.join(bad))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == ""


def test_results_are_frozen():
    m = g.load(bundled_example("press"))
    with pytest.raises(dataclasses.FrozenInstanceError):
        m.name = "x"  # type: ignore[misc]
    cycle = g.analyse_cycle(m)
    with pytest.raises(dataclasses.FrozenInstanceError):
        cycle.stroke = 0.0  # type: ignore[misc]
    kin = g.sweep(m, cycle)
    with pytest.raises(dataclasses.FrozenInstanceError):
        kin.phi = np.zeros(3)  # type: ignore[misc]
