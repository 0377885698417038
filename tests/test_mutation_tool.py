"""The mutation-testing driver (``tools/mutation.py``) run in-process, mutmut stood in for.

What the driver computes is tested on hand-made inputs: the scratch project it lays out for a
package (on a small repository in a temporary folder: the folders copied, the stale ones
replaced, the ``pyproject.toml`` with the pytest options and the ``[tool.mutmut]`` section),
the counts it reads from mutmut's ``.meta`` files (each exit code's class), the score table
and its survivors, the command and environment ``run_package`` starts mutmut with and the cut
at the budget (with a stand-in for ``subprocess.Popen``), and the options of ``main`` (with a
stand-in for ``run_package``). No mutmut run starts.

The tool is loaded under its dotted name ``tools.mutation``, the name mutmut's trampolines
recognise. Oracle in each test: the hand-made input and the result written out by hand.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tomllib
import types
from pathlib import Path

import pytest

from tests._tools import help_text, load_tool

mutation = load_tool("mutation")
ROOT = Path(__file__).resolve().parents[1]


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# --- the packages ------------------------------------------------------------------------------


def test_mutation_every_package_mutates_files_that_exist():
    """Oracle: the repository itself: each package's globs match a file (a misspelt glob would
    mutate nothing and score nothing), and no test file is named twice."""
    for name, spec in mutation.PACKAGES.items():
        for pattern in spec.mutate:
            assert list(ROOT.glob(pattern)), (name, pattern)
        assert len(set(spec.tests)) == len(spec.tests), name


def test_mutation_exit_code_classes():
    """Oracle: mutmut's exit codes sorted by hand into killed (timeouts, crashes and type
    checks included), survived (no test reaching a mutant included) and the rest."""
    from mutmut.stats import status_by_exit_code

    killed = [1, 3, 36, 24, -24, 152, 255, -11, -9, 37]
    survived = [0, 5, 33]
    assert {status_by_exit_code[c] for c in killed} <= mutation.KILLED
    assert {status_by_exit_code[c] for c in survived} <= mutation.SURVIVED
    assert mutation.KILLED == {"killed", "timeout", "segfault", "caught by type check"}
    assert mutation.SURVIVED == {"survived", "no tests"}
    for code in (None, 2, 34, 35):
        assert status_by_exit_code[code] not in mutation.KILLED | mutation.SURVIVED


# --- scratch_project ---------------------------------------------------------------------------


PYPROJECT = """\
[tool.pytest.ini_options]
testpaths = ["tests"]
addopts = "-ra --strict-markers"
markers = ["slow: a slow test"]
filterwarnings = ["error"]
xfail_strict = true

[tool.ruff]
line-length = 110
"""


def _repo(root: Path) -> Path:
    """A small repository: the package, its tests and tools (each with a ``__pycache__`` and
    a ``_build`` folder), the book and its configuration."""
    for folder in ("navcore", "tests", "tools", "book"):
        _write(root / folder / "m.py", f"# {folder}\n")
        _write(root / folder / "__pycache__" / "m.pyc", "")
        _write(root / folder / "_build" / "x.html", "")
    _write(root / "book" / "_ext" / "e.py", "# ext\n")
    _write(root / "_config.yml", "title: T\n")
    _write(root / "ARCHITECTURE.md", "# layers\n")
    _write(root / "pyproject.toml", PYPROJECT)
    return root


@pytest.fixture
def repo(tmp_path, monkeypatch) -> Path:
    """The small repository as the tool's checkout, its scratch projects under ``work``."""
    root = _repo(tmp_path / "repo")
    monkeypatch.setattr(mutation, "ROOT", root)
    monkeypatch.setattr(mutation, "WORK", tmp_path / "work")
    return root


