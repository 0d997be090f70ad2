"""Where things go on sheet 1 (kinematics): the regions of an A1/A2/A3 page.

The page is cut as a student cuts it:

* a **left column** holding the plan of positions (top) and the kinematic
  diagrams s(φ), v(φ), a(φ) (below it);
* **rows of cells** to its right, one cell per plan, each as large as its own plan
  needs: the velocity plans of all positions, then the acceleration plans of the
  analysed positions, in reading order; under them a scheme of the mechanism in each
  analysed position (with its ω and ε) and the structural scheme (the Assur groups);
* a **bottom strip** under the grid with the table of the plans, and the block of
  scales above the title block.

The cells' sizes fix the scales Kv and Ka (each plan fills its cell), so the
layout is computed before the plans are drawn, from sizes only. Paper mm, y down.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import LayoutError
from ..fonts import lettering_width
from ..paper import GRAPH26_SIZE, TITLE_BLOCK_SIZE, Page, Rect

GAP = 8.0  #: clearance between regions, mm
CAPTION = 7.0  #: caption strip above a plan cell, mm
ROW = 7.0  #: row height of the table (3.5 mm lettering)
SCALES_BLOCK = 27.0  #: height of the block of scales (three lines of 3.5 mm + title)
STRUCTURE_LINE = 6.0  #: line pitch of the structural analysis block (3.5 mm lettering), mm


def structure_block_height(n_groups: int) -> float:
    """Height of sheet 1's block of the structural analysis: its title, W, the formula of
    structure, a line per Assur group, the stroke (swing) and time ratio, the arcs."""
    return 13.0 + STRUCTURE_LINE * (4 + n_groups)
DIAGRAM_MIN = (200.0, 130.0)  #: smallest useful box of the three diagrams, mm
DIAGRAM_MAX_H = 330.0
DIAGRAM_PREF_H = 180.0  #: the diagrams' height the schemes leave them in the left column, mm


DIAGRAM_FLOOR_H = 85.0  #: the three diagrams' box is never lower: their axes, pads and
#: lettering take 54 mm (drawing.figures), each diagram is at least 10 mm high


def diagram_min(page: Page) -> tuple[float, float]:
    """Smallest box of the diagrams on ``page``: DIAGRAM_MIN on A1, in proportion below
    (never lower than DIAGRAM_FLOOR_H)."""
    k = min(1.0, page.frame.height / 584.0)
    return DIAGRAM_MIN[0] * k, max(DIAGRAM_MIN[1] * k, DIAGRAM_FLOOR_H)


@dataclass(frozen=True, slots=True)
class Sheet1Layout:
    """Regions of sheet 1 (mm on paper, y down).

    ``plan_box`` is where the plan of positions goes (its own size, centred in the
    left column), ``diagrams`` the box of the three diagrams, ``v_cells`` the cells of the
    velocity plans (one per drawn position), ``a_cells`` the cells of the acceleration
    plans (the positions chosen for them), ``schemes`` one cell per analysed position,
    ``groups`` the cell of the structural scheme, ``table`` the top-left corner and width
    available for the table of the plans, ``scales`` the box of the list of scales.
    """

    page: Page
    plan_box: Rect
    diagrams: Rect
    v_cells: tuple[Rect, ...]
    a_cells: tuple[Rect, ...]
    table: Rect
    scales: Rect
    plan_size: float = 0.0  #: the smaller defining vector (pa, πa) the cells allow, mm
    structure: Rect | None = None  #: the block of the structural analysis
    schemes: tuple[Rect, ...] = ()  #: the mechanism in each analysed position, its ω and ε
    groups: Rect | None = None  #: the structural scheme: the Assur groups drawn apart
    column: Rect | None = None  #: the left column the plan of positions heads

    @property
    def cells(self) -> tuple[Rect, ...]:
        """Every plan cell: the velocity plans', then the acceleration plans'."""
        return self.v_cells + self.a_cells

    @staticmethod
    def inner(cell: Rect) -> tuple[float, float]:
        """Room for one plan in a cell (below its caption, with a margin for letters)."""
        return cell.width - 2 * CELL_MARGIN, cell.height - CAPTION - 2 * CELL_MARGIN


CELL_MARGIN = 5.0  #: room kept on each side of a plan in its cell for its letters, mm
OVERSHOOT = 6.0  #: construction lines run this far past their intersection, mm
VECTOR_MAX = 100.0  #: the method's longest main vector of a plan, mm
MIN_PLAN = 4.0  #: the shortest defining vector (pa) a plan is drawn with, mm
VECTOR_HARD = 150.0  #: the longest vector a plan may have: the method wants 50-100 mm, but one Kv
#: for every position cannot keep a shaper's pa (at the dead centres the longest vector) at 50 mm
#: and its idle stroke (2.3·pa) under 100 mm: the plans of most positions are kept at 50 mm
#: or more, the idle stroke's fastest then over 100 mm


MIN_CELL_W = 64.0  #: narrowest plan cell: its caption («План ускорений, пол. 10») fits, mm
SCHEME_H = (60.0, 140.0)  #: least and greatest height of a scheme of an analysed position, mm
GROUPS_H = 60.0  #: least height of the cell of the structural scheme (the Assur groups), mm
COLUMN_SHARE = 0.34  #: the left column (positions, diagrams) is at least this share of the frame


def cell_room(cell: Rect) -> tuple[float, float]:
    """Room for a plan's own extent in ``cell``: less its caption, margins and the
    construction lines' overshoot, mm."""
    return (cell.width - 2 * CELL_MARGIN - 2 * OVERSHOOT,
            cell.height - CAPTION - 2 * CELL_MARGIN - 2 * OVERSHOOT)


