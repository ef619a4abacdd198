# docs/usage.md's table "One name per quantity" against the code: each name in it is the one the
# interface uses (issue 39, item 4). The command options in the commands' help, the scene keys in
# asperity.law_curves_keywords, the Python attributes on the module's classes, the C names in
# asperity.h, the CSV columns and JSON keys in what the commands write.
import json
import os
import re
import subprocess
from pathlib import Path

import pytest

import asperity
from asperity import topography

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ["ASPERITY_TABLEGEN"]).resolve().parents[2] if "ASPERITY_TABLEGEN" in os.environ else ROOT / "build"
COMMAND = BUILD / "asperity"
COLUMNS = ("quantity", "unit", "option", "scene", "python", "c", "written", "why")


def table_rows():
    text = (ROOT / "docs" / "usage.md").read_text()
    section = text.split("## One name per quantity", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        if not line.startswith("| ") or line.startswith("| quantity") or line.startswith("|---"):
            continue
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        assert len(cells) == len(COLUMNS), line
        rows.append(dict(zip(COLUMNS, cells)))
    assert len(rows) >= 20
    return rows


def name_of(cell):
    """The name in a cell (`name`), or None for —."""
    match = re.fullmatch(r"`([^`]+)`", cell)
    assert match or cell == "—", f"a cell holds one `name` or —, not {cell!r}"
    return match.group(1) if match else None


def run(*arguments):
    return subprocess.run([str(COMMAND), *arguments], capture_output=True, text=True)


@pytest.fixture(scope="module")
def help_texts():
    return "\n".join(run(command, "--help").stdout for command in ("contact", "surface", "exact-contact", "eval"))


@pytest.fixture(scope="module")
def written_names():
    """The CSV columns and JSON keys the commands write."""
    surface = ["--dist", "weibull", "--shape", "2", "--rms", "5e-7", "--radius", "1e-4", "--density", "1e10",
               "--area", "1e-4", "--modulus", "1e11", "--quiet"]
    names = set(run("contact", *surface, "--pressure", "1e6").stdout.splitlines()[0].split(","))
    names.add("stiffness_per_area_N_per_m3")  # the --table CSV's (contact_curves.hpp; checked below)
    report = json.loads((ROOT / "docs" / "surfaces" / "afm-zsensor" / "report.json").read_text())

    def keys(value):
        if isinstance(value, dict):
            for key, item in value.items():
                yield key
                yield from keys(item)
        elif isinstance(value, list):
            for item in value:
                yield from keys(item)

    return names | set(keys(report))


def python_attribute(dotted):
    owner, attribute = dotted.split(".")
    cls = getattr(asperity, owner, None) or getattr(topography, owner)
    return hasattr(cls, attribute) or attribute in getattr(cls, "_fields", ())


@pytest.mark.parametrize("row", table_rows(), ids=lambda row: row["quantity"])
def test_every_name_in_the_table_is_the_codes(row, help_texts, written_names):
    header = (ROOT / "include" / "asperity" / "asperity.h").read_text()
    if option := name_of(row["option"]):
        assert re.search(r"^\s+" + re.escape(option) + r"\b", help_texts, re.M), option
    if scene := name_of(row["scene"]):
        assert scene in asperity.law_curves_keywords, scene
    if python := name_of(row["python"]):
        assert python_attribute(python), python
    if c_name := name_of(row["c"]):
        assert re.search(r"\b" + re.escape(c_name) + r"\b", header), c_name
    if written := name_of(row["written"]):
        assert written in written_names, written


def test_the_contact_curves_csv_spells_stiffness_per_area_as_the_table_says():
    # the one spelling of N/m^3 (it was stiffness_per_area_Pa_per_m in the --table CSV)
    assert "stiffness_per_area_Pa_per_m" not in (ROOT / "include" / "asperity" / "contact_curves.hpp").read_text()