def _pyproject(**mutmut: str) -> str:
    """The scratch project's ``pyproject.toml`` for the small repository, by hand."""
    section = {
        "source_paths": '["navcore"]',
        "also_copy": '["tools"]',
        "only_mutate": '["navcore/x/*"]',
        "pytest_add_cli_args_test_selection": '["tests/test_a.py", "tests/test_b.py"]',
        "do_not_mutate_patterns": json.dumps(mutation.NOT_MUTATED),
        "warmup": "collect",
        **mutmut,
    }
    return (
        "[tool.pytest.ini_options]\n"
        'markers = ["slow: a slow test"]\n'
        'filterwarnings = ["error"]\n'
        "xfail_strict = true\n"
        'addopts = "-p no:cacheprovider"\n'
        "\n"
        "[tool.mutmut]\n"
        f"source_paths = {section['source_paths']}\n"
        f"also_copy = {section['also_copy']}\n"
        f"only_mutate = {section['only_mutate']}\n"
        f"pytest_add_cli_args_test_selection = {section['pytest_add_cli_args_test_selection']}\n"
        'pytest_add_cli_args = ["-x", "-q"]\n'
        f"do_not_mutate_patterns = {section['do_not_mutate_patterns']}\n"
        "use_git_change_detection = false\n"
        'process_isolation = "forkserver"\n'
        f'forkserver_warmup = "{section["warmup"]}"\n'
        "timeout_multiplier = 5.0\n"
        "timeout_constant = 10.0\n"
    )


def test_mutation_scratch_project_of_a_model_package(repo, tmp_path, monkeypatch):
    """Oracle: a package mutating ``navcore/x/*`` with two test files: the folders copied
    without caches or builds, and the ``pyproject.toml`` written out by hand."""
    monkeypatch.setitem(
        mutation.PACKAGES, "demo", mutation.Package(["navcore/x/*"], ["test_a.py", "test_b.py"])
    )
    work = mutation.scratch_project("demo")
    assert work == tmp_path / "work" / "demo"
    assert sorted(p.name for p in work.iterdir()) == ["navcore", "pyproject.toml", "tests", "tools"]
    for folder in ("navcore", "tests", "tools"):
        assert sorted(p.name for p in (work / folder).iterdir()) == ["m.py"]
        assert (work / folder / "m.py").read_text() == f"# {folder}\n"
    text = (work / "pyproject.toml").read_text()
    assert text == _pyproject()
    assert tomllib.loads(text)["tool"]["mutmut"]["do_not_mutate_patterns"] == mutation.NOT_MUTATED


def test_mutation_scratch_project_options_of_a_package(repo, tmp_path, monkeypatch):
    """Oracle: a package with a deselection, no lines spared, code run at import, the book
    and its configuration copied and its sources including the tools: the copies and the
    ``[tool.mutmut]`` lines that change, by hand."""
    spec = mutation.Package(
        ["tools/*"],
        ["test_a.py"],
        deselect="slow_one or other",
        sources=("navcore", "tools", "book/_ext"),
        copy=("_config.yml", "book"),
        not_mutated=[],
        import_time=True,
    )
    monkeypatch.setitem(mutation.PACKAGES, "demo", spec)
    work = mutation.scratch_project("demo")
    names = sorted(p.name for p in work.iterdir())
    assert names == ["_config.yml", "book", "navcore", "pyproject.toml", "tests", "tools"]
    assert (work / "_config.yml").read_text() == "title: T\n"
    assert (work / "book" / "_ext" / "e.py").read_text() == "# ext\n"
    assert (work / "book" / "m.py").read_text() == "# book\n"
    assert not (work / "book" / "_build").exists() and not (work / "book" / "__pycache__").exists()
    assert (work / "pyproject.toml").read_text() == _pyproject(
        source_paths='["navcore", "tools", "book/_ext"]',
        also_copy='["_config.yml", "book"]',
        only_mutate='["tools/*"]',
        pytest_add_cli_args_test_selection='["tests/test_a.py", "-k", "not (slow_one or other)"]',
        do_not_mutate_patterns="[]",
        warmup="none",
    )


def test_mutation_scratch_project_of_the_tools_package(repo, tmp_path):
    """Oracle: the repository's own ``tools`` package: its tests, its deselection, the tools
    among the sources (so not copied again), the book and the layer map copied."""
    work = mutation.scratch_project("tools")
    mutmut = tomllib.loads((work / "pyproject.toml").read_text())["tool"]["mutmut"]
    spec = mutation.PACKAGES["tools"]
    assert mutmut["source_paths"] == ["navcore", "tools"]
    assert mutmut["also_copy"] == ["book", "ARCHITECTURE.md"]
    assert mutmut["only_mutate"] == ["tools/*"]
    assert mutmut["pytest_add_cli_args_test_selection"] == [
        *("tests/" + t for t in spec.tests),
        "-k",
        "not (errata_and_ledger_links or interactive_ledger_filters)",
    ]
    names = sorted(p.name for p in work.iterdir())
    assert names == ["ARCHITECTURE.md", "book", "navcore", "pyproject.toml", "tests", "tools"]


