"""The package's metadata: one version, a license file that matches the declared license."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import spinimpact

ROOT = Path(__file__).resolve().parents[1]


def test_one_version_read_from_the_package_metadata():
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
    assert spinimpact.__version__ == declared
    assert f'"{declared}"' not in (ROOT / "src/spinimpact/__init__.py").read_text()
    citation = (ROOT / "CITATION.cff").read_text()
    assert re.search(rf'^version: "{re.escape(declared)}"$', citation, re.MULTILINE)
    assert f"## {declared}" in (ROOT / "CHANGELOG.md").read_text()


def test_the_license_file_is_the_declared_license():
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["license"]
    assert declared == "BSD-3-Clause"
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("BSD 3-Clause License")
    assert "Neither the name of the copyright holder" in text
    assert "license: BSD-3-Clause" in (ROOT / "CITATION.cff").read_text()
