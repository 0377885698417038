"""Stopping a book build stops every process it started, at every phase, and the next build works.

A toy book (tests/_toybook.py) is built by the real build tool. Each test drives the build to
one phase by what it prints, not by a fixed sleep: the chapter's ledger warm-up in its kernel,
a page executing in a worker's kernel, Sphinx reading, Sphinx writing, and the LaTeX run of the
PDF. It then stops the build one of the ways a user or a tool can: Ctrl-C (SIGINT to the whole
process group), SIGINT or SIGTERM to the build process alone, SIGTERM to the group, or the death
of the process that started it (nox killed). Within 10 s no process of the build may be left
(workers, kernels, Sphinx, LaTeX), every entry of the execution cache must be whole and match its
page, and a next build (nothing lingering this time) must succeed.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from _toybook import ROOT, build_command, build_env, make_book

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc"),
]

# The pid is written under another name and renamed, so the test never reads a half-written file.
SLOW_PAGE = """import os, pathlib, time
pathlib.Path("slow-kernel.pid.part").write_text(str(os.getpid()))
os.replace("slow-kernel.pid.part", "slow-kernel.pid")
print("slow page")
time.sleep(600 if os.environ.get("TOY_LINGER") == "page" else 0)"""


def _table() -> dict[int, tuple[int, str]]:
    table = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            table[int(entry.name)] = (int(fields[1]), fields[0])
    return table


def _descendants(pid: int) -> set[int]:
    children: dict[int, list[int]] = {}
    for child, (parent, _) in _table().items():
        children.setdefault(parent, []).append(child)
    found, todo = set(), [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            if child not in found:
                found.add(child)
                todo.append(child)
    return found


def _alive(pid: int) -> bool:
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _cmdline(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_text().replace("\0", " ")[:200]
    except OSError:
        return "?"


class Build:
    """A build started in its own session, its output read line by line."""

    def __init__(self, cmd: list[str], env: dict[str, str], cwd: Path, via_parent: bool = False) -> None:
        if via_parent:  # a stand-in for nox: a shell that runs the build, and is then killed
            cmd = ["/bin/sh", "-c", '"$@"; sleep 600', "sh", *cmd]
            env = dict(env, NAVCORE_STOP_WITH_PARENT="1")
        self.proc = subprocess.Popen(
            cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True,
        )  # fmt: skip
        self.lines: list[str] = []
        self._cond = threading.Condition()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with self._cond:
                self.lines.append(line)
                self._cond.notify_all()

    def wait_for(self, pattern: str, timeout: float = 300) -> None:
        regex = re.compile(pattern)
        with self._cond:
            ok = self._cond.wait_for(lambda: any(regex.search(line) for line in self.lines), timeout)
        assert ok, f"never printed {pattern!r}:\n{''.join(self.lines[-40:])}"

    def log(self) -> str:
        return "".join(self.lines)

    def close(self) -> None:
        self._reader.join(10)
        assert self.proc.stdout is not None
        self.proc.stdout.close()


def _stop_and_check(build: Build, how: str, extra: set[int] = frozenset()) -> None:  # type: ignore[assignment]
    started = _descendants(build.proc.pid) | set(extra)
    if how == "int-group":
        os.killpg(build.proc.pid, signal.SIGINT)
    elif how == "term-group":
        os.killpg(build.proc.pid, signal.SIGTERM)
    elif how == "int-top":
        build.proc.send_signal(signal.SIGINT)
    elif how == "term-top":
        build.proc.send_signal(signal.SIGTERM)
    elif how == "parent-killed":
        build.proc.send_signal(signal.SIGKILL)
    else:  # pragma: no cover
        raise ValueError(how)
    t0 = time.monotonic()
    try:
        while time.monotonic() - t0 < 10 and any(_alive(p) for p in started | {build.proc.pid}):
            time.sleep(0.1)
            build.proc.poll()
        left = [(p, _cmdline(p)) for p in started if _alive(p)]
        assert not left, f"still running {time.monotonic() - t0:.1f} s after {how}: {left}\n{build.log()}"
        if how != "parent-killed":
            assert build.proc.wait(1) != 0
    finally:
        for pid in started | {build.proc.pid}:
            if _alive(pid):
                os.kill(pid, signal.SIGKILL)
        build.proc.wait()
        build.close()


def _check_cache(tmp: Path, book: Path) -> int:
    """Every entry of the execution cache is whole (notebook and dependency record) and matches a page."""
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        import build_book
    finally:
        sys.path.pop(0)
    from jupyter_cache import get_cache

    folders = [p for p in (tmp / "jupyter_cache").iterdir() if p.is_dir()]
    assert len(folders) == 1
    cache = get_cache(str(folders[0]))
    pages = {str(p): build_book._read_notebook(p) for p in book.rglob("[0-9]*.md")}
    records = cache.list_cache_records()
    for record in records:
        folder = Path(cache._get_notebook_path_cache(record.hashkey)).parent
        assert (folder / "base.ipynb").exists()
        assert set(json.loads((folder / "navcore-deps.json").read_text())) == {
            "modules",
            "files",
            "module_list",
        }
        assert cache.match_cache_notebook(pages[record.uri]).pk == record.pk
    return len(records)


def _next_build_succeeds(cmd: list[str], tmp: Path, builder_dir: str = "html") -> str:
    proc = subprocess.run(cmd, cwd=tmp, env=build_env(tmp), capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert any((tmp / "out" / "_build" / builder_dir).iterdir())
    return proc.stdout


@pytest.mark.parametrize("how", ["term-top", "int-top", "parent-killed"])
def test_stop_while_a_page_executes(how: str, tmp_path: Path) -> None:
    book, config = make_book(tmp_path, {"b": {"1-quick.md": "1 + 1", "2-slow.md": SLOW_PAGE}})
    cmd = build_command(book, config, tmp_path / "out")
    build = Build(cmd, build_env(tmp_path, TOY_LINGER="page"), tmp_path, via_parent=how == "parent-killed")
    build.wait_for(r"prefill:\s+[\d.]+ s\s+b/1-quick.md")  # the quick page is stored
    marker = book / "b" / "slow-kernel.pid"
    deadline = time.monotonic() + 120
    while not marker.exists() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert marker.exists(), "the slow page did not start within 120 s"
    kernel = int(marker.read_text())  # the slow page is running in its kernel
    _stop_and_check(build, how, {kernel})
    assert _check_cache(tmp_path, book) == 1  # the quick page, whole; the slow one not at all
    out = _next_build_succeeds(cmd, tmp_path)
    assert "b/2-slow.md (not in the cache)" in out and "1-quick.md" not in out


def test_ctrl_c_during_the_ledger_warm_up(tmp_path: Path) -> None:
    """A chapter named for a paper evaluates that paper's claims first, in its kernel."""
    book, config = make_book(tmp_path, {"wf": {"1-quick.md": "1 + 1"}})
    cmd = build_command(book, config, tmp_path / "out")
    build = Build(cmd, build_env(tmp_path, NAVCORE_CACHE="off"), tmp_path)
    build.wait_for(r"prefill: WF: evaluating the chapter's claims")
    _stop_and_check(build, "int-group")
    assert _check_cache(tmp_path, book) == 0
    assert "wf/1-quick.md (not in the cache)" in _next_build_succeeds(cmd, tmp_path)


