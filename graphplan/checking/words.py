"""Numbers, units and short phrases of the reports in English and Russian."""

from __future__ import annotations

from ..numbers import report as num  # the checker's reports' numbers
from ..numbers import signed
from ..units import UNITS_RU, unit_text


def qty(x: float | None, unit: str, lang: str = "en", digits: int = 5) -> str:
    """``"4456.1 N"`` / ``"4456,1 Н"``."""
    u = "" if unit == "1" else unit_text(unit, lang)  # a ratio (K) has no unit
    return f"{num(x, lang, digits)} {u}".strip()


def pct(rel: float | None, lang: str = "en") -> str:
    """A relative difference as a signed percentage: ``+9.4 %``."""
    if rel is None:
        return "—"
    s = f"{signed(rel * 100, 1)} %"
    return s.replace(".", ",") if lang == "ru" else s


def scale_text(symbol: str, per_mm: float, lang: str = "en") -> str:
    """``Kl = 0.002 m/mm``."""
    unit = {"Kl": "m/mm", "Kv": "(m/s)/mm", "Ka": "(m/s²)/mm", "Kp": "N/mm"}.get(symbol, "")
    return f"{symbol} = {qty(per_mm, unit, lang, 6)}"


VERDICT_WORDS = {"en": {"ok": "ok", "inaccurate": "inaccurate", "wrong": "wrong",
                        "not compared": "not compared"},
                 "ru": {"ok": "верно", "inaccurate": "неточно", "wrong": "неверно",
                        "not compared": "не сравнено"}}

KIND_WORDS = {
    "en": {"arithmetic": "arithmetic", "consistency": "consistency", "unit": "unit",
           "scale": "scale", "sign": "sign", "other-variant": "other variant/position",
           "lever-arm": "lever arm", "geometry": "geometry", "formula": "formula",
           "label": "label", "propagated": "propagated", "model": "model",
           "coriolis": "Coriolis", "unreadable": "unreadable",
           # a drawing's (checking/drawing)
           "direction": "direction", "missing": "left out", "closure": "not closed"},
    "ru": {"arithmetic": "арифметика", "consistency": "согласованность", "unit": "единицы",
           "scale": "масштаб", "sign": "знак", "other-variant": "чужой вариант/положение",
           "lever-arm": "плечо", "geometry": "геометрия", "formula": "формула",
           "label": "обозначение", "propagated": "следствие", "model": "расчёт",
           "coriolis": "Кориолис", "unreadable": "не прочитано",
           "direction": "направление", "missing": "пропущено", "closure": "не замкнут"},
}


__all__ = ["KIND_WORDS", "UNITS_RU", "VERDICT_WORDS", "num", "pct", "qty", "scale_text",
           "unit_text"]