def test_mutation_scratch_project_refreshes_copies_and_drops_old_verdicts(repo, tmp_path, monkeypatch):
    """Oracle: a second layout after the repository changed: a stale copied file is gone, the
    new one is there, a file in the project that is not a copy stays; mutmut's ``mutants``
    folder goes, unless kept."""
    monkeypatch.setitem(mutation.PACKAGES, "demo", mutation.Package(["navcore/x/*"], ["test_a.py"]))
    work = mutation.scratch_project("demo")
    _write(work / "navcore" / "stale.py", "")
    _write(work / "mutants" / "navcore" / "m.py.meta", "{}")
    _write(work / "mutmut-run.log", "log")
    _write(repo / "navcore" / "new.py", "")
    mutation.scratch_project("demo", keep=True)
    assert sorted(p.name for p in (work / "navcore").iterdir()) == ["m.py", "new.py"]
    assert (work / "mutants" / "navcore" / "m.py.meta").exists()
    mutation.scratch_project("demo")
    assert not (work / "mutants").exists()
    assert (work / "mutmut-run.log").read_text() == "log"
    mutation.scratch_project("demo")  # no mutants folder to remove
    assert not (work / "mutants").exists()


# --- count_results and table -------------------------------------------------------------------


def _meta(work: Path, module: str, codes: dict) -> None:
    _write(work / "mutants" / module, json.dumps({"exit_code_by_key": codes, "durations_by_key": {}}))


def test_mutation_count_results_reads_each_exit_code(tmp_path):
    """Oracle: two modules' ``.meta`` files with one mutant of each class, a file with no
    verdicts and files that are not ``.py.meta``: the counts and the survivors, in the order
    of the files and of their mutants."""
    _meta(
        tmp_path,
        "tools/b.py.meta",
        {"tools.b.x_f__mutmut_1": 0, "tools.b.x_f__mutmut_2": 1, "tools.b.x_f__mutmut_3": 33},
    )
    _meta(
        tmp_path,
        "tools/a.py.meta",
        {
            "tools.a.x_g__mutmut_1": 3,
            "tools.a.x_g__mutmut_2": 36,
            "tools.a.x_g__mutmut_3": -11,
            "tools.a.x_g__mutmut_4": 37,
            "tools.a.x_g__mutmut_5": 5,
            "tools.a.x_g__mutmut_6": None,
            "tools.a.x_g__mutmut_7": None,
            "tools.a.x_g__mutmut_8": 34,
            "tools.a.x_g__mutmut_9": 2,
            "tools.a.x_g__mutmut_10": None,
        },
    )
    _write(tmp_path / "mutants" / "tools" / "c.py.meta", "{}")
    _meta(tmp_path, "tools/d.meta", {"tools.d.x_h__mutmut_1": 0})
    _meta(tmp_path, "mutmut-stats.json", {"tools.d.x_h__mutmut_2": 0})
    assert mutation.count_results(tmp_path) == {
        "killed": 5,
        "survived": 3,
        "not checked": 3,
        "other": 2,
        "total": 13,
        "survivors": [
            "tools.a.x_g__mutmut_5 (no tests)",
            "tools.b.x_f__mutmut_1 (survived)",
            "tools.b.x_f__mutmut_3 (no tests)",
        ],
    }


def test_mutation_count_results_without_a_run(tmp_path):
    """Oracle: no ``mutants`` folder: every count zero, no survivors."""
    assert mutation.count_results(tmp_path / "none") == {
        "killed": 0,
        "survived": 0,
        "not checked": 0,
        "other": 0,
        "total": 0,
        "survivors": [],
    }


def _row(package, killed, survived, not_checked=0, minutes=1.26, cut=False, survivors=()) -> dict:
    return {
        "package": package,
        "total": killed + survived + not_checked,
        "killed": killed,
        "survived": survived,
        "not checked": not_checked,
        "minutes": minutes,
        "cut": cut,
        "survivors": list(survivors),
    }


LEGEND = [
    "",
    "Score = killed / (killed + survived); timeouts count as killed, mutants no test",
    "reaches as survived; unchecked mutants (budget) are excluded from the score.",
    "Survivors examined and found equivalent are described in tests/mutation_equivalents.md.",
]


