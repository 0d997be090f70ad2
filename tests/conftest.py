"""Test settings shared by every test module.

Hypothesis explores new random cases on every local run; CI (``.ci/run`` sets
``HYPOTHESIS_PROFILE=ci``) runs the same derandomized cases every time, so that a
submission lands or not on its own merits. A case found locally is printed with its
reproduction blob.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "dev"))

# the tests' shared helper modules (norm_measures, message_scan, test_json_contract's
# validate) are importable by name from any test module, run alone or in the suite
# (``--import-mode=importlib`` does not put tests/ on sys.path)
sys.path.insert(0, str(Path(__file__).resolve().parent))


@pytest.fixture(scope="session")
def solved():
    """``solved(name_or_path)`` → the :class:`graphplan.project.Project` of an example (a
    bundled example's name or a variant's path), solved once for the whole test session:
    its stages (loads, reactions, sheet scales, the machine unit…) are solved on first use
    and shared by every test that asks for the same example."""
    from graphplan import load
    from graphplan.files import bundled_example
    from graphplan.project import solve_project

    projects: dict[str, object] = {}

    def get(example):
        path = Path(example) if str(example).endswith(".toml") else bundled_example(example)
        key = str(Path(path).resolve())
        if key not in projects:
            projects[key] = solve_project(load(path))
        return projects[key]

    return get


@pytest.fixture(scope="session")
def drawn(solved):
    """``drawn(name_or_path, n, lang="ru", fmt=None)`` → sheet ``n`` (1, 2 or 3) of an
    example, on the variant's format or on ``fmt`` ("A1", "A2", "A3"), drawn once for the
    whole test session (kept as a stage of the example's :func:`solved` project) and shared
    by every test that asks for the same sheet."""

    def get(example, n: int, lang: str = "ru", fmt: str | None = None):
        project = solved(example)

        def draw():
            from graphplan.drawing import dynamics_sheet, kinematics_sheet, kinetostatics_sheet
            from graphplan.paper import Page

            kw = {"page": Page(fmt)} if fmt else {}
            return (kinematics_sheet, kinetostatics_sheet, dynamics_sheet)[n - 1](
                project, lang=lang, **kw)

        return project.stage(("tests: sheet", n, lang, fmt), draw)

    return get