@pytest.mark.parametrize(("phase", "how"), [("reading", "int-group"), ("writing", "term-top")])
def test_stop_while_sphinx_runs(phase: str, how: str, tmp_path: Path) -> None:
    book, config = make_book(tmp_path, {"b": {"1-quick.md": "1 + 1"}})
    cmd = build_command(book, config, tmp_path / "out")
    build = Build(cmd, build_env(tmp_path, TOY_LINGER=phase), tmp_path)
    build.wait_for(f"toy: sphinx {phase}")
    _stop_and_check(build, how)
    assert _check_cache(tmp_path, book) == 1
    assert "all 1 notebooks are in the cache" in _next_build_succeeds(cmd, tmp_path)


@pytest.mark.skipif(shutil.which("xelatex") is None, reason="no XeLaTeX")
def test_ctrl_c_during_the_latex_run(tmp_path: Path) -> None:
    book, config = make_book(tmp_path, {"b": {"1-quick.md": "1 + 1"}}, slow_latex=True)
    cmd = build_command(book, config, tmp_path / "out", builder="pdflatex")
    build = Build(cmd, build_env(tmp_path), tmp_path)
    build.wait_for(r"latex: typesetting")
    deadline = time.monotonic() + 60  # and XeLaTeX is running (latexmk is quiet)
    while time.monotonic() < deadline and not any(
        "xelatex" in _cmdline(p) for p in _descendants(build.proc.pid)
    ):
        time.sleep(0.1)
    time.sleep(0.5)  # inside the TeX run, not at its first line
    _stop_and_check(build, "int-group")
    assert _check_cache(tmp_path, book) == 1
    make_book(tmp_path, {"b": {"1-quick.md": "1 + 1"}})  # a quick preamble this time
    _next_build_succeeds(cmd, tmp_path, "latex")
    assert (tmp_path / "out" / "_build" / "latex" / "book.pdf").exists()
