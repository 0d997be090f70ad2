"""The layer rule of the stage packages (issue 16), read off the source by an AST walk.

A module imports only from its own package and from LOWER layers, in this order:

    base (errors, numbers, units, geometry, files, paper, console, safe_text, i18n, fonts)
    → model → kinematics → forces → dynamics → plans → project → reports → drawing → render
    → checking | teaching → note → shell

``checking`` and ``teaching`` are applications side by side: neither imports the other. The
shell is the package root's public API, ``cli``, ``outputs`` (writing the files) and
``__main__``. Every import counts, at the top of a module or inside a function, and so does
an import under ``if TYPE_CHECKING``. The only upward imports allowed are the ones named in
:data:`ALLOWED_UPWARD`, each with its reason; and there is no import cycle between modules
outside those edges.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent / "graphplan"

#: Layers, lowest first; a package's rank is its index (checking and teaching share one).
LAYERS: tuple[tuple[str, ...], ...] = (
    ("errors", "numbers", "units", "geometry", "files", "paper", "console", "safe_text",
     "i18n", "fonts"),
    ("model",),
    ("kinematics",),
    ("forces",),
    ("dynamics",),
    ("plans",),
    ("project",),
    ("reports",),
    ("drawing",),
    ("render",),
    ("checking", "teaching"),
    ("note",),  # the explanatory note: the answer key's lines (checking) written as a document
    ("", "cli", "outputs", "__main__"),  # "": the package root (graphplan/__init__.py)
)
#: Packages of one layer that still must not import each other.
APART = {"checking", "teaching"}

#: Upward imports that stay for now, each with its reason: (importer, imported) → why.
#: Imports inside a Jupyter display hook (a method named ``_repr_*_``) are the standing
#: exception and need no entry: a value shows itself as the picture or table of its stage.
#: None is left: the loader's motor names and speeds moved to model/settings.py, the tables'
#: text widths to the base module fonts.py and the tables' items to drawing/tables.py.
ALLOWED_UPWARD: dict[tuple[str, str], str] = {}


def _unit(module: str) -> str:
    """The layer unit of a module: its stage package, a base module, or a shell module."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def _rank(module: str) -> int:
    unit = _unit(module)
    for k, names in enumerate(LAYERS):
        if unit in names:
            return k
    raise AssertionError(f"{module}: not in any layer of tests/test_architecture.py")


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(ROOT.rglob("*.py")):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


MODULES = _modules()


def _target(base: str, name: str) -> str:
    """``from base import name``: the module ``base.name`` if it is one, else ``base``."""
    sub = f"{base}.{name}"
    return sub if sub in MODULES else base