def _cell_size(shape: tuple[float, float], size: float) -> tuple[float, float]:
    """The cell a plan of ``shape`` (mm per mm of its defining vector) needs at ``size``."""
    return (max(MIN_CELL_W, shape[0] * size + 2 * CELL_MARGIN + 2 * OVERSHOOT),
            shape[1] * size + CAPTION + 2 * CELL_MARGIN + 2 * OVERSHOOT)


def _shelves(x0: float, y0: float, width: float, boxes: list[tuple[float, float]]
             ) -> tuple[float, list[list[int]]]:
    """Boxes laid in rows, in reading order (a row is as tall as its tallest box): the
    total height and the indices of each row."""
    rows: list[list[int]] = []
    x = math.inf
    for i, (w, _) in enumerate(boxes):
        if x + w > width + 1e-9:
            rows.append([])
            x = 0.0
        rows[-1].append(i)
        x += w
    return sum(max(boxes[i][1] for i in r) for r in rows), rows


def _place(x0: float, y0: float, width: float, boxes: list[tuple[float, float]],
           rows: list[list[int]], extra_h: list[float] | None = None
           ) -> tuple[list[Rect], float]:
    """The rectangles of ``boxes`` in ``rows``, each row stretched to ``width`` (the spare
    width shared by its boxes) and made ``extra_h[i]`` taller: the rects and their bottom."""
    out: list[Rect | None] = [None] * len(boxes)
    y = y0
    for n, r in enumerate(rows):
        h = max(boxes[i][1] for i in r) + (extra_h[n] if extra_h else 0.0)
        spare = (width - sum(boxes[i][0] for i in r)) / len(r)
        x = x0
        for i in r:
            w = boxes[i][0] + spare
            out[i] = Rect(x, y, x + w, y + h)
            x += w
        y += h
    return [r for r in out if r is not None], y


SCHEME_ROOM = 12.0  #: kept round a scheme in its cell for its arrows and letters, mm
SCHEME_PAD = 10.0  #: what a scheme draws at a fixed paper size over its links' height (the
#: arrows of ω and ε, blocks, a guide's hatching, the groups' formulas), and its caption's
#: gap over the drawing, mm


def _usable(boxes: list[tuple[float, float]], rows: list[list[int]], width: float,
            extent: tuple[float, float] | None, room: float) -> list[float]:
    """Extra height each row of schemes (``boxes`` in ``rows``, cells stretched to share
    ``width``) can use: its mechanism (``extent``, m) drawn as wide as its cell allows is
    that tall, plus SCHEME_PAD, within SCHEME_H's range; ``room`` in all, shared in
    proportion when short. Without ``extent``, SCHEME_H's range."""
    want = []
    for r in rows:
        spare = (width - sum(boxes[i][0] for i in r)) / len(r)
        base = max(boxes[i][1] for i in r)
        if extent is None or extent[0] <= 0.0:
            ask = math.inf
        else:
            ask = max(extent[1] * (boxes[i][0] + spare - 2 * SCHEME_ROOM) / extent[0]
                      for i in r) + SCHEME_PAD + 2 * SCHEME_ROOM + CAPTION - base
        want.append(min(max(ask, 0.0), SCHEME_H[1] - SCHEME_H[0]))
    total = sum(want)
    k = 1.0 if total <= room else max(room, 0.0) / max(total, 1e-9)
    return [w * k for w in want]


def _tiled(region: Rect, aspects: list[float]) -> list[Rect]:
    """Cells for figures of the given aspects (width/height) in reading order, in as many
    rows as make the smallest figure largest, each row's cells as wide as their figures
    ask (the row's width shared in their proportion), the rows of equal height."""
    best: tuple[float, list[Rect]] | None = None
    n = len(aspects)
    for n_rows in range(1, n + 1):
        per = math.ceil(n / n_rows)
        rows = [list(range(i, min(i + per, n))) for i in range(0, n, per)]
        rh = (region.height - GAP * (len(rows) - 1)) / len(rows)
        inner_h = rh - CAPTION - 2 * SCHEME_ROOM
        out, worst = [], math.inf
        for r, row in enumerate(rows):
            total = sum(aspects[i] for i in row)
            x = region.x0
            y = region.y0 + r * (rh + GAP)
            for i in row:
                w = region.width * aspects[i] / total
                out.append(Rect(x, y, x + w, y + rh))
                x += w
                side = min((w - 2 * SCHEME_ROOM) / aspects[i], inner_h)
                worst = min(worst, side)
        if best is None or worst > best[0]:
            best = (worst, out)
    return best[1] if best else []