def test_mutation_table_rows_scores_and_survivors():
    """Oracle: four packages (3 of 4 killed; 2 of 3 with one unchecked; none judged, cut at
    the budget; all killed) and two with survivors: the table written out by hand."""
    rows = [
        _row("gnss", 3, 1, survivors=["a.x_f__mutmut_1 (survived)"]),
        _row("tools", 2, 1, not_checked=1, minutes=30.04, survivors=["b (no tests)", "c (survived)"]),
        _row("units", 0, 0, not_checked=5, minutes=0.0, cut=True),
        _row("frames", 7, 0, minutes=2.0),
    ]
    assert (
        mutation.table(rows)
        == "\n".join(
            [
                "| package | mutants | killed | survived | not checked | score | minutes | complete |",
                "|---|---:|---:|---:|---:|---:|---:|---|",
                "| gnss | 4 | 3 | 1 | 0 | 75.0 % | 1.3 | yes |",
                "| tools | 4 | 2 | 1 | 1 | 66.7 % | 30.0 | no (budget) |",
                "| units | 5 | 0 | 0 | 5 | - | 0.0 | no (budget) |",
                "| frames | 7 | 7 | 0 | 0 | 100.0 % | 2.0 | yes |",
                *LEGEND,
                "",
                "Survivors in gnss:",
                "",
                "- `a.x_f__mutmut_1 (survived)`",
                "",
                "Survivors in tools:",
                "",
                "- `b (no tests)`",
                "- `c (survived)`",
            ]
        )
        + "\n"
    )


def test_mutation_table_a_cut_run_with_every_mutant_checked_is_incomplete():
    """Oracle: a run stopped at the budget just after its last mutant: not complete; a run
    with none killed scores 0.0 %."""
    text = mutation.table([_row("ledger", 0, 2, cut=True)])
    assert text.splitlines()[2] == "| ledger | 2 | 0 | 2 | 0 | 0.0 % | 1.3 | no (budget) |"
    assert text == "\n".join([*text.splitlines()[:3], *LEGEND]) + "\n"


def test_mutation_table_says_why_a_run_is_incomplete():
    """Oracle: the rows written out by hand: mutmut failing (exit 1, not cut) is named as such
    even with every mutant unchecked; a failure at the budget's cut is the budget; a run with
    no mutants has no results; mutants in no column are counted in the last column and the
    legend says what they are (and only then)."""
    failed = {**_row("gnss", 0, 0, not_checked=3), "returncode": 1}
    cut = {**_row("units", 1, 0, not_checked=2, cut=True), "returncode": -15}
    empty = {**_row("frames", 0, 0), "returncode": 0}
    other = {**_row("ledger", 2, 1), "total": 5, "other": 2, "returncode": 0}
    lines = mutation.table([failed, cut, empty, other]).splitlines()
    assert lines[2:6] == [
        "| gnss | 3 | 0 | 0 | 3 | - | 1.3 | no (mutmut exited 1) |",
        "| units | 3 | 1 | 0 | 2 | 100.0 % | 1.3 | no (budget) |",
        "| frames | 0 | 0 | 0 | 0 | - | 1.3 | no (no results) |",
        "| ledger | 5 | 2 | 1 | 0 | 66.7 % | 1.3 | yes; 2 other |",
    ]
    assert lines[6:9] == LEGEND[:3]
    assert lines[9] == "'other': mutants mutmut reports as skipped, suspicious or interrupted (in no column)."
    assert "'other'" not in mutation.table([empty])


# --- run_package -------------------------------------------------------------------------------


class _Mutmut:
    """A stand-in for ``subprocess.Popen`` running mutmut: records the command and keyword
    arguments; ``wait`` raises ``TimeoutExpired`` the first time if ``hangs``."""

    def __init__(self, hangs: bool = False, returncode: int = 0):
        self.hangs, self.returncode, self.calls, self.waits, self.pid = hangs, returncode, [], [], 4242

    def __call__(self, cmd, **kwargs):
        kwargs["stdout"].write("mutmut output\n")
        self.calls.append((cmd, {**kwargs, "stdout": kwargs["stdout"].name}))
        return self

    def wait(self, timeout=None):
        self.waits.append(timeout)
        if self.hangs and len(self.waits) == 1:
            raise subprocess.TimeoutExpired("mutmut", timeout)
        return self.returncode


