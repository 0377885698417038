"""The benchmark session's tool (``tools/bench.py``) run in-process, its heavy work stood in for.

``nox -s bench`` builds the book three times and times the library in fresh processes; none of
that runs here. Each measuring function gets a stand-in for ``subprocess`` (the commands it
starts are recorded, their output is written by hand) and for the clock (the instants it reads
are given in turn), and ``main`` gets stand-ins for the measuring functions, so that what is
tested is what the tool computes from the timings and writes in ``_build/bench.md``: the
commands and environments, the ratios and their formatting, the aims met or not (a ratio
exactly at its aim included), the failed measurements, and the options of ``main``.

The tool is loaded under its dotted name ``tools.bench``, the name mutmut's trampolines
recognise (tools/mutation.py). Oracle in each test: the hand-made timings and the report's
lines written out by hand.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import types
from pathlib import Path

import pytest

import navcore
from tests._tools import help_text, load_tool

bench = load_tool("bench")


class _Clock:
    """A stand-in for the ``time`` module: ``perf_counter`` reads the given instants in turn."""

    def __init__(self, *instants: float):
        self.instants = list(instants)

    def perf_counter(self) -> float:
        return self.instants.pop(0)


class _Build:
    """A stand-in for ``subprocess.Popen`` running the book build: records the command and its
    keyword arguments, and gives the log lines and exit status written by hand."""

    def __init__(self, lines: list[str], returncode: int = 0):
        self.lines, self.returncode, self.calls = lines, returncode, []

    def __call__(self, cmd, **kwargs):
        self.calls.append((cmd, kwargs))
        self.stdout = iter(self.lines)
        return self

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


class _Runs:
    """A stand-in for ``subprocess.run``: records each command and its keyword arguments and
    answers with ``answer(cmd, kwargs)``, a ``(returncode, stdout, stderr)``."""

    def __init__(self, answer):
        self.answer, self.calls = answer, []

    def __call__(self, cmd, **kwargs):
        self.calls.append((cmd, kwargs))
        code, out, err = self.answer(cmd, kwargs)
        return subprocess.CompletedProcess(cmd, code, out, err)


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


NOTEBOOK = (
    "---\njupytext:\n  text_representation:\n    extension: .md\n    format_name: myst\n"
    "kernelspec:\n  display_name: Python 3\n  language: python\n  name: python3\n---\n"
)


# --- clean_full_build and incremental_build ------------------------------------------------------


LOG = [
    "prefill: 2 pages to execute\n",
    "prefill:   wf/a (no cached result)\n",
    "prefill:   sp/b.md (imports navcore.gnss (changed))\n",
    "other line\n",
    "sphinx: reading\n",
    "execution: 3 pages\n",
    "sphinx: writing\n",
]


def test_bench_clean_build_command_environment_and_times(tmp_path, monkeypatch, capsys):
    """Oracle: a build log written by hand with three clock readings (start, first ``sphinx:``
    line, end) and a ``page-times.json``: the split, the executed pages, the command."""
    build = _Build(LOG)
    monkeypatch.setattr(bench.subprocess, "Popen", build)
    monkeypatch.setattr(bench, "time", _Clock(10.0, 12.5, 20.0))
    monkeypatch.delenv("PYTHONPATH", raising=False)
    for name, value in (
        ("NAVCORE_BOOK_CACHE", "/b"),
        ("NAVCORE_CACHE", "/c"),
        ("NAVCORE_NO_DISK_CACHE", "0"),
    ):
        monkeypatch.setenv(name, value)  # replaced, whatever the session set
    times = {"chapters": {"wf": 1.5}, "pages": {"wf/a.md": 0.5}}
    times_file = _write(tmp_path / "full" / "_build" / "page-times.json", json.dumps(times))
    result = bench.clean_full_build(3, tmp_path)
    assert result == {
        "total": 10.0,
        "execution": 2.5,
        "sphinx": 7.5,
        "chapters": {"wf": 1.5},
        "pages": {"wf/a.md": 0.5},
        "executed": {"wf/a": "no cached result", "sp/b.md": "imports navcore.gnss (changed)"},
    }
    assert not times_file.exists()
    ((cmd, kwargs),) = build.calls
    tool = str(bench.ROOT / "tools" / "build_book.py")
    assert cmd == [sys.executable, tool, "--cache", "--out", str(tmp_path / "full"), "--jobs", "3"]
    env = kwargs.pop("env")
    assert kwargs == {"cwd": bench.ROOT, "stdout": subprocess.PIPE, "stderr": subprocess.STDOUT, "text": True}
    assert env == {
        **os.environ,
        "NAVCORE_BOOK_CACHE": str(tmp_path / "jupyter_cache"),
        "NAVCORE_CACHE": str(tmp_path / "ledger_cache"),
        "NAVCORE_NO_DISK_CACHE": "1",
    }
    assert "PYTHONPATH" not in env
    assert capsys.readouterr().out == (
        "    prefill: 2 pages to execute\n"
        "    prefill:   wf/a (no cached result)\n"
        "    prefill:   sp/b.md (imports navcore.gnss (changed))\n"
        "    execution: 3 pages\n"
    )


@pytest.mark.parametrize("jobs", [None, 0])
def test_bench_clean_build_without_jobs_and_without_sphinx_or_page_times(tmp_path, monkeypatch, jobs):
    """Oracle: no ``--jobs`` without a job count; a log with no ``sphinx:`` line is all Sphinx
    (no execution measured); no ``page-times.json`` gives empty tables."""
    build = _Build(["prefill: nothing to execute\n", "done\n"])
    monkeypatch.setattr(bench.subprocess, "Popen", build)
    monkeypatch.setattr(bench, "time", _Clock(4.0, 9.0))
    result = bench.clean_full_build(jobs, tmp_path)
    assert result == {
        "total": 5.0,
        "execution": 0.0,
        "sphinx": 5.0,
        "chapters": {},
        "pages": {},
        "executed": {},
    }
    assert build.calls[0][0][-2:] == ["--out", str(tmp_path / "full")]


def test_bench_clean_build_against_a_copy_of_navcore_puts_it_first_on_the_path(tmp_path, monkeypatch):
    """Oracle: the copy alone on ``PYTHONPATH``, then the copy before an existing path."""
    build = _Build([])
    monkeypatch.setattr(bench.subprocess, "Popen", build)
    monkeypatch.setattr(bench, "time", _Clock(0.0, 1.0, 0.0, 1.0))
    monkeypatch.delenv("PYTHONPATH", raising=False)
    bench.clean_full_build(None, tmp_path, tmp_path / "copy")
    assert build.calls[0][1]["env"]["PYTHONPATH"] == str(tmp_path / "copy")
    monkeypatch.setenv("PYTHONPATH", "/elsewhere")
    bench.clean_full_build(None, tmp_path, tmp_path / "copy")
    assert build.calls[1][1]["env"]["PYTHONPATH"] == f"{tmp_path / 'copy'}{os.pathsep}/elsewhere"


def test_bench_clean_build_starts_its_ledger_cache_from_a_store_once(tmp_path, monkeypatch):
    """Oracle: a store with one claim file is copied into the ledger cache; a cache already
    there is left as it is."""
    monkeypatch.setattr(bench.subprocess, "Popen", _Build([]))
    monkeypatch.setattr(bench, "time", _Clock(0.0, 1.0, 0.0, 1.0))
    store = tmp_path / "store"
    _write(store / "claims" / "WF-1.json", "{}")
    work = tmp_path / "work"
    bench.clean_full_build(None, work, ledger_from=store)
    assert (work / "ledger_cache" / "claims" / "WF-1.json").read_text() == "{}"
    _write(store / "claims" / "WF-2.json", "{}")
    bench.clean_full_build(None, work, ledger_from=store)
    assert sorted(p.name for p in (work / "ledger_cache" / "claims").iterdir()) == ["WF-1.json"]


def test_bench_a_failed_clean_build_prints_the_last_forty_lines_and_exits(tmp_path, monkeypatch, capsys):
    """Oracle: a log of 45 numbered lines and exit status 2; lines 5 to 44 are printed."""
    lines = [f"line {i}\n" for i in range(45)]
    monkeypatch.setattr(bench.subprocess, "Popen", _Build(lines, returncode=2))
    monkeypatch.setattr(bench, "time", _Clock(0.0, 1.0))
    with pytest.raises(SystemExit) as exc:
        bench.clean_full_build(None, tmp_path)
    assert exc.value.code == "the clean full build failed (exit 2)"
    assert capsys.readouterr().out == "".join(lines[5:]) + "\n"


def test_bench_incremental_build_touches_one_module_in_a_copy_of_navcore(tmp_path, monkeypatch):
    """Oracle: a repository of one module, its ``__pycache__``, the book, the tests and the
    papers' texts beside it; the copy, its links and the build's arguments by hand."""
    root = tmp_path / "repo"
    _write(root / "navcore" / "location" / "emitter.py", "x = 1\n")
    _write(root / "navcore" / "__pycache__" / "m.pyc", "")
    _write(root / "book" / "p.md", "")
    _write(root / "tests" / "t.py", "")
    (tmp_path / "shared").mkdir()
    monkeypatch.setattr(bench, "ROOT", root)
    calls = []
    monkeypatch.setattr(bench, "clean_full_build", lambda *a, **k: calls.append((a, k)) or {"total": 1.0})
    work = tmp_path / "work"
    work.mkdir()
    assert bench.incremental_build(4, work, "navcore/location/emitter.py") == {"total": 1.0}
    source = work / "navcore-copy"
    assert calls == [((4, work, source), {})]
    touched = source / "navcore" / "location" / "emitter.py"
    assert touched.read_text() == "x = 1\n# a comment added by the benchmark\n"
    assert (root / "navcore" / "location" / "emitter.py").read_text() == "x = 1\n"
    assert not (source / "navcore" / "__pycache__").exists()
    assert (source / "book").resolve() == root / "book" and (source / "book").is_symlink()
    assert (source / "tests").resolve() == root / "tests" and (source / "tests").is_symlink()
    assert (work / "shared").is_symlink() and (work / "shared").resolve() == tmp_path / "shared"


def test_bench_incremental_build_without_the_papers_texts_or_with_them_linked(tmp_path, monkeypatch):
    """Oracle: no ``shared`` folder beside the checkout, no link; one already in the work
    folder is kept."""
    root = tmp_path / "repo"
    _write(root / "navcore" / "m.py", "")
    monkeypatch.setattr(bench, "ROOT", root)
    monkeypatch.setattr(bench, "clean_full_build", lambda *a, **k: {})
    work = tmp_path / "work"
    work.mkdir()
    bench.incremental_build(None, work, "navcore/m.py")
    assert not (work / "shared").exists() and not (work / "shared").is_symlink()
    (tmp_path / "shared").mkdir()
    second = tmp_path / "second"
    _write(second / "shared" / "kept.txt", "")
    bench.incremental_build(None, second, "navcore/m.py")
    assert (second / "shared" / "kept.txt").exists() and not (second / "shared").is_symlink()


# --- strip_code_cells and floor_build ------------------------------------------------------------


def test_bench_strip_code_cells_removes_code_from_notebooks_only(tmp_path):
    """Oracle: two notebooks with code and text cells and one plain page; the count is two, the
    notebooks keep their text and lose their code, the plain page is untouched."""
    cell = "```{code-cell} ipython3\nx = 1\n```\n"
    _write(tmp_path / "a.md", NOTEBOOK + "\n# A\n\n" + cell + "\nafter\n")
    _write(tmp_path / "sub" / "b.md", NOTEBOOK + "\n# B\n\n" + cell)
    plain = "# Plain\n\n" + cell
    _write(tmp_path / "c.md", plain)
    _write(tmp_path / "d.txt", NOTEBOOK + cell)
    assert bench.strip_code_cells(tmp_path) == 2
    for name, words in (("a.md", ["# A", "after"]), ("sub/b.md", ["# B"])):
        text = (tmp_path / name).read_text()
        assert "code-cell" not in text and "x = 1" not in text
        assert all(w in text for w in words) and "kernelspec:" in text
    assert (tmp_path / "c.md").read_text() == plain
    assert (tmp_path / "d.txt").read_text() == NOTEBOOK + cell


def _floor_repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    _write(root / "book" / "_toc.yml", "root: index\n")
    _write(root / "book" / "index.md", "# Index\n")
    _write(root / "book" / "_build" / "old.html", "")
    _write(root / "book" / "_toc_subset_1.yml", "")
    config = {
        "title": "T",
        "execute": {"execute_notebooks": "cache"},
        "sphinx": {
            "local_extensions": {"ext_a": "book/_ext"},
            "config": {"nb_execution_raise_on_error": True},
        },
    }
    _write(root / "_config.yml", json.dumps(config))
    return root


def test_bench_floor_build_command_configuration_and_time(tmp_path, monkeypatch):
    """Oracle: a repository with a toc, a page, a stale build and a toc subset; the copied
    book, the configuration written (forced execution, errors not raised, extensions at
    absolute paths) and the ``jupyter-book`` command by hand."""
    import yaml

    root = _floor_repo(tmp_path)
    monkeypatch.setattr(bench, "ROOT", root)
    stripped = []
    monkeypatch.setattr(bench, "strip_code_cells", lambda book: stripped.append(book) or 7)
    runs = _Runs(lambda cmd, kwargs: (0, "", ""))
    monkeypatch.setattr(bench.subprocess, "run", runs)
    monkeypatch.setattr(bench, "time", _Clock(3.0, 8.5))
    work = tmp_path / "work"
    work.mkdir()
    assert bench.floor_build(work) == {"total": 5.5, "pages": 7}
    book = work / "floor-src"
    assert stripped == [book]
    assert sorted(p.name for p in book.iterdir()) == ["_toc.yml", "index.md"]
    config = yaml.safe_load((work / "_config_floor.yml").read_text())
    assert config == {
        "title": "T",
        "execute": {"execute_notebooks": "force"},
        "sphinx": {
            "local_extensions": {"ext_a": str(root / "book/_ext")},
            "config": {"nb_execution_raise_on_error": False},
        },
    }
    assert list(config) == ["title", "execute", "sphinx"]
    ((cmd, kwargs),) = runs.calls
    assert cmd == [
        str(Path(sys.executable).with_name("jupyter-book")), "build", str(book),
        "--config", str(work / "_config_floor.yml"), "--toc", str(book / "_toc.yml"),
        "--path-output", str(work / "floor"), "--builder", "html", "--all", "--keep-going", "-q",
    ]  # fmt: skip
    assert kwargs == {"cwd": work, "capture_output": True, "text": True}


def test_bench_floor_build_fails_only_without_an_index_page(tmp_path, monkeypatch, capsys):
    """Oracle: a failing build with no ``index.html`` exits, printing the ends of its output;
    a failing build (missing glued figures) that wrote its ``index.html`` is timed; a
    configuration without local extensions is accepted."""
    root = _floor_repo(tmp_path)
    config = json.loads((root / "_config.yml").read_text())
    del config["sphinx"]["local_extensions"]
    _write(root / "_config.yml", json.dumps(config))
    monkeypatch.setattr(bench, "ROOT", root)
    monkeypatch.setattr(bench, "strip_code_cells", lambda book: 1)
    out, err = "o" * 3000 + "OUT-END", "e" * 3000 + "ERR-END"
    monkeypatch.setattr(bench.subprocess, "run", _Runs(lambda cmd, kwargs: (1, out, err)))
    monkeypatch.setattr(bench, "time", _Clock(0.0, 2.0, 0.0, 3.0))
    work = tmp_path / "work"
    work.mkdir()
    with pytest.raises(SystemExit) as exc:
        bench.floor_build(work)
    assert exc.value.code == "the floor build failed"
    assert capsys.readouterr().out == f"{out[-3000:]} {err[-3000:]}\n"
    _write(work / "floor" / "_build" / "html" / "index.html", "")
    (work / "floor-src").rename(work / "floor-src-old")
    assert bench.floor_build(work) == {"total": 3.0, "pages": 1}
    assert capsys.readouterr().out == ""


# --- pages, models and the ledger in fresh processes ---------------------------------------------


@pytest.mark.parametrize(("err", "status"), [(None, "ok"), (KeyError("x"), "error: KeyError")])
def test_bench_time_page_executes_one_page_alone(tmp_path, monkeypatch, err, status):
    """Oracle: the executor's time and error written by hand, and what it was given."""
    page = _write(tmp_path / "wf" / "a.md", "")
    calls = []

    def single_nb_execution(nb, **kwargs):
        calls.append((nb, kwargs))
        return types.SimpleNamespace(time=2.25, err=err)

    utils = types.ModuleType("jupyter_cache.executors.utils")
    utils.single_nb_execution = single_nb_execution
    monkeypatch.setitem(sys.modules, "jupyter_cache.executors.utils", utils)
    monkeypatch.setattr(bench.build_book, "_read_notebook", lambda path: ("notebook", path))
    assert bench.time_page(page) == (2.25, status)
    assert calls == [
        (("notebook", page), {"cwd": str(tmp_path / "wf"), "allow_errors": False, "timeout": 1800})
    ]


