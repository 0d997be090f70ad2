"""Teaching the graphical method: every construction as a lesson, step by step.

``graphplan teach VARIANT.toml --position N --plan velocity`` (see
:mod:`graphplan.teaching.command`) writes a self-contained HTML page
(:func:`teaching_page`) and, on request, the numbered SVG frames of the steps for
slides (:func:`frame_svg`). In a notebook a :class:`Lesson` shows itself (the page in a
sandboxed frame), and so do the plans and sheets (their ``_repr_svg_``).

>>> from graphplan.project.analysis import analyze            # doctest: +SKIP
>>> from graphplan.model.loader import load
>>> les = lesson(analyze(load("examples/press.toml")), "velocity", "2")
>>> [s.kind for s in les.steps]
['pole', 'lay', 'intersect', 'read', 'similar', 'similar']

The lessons: :func:`~graphplan.teaching.kinematic.plan_lesson` (velocity and
acceleration plans), :func:`~graphplan.teaching.forces.forces_lesson` (the force plans
of the groups and the crank), :func:`~graphplan.teaching.lever.lever_lesson`
(Zhukovsky's lever), :func:`~graphplan.teaching.flywheel.flywheel_lesson` (work
diagrams and the energy–mass diagram).
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

from ..errors import InputError
from .model import Lesson, LessonStep, Mark, Panel, Result, Term

PLANS: tuple[str, ...] = ("velocity", "acceleration", "forces", "zhukovsky", "flywheel")
#: Plans drawn for one position (the flywheel is of the whole cycle).
POSITION_PLANS = PLANS[:4]


def position_index(analysis, label: str) -> int:
    """Index of the position labelled ``label`` (``"2"``, ``"(2)"``)."""
    labels = analysis.kin.labels
    if label in labels:
        return labels.index(label)
    raise InputError(f"{analysis.mech.source}: --position: expected one of "
                     f"{', '.join(labels)} (got {label!r})")


def lesson(analysis, plan: str = "velocity", position: str | None = None) -> Lesson:
    """The lesson of ``plan`` at the position labelled ``position`` (the scales of sheet 1).

    Raises
    ------
    InputError
        An unknown plan or position, or no position for a plan that needs one.
    GraphplanError
        What the construction raises (e.g. no δ for the flywheel).
    """
    if plan not in PLANS:
        raise InputError(f"plan: expected one of {', '.join(PLANS)} (got {plan!r})")
    if plan == "flywheel":
        from .flywheel import flywheel_lesson

        return flywheel_lesson(analysis)
    if position is None:
        raise InputError(f"the {plan} plan needs a position (--position N)")
    k = position_index(analysis, str(position))
    if plan in ("velocity", "acceleration"):
        from .kinematic import plan_lesson

        les = plan_lesson(analysis, k, plan)
    elif plan == "forces":
        from .forces import forces_lesson

        les = forces_lesson(analysis, k)
    else:
        from .lever import lever_lesson

        les = lever_lesson(analysis, k)
    return _with_scheme(analysis, k, les)


def _with_scheme(analysis, k: int, les: Lesson) -> Lesson:
    """``les`` with the mechanism at position k beside its plan, each step's links in colour."""
    import dataclasses

    from .scheme import lesson_scheme, step_links

    mech = analysis.mech
    steps = tuple(dataclasses.replace(s, links=step_links(
        mech, s.equation, s.text.get("en", ""), les.panels[s.panel].title.get("en", "")))
        for s in les.steps)
    return dataclasses.replace(les, steps=steps, scheme=lesson_scheme(analysis, k))


def page_name(plan: str, position: str | None) -> str:
    """File name of a page: ``teach-velocity-2.html``, ``teach-forces-(2).html``,
    ``teach-flywheel.html``.

    Characters other than Latin letters, digits and ``()_.-`` become ``_``; a label that
    loses a character that way, or has a capital letter (Windows folders ignore case), gets
    the first 8 hex digits of its SHA-1 too, so that two labels never share a file
    (``(р)`` and ``(х)``: ``teach-velocity-(_)-1b2c….html`` and ``…-(_)-9f0e….html``).
    """
    if position is None:
        return f"teach-{plan}.html"
    label = str(position)
    safe = re.sub(r"[^0-9A-Za-z()_.\-]", "_", label)
    if safe != label or label != label.lower():
        safe += "-" + hashlib.sha1(label.encode("utf-8")).hexdigest()[:8]
    return f"teach-{plan}-{safe}.html"


def __getattr__(name: str):
    # the drawing and the page import svgwrite and shapely: only when they are asked for
    # (the command line builds its parser, and so imports this package, on every run)
    if name == "frame_svg":
        from .drawing import frame_svg

        return frame_svg
    if name == "teaching_page":
        from .page import teaching_page

        return teaching_page
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def write_lesson(les: Lesson, out_dir: str | Path, *, lang: str = "ru", frames: bool = False,
                 protect: tuple[Path, ...] = ()) -> list[Path]:
    """Write the page of ``les`` (and its numbered SVG frames) into ``out_dir``, atomically.

    The frames go to ``out_dir/<page name without .html>/step-01.svg`` …, each with the
    fonts it needs embedded.
    """
    from ..files import write_atomic
    from .drawing import frame_svg, frame_texts
    from .page import teaching_page
    from .webfonts import font_face_css

    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out}: the output must be a directory")
    name = page_name(les.plan, les.position)
    written = [write_atomic(out / name, teaching_page(les, lang), protect=protect)]
    if frames:
        css = font_face_css(frame_texts(les, lang))
        folder = out / name.removesuffix(".html")
        width = max(2, len(str(len(les.steps))))
        for s in les.steps:
            svg = frame_svg(les, s.number, lang=lang, standalone=True, font_css=css)
            written.append(write_atomic(folder / f"step-{s.number:0{width}d}.svg", svg,
                                        protect=protect))
    return written


__all__ = ["PLANS", "Lesson", "LessonStep", "Mark", "Panel", "Result", "Term", "frame_svg",
           "lesson", "page_name", "position_index", "teaching_page", "write_lesson"]