def _run_setup(tmp_path, monkeypatch, proc: _Mutmut) -> list:
    """Stand-ins for the scratch project (recorded), mutmut, the clock and the counts."""
    work = tmp_path / "work"
    work.mkdir()
    projects = []
    monkeypatch.setattr(
        mutation, "scratch_project", lambda package, keep: projects.append((package, keep)) or work
    )
    monkeypatch.setattr(mutation.subprocess, "Popen", proc)
    monkeypatch.setattr(mutation, "time", types.SimpleNamespace(monotonic=iter([100.0, 190.0]).__next__))
    monkeypatch.setattr(mutation, "count_results", lambda w: {"killed": 1, "work": w})
    return projects


def test_mutation_run_package_starts_mutmut_in_the_scratch_project(tmp_path, monkeypatch):
    """Oracle: the command, its folder, log and environment (caches off, the CI profile), the
    budget in seconds, and the counts with the minutes (90 s) and the status."""
    proc = _Mutmut(returncode=3)
    projects = _run_setup(tmp_path, monkeypatch, proc)
    monkeypatch.setenv("NAVCORE_OTHER", "kept")
    for name in ("HYPOTHESIS_PROFILE", "NAVCORE_CACHE", "NAVCORE_TEST_CACHE", "NAVCORE_NO_DISK_CACHE"):
        monkeypatch.setenv(name, "replaced")  # whatever the session (or a mutation run) set
    counts = mutation.run_package("gnss", 2.5, 3)
    work = tmp_path / "work"
    assert counts == {
        "killed": 1,
        "work": work,
        "package": "gnss",
        "minutes": 1.5,
        "cut": False,
        "returncode": 3,
    }
    assert projects == [("gnss", False)]
    ((cmd, kwargs),) = proc.calls
    assert cmd == [sys.executable, "-m", "mutmut", "run", "--max-children", "3"]
    assert kwargs == {
        "cwd": work,
        "env": {
            **os.environ,
            "HYPOTHESIS_PROFILE": "ci",
            "NAVCORE_CACHE": "off",
            "NAVCORE_TEST_CACHE": "off",
            "NAVCORE_NO_DISK_CACHE": "1",
        },
        "stdout": str(work / "mutmut-run.log"),
        "stderr": subprocess.STDOUT,
        "start_new_session": True,
    }
    assert proc.waits == [150.0]
    assert (work / "mutmut-run.log").read_text() == "mutmut output\n"


@pytest.mark.parametrize(
    ("keep", "mutants", "expected_keep"),
    [(True, None, True), (False, ["tools.a*", "tools.b*"], True), (False, [], False)],
)
def test_mutation_run_package_keeps_the_verdicts_for_named_mutants(
    tmp_path, monkeypatch, keep, mutants, expected_keep
):
    """Oracle: ``keep``, or named mutants (which are added to the command), keep the
    scratch project's verdicts."""
    proc = _Mutmut()
    projects = _run_setup(tmp_path, monkeypatch, proc)
    mutation.run_package("tools", 1.0, 1, keep, mutants)
    assert projects == [("tools", expected_keep)]
    assert proc.calls[0][0][4:] == ["--max-children", "1", *(mutants or [])]


def test_mutation_run_package_stops_mutmut_at_the_budget(tmp_path, monkeypatch):
    """Oracle: mutmut still running at the budget: its process group is sent SIGTERM, waited
    for, and the run is marked cut."""
    proc = _Mutmut(hangs=True, returncode=-15)
    _run_setup(tmp_path, monkeypatch, proc)
    killed = []
    monkeypatch.setattr(mutation.os, "killpg", lambda pid, sig: killed.append((pid, sig)))
    counts = mutation.run_package("gnss", 0.5, 2)
    assert killed == [(4242, 15)]
    assert proc.waits == [30.0, None]
    assert (counts["cut"], counts["returncode"], counts["minutes"]) == (True, -15, 1.5)


# --- main --------------------------------------------------------------------------------------


def test_mutation_main_help_describes_the_options(capsys):
    """Oracle: the docstring's first line and the options' help, as written in the tool."""
    out = help_text(mutation.main, capsys)
    for text in (
        "Mutation testing with mutmut, one package at a time: the models, the ledger, the tools.",
        "--budget-min BUDGET_MIN wall-clock minutes per package",
        "--max-children MAX_CHILDREN",
        "--out OUT",
        "--report-only tabulate the last runs, run nothing",
        "--keep reuse mutmut's cached verdicts (if the tests did not change)",
        "--mutants PATTERN [PATTERN ...] re-run only these mutants (globs), one package",
        "PACKAGE packages to run (default all): " + ", ".join(mutation.PACKAGES),
    ):
        assert text in out


