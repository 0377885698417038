"""Check navcore's imports against the layer map in ARCHITECTURE.md.

ARCHITECTURE.md (at the top of the repository) declares, in its table of layers, which layer
each package or module of navcore belongs to. This tool reads every ``import`` statement in
navcore, at module level or inside a function, ``TYPE_CHECKING`` blocks included (a lazy import
is still a dependency), and reports:

- a module the map does not place (a new module must be given its layer);
- an import that points to a higher layer than its importer's;
- a cycle between files, or between packages (the top-level subpackages and modules of
  navcore: ``navcore.ledger``, ``navcore.units``, ...).

Usage: ``python tools/import_layers.py`` prints the findings and exits 1 when there are any;
``--graph`` also prints the package-level arrows.
"""

from __future__ import annotations

import argparse
import ast
import re
import sys
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: A row of the layer table: ``| 3 | `navcore.inertial`, `navcore.gnss` | ... |``.
_LAYER_ROW = re.compile(r"^\|\s*(\d+)\s*\|([^|]*)\|")
_NAME = re.compile(r"`(navcore(?:\.\w+)*)`")


@dataclass(frozen=True)
class Finding:
    """One violation of the layer map: its kind and a sentence for a reader."""

    kind: str
    text: str


def read_layers(architecture: Path) -> dict[str, int]:
    """Package or module name -> layer, from the layer table of ARCHITECTURE.md.

    Only the second column's backticked ``navcore...`` names count; a name listed twice is an
    error.

    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = Path(d) / "A.md"
    ...     _ = p.write_text("| layer | modules |\\n| --- | --- |\\n| 0 | `navcore.units` |\\n")
    ...     read_layers(p)
    {'navcore.units': 0}
    """
    layers: dict[str, int] = {}
    for line in architecture.read_text(encoding="utf-8").splitlines():
        row = _LAYER_ROW.match(line)
        if not row:
            continue
        for name in _NAME.findall(row.group(2)):
            if name in layers:
                raise ValueError(f"{name} is placed twice in the layer table")
            layers[name] = int(row.group(1))
    if not layers:
        raise ValueError(f"no layer table in {architecture}")
    return layers


def module_files(package_dir: Path) -> dict[str, Path]:
    """Dotted module name -> file, for every ``.py`` file under ``package_dir``."""
    out = {}
    for path in sorted(package_dir.rglob("*.py")):
        parts = list(path.relative_to(package_dir.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


def _resolve(target: str, modules: Mapping[str, Path]) -> str | None:
    """The module a dotted import target lands in (``navcore.ledger.Claim`` -> ``navcore.ledger``)."""
    while target:
        if target in modules:
            return target
        target = target.rpartition(".")[0]
    return None


def imports_of(name: str, path: Path, modules: Mapping[str, Path]) -> set[str]:
    """The navcore modules that module ``name`` (file ``path``) imports, anywhere in its body."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    targets: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            targets += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            for alias in node.names:
                full = f"{module}.{alias.name}"
                targets.append(full if full in modules else module)
    found = {_resolve(t, modules) for t in targets if t == "navcore" or t.startswith("navcore.")}
    return {t for t in found if t and t != name}


def layer_of(name: str, layers: Mapping[str, int]) -> tuple[str, int] | None:
    """The map entry that places module ``name``: the longest listed prefix, with its layer.

    >>> layer_of("navcore.ledger.core", {"navcore": 0, "navcore.ledger": 7})
    ('navcore.ledger', 7)
    >>> layer_of("navcore.new_module", {"navcore": 0}) is None
    True
    """
    probe = name
    while "." in probe:
        if probe in layers:
            return probe, layers[probe]
        probe = probe.rpartition(".")[0]
    # the bare package name places the package's own __init__ only, never a new module
    return (name, layers[name]) if name in layers else None


def package_of(name: str) -> str:
    """The top-level part of navcore a module belongs to (``navcore.ledger.core`` -> ``navcore.ledger``)."""
    return ".".join(name.split(".")[:2])


def cycles(graph: Mapping[str, Iterable[str]]) -> list[list[str]]:
    """The strongly connected components with more than one node (Tarjan), each sorted.

    >>> cycles({"a": ["b"], "b": ["a"], "c": ["a"]})
    [['a', 'b']]
    """
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = 0

    def visit(v: str) -> None:
        nonlocal counter
        index[v] = low[v] = counter
        counter += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(found)


def check(package_dir: Path, architecture: Path) -> tuple[list[Finding], dict[str, set[str]]]:
    """Every finding for the package at ``package_dir`` under the map in ``architecture``.

    Returns the findings and the package-level graph (package -> packages it imports).
    """
    layers = read_layers(architecture)
    modules = module_files(package_dir)
    graph = {name: imports_of(name, path, modules) for name, path in modules.items()}
    findings: list[Finding] = []
    placed = {}
    for name in modules:
        entry = layer_of(name, layers)
        if entry is None:
            findings.append(Finding("unplaced", f"{name} has no layer in the map"))
        else:
            placed[name] = entry[1]
    for entry in sorted(layers):
        if _resolve(entry, modules) != entry and not any(m.startswith(entry + ".") for m in modules):
            findings.append(Finding("stale", f"the map places {entry}, which does not exist"))
    for name, targets in sorted(graph.items()):
        for target in sorted(targets):
            if name in placed and target in placed and placed[target] > placed[name]:
                findings.append(
                    Finding(
                        "upward",
                        f"{name} (layer {placed[name]}) imports {target} (layer {placed[target]})",
                    )
                )
    packages: dict[str, set[str]] = {}
    for name, targets in graph.items():
        for target in targets:
            a, b = package_of(name), package_of(target)
            if a != b:
                packages.setdefault(a, set()).add(b)
    for component in cycles(graph):
        findings.append(Finding("file cycle", "files import each other: " + ", ".join(component)))
    for component in cycles(packages):
        findings.append(Finding("package cycle", "packages import each other: " + ", ".join(component)))
    return findings, packages


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--graph", action="store_true", help="also print the package-level arrows")
    args = parser.parse_args(argv)
    findings, packages = check(ROOT / "navcore", ROOT / "ARCHITECTURE.md")
    if args.graph:
        for source in sorted(packages):
            print(f"{source} -> {', '.join(sorted(packages[source]))}")
    for finding in findings:
        print(f"{finding.kind}: {finding.text}")
    print(f"{len(findings)} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
