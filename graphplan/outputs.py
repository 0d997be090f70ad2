"""The project's output files for one variant: the sheets, the tables and the JSON report.

``graphplan sheets VARIANT.toml -o DIR`` writes into DIR:

* ``sheet1.svg`` — sheet 1, kinematic analysis (A1 unless the variant says otherwise);
* ``sheet2.svg`` — sheet 2, force analysis: schemes with loads and reactions, force plans,
  Zhukovsky's lever of the chosen positions, the curve Mур(φ), the table;
* ``plans.ru.md``, ``plans.en.md`` — the tables of the plans, as a hand calculation;
* ``plans.csv`` — the same readings, one row per segment, for scripts;
* ``forces.ru.md``, ``forces.en.md``, ``forces.csv`` — the force analysis in the layout of
  the seed: loads, what was neglected, moment equations, Kp, polygon segments, reactions,
  h21, Mур from the force plans and from Zhukovsky's lever (exact and drafted);
* ``sheet3.svg``, ``dynamics.ru.md``, ``dynamics.en.md``, ``dynamics.csv`` — when the
  variant gives ``dynamics.delta``: sheet 3 (work diagrams, energy–mass diagram,
  flywheel, motor, the check by simulation) and its hand calculation;
* ``analysis.json`` — the report of ``graphplan analyze --json``;
* with ``--format dxf,pdf,png``, each sheet also (or instead of the SVG) as
  ``sheetN.dxf`` (CAD, layers, 1:1 mm), ``sheetN.pdf`` (true size) and ``sheetN.png``
  (a preview at ``--dpi``): :mod:`graphplan.render.formats`.

The files are replaced as a set (:func:`graphplan.files.write_set`: written beside the
folder, then swapped in; a crash leaves the old set or the new one, never a mix); the
variant file is never overwritten. With
several variants, each goes into ``DIR/<variant name>/``.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True, slots=True)
class Written:
    """Files written for one variant."""

    variant: Path
    files: tuple[Path, ...]
    warnings: tuple[str, ...] = ()


def project_files(analysis, *, lang: str = "ru", precision: float | None = None,
                  formats: tuple[str, ...] = ("svg",), dpi: float | None = None
                  ) -> dict[str, str | bytes]:
    """Name → content of every output file of a variant (nothing is written here).

    ``formats`` are the sheets' formats (:data:`graphplan.render.formats.FORMATS`; SVG text,
    the others bytes), ``dpi`` the resolution of the PNG previews.
    """
    from .render import PreviewPool, parse_formats, resolve

    # the PNG previews and the DXF files are made by worker processes (where there are
    # any) while the tables and the next sheets are made; collected at the end
    slow = {"png", "dxf"} & set(parse_formats(formats))
    with PreviewPool(3 * len(slow)) as pool:
        return resolve(_project_files(analysis, lang, precision, formats, dpi, pool))


def _project_files(analysis, lang, precision, formats, dpi, pool) -> dict:
    from .drawing import kinematics_sheet, kinetostatics_sheet
    from .render import DEFAULT_DPI, sheet_files
    from .reports import forces_csv, forces_markdown, plans_csv, plans_markdown

    prec = analysis.mech.drawing.reading_mm if precision is None else precision
    dpi = DEFAULT_DPI if dpi is None else dpi

    def sheets(named) -> dict[str, str | bytes]:
        return sheet_files(named, formats, dpi=dpi, pool=pool)

    out = {
        **sheets({"sheet1": kinematics_sheet(analysis, lang=lang),
                  "sheet2": kinetostatics_sheet(analysis, lang=lang)}),
        "plans.ru.md": plans_markdown(analysis, "ru", prec),
        "plans.en.md": plans_markdown(analysis, "en", prec),
        "plans.csv": plans_csv(analysis, "en", prec),
        "forces.ru.md": forces_markdown(analysis, "ru", prec),
        "forces.en.md": forces_markdown(analysis, "en", prec),
        "forces.csv": forces_csv(analysis, prec),
    }
    from .dynamics import DynamicsSettings

    unit = None
    if DynamicsSettings.of(analysis.mech).delta is not None:  # sheet 3 needs δ
        from .drawing import dynamics_sheet
        from .reports import dynamics_csv, dynamics_markdown

        unit = analysis.unit
        out.update(sheets({"sheet3": dynamics_sheet(analysis, lang=lang, unit=unit)}))
        out["dynamics.ru.md"] = dynamics_markdown(unit, "ru")
        out["dynamics.en.md"] = dynamics_markdown(unit, "en")
        out["dynamics.csv"] = dynamics_csv(unit)
    out["analysis.json"] = json.dumps(analysis.to_json(unit), ensure_ascii=False, indent=1,
                                      allow_nan=False) + "\n"
    return out


def write_project(variant: str | Path, out_dir: str | Path, *, lang: str | None = None,
                  precision: float | None = None, page: str | None = None,
                  formats: str | tuple[str, ...] = ("svg",), dpi: float | None = None
                  ) -> Written:
    """Analyse ``variant`` and write its output files into ``out_dir``.

    ``page`` ("A1", "A2", "A3") overrides the variant's ``drawing.format``; ``formats``
    and ``dpi`` as in :func:`project_files` (``formats`` also as ``"svg,dxf"``; a bad format
    or dpi and a missing export package are reported before any work is done).
    """
    from .files import OutputError, write_set
    from .model import load
    from .project import analyze
    from .render import check_dpi, check_formats, parse_formats

    formats = parse_formats(formats)
    check_formats(formats)
    if dpi is not None:
        check_dpi(dpi)
    variant = Path(variant)
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise OutputError(f"{out}: exists and is not a folder (the output must be a folder)")
    mech = load(variant)
    if page:  # the format decides the scales: the sheet, tables and JSON must agree
        mech = mech.on_format(page)
    lang = lang or mech.drawing.language
    analysis = analyze(mech)
    texts = project_files(analysis, lang=lang, precision=precision, formats=formats,
                          dpi=dpi)
    return Written(variant, write_set(out, texts, protect=(variant,)), analysis.warnings)
