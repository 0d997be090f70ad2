"""A variant file to start from: ``graphplan new FAMILY -o VARIANT.toml``.

The family's bundled example (press, engine, compressor, pump, shaper, slotter, crusher,
four-bar, …) with every key explained in Russian (or English) on the line above it — its
meaning, its unit and its sign convention, said where it is used — and a header that says
how to edit and check the file. A student changes the numbers of their own variant and runs
``graphplan analyze`` to see the mechanism before drawing the sheets.
"""

from __future__ import annotations

import re

from ..errors import InputError
from ..files import bundled_example, examples_dir

#: Russian (and a few English) names of the families → the bundled example
ALIASES = {
    "пресс": "press", "кривошипный_пресс": "press", "двигатель": "engine", "двс": "engine",
    "компрессор": "compressor", "насос": "pump", "строгальный": "shaper",
    "поперечно-строгальный": "shaper", "долбёжный": "slotter", "долбежный": "slotter",
    "дробилка": "crusher", "щековая_дробилка": "crusher", "четырёхзвенник": "fourbar",
    "четырехзвенник": "fourbar", "four-bar": "fourbar", "crank-rocker": "fourbar",
    "кулисный": "scotch_yoke", "шестизвенник": "sixbar_press",
}

#: (section, key) or key → what it is, in Russian and English
KEYS: dict[str, tuple[str, str]] = {
    "variant": ("вариант задания", "the variant"),
    "name": ("короткое имя варианта (по умолчанию — имя файла)",
             "short name (default: the file name)"),
    "description": ("одна строка: что это за механизм", "one line describing the mechanism"),
    "length_unit": ("единица всех длин файла: \"mm\" (мм) или \"m\" (м)",
                    "unit of every length in the file: \"mm\" or \"m\""),
    "frame": ("стойка (неподвижное звено)", "the frame"),
    "frame.link": ("номер звена стойки", "the frame's link number"),
    "frame.points": ("неподвижные точки стойки { ИМЯ = [x, y] }, в единицах length_unit; "
                     "ось x вправо, ось y вверх",
                     "fixed points { NAME = [x, y] }, length unit; x to the right, y up"),
    "crank": ("кривошип (начальное звено)", "the crank (the driving link)"),
    "link": ("номер звена", "link number"),
    "joints": ("[ось, палец]: точка стойки и имя новой точки кривошипа",
               "[pivot, pin]: a frame point and the crank's new point"),
    "length": ("длина кривошипа l_OA, в единицах length_unit", "l_OA, length unit"),
    "rpm": ("частота вращения кривошипа n1, об/мин (или omega)", "n1, rev/min (or omega)"),
    "omega": ("угловая скорость кривошипа ω1, рад/с (вместо rpm)", "ω1 instead of rpm, rad/s"),
    "direction": ("направление вращения: \"ccw\" — против часовой стрелки (ω1 > 0), "
                  "\"cw\" — по часовой (ω1 < 0)",
                  "sense of rotation: \"ccw\" (ω1 > 0) or \"cw\" (ω1 < 0)"),
    "mass": ("масса звена, кг", "mass, kg"),
    "weight": ("вес звена G вместо массы, Н", "weight G instead of the mass, N"),
    "inertia": ("момент инерции звена относительно центра масс I_S, кг·м²",
                "moment of inertia about the centre of mass, kg·m²"),
    "centre": ("центр масс звена: точка звена", "the centre of mass: a point of the link"),
    "dyads": ("группы Ассура (диады) в порядке присоединения",
              "the Assur groups (dyads) in the order they are attached"),
    "kind": ("вид диады: RRR (ВВВ), RRP (ВВП), RPR (ВПВ), PRP (ПВП), RPP (ВПП)",
             "kind of the dyad: RRR, RRP, RPR, PRP, RPP"),
    "dyads.links": ("[i, j]: два новых звена диады", "[i, j]: the two new links"),
    "branch": ("ветвь сборки \"+\" или \"-\": какое из двух положений диады взять; "
               "graphplan analyze предупредит, если выходное звено пойдёт не туда",
               "assembly branch \"+\" or \"-\"; graphplan analyze warns when the output "
               "moves against the working direction"),
    "points": ("точка на звене: центр масс, точка приложения силы, конец коромысла",
               "a point on a link: a centre of mass, where a force acts, a rocker's end"),
    "points.name": ("имя новой точки", "a new point's name"),
    "points.link": ("звено, которому принадлежит точка", "the link the point belongs to"),
    "points.from": ("начало отсчёта F: точка этого звена", "origin F: a point of that link"),
    "points.toward": ("направление d = F→toward: другая точка того же звена",
                      "direction d = F→toward: another point of the link"),
    "along": ("расстояние вдоль d, в единицах length_unit", "distance along d, length unit"),
    "across": ("расстояние поперёк d, положительно влево от d, в единицах length_unit",
               "distance across d, positive to the left of d, length unit"),
    "fraction": ("вместо along: доля расстояния F→toward (0.5 — середина)",
                 "instead of along: the fraction of F→toward (0.5: the mid-point)"),
    "links": ("звено: масса, момент инерции, центр масс", "a link: mass, inertia, centre"),
    "lengths": ("длины звеньев диады [l_i, l_j], в единицах length_unit",
                "[l_i, l_j], length unit"),
    "offset": ("смещение кулисы от шарнира (RPR), в единицах length_unit",
               "RPR: the offset of the slot from the pin, length unit"),
    "guide": ("направляющая: прямая на звене", "a guide: a straight line on a link"),
    "through": ("точка звена (имя) или [x, y] для направляющей на стойке",
                "a point of that link (a name), or [x, y] for a frame guide"),
    "angle": ("направление, градусы: на стойке от оси x против часовой стрелки "
              "(0 — вправо, 90 — вверх), на звене — от его оси",
              "direction, degrees: from +x counter-clockwise on the frame, from the link's "
              "axis on a link"),
    "toward": ("вместо angle: направление на эту точку", "instead of angle: toward this point"),
    "guides": ("две направляющие (ПВП)", "PRP: the two guides"),
    "slot_angle": ("угол паза на кулисе (ВПП), градусы", "RPP: the angle of the slot, degrees"),
    "gravity": ("силы тяжести", "gravity"),
    "enabled": ("false — не учитывать силы тяжести", "false leaves the weights out"),
    "g": ("ускорение свободного падения, м/с²", "m/s²"),
    "loads": ("нагрузки: силы и моменты полезного сопротивления и движущие силы "
              "(docs/variant-format.md §6)",
              "technological loads and driving forces (docs/variant-format.md §6)"),
    "point": ("точка приложения силы", "where a force acts"),
    "max": ("масштаб значений диаграммы: нагрузка = значение·max, Н или Н·м",
            "the diagram's scale: load = value·max, N or N·m"),
    "value": ("постоянная нагрузка вместо диаграммы, Н или Н·м", "a constant load, N or N·m"),
    "unit": ("единица max и value: \"N\" (по умолчанию), \"kN\"; у момента \"N·m\", \"kN·m\"",
             "unit of max and value: \"N\" (default), \"kN\"; a moment's \"N·m\", \"kN·m\""),
    "diagram": ("диаграмма [[x, значение], …]: x — доля хода 0…1 (over = \"stroke\") или "
                "угол кривошипа", "[[x, value], …]: x the travel fraction or the crank angle"),
    "sense": ("\"resists\" — сопротивление (против движения, по умолчанию), \"drives\" — "
              "движущая сила, \"diagram\" — знак задан диаграммой",
              "resists (default), drives, or diagram: the value's sign"),
    "over": ("абсцисса диаграммы: \"stroke\" — доля хода звена, \"crank\" — угол кривошипа",
             "the abscissa: the travel fraction (stroke) or the crank angle (crank)"),
    "stroke": ("на каком ходе действует нагрузка: \"working\" (рабочий), \"idle\" "
               "(холостой) или \"both\"", "the strokes: working, idle or both"),
    "strokes": ("по диаграмме на каждый ход цикла (индикаторная диаграмма)",
                "one diagram per stroke of the cycle (an indicator diagram)"),
    "travel": ("столбец s/H табличной индикаторной диаграммы",
               "the travel column s/H of a tabulated indicator diagram"),
    "travel_link": ("звено, перемещение которого — абсцисса (по умолчанию нагруженный "
                    "ползун или выходное звено)", "the link whose travel is the abscissa"),
    "working": ("направление рабочего хода выходного звена: \"+\" — по оси, \"-\" — против",
                "the working stroke's direction: + along the axis, - against it"),
    "phase": ("угол кривошипа от начала цикла, с которого начинается список ходов, градусы",
              "crank angle before which the stroke list does not start, degrees"),
    "bore": ("диаметр цилиндра D (length_unit): сила газов (p − p_атм)·πD²/4",
             "cylinder bore D: a gas force (p − p_ambient)·πD²/4"),
    "rod": ("диаметр штока d: полость со стороны штока цилиндра двойного действия, "
            "сила (p − p_атм)·π(D² − d²)/4 к крышке",
            "the piston rod's diameter d: the rod's side of a double-acting cylinder, a force "
            "(p − p_ambient)·π(D² − d²)/4 toward the head"),
    "p_max": ("значения диаграммы — доли p_max (в pressure_unit)",
              "the diagram's values are fractions of p_max"),
    "p_ambient": ("атмосферное давление, вычитается из давлений (pressure_unit)",
                  "subtracted from the pressures"),
    "pressure_unit": ("единица давлений: \"MPa\", \"kPa\", \"Pa\", \"bar\"",
                      "unit of the pressures"),
    "positions": ("положения механизма для расчёта", "the positions to analyse"),
    "count": ("число равных шагов за оборот кривошипа (обычно 8 или 12)",
              "equal steps over one turn (8 or 12 as a rule)"),
    "first": ("первое положение: \"start\" (начало рабочего хода), \"end\" или угол, градусы",
              "start, end, or a crank angle in degrees"),
    "number_from": ("номер первого положения", "label of the first position"),
    "extra": ("дополнительные положения (например, рабочие (2), (3))",
              "extra named positions"),
    "label": ("обозначение положения, например \"(2)\"", "its label, e.g. (2)"),
    "phi": ("угол кривошипа, градусы", "crank angle, degrees"),
    "from": ("крайнее положение, от которого отсчитывается поворот", "a dead centre"),
    "turn": ("поворот кривошипа от него, градусы", "crank turn from it, degrees"),
    "cycle": ("цикл, градусы поворота кривошипа: 360 или 720 (четырёхтактный двигатель)",
              "the cycle, degrees of crank: 360, or 720 for a four-stroke process"),
    "output": ("выходное звено", "the output link"),
    "kinetostatics": ("силовой расчёт", "force analysis"),
    "neglect_below": ("порог правила пренебрежения: 0.10 — нагрузки меньше 10 % не "
                      "учитываются", "relative threshold of the neglect rule (0.10: 10 %)"),
    "shift_inertia_force": ("заменить силу и момент инерции одной смещённой силой",
                            "one shifted force instead of force and couple"),
    "dynamics": ("динамика машинного агрегата (лист 3)", "the machine unit (sheet 3)"),
    "delta": ("коэффициент неравномерности хода δ", "coefficient of fluctuation δ"),
    "efficiency": ("КПД привода η", "efficiency of the drive η"),
    "crank_inertia": ("момент инерции деталей вала кривошипа, кг·м²",
                      "inertia of the crank shaft's parts, kg·m²"),
    "flywheel": ("маховик", "the flywheel"),
    "shape": ("форма маховика: \"rim\" (обод) или \"disc\" (диск)", "rim or disc"),
    "shaft": ("вал, на котором стоит маховик: \"crank\" или \"motor\"",
              "the shaft it sits on: crank or motor"),
    "b_ratio": ("отношение ширины обода к диаметру b/D", "b/D"),
    "h_ratio": ("отношение толщины обода к диаметру h/D", "h/D"),
    "density": ("плотность материала маховика, кг/м³", "density, kg/m³"),
    "grid": ("сетка интегрирования", "integration grid"),
    "intervals": ("число интервалов диаграмм", "intervals of the diagrams"),
    "motor_series": ("серия электродвигателей каталога", "motor catalogue series"),
    "motor_speed": ("синхронная частота вращения двигателя, об/мин",
                    "synchronous speed, rev/min"),
    "drawing": ("листы чертежей", "the sheets"),
    "format": ("формат листа: A1, A2 или A3", "sheet format: A1, A2 or A3"),
    "Kl": ("масштаб длин, м/мм", "scale of lengths, m/mm"),
    "Kv": ("масштаб скоростей, (м/с)/мм", "scale of velocities, (m/s)/mm"),
    "Ka": ("масштаб ускорений, (м/с²)/мм", "scale of accelerations, (m/s²)/mm"),
    "Kp": ("масштаб сил, Н/мм", "scale of forces, N/mm"),
    "reading_mm": ("точность чтения отрезков на планах, мм (0 — точно)",
                   "reading precision of the plans, mm (0: exact)"),
    "language": ("язык надписей листов: \"ru\" или \"en\"", "ru or en"),
    "accelerations": ("положения, планы ускорений которых чертятся на листе 1",
                      "the positions of sheet 1's acceleration plans"),
    "title_block": ("основная надпись (штамп)", "the title block"),
    "title": ("наименование изделия в основной надписи", "the title"),
    "designation": ("обозначение документа, например ТММ.КП.00.00.00", "the designation"),
    "author": ("разработал (ФИО студента)", "the author"),
    "checker": ("проверил (ФИО преподавателя)", "the checker"),
    "teacher": ("преподаватель", "the teacher"),
    "group": ("группа", "the group"),
    "school": ("кафедра / учебное заведение", "the school"),
    "sheet": ("номер листа", "the sheet number"),
    "sheets": ("число листов (заполняется на первом листе)", "the number of sheets"),
    "date": ("дата", "the date"),
    "litera": ("литера (У — учебный)", "the litera"),
    "scale": ("масштаб изображения", "the scale"),
}