@pytest.mark.parametrize(("code", "status"), [(0, "ok"), (1, "error"), (-9, "error")])
def test_bench_time_subprocess_runs_the_code_in_a_fresh_interpreter(monkeypatch, code, status):
    """Oracle: the command and the status from the exit code, the time between two readings."""
    runs = _Runs(lambda cmd, kwargs: (code, "", ""))
    monkeypatch.setattr(bench.subprocess, "run", runs)
    monkeypatch.setattr(bench, "time", _Clock(1.0, 3.5))
    assert bench.time_subprocess("print(1)") == (2.5, status)
    assert runs.calls == [
        ([sys.executable, "-c", "print(1)"], {"capture_output": True, "text": True, "cwd": bench.ROOT})
    ]


def test_bench_ledger_times_uncached_filling_and_cached(monkeypatch, capsys):
    """Oracle: three runs timed by hand, the second failing; the table's rows and each run's
    cache setting (off, then one fresh folder twice, removed afterwards)."""
    codes = iter([0, 1, 0])
    runs = _Runs(lambda cmd, kwargs: (next(codes), "", ""))
    monkeypatch.setattr(bench.subprocess, "run", runs)
    monkeypatch.setattr(bench, "time", _Clock(0.0, 1.25, 2.0, 9.0, 10.0, 10.5))
    monkeypatch.setenv("NAVCORE_OTHER", "kept")
    rows = bench.ledger_times()
    expected = [
        "| ledger, fresh process, all claims with their bands | seconds | status |",
        "|---|---:|---|",
        "| uncached (NAVCORE_CACHE=off) | 1.2 | ok |",
        "| filling a fresh cache | 7.0 | error |",
        "| cached (read from the cache) | 0.5 | ok |",
    ]
    assert rows == expected
    assert capsys.readouterr().out == "\n".join(expected[2:]) + "\n"
    code = "from navcore import ledger; assert all(e.passes for e in ledger.evaluations())"
    caches = []
    for cmd, kwargs in runs.calls:
        assert cmd == [sys.executable, "-c", code]
        env = kwargs.pop("env")
        assert kwargs == {"capture_output": True, "text": True, "cwd": bench.ROOT}
        assert env == {**os.environ, "NAVCORE_CACHE": env["NAVCORE_CACHE"]}
        caches.append(env["NAVCORE_CACHE"])
    fresh = Path(caches[1])
    assert caches == ["off", str(fresh), str(fresh)]
    assert fresh.name.startswith("navcore-ledger-bench-") and fresh.parent == Path(tempfile.gettempdir())
    assert not fresh.exists()


