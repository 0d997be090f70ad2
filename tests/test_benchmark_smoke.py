"""A smoke run of the speed benchmark (issue 21): it keeps working; no speed is judged here.

The speed is measured by ``python -m benchmarks`` itself (medians, peers in the same run,
cold whole commands), never in a test; these tests run its parts on tiny sizes and check
the shape of what they write and that the closed-form yardstick computes what graphplan
computes.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def test_the_closed_form_crank_slider_computes_what_graphplan_computes():
    # the yardstick of "near the limit" must do the same work, or the ratio means nothing
    import graphplan as g
    from benchmarks.closed_form import check

    mech = g.load(ROOT / "examples" / "press.toml")
    cycle = g.analyse_cycle(mech)
    phi = (np.arange(48) + 0.5) * (2 * math.pi / 48)
    agree = check(mech, cycle, phi)
    assert set(agree) == {"points", "accelerations", "R12", "R23", "M_bal"}
    assert max(agree.values()) < 1e-9, agree


def test_the_sweep_its_targets_chart_and_tables(tmp_path):
    # pylinkage is left out here (its numba path compiles for seconds): the benchmark's own
    # smoke run (tests/test_stability.py) times it
    from benchmarks.charts import sweep_chart
    from benchmarks.report import tables
    from benchmarks.run import targets
    from benchmarks.sweep import ratios, sweep

    sw = sweep("press", (12, 360), budget_s=0.01, default_budget_s=0.01, log=lambda m: None,
               with_peers=False)
    assert sw["sizes"] == [12, 360]
    for m in ("graphplan kinematics", "graphplan full cycle", "closed form: kinematics",
              "closed form: full cycle"):
        assert all(t is not None and t > 0 for t in sw["median_s"][m])
    res = {"environment": {"cpus": 2, "machine": "x", "repetitions": 1, "python": "",
                           "numpy": "", "pylinkage": None, "numba": None},
           "mechanisms": {}, "sweep": {**sw, "ratios": ratios(sw)}}
    judged = targets(res)
    # at N = 360 the closed-form target is judged; without the peer no peer target
    assert [t["target"].split(":")[0] for t in judged] == ["sweep N = 360"]
    assert judged[0]["met"] in (True, False) and judged[0]["value"] > 0
    assert sweep_chart(res, tmp_path).is_file() and (tmp_path / "bench-sweep.png").is_file()
    assert "The N sweep" in tables({**res, "targets": judged})


def test_a_generated_class_and_the_cold_commands(tmp_path):
    from benchmarks.commands import time_commands, write_class
    from benchmarks.report import tables
    from benchmarks.run import targets

    files = write_class(tmp_path / "class", 3)
    assert len(files) == 3 and all(f.read_text(encoding="utf-8").startswith("[work]")
                                   for f in files)
    got = time_commands(runs=1, class_size=2, names=["sheets press"], log=lambda m: None)
    assert set(got) == {"sheets press"}
    for e in got.values():
        assert e["runs"] == 1 and e["median_s"] > 0 and e["first_run_s"] > 0
        assert "OUT" in e["command"] and str(tmp_path) not in e["command"]
    res = {"environment": {"repetitions": 1, "python": "", "numpy": "", "pylinkage": None,
                           "numba": None, "cpus": 2, "machine": "x"},
           "mechanisms": {}, "commands": time_commands(runs=1, class_size=2,
                                                        names=["check a class"],
                                                        log=lambda m: None)}
    cold = targets(res)
    # a class of 2 is not the class of 100 the target is set for: not judged
    assert len(cold) == 1 and cold[0]["met"] is None and "not judged" in cold[0]["note"]
    assert "Whole commands, cold" in tables({**res, "targets": cold})
