"""Evaluate the ledger in two fresh processes at once and compare their JSON exports byte for byte.

Usage: ``python tools/ledger_twice.py OUT.json [LEDGER ARGS ...]`` (``nox -s ledger -- --twice``
runs it with the evaluation caches off). The first process prints the ledger and writes
``OUT.json``; the second writes ``OUT.second.json``. The two run side by side, one per core,
so the determinism gate of ``.ci/run`` costs one evaluation's wall-clock time, not two.
Exit status: a process's own (1 if a claim fails its check), else 1 if the exports differ.
"""

from __future__ import annotations

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

    def command(out: Path) -> list[str]:
        return [sys.executable, "-m", "navcore", "ledger", "--json-out", str(out), *extra]

    runs = [subprocess.Popen(command(first)), subprocess.Popen(command(second), stdout=subprocess.DEVNULL)]
    codes = [run.wait() for run in runs]
    if any(codes):
        return next(code for code in codes if code)
    if first.read_bytes() != second.read_bytes():
        print(f"two evaluations of the ledger differ: {first} and {second}", file=sys.stderr)
        return 1
    print(f"two evaluations of the ledger, in separate processes, wrote identical JSON ({first})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