def sheet1_layout(page: Page, plan_w: float, plan_h: float, n_positions: int,
                  v_shapes: tuple[tuple[float, float], ...],
                  a_shapes: tuple[tuple[float, float], ...] = (),
                  longest: tuple[float, float] = (2.0, 2.0), n_groups: int = 1,
                  scheme_aspect: float = 1.0, groups_aspect: float = 2.0,
                  sizes: tuple[float, float] | None = None,
                  n_schemes: int | None = None,
                  scheme_extent: tuple[float, float] | None = None) -> Sheet1Layout:
    """Cut ``page`` for a plan of positions of ``plan_w``×``plan_h`` mm and N positions.

    The left column holds the plan of positions and under it the kinematic diagrams (the
    rest of its height). Right of it, above the strip of the table, the velocity plans
    (``v_shapes``: each plan's width and height per mm of its defining vector pa, in cell
    order) are laid in rows, each cell as large as its own plan needs, then the
    acceleration plans (``a_shapes``, per mm of πa). The schemes — the mechanism in each
    analysed position with its ω and ε (``scheme_aspect`` = width/height) and the
    structural scheme with the Assur groups drawn apart (``groups_aspect``) — go beside a
    plan of positions narrower than its column, or under it when the column is tall
    enough for them and the diagrams, else after the plans. The defining vectors are made
    as long as the place allows (neither plan's longest vector over VECTOR_HARD,
    ``longest`` per mm of it); the height left grows the schemes, then every row.

    ``scheme_extent``: the width and height (m) of the mechanism in the analysed positions:
    under the plan of positions a row of schemes grows only as much as its drawing, at the
    scale its width allows, can use (the rest goes to the diagrams; unknown: as much as
    SCHEME_H allows).

    ``n_schemes``: how many of the acceleration plans (the first) get the scheme of their
    position's ω and ε (all by default: the analysed positions; further plans have none).

    ``sizes``: the defining vectors (pa, πa, mm) the plans are drawn at, once their scales
    are chosen. Each cell is then made as large as its plan at that size needs, and the
    height the plans leave under them on the right, when it holds the kinematic diagrams,
    takes them (as long as that band is wide), the schemes moving to the left column under
    the plan of positions, grown to its foot.
    Raises LayoutError when the plan of positions leaves no room.
    """
    f = page.frame
    top = f.y0 + GRAPH26_SIZE[1] + 4.0
    dmin_w, dmin_h = diagram_min(page)
    left_w = max(plan_w, dmin_w, COLUMN_SHARE * f.width)
    if plan_h + GAP + dmin_h > f.y1 - top - 4.0 or plan_w > f.width * 0.55:
        raise LayoutError(
            f"the plan of positions ({plan_w:.0f}×{plan_h:.0f} mm) does not leave room for the "
            f"plans on {page.format}: choose a smaller Kl (drawing.Kl) or a larger format"
        )
    x0 = f.x0 + 4.0
    gx0, gx1 = x0 + left_w + GAP + 4.0, f.x1 - 4.0
    W = gx1 - gx0
    n_s = len(a_shapes) if n_schemes is None else min(n_schemes, len(a_shapes))

    def extras(width: float) -> list[tuple[float, float]]:
        s_w = min(width, max(SCHEME_H[0] * scheme_aspect, MIN_CELL_W))
        g_w = min(width, max(GROUPS_H * groups_aspect, MIN_CELL_W))
        return [(s_w, SCHEME_H[0] + CAPTION)] * n_s + [(g_w, GROUPS_H + CAPTION)]

    def grown(rows, room):
        """Extra height of each row of schemes: ``room`` shared, SCHEME_H's range each."""
        each = min(room / max(len(rows), 1), SCHEME_H[1] - SCHEME_H[0])
        return [max(each, 0.0)] * len(rows)

    # the schemes beside a plan of positions narrower than the column, or between it and
    # the diagrams when the column is tall enough for both, else after the plans
    side_w = left_w - plan_w - GAP
    beside = under = False
    schemes: list[Rect] = []
    if side_w >= MIN_CELL_W:
        ex = extras(side_w)
        h_side, rows_side = _shelves(0.0, 0.0, side_w, ex)
        beside = h_side <= plan_h
        if beside:
            plan_box = Rect(x0, top, x0 + plan_w, top + plan_h)
            schemes, _ = _place(x0 + plan_w + GAP, top, side_w, ex, rows_side,
                                grown(rows_side, plan_h - h_side))
    if not beside:
        plan_box = Rect(x0 + (left_w - plan_w) / 2, top, x0 + (left_w + plan_w) / 2,
                        top + plan_h)
    rest = f.y1 - 4.0 - (plan_box.y1 + GAP)
    d_top = plan_box.y1 + GAP
    if not beside:
        ex = extras(left_w)
        h_left, rows_left = _shelves(0.0, 0.0, left_w, ex)
        under = rest - h_left - GAP >= max(DIAGRAM_PREF_H, dmin_h)
        if under:
            # the rows of schemes as tall as their drawings can use (a flat mechanism's
            # scheme is no larger in a taller cell), the diagrams keeping DIAGRAM_PREF_H; the
            # diagrams the height left up to DIAGRAM_MAX_H, what they cannot use the
            # schemes' rows again
            room = rest - h_left - GAP
            first = _usable(ex, rows_left, left_w, scheme_extent, room - DIAGRAM_PREF_H)
            more = grown(rows_left, room - sum(first) - DIAGRAM_MAX_H)
            schemes, band_bottom = _place(x0, d_top, left_w, ex, rows_left,
                                          [a + b for a, b in zip(first, more, strict=True)])
            d_top = band_bottom + GAP
    d_h = min(f.y1 - 4.0 - d_top, DIAGRAM_MAX_H)
    diagrams = Rect(x0, f.y1 - 4.0 - d_h, x0 + left_w, f.y1 - 4.0)

    table_h = ROW * (n_positions + 1) + CAPTION
    tb_w, tb_h = TITLE_BLOCK_SIZE
    struct_h = structure_block_height(n_groups)
    strip = max(table_h, tb_h + GAP + SCALES_BLOCK + struct_h)
    gy0, gy1 = f.y0 + 4.0, f.y1 - strip - GAP
    H = gy1 - gy0
    cap_v, cap_a = VECTOR_HARD / max(longest[0], 1.0), VECTOR_HARD / max(longest[1], 1.0)
    right_extra = [] if beside or under else extras(W)
    n_plans = len(v_shapes) + len(a_shapes)

    def blocks(size: float):
        sv, sa = min(size, cap_v), min(size, cap_a)
        boxes = [_cell_size(sh, sv) for sh in v_shapes] + [_cell_size(sh, sa) for sh in a_shapes]
        boxes += right_extra
        if any(b[0] > W + 1e-9 for b in boxes):
            return None
        h, rows = _shelves(gx0, gy0, W, boxes)
        return (h, boxes, rows) if h <= H + 1e-9 else None

    lo, hi = 0.0, max(cap_v, cap_a)
    if blocks(MIN_PLAN) is None and right_extra:  # a small format: the plans come first
        right_extra = []
    if blocks(MIN_PLAN) is None:
        raise LayoutError(
            f"{n_plans} plans leave too little room on {page.format}: "
            "choose the positions to draw (drawing.positions) or a larger format")
    for _ in range(40):
        mid = (lo + hi) / 2
        if blocks(mid) is None:
            hi = mid
        else:
            lo = mid
    size = max(lo, MIN_PLAN)
    used, boxes, rows = blocks(size)  # type: ignore[misc]
    # the height left grows the rows of schemes (by SCHEME_H's range), then all rows
    with_schemes = [i for i, r in enumerate(rows) if any(j >= n_plans for j in r)]
    extra_h = [0.0] * len(rows)
    room = H - used
    for i, g in zip(with_schemes, grown(with_schemes, room), strict=True):
        extra_h[i] = g
    room -= sum(extra_h)
    extra_h = [e + room / len(rows) for e in extra_h]
    cells, _ = _place(gx0, gy0, W, boxes, rows, extra_h)
    if right_extra:
        schemes = cells[n_plans:]
    v_cells, a_cells = tuple(cells[:len(v_shapes)]), tuple(cells[len(v_shapes):n_plans])
    tbx = f.x1 - tb_w
    table = Rect(gx0, f.y1 - 4.0 - table_h, tbx - GAP, f.y1 - 4.0)
    scales = Rect(tbx, f.y1 - tb_h - GAP / 2 - SCALES_BLOCK, f.x1 - 4.0, f.y1 - tb_h - GAP / 2)
    structure = Rect(tbx, scales.y0 - struct_h, f.x1 - 4.0, scales.y0)
    column = Rect(x0, top, x0 + left_w, f.y1 - 4.0)
    if sizes is not None and not beside:
        # the plans at their scales, each cell as large as its plan needs; the diagrams in
        # the band they leave, the schemes under the plan of positions
        sv, sa = sizes
        boxes = [_cell_size(sh, sv) for sh in v_shapes] + [_cell_size(sh, sa) for sh in a_shapes]
        used, rows = _shelves(gx0, gy0, W, boxes)
        h_left, _ = _shelves(0.0, 0.0, left_w, extras(left_w))
        rest = f.y1 - 4.0 - (plan_box.y1 + GAP)
        band = H - used - GAP
        aspects = [scheme_aspect] * n_s + [groups_aspect]
        fits = all(b[0] <= W + 1e-9 for b in boxes)
        if fits and band >= dmin_h and dmin_w <= W and h_left <= rest:
            cells, bottom = _place(gx0, gy0, W, boxes, rows)
            schemes = _tiled(Rect(x0, plan_box.y1 + GAP, x0 + left_w, f.y1 - 4.0), aspects)
            diagrams = Rect(gx0, bottom + GAP, gx1, gy1)
            v_cells, a_cells = tuple(cells[:len(v_shapes)]), tuple(cells[len(v_shapes):])
    return Sheet1Layout(page, plan_box, diagrams, v_cells, a_cells, table, scales, size,
                        structure, tuple(schemes[:n_s]), schemes[n_s] if schemes else None,
                        column)