#: The families' one-line descriptions in Russian (the bundled examples' are English)
DESCRIPTION_RU = {
    "compressor": "Двухцилиндровый V-образный компрессор: кривошип, два шатуна и поршня на одном "
                  "пальце (ВВП, ВВП); силы газов по индикаторным диаграммам",
    "crusher": "Щековая дробилка: эксцентрик, шатун и задняя распорная плита (ВВВ), передняя "
               "распорная плита и подвижная щека (ВВВ); момент сопротивления камня на щеке",
    "engine": "Четырёхтактный одноцилиндровый двигатель: кривошип, шатун, поршень (ВВП); сила "
              "газов по индикаторной диаграмме за 720°",
    "fourbar": "Кривошипно-коромысловый четырёхзвенник с моментом сопротивления на коромысле "
               "(диада ВВВ)",
    "offset_slider": "Дезаксиальный кривошипно-ползунный механизм ножовочной пилы, кривошип "
                     "вращается по часовой стрелке (K = 1,10)",
    "press": "Центральный кривошипно-ползунный механизм пресса (курсовой проект по ТММ)",
    "pump": "Поршневой насос простого действия: кривошип, шатун, плунжер (ВВП); давления "
            "всасывания и нагнетания за два хода",
    "scotch_yoke": "Кулисный (синусный) механизм плунжерного насоса: одна диада ВПП",
    "shaper": "Поперечно-строгальный станок: кривошип, качающаяся кулиса (ВПВ), шатун и ползун "
              "(ВВП); H = 0,4 м, K = 1,5",
    "shaper_prp": "Поперечно-строгальный станок, привод кулиса–камень–ползун: ВПВ, затем ПВП; "
                  "H = 0,4 м, K = 1,5",
    "sixbar_press": "Кривошипно-коленный пресс: диада ВВВ, затем диада ВВП на коленном шарнире",
    "slotter": "Долбёжный станок: кривошип, качающаяся кулиса (ВПВ), шатун и вертикальный "
               "долбяк (ВВП); H = 150 мм, K = 1,5",
}

