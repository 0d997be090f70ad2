"""The tables of docs/benchmarks.md, written from results.json between two markers."""

from __future__ import annotations

import re
from pathlib import Path

BEGIN, END = "<!-- results: written by python -m benchmarks -->", "<!-- /results -->"


def _e(x) -> str:
    return "—" if x is None else f"{x:.1e}"


def _ms(entry: dict, key: str) -> str:
    t = entry.get("time", {}).get(key, {}).get("median_s")
    if t is None:
        return "—"
    ms = t * 1e3
    return f"{ms:.3g}"


def _us(entry: dict, key: str) -> str:
    t = entry.get("time", {}).get(key, {}).get("median_s")
    return "—" if t is None else f"{t * 1e6:.3g}"


def _kib(entry: dict) -> str:
    mem = entry.get("peak_memory_bytes", {})
    b = mem.get("full_cycle", mem.get("kinematics_cycle", mem.get("one_position_full")))
    return "—" if b is None else f"{b / 1024:.0f}"


def tables(results: dict) -> str:
    env = results["environment"]
    out = [f"Run of {results.get('grid', '')}, {env['repetitions']} repetitions, "
           f"Python {env['python']}, numpy {env['numpy']}, pylinkage {env['pylinkage']}, "
           f"numba {env['numba']}, {env['cpus']} CPUs ({env['machine']}); the whole run took "
           f"{results.get('total_run_s', 0):.0f} s."
           + (f" Load average of the machine (1/5/15 min) at the start "
              f"{'/'.join(map(str, env['load_average_at_start']))}, at the end "
              f"{'/'.join(map(str, env.get('load_average_at_end') or []))}: with other jobs "
              f"on its {env['cpus']} CPUs every figure is slower and more spread than on a "
              "quiet machine." if env.get("load_average_at_start") else ""), ""]
    if results.get("note"):
        out += [f"*{results['note']}.*", ""]
    for name, m in results["mechanisms"].items():
        out += [f"### {name}", "",
                "| method | positions | velocities | accelerations | reactions | Mур | "
                "kinematics, 360 pos., ms | + kinetostatics, ms | one position, all, µs | "
                "peak memory, KiB |",
                "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
        for meth, e in m["methods"].items():
            if meth.startswith("drafting") and e.get("magnify") != 1.0:
                continue
            er = e["errors"]
            one = _us(e, "one_position_full") if "one_position_full" in e.get("time", {}) \
                else "—"
            out.append(f"| {meth} | {_e(er['positions'])} | {_e(er['velocities'])} | "
                       f"{_e(er['accelerations'])} | {_e(er['reactions'])} | "
                       f"{_e(er['M_bal'])} | {_ms(e, 'kinematics_cycle')} | "
                       f"{_ms(e, 'full_cycle')} | {one} | {_kib(e)} |")
        out.append("")
        draft = [(e["precision_mm"], e["magnify"], e["errors"]) for meth, e in
                 m["methods"].items() if meth.startswith("drafting")]
        if draft:
            mags = sorted({d[1] for d in draft})
            out += [f"Drafting on {name}: error of the accelerations / of Mур by reading "
                    "precision (rows) and drawing scale (columns, ×1 = the sheet's).", "",
                    "| precision | " + " | ".join(f"×{f:g}" for f in mags) + " |",
                    "|---|" + "---:|" * len(mags)]
            for p in sorted({d[0] for d in draft}):
                cells = []
                for f in mags:
                    er = next(d[2] for d in draft if d[0] == p and d[1] == f)
                    cells.append(f"{_e(er['accelerations'])} / {_e(er['M_bal'])}")
                out.append(f"| {p:g} mm | " + " | ".join(cells) + " |")
            out.append("")
    sh = results.get("sheets", {}).get("press")
    if sh:
        out += ["### Sheets of the press (build, SVG, write)", "",
                "| sheet | first in the process, s | median, s | size, KiB |",
                "|---|---:|---:|---:|"]
        for name, s in sh.items():
            if name == "all":
                continue
            out.append(f"| {name} | {s['first_s']:.2f} | {s['median_s']:.2f} | "
                       f"{s['bytes'] / 1024:.0f} |")
        out += [f"| all | {sh['all']['first_s']:.2f} | {sh['all']['median_s']:.2f} | |", ""]
    sw = results.get("sweep")
    if sw:
        sizes = sw["sizes"]
        out += ["### The N sweep (press; median time of one turn, ms)", "",
                "| method | " + " | ".join(f"N = {n:,}" for n in sizes) + " |",
                "|---|" + "---:|" * len(sizes)]
        for name, ts in sw["median_s"].items():
            out.append(f"| {name} | " + " | ".join("—" if t is None else f"{t * 1e3:.3g}"
                                                   for t in ts) + " |")
        labels = {"default_over_full": "pylinkage default / graphplan full cycle (≥ 20)",
                  "numba_over_full_paired": "pylinkage numba / graphplan full cycle, by round "
                                            "(≥ 1)",
                  "full_over_closed_form": "graphplan full cycle / closed form (≤ 4 at 360)",
                  "kinematics_over_closed_form": "graphplan kinematics / closed form",
                  "numba_over_kinematics": "pylinkage numba / graphplan kinematics",
                  "general_over_full": "graphplan general objects / graphplan full cycle"}
        out += ["", "| ratio | " + " | ".join(f"N = {n:,}" for n in sizes) + " |",
                "|---|" + "---:|" * len(sizes)]
        for key, label in labels.items():
            if key not in sw["ratios"]:  # a results.json of an earlier benchmark
                continue
            out.append(f"| {label} | " + " | ".join(
                "—" if v is None else f"{v:.3g}" for v in sw["ratios"][key]) + " |")
        agree = sw.get("closed_form_agreement", {})
        if agree:
            out += ["", "The closed form agrees with graphplan (every load kept, 360 positions) "
                    "to " + ", ".join(f"{k} {v:.1e}" for k, v in agree.items()) + ".", ""]
    cmds = results.get("commands")
    if cmds:
        out += ["### Whole commands, cold (a new process each; s)", "",
                "| command | first run (empty cache) | median | min | max | runs |",
                "|---|---:|---:|---:|---:|---:|"]
        for e in cmds.values():
            out.append(f"| `{e['command']}` | {e['first_run_s']:.2f} | {e['median_s']:.2f} | "
                       f"{e['min_s']:.2f} | {e['max_s']:.2f} | {e['runs']} |")
        out.append("")
    for key, n in (("profile_press_full_cycle_s", 360), ("profile_press_full_cycle_36_s", 36)):
        prof = results.get(key)
        if prof:
            out += [f"### Where the press's full cycle goes ({n} positions, medians)", "",
                    "| part | µs |", "|---|---:|"]
            out += [f"| {k} | {v * 1e6:.0f} |" for k, v in prof.items()]
            out.append("")
    out += ["### Targets", "", "| target | measured | met |", "|---|---|---|"]
    for t in results.get("targets", []):
        if "value_paired_by_round" in t:
            val = (f"numba/graphplan {t['value_paired_by_round']:.3g} (by round; "
                   f"{t['value_numba_over_graphplan']:.3g} of the medians)")
        elif "value_ms" in t:
            val = f"{t['value_ms']:.3g} ms"
        elif "value_s" in t:
            val = f"{t['value_s']:.3g} s (first run {t['first_s']:.3g} s)"
        else:
            val = f"{t['value']:.3g}"
        met = {True: 'yes', False: '**no**', None: 'not judged'}[t['met']]
        out.append(f"| {t['target']} | {val} | {met} |")
    out.append("")
    return "\n".join(out)


def update(doc: Path, results: dict) -> bool:
    """Replace the text between the markers of ``doc``; False if it has none."""
    if not doc.is_file():
        return False
    text = doc.read_text(encoding="utf-8")
    if BEGIN not in text or END not in text:
        return False
    new = re.sub(re.escape(BEGIN) + r".*?" + re.escape(END),
                 lambda _: f"{BEGIN}\n\n{tables(results)}\n{END}", text, flags=re.S)
    doc.write_text(new, encoding="utf-8")
    return True


__all__ = ["BEGIN", "END", "tables", "update"]