@dataclass(frozen=True, slots=True)
class FittedTable:
    """A table cut to the width it has: the columns kept, their widths, and how many of all."""

    header: list[str]
    rows: list[list[str]]
    widths: list[float]
    shown: int
    total: int


def fit_columns(header, rows, width: float, height: float = 3.5,
                pad: float = 3.0) -> FittedTable:
    """Column widths from the lettering; the leading columns that fit into ``width``.

    A table wider than its place loses its last columns (the full table is in the
    markdown tables); the caller says so in the table's title.
    """
    widths = _column_widths(header, rows, height, pad)
    keep, acc = [], 0.0
    for j, wd in enumerate(widths):
        if acc + wd > width:
            break
        keep.append(j)
        acc += wd
    return FittedTable([str(header[j]) for j in keep], [[row[j] for j in keep] for row in rows],
                       [widths[j] for j in keep], len(keep), len(header))


SHEET2_STRIP = 120.0  #: height of sheet 2's bottom strip on A1 (Q(s), Mур(φ), the table), mm
SHEET2_CELL_MIN = 60.0  #: smallest useful cell of sheet 2, mm
LABEL_ROOM = 12.0  #: room kept around a plan in its cell for letters, mm
CHART_W = (180.0, 240.0)  #: widths of the Q(s) and Mур(φ) charts on A1, mm
TABLE_PART_GAP = 4.0  #: between the parts of a split table, mm
TABLE_PAD = 3.0 / 3.5  #: room round a column's widest entry per mm of lettering (3 mm at 3.5)