def test_mutation_main_report_only_tabulates_every_package(tmp_path, monkeypatch, capsys):
    """Oracle: no package named: one row per package of :data:`PACKAGES` in order, the
    counts read from the scratch projects (one with a survivor), nothing run; the table
    printed and written to ``_build/mutation.md`` of the checkout by default."""
    monkeypatch.setattr(mutation, "ROOT", tmp_path)
    monkeypatch.setattr(mutation, "WORK", tmp_path / "work")
    monkeypatch.setattr(mutation, "run_package", lambda *a, **k: pytest.fail("a run started"))
    _meta(tmp_path / "work" / "gnss", "navcore/gnss/a.py.meta", {"navcore.gnss.a.x_f__mutmut_1": 0})
    _meta(tmp_path / "work" / "tools", "tools/b.py.meta", {"tools.b.x_g__mutmut_1": 1})
    assert mutation.main(["--report-only"]) == 0
    text = (tmp_path / "_build" / "mutation.md").read_text()
    rows = text.splitlines()[2 : 2 + len(mutation.PACKAGES)]
    assert [r.split(" | ")[0][2:] for r in rows] == list(mutation.PACKAGES)
    assert "| gnss | 1 | 0 | 1 | 0 | 0.0 % | 0.0 | yes |" in rows
    assert "| tools | 1 | 1 | 0 | 0 | 100.0 % | 0.0 | yes |" in rows
    assert "| frames | 0 | 0 | 0 | 0 | - | 0.0 | no (no results) |" in rows
    assert text.endswith("Survivors in gnss:\n\n- `navcore.gnss.a.x_f__mutmut_1 (survived)`\n")
    assert capsys.readouterr().out == text + "\n"


def test_mutation_main_runs_the_named_packages(tmp_path, monkeypatch, capsys):
    """Oracle: two packages with every option: what each run is given, the lines printed
    before each (the budget as given: 2.5, 30), and the table of their counts in a new
    folder."""
    runs = []

    def run_package(*args):
        runs.append(args)
        return _row(args[0], 1, 0, minutes=0.5)

    monkeypatch.setattr(mutation, "run_package", run_package)
    out = tmp_path / "new" / "dir" / "m.md"
    assert (
        mutation.main(["gnss", "tools", "--budget-min", "2.5", "--max-children", "4", "--out", str(out)]) == 0
    )
    assert mutation.main(["frames", "--keep", "--mutants", "a*", "b*", "--out", str(out)]) == 0
    assert runs == [
        ("gnss", 2.5, 4, False, None),
        ("tools", 2.5, 4, False, None),
        ("frames", 30.0, 2, True, ["a*", "b*"]),
    ]
    printed = capsys.readouterr().out
    assert printed.startswith(
        "mutation testing navcore.gnss (2.5 min budget)\nmutation testing navcore.tools (2.5 min budget)\n"
    )
    assert "mutation testing navcore.frames (30 min budget)\n" in printed
    assert out.read_text() == mutation.table([_row("frames", 1, 0, minutes=0.5)])


def test_mutation_main_refuses_mutants_of_several_packages_and_unknown_packages(monkeypatch, capsys):
    """Oracle: ``--mutants`` with two packages, or with none (all of them), and an unknown
    package: usage errors (status 2), nothing run."""
    monkeypatch.setattr(mutation, "run_package", lambda *a, **k: pytest.fail("a run started"))
    for argv in (["gnss", "tools", "--mutants", "x*"], ["--mutants", "x*"]):
        with pytest.raises(SystemExit) as exc:
            mutation.main(argv)
        assert exc.value.code == 2
        assert capsys.readouterr().err.endswith("error: --mutants needs exactly one package\n")
    with pytest.raises(SystemExit) as exc:
        mutation.main(["nopackage"])
    assert exc.value.code == 2
    assert "unknown package 'nopackage'; choose from estimation, inertial," in capsys.readouterr().err


# --- every unit test reaches its package's run -------------------------------------------------

#: Test files that import one mutated package but belong to no mutation run, with why.
NOT_IN_A_RUN = {
    "test_book_layout.py": "the rendered book's layout (Chromium), not the ledger's code it reads",
    "test_coverage.py": "navcore.coverage, which no package mutates",
    "test_glue_pages.py": "the chapters' glued values against their sources (executes pages)",
    "test_provenance.py": "navcore.provenance, which no package mutates",
    "test_report.py": "navcore.report, which no package mutates",
    "test_traceability.py": "navcore.traceability, which no package mutates",
}