#: A dyad's joints, by its kind (docs/variant-format.md §3)
JOINTS = {
    "RRR": ("[A, B, C]: A — точка соседнего звена звена i, B — новый внутренний шарнир, "
            "C — точка соседнего звена звена j (например, опора на стойке)",
            "[A, B, C]: A on the neighbour of link i, B the new inner joint, C on the "
            "neighbour of link j (e.g. a frame pivot)"),
    "RRP": ("[A, B]: A — существующая точка, B — новый шарнир ползуна",
            "[A, B]: A an existing point, B the slider's new joint"),
    "RPR": ("[A, C]: A — палец, несущий камень (существует), C — опора кулисы",
            "[A, C]: A the pin carrying the block, C the slotted link's pivot"),
    "PRP": ("[B]: новый палец, соединяющий звенья i и j", "[B]: the new pin joining i and j"),
    "RPP": ("[A, D]: A — палец, несущий камень, D — новая точка звена j на его направляющей",
            "[A, D]: A the pin carrying the block, D link j's new point on its guide"),
}

HEADER = {
    "ru": """# Вариант задания graphplan — заготовка семейства «{family}».
# Измените числа на данные своего варианта и проверьте механизм:
#   graphplan analyze {name}           (структура, ход, K, предупреждения)
#   graphplan sheets {name} -o листы   (листы 1–3, таблицы, отчёт)
# Правила файла (TOML): десятичная ТОЧКА (0.08, не 0,08); текст в кавычках;
# сохраните файл в кодировке UTF-8. Единицы: длины — в length_unit, массы — кг,
# силы — Н, моменты — Н·м (у нагрузки можно unit = "kN" или "kN·m"), углы — градусы
# (от оси x против часовой стрелки), частота вращения — об/мин (или omega, рад/с).
# Над каждым ключом — что он значит; все ключи, правила знаков и разобранные
# примеры семейств — в docs/variant-format.ru.md репозитория graphplan.
""",
    "en": """# A graphplan variant — a start from the family "{family}".
# Change the numbers to your variant's and check the mechanism:
#   graphplan analyze {name}
#   graphplan sheets {name} -o sheets
# TOML: a decimal POINT (0.08); text in quotes; save as UTF-8. Units: lengths in
# length_unit, masses kg, forces N, moments N·m, angles degrees (from +x, counter-
# clockwise), speed rev/min (or omega, rad/s); a load may give unit = "kN" or "kN·m".
# Above each key: what it means; every key, the sign conventions and a worked example
# of each family: docs/variant-format.md in the graphplan repository.
""",
}