# --- the library -------------------------------------------------------------------------------


def _library_runs(
    filter_step=(0, "0.25 0.125 0.375\n", ""), mission=(0, "12.34 104.0 5\n", ""), loop=(0, "0.5 0.25\n", "")
) -> _Runs:
    """Each of the three programs answers with its ``(returncode, stdout, stderr)``."""
    answers = {
        bench.FILTER_STEP_CODE: filter_step,
        bench.MISSION_CODE: mission,
        bench.COVARIANCE_LOOP_CODE: loop,
    }
    return _Runs(lambda cmd, kwargs: answers[cmd[2]])


LIBRARY = [
    "",
    "| library | value |",
    "|---|---:|",
    "| filter step (9 states, 3 measurements), filterpy KalmanFilter, µs | 250000.0 |",
    "| filter step, navcore fast path (validate=False), µs | 125000.0 |",
    "| filter step, navcore checked on every call (the default), µs | 375000.0 |",
    "| ratio navcore fast path / filterpy, same run (aim: at most 1.0) | 0.50 |",
    "| ratio navcore checked / filterpy, same run (aim: at most 1.5) | 1.50 |",
    "| covariance analysis, SP sequential-outage mission (104 min, 5 systems, 1-s steps), s | 12.3 |",
]
LOOP = [
    "| propagate_covariance, 10 000 steps, 15 states, s | 0.500 |",
    "| the same recursion as a plain numpy loop, s | 0.250 |",
    "| ratio engine / plain loop, same run (aim: at most 1.2) | 2.00 |",
]


