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


def test_the_mutation_runs_name_test_files_that_exist():
    """Each mutation package's tests (tools/mutation.py) are files of tests/: a misspelt name
    would leave its package's mutants to the other files' tests and lower the score silently."""
    import importlib.util
    import sys

    spec = importlib.util.spec_from_file_location("navcore_mutation_tool", ROOT / "tools" / "mutation.py")
    mutation = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mutation  # its dataclasses look their module up there
    spec.loader.exec_module(mutation)
    missing = [
        f"{name}: {t}"
        for name, pkg in mutation.PACKAGES.items()
        for t in pkg.tests
        if not (ROOT / "tests" / t).is_file()
    ]
    assert not missing, missing