def _imports(module: str, path: Path) -> list[tuple[str, int, bool]]:
    """(imported graphplan module, line, in a display hook) of every import in a module."""
    is_pkg = path.name == "__init__.py"
    package = module if is_pkg else module.rpartition(".")[0]
    out = []

    def walk(node: ast.AST, hook: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
                walk(child, hook or HOOK.fullmatch(child.name) is not None)
                continue
            if isinstance(child, ast.ImportFrom):
                if child.level:
                    parts = package.split(".")
                    parts = parts[: len(parts) - (child.level - 1)]
                    base = ".".join(parts + ([child.module] if child.module else []))
                else:
                    base = child.module or ""
                if base == "graphplan" or base.startswith("graphplan."):
                    out.extend((_target(base, a.name), child.lineno, hook) for a in child.names)
            elif isinstance(child, ast.Import):
                out.extend((a.name, child.lineno, hook) for a in child.names
                           if a.name == "graphplan" or a.name.startswith("graphplan."))
            walk(child, hook)

    walk(ast.parse(path.read_text(encoding="utf-8")), False)
    return out


HOOK = re.compile(r"_repr_\w+_")
ALL_EDGES = sorted({(m, t, line, hook) for m, p in MODULES.items()
                    for t, line, hook in _imports(m, p) if t != m})
#: (importer, imported, line) of the imports that count (display hooks left out)
EDGES = [(m, t, line) for m, t, line, hook in ALL_EDGES if not hook]


def _upward(importer: str, imported: str) -> bool:
    a, b = _rank(importer), _rank(imported)
    if b > a:
        return True
    units = {_unit(importer), _unit(imported)}
    return b == a and len(units) == 2 and units <= APART


def test_every_import_exists():
    """A lazy import of a module that moved fails only when its function runs: caught here."""
    gone = [f"{MODULES[m]}:{line}: {m} imports {t}" for m, t, line, _ in ALL_EDGES
            if t not in MODULES]
    assert not gone, "imports of modules that do not exist:\n" + "\n".join(gone)


def test_every_module_has_a_layer():
    for m in MODULES:
        _rank(m)


def test_no_upward_import():
    if any(t not in MODULES for _, t, _ in EDGES):
        return  # test_every_import_exists names them
    bad = [f"{MODULES[m]}:{line}: {m} imports {t}"
           for m, t, line in EDGES if _upward(m, t) and (m, t) not in ALLOWED_UPWARD]
    assert not bad, "upward imports (lower layers must not know higher ones):\n" + "\n".join(bad)


def test_the_allowed_upward_imports_still_exist():
    """An allowance whose import is gone is dropped from the list (it would hide a new one)."""
    present = {(m, t) for m, t, _ in EDGES}
    stale = [f"{m} → {t}" for m, t in ALLOWED_UPWARD if (m, t) not in present]
    assert not stale, "remove from ALLOWED_UPWARD: " + ", ".join(stale)


def _cycles(edges: set[tuple[str, str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    graph: dict[str, set[str]] = {}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
        graph.setdefault(b, set())
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_cycle():
    edges = {(m, t) for m, t, _ in EDGES if (m, t) not in ALLOWED_UPWARD}
    cycles = _cycles(edges)
    assert not cycles, "import cycles:\n" + "\n".join(" ⇄ ".join(c) for c in cycles)


@pytest.mark.parametrize("package", sorted(
    {m for m in MODULES if MODULES[m].name == "__init__.py" and m != "graphplan"}))
def test_each_package_says_what_it_is_for(package):
    doc = ast.get_docstring(ast.parse(MODULES[package].read_text(encoding="utf-8")))
    assert doc, f"{package}: no docstring"
    assert len(doc.splitlines()[0]) <= 100


def test_the_layer_test_sees_an_upward_import():
    """The rule itself: a kinematics module importing a sheet would be caught."""
    assert _upward("graphplan.kinematics.cycle", "graphplan.drawing.sheet")
    assert _upward("graphplan.checking.engine", "graphplan.teaching.model")
    assert not _upward("graphplan.drawing.sheet1", "graphplan.project.scales")
    assert not _upward("graphplan.plans.forces", "graphplan.plans.constructions")
    hooks = [(m, t) for m, t, _, hook in ALL_EDGES if hook]
    assert ("graphplan.drawing.sheet", "graphplan.render.svg") in hooks  # Sheet._repr_svg_
    assert _cycles({("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")}) == [["a", "b", "c"]]


def test_the_readme_module_map_names_every_package_in_layer_order():
    """README's module map is the tree of the package: a line for every stage package
    (``model/`` …) and every base module, in the order of :data:`LAYERS`."""
    text = (ROOT.parent / "README.md").read_text(encoding="utf-8")
    tree = text.split("Module map", 1)[1].split("```", 2)[1]
    heads = [ln.split()[0] for ln in tree.splitlines()
             if ln.startswith("    ") and not ln.startswith("     ")]
    packages = sorted(p.name for p in ROOT.iterdir()
                      if p.is_dir() and (p / "__init__.py").is_file())
    assert sorted(h.rstrip("/") for h in heads if h.endswith("/")) == packages
    assert set(LAYERS[0]) <= set(tree.split("\n    ", 2)[1].split("\n")[0].split())
    order = [h.rstrip("/") for h in heads if h.endswith("/")]
    rank = {name: k for k, names in enumerate(LAYERS) for name in names}
    assert [rank[p] for p in order] == sorted(rank[p] for p in order)


def test_one_toml_reader():
    """Every TOML input (a variant, a student's work, a class file, settings) is read by
    :func:`graphplan.model.parse_toml`: its one-line errors and hints hold for all of them.
    Was: checking/batch.py read students' files with its own ``tomllib.loads``."""
    readers = sorted(m for m, p in MODULES.items()
                     if any(isinstance(n, (ast.Import, ast.ImportFrom))
                            and "tomllib" in ([a.name for a in n.names] if isinstance(n, ast.Import)
                                              else [n.module or ""])
                            for n in ast.walk(ast.parse(p.read_text(encoding="utf-8")))))
    assert readers == ["graphplan.model.toml_text"]


def _imports_of_graphplan(path: Path):
    """Every ``from graphplan… import name`` (absolute, or relative inside the package) in
    ``path``, at any depth of the module: (line, module, name)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    pkg = None
    if ROOT in path.parents:
        pkg = ".".join(("graphplan", *path.relative_to(ROOT).parent.parts))
    for node in ast.walk(tree):
        if not isinstance(node, ast.ImportFrom):
            continue
        if node.level:
            if pkg is None:
                continue
            base = pkg.split(".")
            base = base[: len(base) - node.level + 1]
            module = ".".join(base + ([node.module] if node.module else []))
        elif node.module and node.module.split(".")[0] == "graphplan":
            module = node.module
        else:
            continue
        for alias in node.names:
            yield node.lineno, module, alias.name


def test_every_import_of_a_graphplan_name_resolves():
    """An import inside a function is not run when a test file is collected: after a module
    is split, a test that imports a moved name from its old place fails only when it runs
    (the session-9 CI run failed on ``from graphplan.drawing.sheet import Rect`` in one test).
    Every ``from graphplan.X import Y`` in the package, the tests, the benchmarks and the
    examples names a module that imports and a name it holds (or a submodule)."""
    import importlib

    here = ROOT.parent
    files = [p for d in ("graphplan", "tests", "benchmarks", "examples", "docs")
             for p in sorted((here / d).rglob("*.py"))]
    broken = []
    for path in files:
        for line, module, name in _imports_of_graphplan(path):
            try:
                mod = importlib.import_module(module)
            except ImportError as exc:
                broken.append(f"{path.relative_to(here)}:{line}: {module} ({exc})")
                continue
            if name == "*" or hasattr(mod, name):
                continue
            try:
                importlib.import_module(f"{module}.{name}")
            except ImportError:
                broken.append(f"{path.relative_to(here)}:{line}: {name} from {module}")
    assert not broken, "imports of names that are not there:\n" + "\n".join(broken)