def test_bench_library_ratios_from_one_run(monkeypatch, capsys):
    """Oracle: the three programs' outputs written by hand (a step of filterpy 0.25 s, of
    navcore 0.125 s and 0.375 s, large enough for every digit of the microseconds to show; a
    104-min mission in 12.34 s; engine 0.5 s, loop 0.25 s): the rows and ratios."""
    runs = _library_runs()
    monkeypatch.setattr(bench.subprocess, "run", runs)
    assert bench.library_benchmarks() == ([*LIBRARY, *LOOP], True)
    for cmd, kwargs in runs.calls:
        assert cmd[:2] == [sys.executable, "-c"]
        assert kwargs == {"capture_output": True, "text": True, "cwd": bench.ROOT}
    assert [cmd[2] for cmd, _ in runs.calls] == [
        bench.FILTER_STEP_CODE,
        bench.MISSION_CODE,
        bench.COVARIANCE_LOOP_CODE,
    ]
    assert capsys.readouterr().out == (
        "filter step: navcore 125000.0, checked 375000.0 us, filterpy 250000.0 us, ratio 0.50|1.50\n"
        "covariance analysis: 104-min mission in 12.3 s\n"
        "covariance engine: 0.500 s, plain numpy loop 0.250 s, ratio 2.00\n"
    )


@pytest.mark.parametrize("failing", ["filter_step", "mission", "loop"])
def test_bench_library_a_failed_measurement_is_a_row_and_a_failure(monkeypatch, failing):
    """Oracle: one of the three programs failing with a traceback: its row gives the last line
    of the error, the other rows are as in a good run, and the whole fails."""
    failure = (1, "", "Traceback (most recent call last):\n  File x\nValueError: boom\n")
    monkeypatch.setattr(bench.subprocess, "run", _library_runs(**{failing: failure}))
    lines, ok = bench.library_benchmarks()
    assert ok is False
    expected = {
        "filter_step": [
            *LIBRARY[:3],
            "| filter step benchmark | failed: ValueError: boom |",
            LIBRARY[-1],
            *LOOP,
        ],
        "mission": [*LIBRARY[:-1], "| covariance-analysis mission | failed: ValueError: boom |", *LOOP],
        "loop": [*LIBRARY, "| covariance engine against a numpy loop | failed: ValueError: boom |"],
    }[failing]
    assert lines == expected