def _mutated_modules() -> dict[str, str]:
    """Dotted name of each module a package mutates -> the package (the tools and the book's
    extensions aside: their tests load files, not modules)."""
    out = {}
    for name, spec in mutation.PACKAGES.items():
        if name in ("tools", "book_ext"):
            continue
        for pattern in spec.mutate:
            for path in ROOT.glob(pattern):
                if path.suffix == ".py":
                    module = ".".join(path.relative_to(ROOT).with_suffix("").parts)
                    out[module.removesuffix(".__init__")] = name
    return out


def _navcore_imports(path: Path) -> set[str]:
    import ast

    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("navcore"):
            out |= {node.module, *(f"{node.module}.{alias.name}" for alias in node.names)}
        elif isinstance(node, ast.Import):
            out |= {alias.name for alias in node.names if alias.name.startswith("navcore")}
    return out


def test_mutation_every_unit_test_file_is_in_a_run():
    """Oracle: the test files' own imports. A file that imports modules of one mutated package
    only (units aside: every package reads its constants) is that package's unit test, and a
    run that leaves it out scores its package without it (test_frames_bulk.py and
    test_pulse_detection.py were missing: the frames run counted 444 of its mutants as
    untested). It is in some package's list, or in NOT_IN_A_RUN with why."""
    modules = _mutated_modules()
    listed = {t for spec in mutation.PACKAGES.values() for t in spec.tests}
    missing = []
    for path in sorted((ROOT / "tests").glob("test_*.py")):
        packages = {modules[m] for m in _navcore_imports(path) if m in modules} - {"units"}
        if len(packages) == 1 and path.name not in listed and path.name not in NOT_IN_A_RUN:
            missing.append(f"{path.name} ({packages.pop()})")
    assert not missing, "unit test files in no mutation run: " + ", ".join(missing)
    assert set(NOT_IN_A_RUN) <= {p.name for p in (ROOT / "tests").glob("test_*.py")} - listed


# --- sampled runs ------------------------------------------------------------------------------


def test_mutation_mutant_names_reads_every_meta_file_sorted(tmp_path):
    """Oracle: two modules' ``.meta`` files (one unchecked, as generation leaves them) and a file
    that is not one: every name, sorted by hand."""
    _meta(tmp_path, "navcore/b.py.meta", {"navcore.b.x_g__mutmut_2": None, "navcore.b.x_g__mutmut_1": None})
    _meta(tmp_path, "navcore/a.py.meta", {"navcore.a.x_f__mutmut_1": 0})
    _write(tmp_path / "mutants" / "navcore" / "c.py", "x = 1\n")
    assert mutation.mutant_names(tmp_path) == [
        "navcore.a.x_f__mutmut_1",
        "navcore.b.x_g__mutmut_1",
        "navcore.b.x_g__mutmut_2",
    ]
    assert mutation.mutant_names(tmp_path / "none") == []


def test_mutation_sample_mutants_is_a_seeded_sorted_subset():
    """Oracle: the sample's defining properties: its size, a subset, sorted, the same for the
    same seed whatever the names' order, another for another seed; all names when the sample
    is as large; a size that is not a positive integer refused, naming the parameter."""
    names = [f"m{i:03d}" for i in range(200)]
    one = mutation.sample_mutants(names, 20, 7)
    assert len(one) == len(set(one)) == 20 and set(one) <= set(names) and one == sorted(one)
    assert mutation.sample_mutants(names[::-1], 20, 7) == one
    assert mutation.sample_mutants(names, 20, 8) != one
    assert mutation.sample_mutants(names[:5], 5, 0) == names[:5]
    assert mutation.sample_mutants(names[4::-1], 9, 0) == names[:5]
    for bad in (0, -1, True, 2.5):
        with pytest.raises(ValueError, match="size must be a positive integer"):
            mutation.sample_mutants(names, bad, 0)


@pytest.mark.parametrize(("killed", "judged"), [(142, 181), (75, 100), (12, 12), (0, 9), (1, 1)])
def test_mutation_wilson_interval_is_scipys(killed, judged):
    """Oracle: scipy's ``binomtest(...).proportion_ci(method="wilson")`` at 95 %."""
    from scipy.stats import binomtest

    ci = binomtest(killed, judged).proportion_ci(confidence_level=0.95, method="wilson")
    assert mutation.wilson_interval(killed, judged) == pytest.approx((ci.low, ci.high), abs=1e-12)