_SECTION = re.compile(r"^\[\[?\s*([A-Za-z_][\w.\"-]*)\s*\]\]?\s*(?:#.*)?$")
_KEY = re.compile(r"^(\s*)([A-Za-z_][A-Za-z0-9_]*)\s*=")


def families() -> tuple[str, ...]:
    """The families (bundled examples) a variant can start from."""
    return tuple(sorted(p.stem for p in examples_dir().glob("*.toml")))


def family_name(name: str) -> str:
    """The bundled example of a family name (Russian names too: «двигатель» → engine)."""
    key = name.strip().lower().replace(" ", "_")
    key = ALIASES.get(key, key)
    if key not in families():
        raise InputError(f"new: family: expected one of {', '.join(families())} (or "
                         f"{', '.join(sorted(ALIASES))}) (got {name!r})")
    return key


def _explain(section: str, key: str, lang: str) -> str | None:
    i = 0 if lang == "ru" else 1
    top = section.split(".")[0]
    for k in (f"{top}.{key}", key):
        if k in KEYS:
            return KEYS[k][i]
    return None


def variant_template(family: str, *, lang: str = "ru", name: str = "variant.toml") -> str:
    """The text of a new variant file of ``family`` (see the module docstring)."""
    if lang not in HEADER:
        raise InputError(f"new: lang: expected 'ru' or 'en' (got {lang!r})")
    fam = family_name(family)
    source = bundled_example(fam).read_text(encoding="utf-8")
    out = [HEADER[lang].format(family=fam, name=name)]
    stem = re.sub(r"[^\w-]", "_", name.removesuffix(".toml")) or fam
    section = ""
    kind = ""
    for line in source.splitlines():
        if lang == "ru":  # the example's own comments are English: the Russian file explains
            if line.lstrip().startswith("#"):  # every key itself
                continue
            line = _drop_comment(line)
        m = _SECTION.match(line)
        if m and not line.lstrip().startswith("#"):
            section = m.group(1)
            what = _explain("", section.split(".")[0] if section.startswith("links.")
                            else section.split(".")[-1], lang)
            if what:
                out.append(f"# [{section}] — {what}")
            out.append(line)
            continue
        k = _KEY.match(line)
        if k and not line.lstrip().startswith("#"):
            if section == "dyads" and k.group(2) == "kind":
                kind = line.split("=", 1)[1].strip().strip('"')
            what = _explain(section, k.group(2), lang)
            if section == "dyads" and k.group(2) == "joints" and kind in JOINTS:
                what = JOINTS[kind][0 if lang == "ru" else 1]
            if what:
                out.append(f"{k.group(1)}# {k.group(2)}: {what}")
            if section == "variant" and k.group(2) == "name":  # the new file's own name
                line = f'name = "{stem}"'
            if section == "variant" and k.group(2) == "description" and lang == "ru":
                line = f'description = "{DESCRIPTION_RU.get(fam, fam)}"'
        out.append(line)
    return re.sub(r"\n{3,}", "\n\n", "\n".join(out)) + "\n"  # where comments were dropped


def _drop_comment(line: str) -> str:
    """``line`` without its trailing ``# comment`` (a ``#`` inside a string is kept)."""
    quote = ""
    for i, ch in enumerate(line):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            return line[:i].rstrip()
    return line
