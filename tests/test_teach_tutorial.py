"""The tutorial (examples/tutorial.py) runs as a script from the variant file to the
flywheel, writes its teaching pages, and prints what the library computes."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from graphplan.dynamics import dynamic_model, flywheel
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.project import analyze

TUTORIAL = Path(__file__).resolve().parent.parent / "examples" / "tutorial.py"


def test_tutorial_runs_from_variant_to_flywheel(tmp_path):
    out = tmp_path / "out"
    run = subprocess.run([sys.executable, str(TUTORIAL), str(out)], capture_output=True,
                         text=True, timeout=300, cwd=tmp_path, check=False)
    assert run.returncode == 0, run.stderr[-2000:]
    names = {p.name for p in out.iterdir()}
    assert {"teach-velocity-2.html", "teach-acceleration-2.html", "teach-forces-(2).html",
            "teach-zhukovsky-(2).html", "teach-flywheel.html", "sheet1.svg"} <= names
    assert len(list((out / "teach-velocity-2").glob("step-*.svg"))) == 6
    # the flywheel it prints is the library's (Wittenbauer) and the simulation meets δ
    fw = flywheel(dynamic_model(analyze(load(bundled_example("press")))))
    m = re.search(r"Iм = ([\d.]+) kg·m²", run.stdout)
    assert float(m[1]) == pytest.approx(fw.I_m, abs=0.05)
    d = re.search(r"simulated δ with this flywheel: ([\d.]+) \(target ([\d.]+)\)", run.stdout)
    assert float(d[1]) == pytest.approx(float(d[2]), rel=0.05)


def test_russian_tutorial_runs_and_speaks_russian(tmp_path):
    out = tmp_path / "out"
    run = subprocess.run([sys.executable, str(TUTORIAL.with_name("tutorial_ru.py")), str(out)],
                         capture_output=True, text=True, timeout=300, cwd=tmp_path, check=False)
    assert run.returncode == 0, run.stderr[-2000:]
    names = {p.name for p in out.iterdir()}
    assert {"teach-velocity-2.html", "teach-flywheel.html", "sheet1.svg"} <= names
    assert 'lang="ru"' in (out / "teach-velocity-2.html").read_text(encoding="utf-8")
    fw = flywheel(dynamic_model(analyze(load(bundled_example("press")))))
    m = re.search(r"Iм = ([\d,]+) кг·м²", run.stdout)
    assert float(m[1].replace(",", ".")) == pytest.approx(fw.I_m, abs=0.5)
    # the units are Russian, the numbers without powers of ten
    assert "Kl = lOA/OA = 0,08/80 = 0,001 м/мм" in run.stdout
    assert not re.search(r"\d[eE][+-]\d", run.stdout)
    assert not re.search(r"\b(m/s|rad/s|kg|N·m)\b", run.stdout)
