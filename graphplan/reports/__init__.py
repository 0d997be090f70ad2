"""Reports of a solved variant: text, Markdown and CSV tables of the plans, forces and dynamics."""

from .diagram_comparison import comparison_rows
from .dynamics_tables import T, dynamics_csv, dynamics_markdown, position_rows
from .force_readings import TINY, LoadRow, PositionForces, force_readings
from .force_tables import curve_markdown, forces_csv, forces_markdown
from .plan_tables import (
    SUMMARY_CELL,
    TINY_MM,
    PositionPlans,
    plan_readings,
    plan_table_rows,
    plans_csv,
    plans_markdown,
    rate_table_rows,
    summary_rows,
)
from .seed_comparison import SEED, SEED_NAME, seed_comparison_markdown
from .tables import TEXT, analysis_text, cycle_text, format_table, kinematics_text, structure_text

__all__ = [
    "SEED",
    "SEED_NAME",
    "SUMMARY_CELL",
    "TEXT",
    "TINY",
    "TINY_MM",
    "LoadRow",
    "PositionForces",
    "PositionPlans",
    "T",
    "analysis_text",
    "comparison_rows",
    "curve_markdown",
    "cycle_text",
    "dynamics_csv",
    "dynamics_markdown",
    "force_readings",
    "forces_csv",
    "forces_markdown",
    "format_table",
    "kinematics_text",
    "plan_readings",
    "plan_table_rows",
    "plans_csv",
    "plans_markdown",
    "position_rows",
    "rate_table_rows",
    "seed_comparison_markdown",
    "structure_text",
    "summary_rows",
]