def test_bench_covariance_loop_ratio_alone(monkeypatch):
    """Oracle: an engine as fast as the loop (ratio 1.00) and a failure without any stderr."""
    monkeypatch.setattr(bench.subprocess, "run", _Runs(lambda cmd, kwargs: (0, "0.125 0.125", "")))
    lines, ok = bench.covariance_loop_ratio()
    assert ok is True and lines[-1] == "| ratio engine / plain loop, same run (aim: at most 1.2) | 1.00 |"
    monkeypatch.setattr(bench.subprocess, "run", _Runs(lambda cmd, kwargs: (1, "", "")))
    assert bench.covariance_loop_ratio() == (
        ["| covariance engine against a numpy loop | failed: no error output |"],
        False,
    )


# --- the ledger, serial against parallel ---------------------------------------------------------


def _ledger_runs(exports: dict[str, str], codes: dict[str, int] | None = None) -> _Runs:
    """Each ``--jobs`` run writes its export (unless it fails) and exits with its code."""

    def answer(cmd, kwargs):
        jobs = cmd[cmd.index("--jobs") + 1]
        code = (codes or {}).get(jobs, 0)
        if code == 0:
            Path(cmd[cmd.index("--json-out") + 1]).write_text(exports[jobs])
        return code, "", f"Traceback\n  File x\nRuntimeError: jobs {jobs}\n"

    return _Runs(answer)


def test_bench_ledger_serial_against_parallel(monkeypatch, capsys):
    """Oracle: 40 s serial and 16 s on 4 cores (ratio 2.50), identical exports; the commands,
    the environment (caches off) and the temporary exports, removed afterwards."""
    runs = _ledger_runs({"1": "{}", "-1": "{}"})
    monkeypatch.setattr(bench.subprocess, "run", runs)
    monkeypatch.setattr(bench, "time", _Clock(0.0, 40.0, 50.0, 66.0))
    monkeypatch.setattr(bench.os, "cpu_count", lambda: 4)
    monkeypatch.setenv("NAVCORE_CACHE", "/c")  # replaced, whatever the session set
    monkeypatch.setenv("NAVCORE_NO_DISK_CACHE", "0")
    assert bench.ledger_parallel_ratio() == (
        [
            "| ledger, cache off, one process (--jobs 1), s | 40.0 |",
            "| ledger, cache off, every core (4), s (aim: at most 30 on 2 cores) | 16.0 |",
            "| ratio serial / parallel, same run | 2.50 |",
            "| the two JSON exports byte-identical | yes |",
        ],
        True,
    )
    assert capsys.readouterr().out == "ledger, cache off: 40.0 s in one process, 16.0 s on 4 cores\n"
    outs = []
    for (cmd, kwargs), jobs in zip(runs.calls, ("1", "-1"), strict=True):
        out = Path(cmd[-1])
        outs.append(out)
        assert cmd == [sys.executable, "-m", "navcore", "ledger", "--jobs", jobs, "--json-out", str(out)]
        assert out.name == f"ledger-{jobs}.json" and out.parent.name.startswith("navcore-bench-ledger-")
        assert kwargs == {
            "cwd": bench.ROOT,
            "env": {**os.environ, "NAVCORE_CACHE": "off", "NAVCORE_NO_DISK_CACHE": "1"},
            "capture_output": True,
            "text": True,
        }
    assert outs[0].parent == outs[1].parent and not outs[0].parent.exists()


def test_bench_ledger_exports_that_differ_fail(monkeypatch):
    """Oracle: exports differing by one byte; no core count known counts one core."""
    monkeypatch.setattr(bench.subprocess, "run", _ledger_runs({"1": "{}", "-1": "{ }"}))
    monkeypatch.setattr(bench, "time", _Clock(0.0, 3.0, 0.0, 3.0))
    monkeypatch.setattr(bench.os, "cpu_count", lambda: None)
    lines, ok = bench.ledger_parallel_ratio()
    assert ok is False
    assert lines[1:] == [
        "| ledger, cache off, every core (1), s (aim: at most 30 on 2 cores) | 3.0 |",
        "| ratio serial / parallel, same run | 1.00 |",
        "| the two JSON exports byte-identical | NO |",
    ]


@pytest.mark.parametrize("jobs", ["1", "-1"])
def test_bench_ledger_a_failed_run_stops_the_comparison(monkeypatch, jobs):
    """Oracle: the failing run's row with the last line of its error, and a failure."""
    runs = _ledger_runs({"1": "{}", "-1": "{}"}, {jobs: 3})
    monkeypatch.setattr(bench.subprocess, "run", runs)
    monkeypatch.setattr(bench, "time", _Clock(0.0, 1.0, 0.0, 1.0))
    assert bench.ledger_parallel_ratio() == (
        [f"| ledger --jobs {jobs} | failed: RuntimeError: jobs {jobs} |"],
        False,
    )
    assert len(runs.calls) == {"1": 1, "-1": 2}[jobs]


# --- main --------------------------------------------------------------------------------------


def _main(monkeypatch, *argv: str) -> int:
    monkeypatch.setattr(sys, "argv", ["bench.py", *argv])
    return bench.main()


