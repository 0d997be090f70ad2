# %% [markdown]
# # Кривошипный пресс: от файла варианта до маховика
#
# Прогулка по graphplan на встроенном прессе (`examples/press.toml`): структура, положения,
# планы скоростей и ускорений как построения, планы сил рабочего положения, рычаг Жуковского
# и маховик — с учебной страницей каждого построения.
#
# Запустите как скрипт, `python examples/tutorial_ru.py [ПАПКА]` (он печатает числа и пишет
# страницы в ПАПКУ, по умолчанию `tutorial-out/`), или откройте как блокнот (ячейки `# %%` —
# формат percent Jupytext; VS Code и JupyterLab с Jupytext выполняют их по одной). В блокноте
# планы, листы и уроки показывают себя сами: план — цветным чертежом, лист — своим SVG, урок —
# интерактивной страницей (вперёд/назад, клавиши ← →, «Проверь себя»).
# English: `examples/tutorial.py`.

# %%
import sys
from pathlib import Path

from graphplan.dynamics import dynamic_model, flywheel, simulate
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.project import analyze, sheet_scales
from graphplan.teaching import lesson, write_lesson
from graphplan.units import UNITS_RU, unit_text

OUT = Path(sys.argv[1]) if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else Path(
    "tutorial-out")


def show(obj, text: str = "") -> None:
    """В блокноте — показать ``obj`` (его представление); в скрипте — напечатать ``text``."""
    try:
        from IPython import get_ipython
        from IPython.display import display

        if get_ipython() is not None:
            display(obj)
            return
    except ImportError:
        pass
    if text:
        print(text)


def num(x: float, digits: int = 4) -> str:
    """Число так, как его пишут в расчёте: с десятичной запятой, без степеней десяти."""
    text = f"{x:.0f}" if abs(x) >= 10 ** digits else f"{x:.{digits}g}"
    return text.replace(".", ",")


def scale_ru(basis: str) -> str:
    """Строка масштаба по-русски: ``Kl = lOA/OA = 0,08/80 = 0,001 м/мм``."""
    head, _, unit = basis.rpartition(" ")
    return head.replace(".", ",") + " " + unit_text(unit, "ru") if unit in UNITS_RU else basis


# %% [markdown]
# ## 1. Вариант и его структура
# Файл варианта задаёт звенья в мм, частоту вращения кривошипа, группу Ассура (группа
# II класса 2-го порядка ВВП: шатун A–B и ползун B на вертикальной направляющей), массы и силу
# технологического сопротивления. `analyze` проверяет структуру (формула Чебышева, группы
# Ассура) и точно решает положения, скорости и ускорения во всех положениях.

# %%
mech = load(bundled_example("press"))
a = analyze(mech)
print("подвижность:", a.structure.mobility_equation)
print("формула строения:", a.structure.formula)
print(f"ω1 = {num(mech.crank.omega)} рад/с, ход H = {num(a.cycle.stroke * 1000)} мм")
print("положения:", ", ".join(a.kin.labels))

# %% [markdown]
# ## 2. План скоростей положения 2, линия за линией
# Каждый шаг построения чертится в миллиметрах листа в масштабах листа 1; величины читаются
# с чертежа (`v_B = pb·Kv`).

# %%
sc = sheet_scales(mech, a.kin)
k = a.kin.labels.index("2")
vp = velocity_plan(mech, a.kin, k, sc.kl, sc.kv)
print(scale_ru(sc.kl.basis))
print(scale_ru(sc.kv.basis))
for s in vp.steps:
    print(f"{s.number}. {s.text_ru}")
show(vp)

# %% [markdown]
# То же построение как урок: по одному шагу — векторное уравнение, что известно и что нет,
# перевод в масштаб. Страница самодостаточна (открывается без сети).

# %%
les = lesson(a, "velocity", "2")
page = write_lesson(les, OUT, lang="ru", frames=True)[0]
print("учебная страница:", page)
show(les)

# %% [markdown]
# ## 3. План ускорений положения 2
# Нормальные ускорения ω²·l берутся из отсчётов плана скоростей; касательное ускорение и
# относительное ускорение ползуна замыкают уравнение.

# %%
ap = acceleration_plan(mech, a.kin, k, sc.kl, sc.ka, vp)
for name, r in ap.readings.items():
    print(f"{name} = {num(r.mm)} мм → {r.quantity} = {num(r.value)} {unit_text(r.unit, 'ru')}")
print(f"ε2 = {num(ap.rates['2'])} рад/с² (против часовой стрелки — положительно)")
print("учебная страница:", write_lesson(lesson(a, "acceleration", "2"), OUT, lang="ru")[0])
show(ap)

# %% [markdown]
# ## 4. Силовой анализ рабочего положения (2)
# Сначала группа 2–3 (уравнение моментов относительно B с плечами, измеренными на схеме, затем
# многоугольник сил в масштабе Kp), затем кривошип: Мур из ΣM_O = 0.

# %%
kw = a.kin.labels.index("(2)")
forces = a.forces  # проект решает каждую стадию один раз (solve_project)
print(f"Мур в (2), точная кинетостатика: {num(forces.M_bal[kw], 6)} Н·м")
fl = lesson(a, "forces", "(2)")
for r in fl.results:
    print(f"  {r.segment} = {num(r.mm)} мм → {r.quantity} = {num(r.value, 6)} "
          f"{unit_text(r.unit, 'ru')}")
print("учебная страница:", write_lesson(fl, OUT, lang="ru")[0])

# %% [markdown]
# ## 5. Рычаг Жуковского для (2)
# План скоростей, повёрнутый на 90°, каждая сила — в изображении своей точки: сумма их моментов
# относительно полюса даёт тот же Мур (баланс мощностей).

# %%
lv = lesson(a, "zhukovsky", "(2)")
print(lv.steps[-1].notes[0]["ru"])
print("учебная страница:", write_lesson(lv, OUT, lang="ru")[0])

# %% [markdown]
# ## 6. Маховик
# Приведённый момент сопротивления Mс(φ) графически интегрируется в диаграммы работ; диаграмма
# энергомасс и касательные к ней под углами ψmax, ψmin дают момент инерции маховика для δ;
# моделирование проверяет его.

# %%
model = dynamic_model(a)
fw = flywheel(model)
print(f"δ = {num(fw.delta)}, Mд = {num(fw.M_d, 5)} Н·м, ΔTmax = {fw.dT_max:.0f} Дж")
print(f"kl = {num(fw.segment_mm)} мм → JI = {num(fw.J_I, 5)} кг·м², Iм = {num(fw.I_m, 5)} кг·м²")
print(f"обод: D = {num(fw.size.D)} м, масса {fw.size.mass:.0f} кг")
sim = simulate(model, fw.I_m, cycles=3)
print(f"δ при моделировании с этим маховиком: {num(sim.delta_actual)} (задано {num(fw.delta)})")
print("учебная страница:", write_lesson(lesson(a, "flywheel"), OUT, lang="ru")[0])

# %% [markdown]
# ## 7. Лист
# Лист 1 (кинематический анализ) в блокноте показывает себя сам; в скрипте он записывается.

# %%
from graphplan.drawing import kinematics_sheet  # noqa: E402
from graphplan.render.svg import write_svg  # noqa: E402

sheet = kinematics_sheet(a, lang="ru", diagrams=False)
print("лист 1:", write_svg(sheet, OUT / "sheet1.svg"))
show(sheet)
