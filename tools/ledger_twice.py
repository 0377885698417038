"""Evaluate the ledger in two fresh processes at once and compare their JSON exports byte for byte.

Usage: ``python tools/ledger_twice.py OUT.json [LEDGER ARGS ...]`` (``nox -s ledger -- --twice``).
Both processes evaluate every claim afresh. The first evaluates them itself (``--jobs 1``),
prints the ledger and writes ``OUT.json``, and stores each evaluation in the on-disk cache
without reading it (``NAVCORE_CACHE_REFRESH=1``), so that a book built next reuses them; the
second evaluates them in worker processes (``--jobs 2``, one task per paper module) with the
cache off and writes ``OUT.second.json``. The two run
side by side, so the determinism gate of ``.ci/run`` costs about one evaluation's CPU time on
two cores, and it also shows that the parallel ledger is the serial one, byte for byte.
Exit status: a process's own (1 if a claim fails its check), else 1 if the exports differ.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path


def main(argv: list[str]) -> int:
    if not argv:
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    first, extra = Path(argv[0]), argv[1:]
    second = first.with_name(first.stem + ".second.json")
    first.parent.mkdir(parents=True, exist_ok=True)

    def command(out: Path, jobs: str) -> list[str]:
        return [sys.executable, "-m", "navcore", "ledger", "--jobs", jobs, "--json-out", str(out), *extra]

    base = {k: v for k, v in os.environ.items() if k not in ("NAVCORE_CACHE", "NAVCORE_CACHE_REFRESH")}
    runs = [
        subprocess.Popen(command(first, "1"), env={**base, "NAVCORE_CACHE_REFRESH": "1"}),
        subprocess.Popen(
            command(second, "2"), env={**base, "NAVCORE_CACHE": "off"}, stdout=subprocess.DEVNULL
        ),
    ]
    codes = [run.wait() for run in runs]
    if any(codes):
        return next(code for code in codes if code)
    if first.read_bytes() != second.read_bytes():
        print(f"two evaluations of the ledger differ: {first} and {second}", file=sys.stderr)
        return 1
    print(f"the ledger evaluated in one process and on two workers wrote identical JSON ({first})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