def test_bench_main_help_describes_the_options(monkeypatch, capsys):
    """Oracle: the docstring's first line and the options' help, as written in the tool."""
    out = help_text(lambda argv: _main(monkeypatch, *argv), capsys)
    for text in (
        "Benchmark the book build: clean full build, each chapter, and the floor.",
        "--jobs JOBS workers for the build (default: the cores)",
        "--standalone also time each page alone, cold",
        "--models also time each ledger paper and figure",
        "--ledger only time the whole ledger, uncached and cached (no book build)",
        "--library-only only the library numbers (filter step, mission)",
        "--build-only only the book builds (clean, incremental, floor): no library or ledger timings",
        "--ledger-from LEDGER_FROM start the clean build's ledger cache from this stored ledger "
        "(nox -s ledger -- --store writes _build/navcore-cache), as CI's book build does: the "
        "build is timed without the ledger",
        "--out OUT",
        "--touch TOUCH the module a comment is added to (in a copy) for the incremental rebuild",
    ):
        assert text in out


def _no_work(monkeypatch) -> None:
    """Every measurement fails the test if ``main`` starts it."""
    for name in (
        "clean_full_build",
        "incremental_build",
        "floor_build",
        "ledger_times",
        "library_benchmarks",
        "ledger_parallel_ratio",
        "time_page",
        "time_subprocess",
    ):
        monkeypatch.setattr(bench, name, lambda *a, name=name, **k: pytest.fail(f"{name} started"))


def test_bench_main_ledger_only_times_the_ledger(tmp_path, monkeypatch, capsys):
    """Oracle: the ledger's rows given by hand, under their heading, in a new folder."""
    _no_work(monkeypatch)
    monkeypatch.setattr(bench, "ledger_times", lambda: ["| a | 1.0 | ok |"])
    out = tmp_path / "new" / "dir" / "bench.md"
    for _ in range(2):  # the second time into the folder the first made
        assert _main(monkeypatch, "--ledger", "--out", str(out)) == 0
        assert out.read_text() == "# Ledger benchmark\n\n| a | 1.0 | ok |\n"
        assert capsys.readouterr().out == "# Ledger benchmark\n\n| a | 1.0 | ok |\n"


@pytest.mark.parametrize(
    ("library_ok", "ledger_ok", "status"), [(True, True, 0), (False, True, 1), (True, False, 1)]
)
def test_bench_main_library_only(tmp_path, monkeypatch, capsys, library_ok, ledger_ok, status):
    """Oracle: the library's and the ledger's rows given by hand; either failing fails."""
    _no_work(monkeypatch)
    monkeypatch.setattr(
        bench, "library_benchmarks", lambda: (["", "| library | value |", "| x | 1 |"], library_ok)
    )
    monkeypatch.setattr(bench, "ledger_parallel_ratio", lambda: (["| y | 2 |"], ledger_ok))
    out = tmp_path / "new" / "dir" / "bench.md"
    assert _main(monkeypatch, "--library-only", "--out", str(out)) == status
    capsys.readouterr()
    assert _main(monkeypatch, "--library-only", "--out", str(out)) == status
    text = (
        "# Library benchmark\n\n| library | value |\n| x | 1 |\n\n| ledger | value |\n|---|---:|\n| y | 2 |\n"
    )
    assert out.read_text() == text
    assert capsys.readouterr().out == text + "\n"


FULL = {
    "total": 200.0,
    "execution": 150.0,
    "sphinx": 50.0,
    "chapters": {"wf": 12.34, "atc10": 5.0},
    "pages": {"wf/b.md": 2.0, "wf/a.md": 1.05},
    "executed": {},
}
INCREMENTAL = {
    "total": 50.0,
    "execution": 20.0,
    "executed": {"wf/b.md": "imports navcore.gnss", "wf/a.md": "new"},
}
FLOOR = {"total": 160.0, "pages": 42}


def _builds(monkeypatch, full=FULL, incremental=INCREMENTAL, floor=FLOOR) -> list:
    """Stand-ins for the three builds, recording their arguments and the work folder's state."""
    calls = []

    def clean(*args, **kwargs):
        calls.append(("clean", args, kwargs, args[1].is_dir()))
        return full

    monkeypatch.setattr(bench, "clean_full_build", clean)
    monkeypatch.setattr(
        bench, "incremental_build", lambda *a, **k: calls.append(("incremental", a, k)) or incremental
    )
    monkeypatch.setattr(bench, "floor_build", lambda *a, **k: calls.append(("floor", a, k)) or floor)
    return calls


def test_bench_main_build_only_report(tmp_path, monkeypatch, capsys):
    """Oracle: the three builds' timings given by hand (full 200 s, floor 160 s, incremental
    50 s): every row of the report, the ratios 1.25 and 0.25, both aims met, and what each
    build was given (one temporary work folder, removed afterwards)."""
    _no_work(monkeypatch)
    calls = _builds(monkeypatch)
    monkeypatch.setattr(bench.os, "cpu_count", lambda: 2)
    out = tmp_path / "bench.md"
    assert _main(monkeypatch, "--build-only", "--out", str(out)) == 0
    expected = [
        "# Build benchmark (2 cores, jobs = 2)",
        "",
        "The clean build's ledger: evaluated (empty cache)",
        "",
        "| measurement | seconds |",
        "|---|---:|",
        "| clean full build, total | 200.0 |",
        "| of which: executing the notebooks (parallel, before Sphinx) | 150.0 |",
        "| of which: Sphinx (reading from the cache, writing HTML) | 50.0 |",
        "| floor: the same build without code cells (42 notebooks) | 160.0 |",
        "| ratio full / floor (aim: at most 1.3) | 1.25 |",
        "| incremental rebuild after a comment in navcore/location/emitter.py, total | 50.0 |",
        "| of which: executing the 2 pages that depend on it | 20.0 |",
        "| ratio incremental / clean full build | 0.25 |",
        "",
        "| chapter | execution in the build (s, one kernel per chapter, ledger included) |",
        "|---|---:|",
        "| atc10 | 5.0 |",
        "| wf | 12.3 |",
        "",
        "| page | execution in the build (s) |",
        "|---|---:|",
        "| wf/a.md | 1.1 |",
        "| wf/b.md | 2.0 |",
        "",
        "Pages the incremental rebuild executed (2), and why:",
        "",
        "- wf/b.md (imports navcore.gnss)",
        "- wf/a.md (new)",
        "",
        "- met: full build under 5 min",
        "- met: full build within 1.3x of the floor",
    ]
    assert out.read_text() == "\n".join(expected) + "\n"
    assert capsys.readouterr().out == (
        "clean full build (HTML, every chapter executed) ...\n"
        "incremental rebuild after a comment in navcore/location/emitter.py ...\n"
        "floor build (the same book without code cells) ...\n" + "\n".join(expected) + f"\nwritten to {out}\n"
    )
    work = calls[0][1][1]
    assert calls == [
        ("clean", (None, work), {"ledger_from": None}, True),
        ("incremental", (None, work, "navcore/location/emitter.py"), {}),
        ("floor", (work,), {}),
    ]
    assert work.name.startswith("navcore-bench-") and work.parent == Path(tempfile.gettempdir())
    assert not work.exists()