def test_mutation_wilson_interval_refuses_impossible_counts():
    """Oracle: counts no run can give (nothing judged, more killed than judged, negative)."""
    for killed, judged in ((0, 0), (3, 2), (-1, 4)):
        with pytest.raises(ValueError, match="killed <= judged"):
            mutation.wilson_interval(killed, judged)


def test_mutation_run_package_runs_a_seeded_sample_of_the_generated_mutants(tmp_path, monkeypatch):
    """Oracle: the generation (a stand-in writing ten unchecked names, as mutmut's generation
    does) runs before mutmut, in the scratch project, with the run's environment; mutmut is given
    the sample drawn by :func:`sample_mutants` from those ten; the counts say the sample's size,
    seed and population. Named mutants and a sample together are refused."""
    proc = _Mutmut()
    projects = _run_setup(tmp_path, monkeypatch, proc)
    work = tmp_path / "work"
    generated = []

    def generate(cmd, **kwargs):
        generated.append((cmd, kwargs["cwd"], kwargs["env"]["NAVCORE_NO_DISK_CACHE"], kwargs["check"]))
        _meta(work, "navcore/a.py.meta", {f"navcore.a.x_f__mutmut_{i}": None for i in range(10)})

    monkeypatch.setattr(mutation.subprocess, "run", generate)
    counts = mutation.run_package("gnss", 1.0, 1, sample=4, seed=11)
    assert generated == [([sys.executable, "-c", mutation._GENERATE], work, "1", True)]
    names = [f"navcore.a.x_f__mutmut_{i}" for i in range(10)]
    assert proc.calls[0][0][4:] == ["--max-children", "1", *mutation.sample_mutants(names, 4, 11)]
    assert projects == [("gnss", False)]  # a sample starts afresh
    assert (counts["sample"], counts["seed"], counts["population"]) == (4, 11, 10)
    with pytest.raises(ValueError, match="mutants or sample, not both"):
        mutation.run_package("gnss", 1.0, 1, mutants=["x*"], sample=3)


def test_mutation_table_reports_a_sample_with_its_interval():
    """Oracle: a sample of 20 of 100 mutants, 15 killed and 4 survived (one unchecked, cut): the
    score of the 19 judged and scipy's Wilson interval, and how many of the sample were not
    checked; without the unchecked one, no such clause."""
    from scipy.stats import binomtest

    row = {**_row("papers", 15, 4, not_checked=81), "sample": 20, "seed": 5, "population": 100}
    ci = binomtest(15, 19).proportion_ci(method="wilson")
    text = mutation.table([row])
    assert (
        f"| papers | 100 | 15 | 4 | 81 | 78.9 % | 1.3 | sample of 20 (seed 5), 95 % interval "
        f"{100 * ci.low:.1f}-{100 * ci.high:.1f} %, 1 of the sample not checked |"
    ) in text
    row = {**_row("papers", 16, 4, not_checked=80), "sample": 20, "seed": 5, "population": 100}
    assert mutation.table([row]).count("of the sample not checked") == 0


def test_mutation_main_passes_a_sample_and_refuses_bad_ones(monkeypatch, capsys):
    """Oracle: ``--sample 30 --seed 4`` reaches each run as keywords; a non-positive sample, or a
    sample with named mutants, kept verdicts or a report: usage errors (status 2), nothing run."""
    runs = []
    monkeypatch.setattr(
        mutation, "run_package", lambda *a, **k: runs.append((a, k)) or _row(a[0], 1, 0, minutes=0.5)
    )
    monkeypatch.setattr(mutation, "WORK", Path("/nonexistent"))
    out = Path(os.devnull)
    assert mutation.main(["papers", "--sample", "30", "--seed", "4", "--out", str(out)]) == 0
    assert runs == [(("papers", 30.0, 2, False, None), {"sample": 30, "seed": 4})]
    for argv, message in (
        (["papers", "--sample", "0"], "--sample must be a positive number of mutants, got 0"),
        (["papers", "--sample", "3", "--keep"], "--sample runs afresh"),
        (["papers", "--sample", "3", "--mutants", "x*"], "--sample runs afresh"),
        (["papers", "--sample", "3", "--report-only"], "--sample runs afresh"),
    ):
        with pytest.raises(SystemExit) as exc:
            mutation.main(argv)
        assert exc.value.code == 2
        assert message in capsys.readouterr().err
    assert len(runs) == 1