@dataclass(frozen=True, slots=True)
class Sheet2Layout:
    """Regions of sheet 2 (mm on paper, y down).

    ``rows``: per analysed position, its cells: the mechanism in the position with its
    loads (and the diagram of the force on its slider beside the slider's path), then in
    the order the force plans are built — for every Assur group from the last attached to
    the first, the group drawn separately and its force plan; then the crank and its force
    plan; then Zhukovsky's lever.
    ``header`` the band at the top (the scales), ``qs`` the chart of the technological
    force Q(s), ``curve`` the chart Mур(φ), ``table`` the box of the table of the force
    analysis (split into parts, its header repeated, when it is wider than the box) and,
    when the sheet draws it, of the table of the links' loads under it.
    """

    page: Page
    rows: tuple[tuple[Rect, ...], ...]
    header: Rect
    qs: Rect
    curve: Rect
    table: Rect
    mechanism: bool = True  #: rows begin with the mechanism's cell (left out on a small page)


#: The words of sheet 2's table: its leading and trailing columns, and the unit of a reaction.
SHEET2_TABLE_WORDS = {
    "ru": {"head": ("Пол.", "φ, °", "Kp, Н/мм"), "kN": "кН",
           "tail": ("h21, мм", "Mур, Н·м", "Mур(Ж), Н·м", "Δ, %")},
    "en": {"head": ("Pos.", "φ, °", "Kp, N/mm"), "kN": "kN",
           "tail": ("h21, mm", "Mур, N·m", "Mур(Zh), N·m", "Δ, %")},
}


def sheet2_table_header(reactions, lang: str) -> list[str]:
    """Columns of the table of sheet 2: position, φ, Kp of the first group, every reaction
    (kN, in the order solved), h21, Mур from the plans and from the lever, their difference."""
    w = SHEET2_TABLE_WORDS[lang]
    return [*w["head"], *(f"{n}, {w['kN']}" for n in reactions), *w["tail"]]


#: The words of sheet 2's table of the links' loads.
SHEET2_LOADS_WORDS = {
    "ru": {"title": "Нагрузки звеньев (силы тяжести и инерции)",
           "head": ("Пол.", "Звено", "m, кг", "G, Н", "aS, м/с²", "Pи, Н", "JS, кг·м²",
                    "ε, 1/с²", "Mи, Н·м")},
    "en": {"title": "Loads of the links (weights and inertia)",
           "head": ("Pos.", "Link", "m, kg", "G, N", "aS, m/s²", "Pи, N", "JS, kg·m²",
                    "ε, 1/s²", "Mи, N·m")},
}


def sheet2_loads_table(mech, kin, positions, lang: str
                       ) -> tuple[list[str], list[list[str]]]:
    """Header and rows of sheet 2's table of the links' loads, the first step of the
    kinetostatics (method B.3): per analysed position and moving link with a mass or a
    moment of inertia, m, the weight G = m·g, the acceleration aS of its centre of mass,
    the inertia force Pи = m·aS, JS, its angular acceleration ε and the inertia moment
    Mи = JS·ε (exact values; the force plans draw them, less those the variant's
    ``neglect_below`` rule leaves out)."""
    from ..numbers import plain

    g = math.hypot(*mech.gravity)
    rows = []
    for k in positions:
        for ln in mech.moving_links:
            props = mech.links.get(ln)
            if props is None or props.centre is None or (props.mass <= 0
                                                         and props.inertia <= 0):
                continue
            a_s = math.hypot(*kin.acc.points[props.centre][k])
            eps = abs(float(kin.acc.epsilon[ln][k])) if ln in kin.acc.epsilon else 0.0
            eps = 0.0 if eps <= 1e-12 * mech.crank.omega**2 else eps  # a dead centre's round-off
            rows.append([kin.labels[k], ln, plain(props.mass, 4), plain(props.mass * g, 5),
                         plain(a_s, 4), plain(props.mass * a_s, 5),
                         plain(props.inertia, 4) if props.inertia > 0 else "—",
                         plain(eps, 4) if props.inertia > 0 else "—",
                         plain(props.inertia * eps, 4) if props.inertia > 0 else "—"])
    return list(SHEET2_LOADS_WORDS[lang]["head"]), rows