@pytest.mark.parametrize(
    ("total", "floor", "marks"),
    [
        (299.9, 300.0, ["met", "met"]),
        (300.0, 300.0, ["NOT met", "met"]),
        (130.0, 100.0, ["met", "met"]),
        (130.1, 100.0, ["met", "NOT met"]),
        (400.0, 100.0, ["NOT met", "NOT met"]),
    ],
)
def test_bench_main_aims_at_their_bounds(tmp_path, monkeypatch, total, floor, marks):
    """Oracle: a full build exactly at 300 s misses "under 5 min"; exactly 1.3 times the floor
    meets "within 1.3x"; just over it does not; the aims are reported, the status stays 0."""
    _no_work(monkeypatch)
    _builds(monkeypatch, full={**FULL, "total": total}, floor={**FLOOR, "total": floor})
    out = tmp_path / "bench.md"
    assert _main(monkeypatch, "--build-only", "--out", str(out)) == 0
    assert out.read_text().splitlines()[-2:] == [
        f"- {marks[0]}: full build under 5 min",
        f"- {marks[1]}: full build within 1.3x of the floor",
    ]


def test_bench_main_options_jobs_touch_and_a_stored_ledger(tmp_path, monkeypatch):
    """Oracle: ``--jobs 3``, ``--touch`` and ``--ledger-from`` a store (given relative to the
    working folder): the heading, the ledger's line, each build's arguments; no page executed
    gives "- none"."""
    _no_work(monkeypatch)
    calls = _builds(monkeypatch, incremental={**INCREMENTAL, "executed": {}})
    monkeypatch.setattr(bench.os, "cpu_count", lambda: 8)
    (tmp_path / "store" / "claims").mkdir(parents=True)
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "bench.md"
    argv = ["--build-only", "--jobs", "3", "--touch", "navcore/gnss/antijam.py", "--ledger-from", "store"]
    assert _main(monkeypatch, *argv, "--out", str(out)) == 0
    lines = out.read_text().splitlines()
    assert lines[0] == "# Build benchmark (8 cores, jobs = 3)"
    assert lines[2] == "The clean build's ledger: read from the store store"
    assert "| incremental rebuild after a comment in navcore/gnss/antijam.py, total | 50.0 |" in lines
    assert "| of which: executing the 0 pages that depend on it | 20.0 |" in lines
    start = lines.index("Pages the incremental rebuild executed (0), and why:")
    assert lines[start + 1 : start + 4] == ["", "- none", ""]
    work = calls[0][1][1]
    assert calls[0][1:3] == ((3, work), {"ledger_from": tmp_path / "store"})
    assert calls[1][1] == (3, work, "navcore/gnss/antijam.py")


def test_bench_main_a_store_without_claims_is_refused(tmp_path, monkeypatch):
    """Oracle: a ``--ledger-from`` folder with no ``claims`` folder exits before any build."""
    _no_work(monkeypatch)
    (tmp_path / "store").mkdir()
    with pytest.raises(SystemExit) as exc:
        _main(monkeypatch, "--ledger-from", str(tmp_path / "store"), "--out", str(tmp_path / "b.md"))
    assert exc.value.code == f"--ledger-from {tmp_path / 'store'}: no stored ledger (a claims folder) there"


def test_bench_main_standalone_times_each_notebook_of_the_toc(tmp_path, monkeypatch, capsys):
    """Oracle: a toc of two notebooks and a plain page; each notebook timed alone, the plain
    page not; the rows and the printed lines; either page failing fails the run, also when
    the library and the ledger pass."""
    _no_work(monkeypatch)
    _builds(monkeypatch)
    root = tmp_path / "repo"
    pages = [
        _write(root / "book" / "wf" / "a.md", NOTEBOOK),
        _write(root / "book" / "plain.md", "# Plain\n"),
        _write(root / "book" / "sp" / "b.md", NOTEBOOK),
    ]
    monkeypatch.setattr(bench, "ROOT", root)
    tocs = []
    monkeypatch.setattr(bench.build_book, "toc_pages", lambda toc: tocs.append(toc) or pages)
    timed = []
    results = {"a.md": (1.25, "ok"), "b.md": (12.0, "error: KeyError")}
    monkeypatch.setattr(bench, "time_page", lambda page: timed.append(page) or results[page.name])
    out = tmp_path / "bench.md"
    assert _main(monkeypatch, "--build-only", "--standalone", "--out", str(out)) == 1
    assert tocs == [root / "book" / "_toc.yml"]
    assert timed == [pages[0], pages[2]]
    assert out.read_text().splitlines()[-5:] == [
        "",
        "| page alone, fresh kernel, cold (as a reader runs it) | seconds | status |",
        "|---|---:|---|",
        "| wf/a.md | 1.2 | ok |",
        "| sp/b.md | 12.0 | error: KeyError |",
    ]
    printed = capsys.readouterr().out
    assert "     1.2 s  wf/a.md (alone)  ok\n    12.0 s  sp/b.md (alone)  error: KeyError\n" in printed
    assert out.read_text().startswith("# Build benchmark")  # the builds' rows before the pages
    results["b.md"] = (12.0, "ok")
    assert _main(monkeypatch, "--build-only", "--standalone", "--out", str(out)) == 0
    results["a.md"] = (1.25, "error: KeyError")  # a failure before a page that passes
    assert _main(monkeypatch, "--build-only", "--standalone", "--out", str(out)) == 1
    results["a.md"] = (1.25, "ok")
    monkeypatch.setattr(bench, "library_benchmarks", lambda: ([], True))
    monkeypatch.setattr(bench, "ledger_parallel_ratio", lambda: ([], True))
    assert _main(monkeypatch, "--standalone", "--out", str(out)) == 0
    results["b.md"] = (12.0, "error: KeyError")  # a page failing, then the library passing
    assert _main(monkeypatch, "--standalone", "--out", str(out)) == 1


