"""Stopping a book build stops every process it started and leaves the execution cache valid.

A two-chapter toy book is executed by the build's own pre-execution step (one worker per
chapter, each with its own kernel). Chapter ``b`` is quick and is stored in the cache;
chapter ``a`` sleeps in its kernel. The build is then stopped the three ways it can be:
Ctrl-C (SIGINT to the whole process group), SIGTERM to the build process alone, and the death
of the process that started it (nox killed: SIGKILL to the parent). Within a few seconds no
process of the build may be left (workers and kernels included), and the cache must hold
exactly the finished chapter, readable and matching its page.
"""

from __future__ import annotations

import importlib.util
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.slow

HEADER = """---
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---

# {title}

```{{code-cell}} ipython3
{code}
```
"""

SLOW = """import os, pathlib, time
pathlib.Path({mark!r}).write_text(str(os.getpid()))
time.sleep(600)"""

RUNNER = """
import sys
from pathlib import Path
sys.path.insert(0, {tools!r})
import build_book as mod
if {stop_with_parent}:
    mod._set_parent_death_signal()
book = Path({book!r})
pages = sorted(book.rglob("*.md"))
try:
    mod.prefill(Path({cache!r}), pages, jobs=2, book=book)
except KeyboardInterrupt:
    sys.exit(130)
"""


def _children() -> dict[int, list[int]]:
    tree: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        ppid = int(stat.rsplit(")", 1)[1].split()[1])
        tree.setdefault(ppid, []).append(int(entry.name))
    return tree


def _descendants(pid: int) -> set[int]:
    tree, found, todo = _children(), set(), [pid]
    while todo:
        for child in tree.get(todo.pop(), []):
            if child not in found:
                found.add(child)
                todo.append(child)
    return found


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _wait(predicate, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.2)
    return predicate()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
@pytest.mark.parametrize("how", ["sigint-group", "sigterm-build", "parent-killed"])
def test_interrupt_stops_every_process_and_keeps_the_cache_valid(how: str, tmp_path: Path) -> None:
    from jupyter_cache import get_cache

    book = tmp_path / "book"
    mark = tmp_path / "slow-kernel.pid"
    (book / "a").mkdir(parents=True)
    (book / "b").mkdir()
    (book / "a" / "1-slow.md").write_text(HEADER.format(title="Slow", code=SLOW.format(mark=str(mark))))
    (book / "b" / "1-quick.md").write_text(HEADER.format(title="Quick", code="1 + 1"))
    cache = tmp_path / "cache"
    runner = RUNNER.format(
        tools=str(ROOT / "tools"),
        book=str(book),
        cache=str(cache),
        stop_with_parent=how == "parent-killed",
    )
    if how == "parent-killed":
        # a stand-in for nox: a shell that runs the build and is then killed
        cmd = ["/bin/sh", "-c", f'"{sys.executable}" -c "$0"; sleep 600', runner]
    else:
        cmd = [sys.executable, "-c", runner]
    proc = subprocess.Popen(cmd, cwd=tmp_path, start_new_session=True)
    try:
        assert _wait(mark.exists, 120), "the slow page never started"
        kernel = int(mark.read_text())
        # the quick chapter is stored before the slow one is interrupted
        assert _wait(lambda: len(get_cache(str(cache)).list_cache_records()) == 1, 60)
        started = _descendants(proc.pid) | {kernel}
        assert len(started) >= 3, started  # at least two workers and the slow kernel
        if how == "sigint-group":
            os.killpg(proc.pid, signal.SIGINT)
        elif how == "sigterm-build":
            proc.send_signal(signal.SIGTERM)
        else:
            proc.send_signal(signal.SIGKILL)
        t0 = time.monotonic()
        assert _wait(lambda: not any(_alive(p) for p in started), 10), [
            (p, Path(f"/proc/{p}/cmdline").read_text()) for p in started if _alive(p)
        ]
        assert time.monotonic() - t0 < 10
        if how != "parent-killed":
            assert proc.wait(10) != 0
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()

    # the cache holds the finished chapter, whole and matching its page, and nothing else
    spec = importlib.util.spec_from_file_location("build_book_t", ROOT / "tools" / "build_book.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    store = get_cache(str(cache))
    records = store.list_cache_records()
    assert len(records) == 1
    bundle = store.get_cache_bundle(records[0].pk)
    assert bundle.nb.cells[0].outputs[0]["data"]["text/plain"] == "2"
    store.match_cache_notebook(mod._read_notebook(book / "b" / "1-quick.md"))
    with pytest.raises(KeyError):
        store.match_cache_notebook(mod._read_notebook(book / "a" / "1-slow.md"))