def sheet2_cell_min(page: Page) -> float:
    """The smallest cell sheet 2 draws a group, a plan or the lever in: SHEET2_CELL_MIN on
    A1, less on a smaller format (but never under 45 mm)."""
    return max(45.0, SHEET2_CELL_MIN * min(1.0, page.frame.height / 584.0) ** 0.5)


@dataclass(frozen=True, slots=True)
class FigureShape:
    """What one figure of sheet 2 asks of its cell: its drawing's width over height
    (``aspect``), the longest side it is drawn at at most (``cap``, mm: a force plan's
    longest vector stays within the method's 100 mm, a group is not drawn larger than a
    draftsman would), the room its cell keeps around it (``pad_w``, ``pad_h``: the arrows
    of its loads, its letters, its caption and equations, mm) and the least width of its
    cell (its caption fits), mm."""

    aspect: float
    cap: float
    pad_w: float
    pad_h: float
    min_w: float = 60.0

    def content_h(self, h: float) -> float:
        """Height of the drawing in a cell ``h`` mm tall, as wide as it wants."""
        return max(min(h - self.pad_h, self.cap / max(self.aspect, 1.0)), 0.0)


UNIFORM = FigureShape(1.0, math.inf, 2 * LABEL_ROOM, CAPTION + 2 * LABEL_ROOM)


def _row(shapes: list[FigureShape], width: float, h: float
         ) -> tuple[list[float], float, float, float]:
    """One row of figures ``h`` mm tall in ``width``: each cell as wide as its figure at
    that height wants, all narrowed alike when they do not fit (never under a cell's
    least width), the width left shared in proportion. Returns the cells' widths, the
    height the row uses, the area of its drawings (mm²) and the width it needs."""
    c = [s.content_h(h) for s in shapes]
    nat = [s.aspect * ci for s, ci in zip(shapes, c, strict=True)]

    def total(f: float) -> float:
        return sum(max(s.min_w, s.pad_w + n * f) for s, n in zip(shapes, nat, strict=True))

    f = 1.0
    if total(1.0) > width:
        lo, hi = 0.0, 1.0
        for _ in range(30):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if total(mid) <= width else (lo, mid)
        f = lo
    widths = [max(s.min_w, s.pad_w + n * f) for s, n in zip(shapes, nat, strict=True)]
    need = sum(widths)
    spare = max(width - need, 0.0)
    widths = [w + spare * w / sum(widths) for w in widths]
    # a figure narrowed by f is f times smaller in both directions
    used = max(s.pad_h + ci * f for s, ci in zip(shapes, c, strict=True))
    area = sum((1.0 + s.aspect) * ci * f for s, ci in zip(shapes, c, strict=True))
    return widths, used, area, need


def _splits(n: int, parts: int) -> list[list[int]]:
    """The ways to cut a sequence of n into ``parts`` consecutive non-empty runs (the
    first index of each run)."""
    import itertools

    return [[0, *cut] for cut in itertools.combinations(range(1, n), parts - 1)]


