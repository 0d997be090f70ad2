"""The JSON contract: every example's output validates against the shipped JSON Schemas.

``graphplan/data/schema/`` holds the schemas of ``analyze --json`` / ``analysis.json``,
``check --json`` and the variant file (docs/json.md). The schemas are strict where the
keys are documented and open where the format grows; these tests keep them honest both
ways: every output and every example variant validates, the variant schema names exactly
the sections and keys the loader accepts, and every key of the schemas is in the docs.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import tomllib
from importlib import resources
from pathlib import Path

import pytest

jsonschema = pytest.importorskip("jsonschema")

from graphplan.model import loader  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
SCHEMAS = Path(str(resources.files("graphplan") / "data" / "schema"))


def schema(name: str) -> dict:
    data = json.loads((SCHEMAS / f"{name}.schema.json").read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(data)
    return data


def validate(instance, name: str) -> None:
    validator = jsonschema.Draft202012Validator(schema(name))
    errors = sorted(validator.iter_errors(instance), key=lambda e: list(e.absolute_path))
    assert not errors, "\n".join(f"{'/'.join(map(str, e.absolute_path))}: {e.message}"
                                 for e in errors[:10])


@pytest.mark.parametrize("variant", EXAMPLES, ids=lambda p: p.stem)
def test_every_examples_report_validates(variant):
    report = ROOT / "drawings" / variant.stem / "analysis.json"
    validate(json.loads(report.read_text(encoding="utf-8")), "analysis")


def test_analyze_json_validates_and_is_the_report():
    out = subprocess.run([sys.executable, "-m", "graphplan", "analyze", "--json"],
                         capture_output=True, cwd=ROOT, check=True, timeout=600,
                         env={**__import__("os").environ, "PYTHONPATH": str(ROOT)})
    data = json.loads(out.stdout.decode("utf-8"))
    validate(data, "analysis")
    assert data["positions"][0]["omega"]["1"] == pytest.approx(55 * 3.141592653589793 / 30)


def test_check_json_validates(tmp_path):
    from graphplan.checking.checks import checker_for
    from graphplan.checking.student import load_student

    work = load_student(ROOT / "examples" / "seed-check" / "seed.toml")
    report = checker_for(work, {}, (), None).run().to_json()
    validate(report, "check")
    assert report["summary"]["wrong"] > 0
    committed = ROOT / "examples" / "seed-check" / "report.json"
    validate(json.loads(committed.read_text(encoding="utf-8")), "check")


@pytest.mark.parametrize("variant", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_variant_validates(variant):
    validate(tomllib.loads(variant.read_text(encoding="utf-8")), "variant")


def test_a_typo_in_a_variant_is_caught_by_the_schema():
    data = tomllib.loads(EXAMPLES[0].read_text(encoding="utf-8"))
    data["crank"]["rmp"] = 50
    with pytest.raises(AssertionError, match="rmp"):
        validate(data, "variant")


def test_the_variant_schema_names_what_the_loader_accepts():
    # a section or key added to the loader must be added to the schema (docs/json.md)
    props = schema("variant")["properties"]
    assert set(props) == set(loader.SECTIONS)
    for section, keys in loader.SECTIONS.items():
        if keys is not None:
            assert set(props[section]["properties"]) == keys, section
    assert set(props["loads"]["items"]["properties"]) >= loader.LOAD_KEYS


def _keys(node, out: set[str]) -> set[str]:
    if isinstance(node, dict):
        out.update(node.get("properties", {}))
        for v in node.values():
            _keys(v, out)
    elif isinstance(node, list):
        for v in node:
            _keys(v, out)
    return out


@pytest.mark.parametrize("name", ["analysis", "check"])
def test_every_key_of_the_schemas_is_documented(name):
    docs = (ROOT / "docs" / "json.md").read_text(encoding="utf-8")
    documented = set(re.findall(r"`([^`\s]+)`", docs))
    missing = sorted(_keys(schema(name), set()) - documented)
    assert not missing, f"docs/json.md does not name: {missing}"


def test_every_schema_key_has_a_description():
    for name in ("analysis", "check", "variant"):
        def walk(node, path, name=name):
            if isinstance(node, dict):
                for k, v in node.get("properties", {}).items():
                    assert "description" in v or "$ref" in v, f"{name}: {path}.{k}"
                for k, v in node.items():
                    if k not in ("if", "then"):
                        walk(v, f"{path}.{k}")
            elif isinstance(node, list):
                for v in node:
                    walk(v, path)
        walk(schema(name), "$")