def test_bench_main_models_times_each_paper_and_figure(tmp_path, monkeypatch):
    """Oracle: the ledger's rows and two figures given by hand, each model's program and its
    status; one failing figure fails the run."""
    _no_work(monkeypatch)
    _builds(monkeypatch)
    figures = types.ModuleType("navcore.figures")
    figures.registry = lambda: ["F1", "F2"]
    monkeypatch.setitem(sys.modules, "navcore.figures", figures)
    monkeypatch.setattr(navcore, "figures", figures, raising=False)
    monkeypatch.setattr(bench, "ledger_times", lambda: ["| ledger rows |"])
    codes = []
    statuses = {}

    def time_subprocess(code):
        codes.append(code)
        return 1.0 + len(codes), statuses.get(len(codes), "ok")

    monkeypatch.setattr(bench, "time_subprocess", time_subprocess)
    out = tmp_path / "bench.md"
    assert _main(monkeypatch, "--build-only", "--models", "--out", str(out)) == 0
    assert out.read_text().startswith("# Build benchmark")  # the builds' rows before the models
    assert out.read_text().splitlines()[-11:] == [
        "",
        "| ledger rows |",
        "",
        "| model, fresh process | seconds | status |",
        "|---|---:|---|",
        "| ledger WF | 2.0 | ok |",
        "| ledger SP | 3.0 | ok |",
        "| ledger ATC10 | 4.0 | ok |",
        "| ledger KZL | 5.0 | ok |",
        "| figure F1 | 6.0 | ok |",
        "| figure F2 | 7.0 | ok |",
    ]
    head = "import os; os.environ['NAVCORE_CACHE'] = 'off'; os.environ['NAVCORE_NO_DISK_CACHE'] = '1'\n"
    assert codes == [
        *(
            head + f"from navcore import ledger; assert all(e.passes for e in ledger.evaluations('{paper}'))"
            for paper in ("WF", "SP", "ATC10", "KZL")
        ),
        "from navcore import figures; figures.render('F1')",
        "from navcore import figures; figures.render('F2')",
    ]
    for failing in (1, 6):
        codes.clear()
        statuses.clear()
        statuses[failing] = "error"
        assert _main(monkeypatch, "--build-only", "--models", "--out", str(out)) == 1


@pytest.mark.parametrize(
    ("library_ok", "ledger_ok", "status"), [(True, True, 0), (False, True, 1), (True, False, 1)]
)
def test_bench_main_whole_run_adds_the_library_and_the_ledger(
    tmp_path, monkeypatch, library_ok, ledger_ok, status
):
    """Oracle: after the builds, the library's rows and the ledger's under their heading;
    either failing fails the run; no core count known counts one core."""
    _no_work(monkeypatch)
    _builds(monkeypatch)
    monkeypatch.setattr(bench, "library_benchmarks", lambda: (["", "| library |"], library_ok))
    monkeypatch.setattr(bench, "ledger_parallel_ratio", lambda: (["| ledger row |"], ledger_ok))
    monkeypatch.setattr(bench.os, "cpu_count", lambda: None)
    out = tmp_path / "bench.md"
    assert _main(monkeypatch, "--out", str(out)) == status
    assert out.read_text().splitlines()[0] == "# Build benchmark (1 cores, jobs = 1)"
    assert out.read_text().splitlines()[-8:] == [
        "- met: full build under 5 min",
        "- met: full build within 1.3x of the floor",
        "",
        "| library |",
        "",
        "| ledger | value |",
        "|---|---:|",
        "| ledger row |",
    ]


def test_bench_write_makes_the_folder_and_says_where(tmp_path, capsys):
    """Oracle: two lines written to a new folder, the status from ``ok``."""
    out = tmp_path / "a" / "b" / "bench.md"
    assert bench._write(out, ["x", "y"], True) == 0
    assert out.read_text() == "x\ny\n"
    assert capsys.readouterr().out == f"x\ny\nwritten to {out}\n"
    assert bench._write(out, [], False) == 1
    assert out.read_text() == "\n"


def test_bench_default_report_is_in_the_build_folder(monkeypatch):
    """Oracle: without ``--out`` the report goes to ``_build/bench.md`` of the checkout."""
    _no_work(monkeypatch)
    written = []
    monkeypatch.setattr(bench, "ledger_times", lambda: [])
    monkeypatch.setattr(Path, "write_text", lambda self, text: written.append(self))
    monkeypatch.setattr(Path, "mkdir", lambda self, **k: None)
    assert _main(monkeypatch, "--ledger") == 0
    assert written == [bench.ROOT / "_build" / "bench.md"]