def _sheet2_grid(x0, y0, w, h, shapes: list[list[FigureShape]], row_least: float = 0.0):
    """Cells of the positions' figures (``shapes``: per position, its figures in order),
    a position's cells consecutive in reading order: either several positions in a row, or
    each position in one or more rows cut where the rows come out most even. Of these the
    arrangement whose drawings are the largest (their total area, each figure as large as
    its row's height and width let it), no row lower than ``row_least`` where the height
    allows (the lever's arrows, the letters need it). Returns (the smallest drawing side,
    the rows of cells per position, the height used, the drawings' area, the width the
    rows need, the rows' height)."""
    n_pos = len(shapes)
    per_pos = len(shapes[0])
    best = None
    options: list[list[list[tuple[int, int]]]] = []
    for m in range(1, n_pos + 1):  # m positions side by side in a row
        rows = [[(p, i) for p in range(r, min(r + m, n_pos)) for i in range(per_pos)]
                for r in range(0, n_pos, m)]
        options.append(rows)
    for r in range(2, min(per_pos, 3) + 1):  # each position in r rows
        def cut_cost(starts, p=0):
            runs = [list(range(a, b)) for a, b in zip(starts, [*starts[1:], per_pos],
                                                        strict=True)]
            return max(sum(shapes[p][i].aspect + 0.3 for i in run) for run in runs), runs
        starts = min(_splits(per_pos, r), key=lambda st: cut_cost(st)[0])
        runs = cut_cost(starts)[1]
        options.append([[(p, i) for i in run] for p in range(n_pos) for run in runs])
    for rows in options:
        rh = h / len(rows)
        if rh - CAPTION < 20.0:
            continue
        laid = [_row([shapes[p][i] for p, i in row], w, rh) for row in rows]
        if any(nd > w + 1e-6 for _, _, _, nd in laid):  # the least widths overflow
            continue
        if any(rh < max(shapes[p][i].pad_h for p, i in row) + 10.0 for row in rows):
            continue  # a figure's arrows and letters need more height than the row has
        area = sum(a for _, _, a, _ in laid)
        if best is None or area > best[0] * 1.02:
            best = (area, rows, laid, rh)
    fits = best is not None
    if best is None:  # nothing fits: one row per position, as narrow as it comes
        rows = [[(p, i) for i in range(per_pos)] for p in range(n_pos)]
        rh = h / n_pos
        best = (0.0, rows, [_row([shapes[p][i] for p, i in row], w, rh) for row in rows], rh)
    _, rows, laid, rh = best
    # each row as tall as its figures use; what is left of the height is the caller's
    used = [min(rh, max(u, row_least)) for _, u, _, _ in laid]
    out: list[list[Rect | None]] = [[None] * per_pos for _ in range(n_pos)]
    y = y0
    side = math.inf
    for row, (widths, _, _, _), uh in zip(rows, laid, used, strict=True):
        x = x0
        for (p, i), wd in zip(row, widths, strict=True):
            out[p][i] = Rect(x, y, x + wd, y + uh)
            side = min(side, wd, rh - CAPTION) if fits else 0.0
            x += wd
        y += uh
    need = max(nd for _, _, _, nd in laid)
    return (side, tuple(tuple(c for c in cells if c is not None) for cells in out), y - y0,
            best[0], need, rh)


def _stretch(rows, y0: float, extra: float):
    """The cells moved down and made taller so that ``extra`` mm more height is shared by
    their rows alike."""
    tops = sorted({round(c.y0, 6) for cells in rows for c in cells})
    each = extra / max(len(tops), 1)
    shift = {t: n * each for n, t in enumerate(tops)}
    return tuple(tuple(Rect(c.x0, c.y0 + shift[round(c.y0, 6)], c.x1,
                            c.y1 + shift[round(c.y0, 6)] + each) for c in cells)
                 for cells in rows)


COLUMN_AREA = 0.8  #: the column is taken when its figures are this share of the strip's or more
SIDE_W = 250.0  #: least width of sheet 2's column of the charts and the table (A1), mm
CHART_MIN_H = 150.0  #: Q(s) goes under the table when it has this much height there, A1, mm
STRIP_MAX = 0.42  #: sheet 2's strip of the charts grows to this share of the frame's height


