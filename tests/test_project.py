"""Project promises: the README's test command is what CI runs; the top level is complete."""

from __future__ import annotations

import os
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_ci_runs_the_readme_test_command():
    readme = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```console\n(.*?)\n```", readme, flags=re.S)
    test_cmd = next(b for b in blocks if "nox -s tests" in b).strip()
    assert test_cmd in (ROOT / ".ci" / "run").read_text()


def test_top_level_layout():
    for name in (
        "book",
        "navcore",
        "figures",
        "tests",
        "_config.yml",
        "noxfile.py",
        "pyproject.toml",
        "README.md",
        ".ci/run",
        ".gitignore",
        "requirements/lock.txt",
        "book/_toc.yml",
    ):
        assert (ROOT / name).exists(), name


def test_hypothesis_is_derandomised_in_ci():
    """Oracle: the environment (CI set, or HYPOTHESIS_PROFILE=ci) decides the loaded profile."""
    from hypothesis import settings

    want_ci = os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev") == "ci"
    assert settings.default.derandomize is want_ci
    ci = settings.get_profile("ci")
    assert ci.derandomize is True and ci.deadline is None