def sheet2_layout(page: Page, n_groups: int, n_wanted: int, table_height,
                  shapes=None, table_width: float | None = None,
                  mechanism: bool = True) -> Sheet2Layout:
    """Cut ``page`` for sheet 2: as many of the ``n_wanted`` positions as give cells of at
    least :func:`sheet2_cell_min` (at least one), the strip of the charts and the table.

    ``shapes`` (per wanted position, a :class:`FigureShape` per figure in the order of the
    force plans) sizes each cell to its figure (:func:`_sheet2_grid`): a thin group or plan
    gets a narrow cell, one analysed position gets large figures. The height the figures do
    not use (each is drawn at most at its cap) goes to the strip, whose charts grow up to
    STRIP_MAX of the frame, then back to the rows. ``table_height(width)`` is the height
    the table needs (split into parts) in a box ``width`` mm wide, ``table_width`` its
    width in one part: the table stands above the title block, as wide as it needs, the
    two charts share the rest of the strip's width. Raises LayoutError when even one
    position leaves no useful cell.
    """
    f = page.frame
    k = min(1.0, f.height / 584.0)
    kw = min(1.0, f.width / 816.0)
    x0, x1 = f.x0 + 4.0, f.x1 - 4.0
    tb_w, tb_h = TITLE_BLOCK_SIZE
    charts_min = (CHART_W[0] + CHART_W[1]) * kw + GAP
    t_w = x1 - x0 - charts_min - GAP
    if table_width is not None:
        t_w = min(max(table_width, tb_w - 4.0), t_w)
    t_h = table_height(t_w)
    strip = max(SHEET2_STRIP * k, t_h + GAP + tb_h + 2.0)
    header = Rect(f.x0 + GRAPH26_SIZE[0] + GAP, f.y0 + 1.0, x1, f.y0 + GRAPH26_SIZE[1] - 1.0)
    y0 = f.y0 + GRAPH26_SIZE[1] + 3.0
    per_pos = 2 * n_groups + 3 + mechanism
    least = sheet2_cell_min(page)
    H = f.y1 - strip - GAP - y0
    side_min = SIDE_W * kw
    for n in range(max(n_wanted, 1), 0, -1):
        sh = [list(shapes[p]) if shapes else [UNIFORM] * per_pos for p in range(n)]
        side, rows, used, area, _, rh = _sheet2_grid(x0, y0, x1 - x0, H, sh, 2 * least)
        # several positions in rows under twice the least cell: their plans too small to read
        side = side if n == 1 or rh >= 2 * least else min(side, rh / 2)
        # the charts and the table in a column right of the figures, when the figures
        # leave that width free at the full height of the frame
        col = None
        if shapes and n > 1:  # one position: its figures are few, the charts wide
            full = f.y1 - 4.0 - y0
            wg = x1 - x0 - side_min - GAP
            g = _sheet2_grid(x0, y0, wg, full, sh, 2 * least)
            # the column holds the table and two charts of a useful height
            charts_h = f.y1 - tb_h - 2 * GAP - y0 - table_height(x1 - x0 - GAP - g[4])
            if (g[0] >= least and g[4] <= wg + 1e-6 and g[3] >= COLUMN_AREA * area
                    and charts_h >= 2 * CHART_MIN_H * k):
                wg = g[4]  # the rows as wide as they need, the column the rest
                col = (wg, _sheet2_grid(x0, y0, wg, full, sh, 2 * least))
        if side >= least or n == 1 or col is not None:
            break
    if col is not None:
        wg, (side, rows, used, area, _, _) = col
        rows = _stretch(rows, y0, f.y1 - 4.0 - y0 - used)
        cx0 = x0 + wg + GAP
        t_w2 = x1 - cx0
        t_h2 = table_height(t_w2)
        cy1 = f.y1 - tb_h - GAP
        table = Rect(cx0, y0, x1, y0 + t_h2)
        top = y0 + t_h2 + GAP
        hm = (cy1 - top - GAP) * 0.55
        return Sheet2Layout(page, rows, header, Rect(cx0, top + hm + GAP, x1, cy1),
                            Rect(cx0, top, x1, top + hm), table, mechanism)
    if side < 0.75 * least:
        raise LayoutError(f"sheet 2 leaves cells of {side:.0f} mm on {page.format}: "
                          "choose a larger format")
    left = H - used
    # one analysed position: its figures are drawn at their caps, the charts take all the
    # height they leave (several positions: the rows keep what the strip does not take)
    grow = left if len(rows) == 1 else min(left, max(STRIP_MAX * f.height - strip, 0.0))
    strip += grow
    rows = _stretch(rows, y0, left - grow)
    sy0, sy1 = f.y1 - strip, f.y1 - 4.0
    tx0 = x1 - t_w
    table = Rect(tx0, sy0, x1, f.y1 - tb_h - GAP)
    under = Rect(tx0, sy0 + t_h + GAP, x1, f.y1 - tb_h - GAP)
    if under.height >= 0.6 * CHART_MIN_H * k:
        # a tall strip: Q(s) under the table, above the title block; Mур(φ) the rest
        return Sheet2Layout(page, rows, header, under, Rect(x0, sy0, tx0 - GAP, sy1), table,
                            mechanism)
    wc = tx0 - GAP - x0 - GAP
    wq = wc * CHART_W[0] / (CHART_W[0] + CHART_W[1])
    return Sheet2Layout(page, rows, header, Rect(x0, sy0, x0 + wq, sy1),
                        Rect(x0 + wq + GAP, sy0, tx0 - GAP, sy1), table, mechanism)

def plan_room(cell: Rect) -> float:
    """The largest extent (diameter) of a plan that fits ``cell`` with its letters, mm."""
    return min(cell.width, cell.height - CAPTION) - 2 * LABEL_ROOM


def _column_widths(header, rows, height: float = 3.5, pad: float = 3.0) -> list[float]:
    """Each column as wide as its widest entry lettered at ``height`` (type B), plus ``pad``."""
    return [max(lettering_width(c, height) for c in
                [str(header[j])] + [str(row[j]) for row in rows] if c.strip()) + pad
            for j in range(len(header))]


def table_parts(header, rows, width: float, key: int = 1) -> list[FittedTable]:
    """A table too wide for ``width`` split into parts one under the other, each as wide
    as fits, every part after the first repeating the ``key`` leading columns (the
    position), as a continued table is drawn (GOST 2.105: «Продолжение таблицы»).

    Nothing is left out; a single column wider than ``width`` is a LayoutError.
    """
    widths = _column_widths(header, rows)
    n = len(header)
    parts: list[list[int]] = []
    j = 0
    while j < n:
        cols = list(range(min(key, n))) if parts else []
        acc = sum(widths[c] for c in cols)
        start = max(j, len(cols)) if not parts else j
        j = start
        while j < n and acc + widths[j] <= width + 1e-9:
            cols.append(j)
            acc += widths[j]
            j += 1
        if j == start:
            raise LayoutError(f"a table column ({header[j]!r}) is wider than the "
                              f"{width:.0f} mm its place has")
        parts.append(cols)
    return [FittedTable([str(header[c]) for c in cols], [[row[c] for c in cols] for row in rows],
                        [widths[c] for c in cols], len(cols), n) for cols in parts]


def split_table_height(header, rows, width: float, key: int = 1) -> float:
    """Height of the table under its title, split by :func:`table_parts` (inf: cannot)."""
    try:
        parts = table_parts(header, rows, width, key)
    except LayoutError:
        return math.inf
    return sum(CAPTION + ROW * (len(rows) + 1) for _ in parts) + TABLE_PART_GAP * (
        len(parts) - 1)
