"""Measure how much of ``navcore/papers`` is paper data and how much is model code.

A paper module should hold, for one section of its paper, the inputs, claims and errata and
little else (issue 33, "papers as data"). This script reads every module of
``navcore/papers`` with :mod:`ast` (nothing is imported or run) and reports, per module, its
lines and the functions that read no paper input and are not a claim's compute: the
candidates to move to a domain package (a model or generic numerics) or to the tests (a
fixture). The last column counts the functions whose own body names no input set (they
may still read inputs through a function they call: the looser count of the issue).

The classification is static and transitive:

* a function *reads a paper input* when its body names an input set (a module-level
  ``X = InputSet(...)`` or a second name ``Y = X`` of one, an input set imported from another
  paper module, or ``alias.IN`` of an imported paper module) or names a function of
  ``navcore/papers`` that does;
* a function is a *claim's compute* when it is named inside a call that builds a claim:
  ``Claim(...)``, ``Erratum(...)`` or a function of the module whose body calls ``Claim``
  (``compute=f``, ``compute=lambda: f(...)``, ``_s("id", ..., f, ...)``), or builds one
  itself;
* methods count under their class (``Class.method``); nested functions count with the
  function that holds them.

Usage::

    python tools/papers_audit.py            # the table and the totals
    python tools/papers_audit.py --list     # ... and the candidate functions, by module

The numbers are a measure, not a verdict: a candidate that assembles a paper's scenario
from arguments its caller read stays in its paper module.
"""

from __future__ import annotations

import argparse
import ast
import sys
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAPERS = ROOT / "navcore" / "papers"
BUILDERS = {"Claim", "Erratum"}


@dataclass
class Function:
    """One top-level function or method of a paper module."""

    module: str
    name: str
    lines: int
    names: set[str] = field(default_factory=set)  # bare names referenced in the body
    attrs: set[tuple[str, str]] = field(default_factory=set)  # (alias, attribute) pairs
    in_claim: bool = False  # named inside a Claim/Erratum call, or builds a Claim
    builds: bool = False  # its body calls Claim (a claim builder such as ``_s``)
    reads: bool = False  # reads a paper input, itself or through a function it names
    reads_directly: bool = False  # its own body names an input set


@dataclass
class Module:
    """What the audit needs of one paper module."""

    name: str
    lines: int
    input_sets: set[str] = field(default_factory=set)
    aliases: dict[str, str] = field(default_factory=dict)  # local alias -> paper module
    imported: dict[str, tuple[str, str]] = field(default_factory=dict)  # local -> (module, name)
    functions: dict[str, Function] = field(default_factory=dict)
    claim_names: set[str] = field(default_factory=set)  # names inside Claim(...) calls
    call_refs: dict[str, set[str]] = field(default_factory=dict)  # callee -> names in its arguments


def _call_name(node: ast.Call) -> str:
    """The called name; ``Claim.statement(...)`` (a constructor of Claim) counts as ``Claim``."""
    f = node.func
    if isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name) and f.value.id in BUILDERS:
        return f.value.id
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""


def _references(node: ast.AST) -> tuple[set[str], set[tuple[str, str]]]:
    names: set[str] = set()
    attrs: set[tuple[str, str]] = set()
    for sub in ast.walk(node):
        if isinstance(sub, ast.Name):
            names.add(sub.id)
        elif isinstance(sub, ast.Attribute) and isinstance(sub.value, ast.Name):
            attrs.add((sub.value.id, sub.attr))
    return names, attrs


def _call_refs(tree: ast.AST) -> dict[str, set[str]]:
    """For each name called in the module, the bare names its calls' arguments reference."""
    out: dict[str, set[str]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            refs = out.setdefault(_call_name(node), set())
            for part in [*node.args, *(k.value for k in node.keywords)]:
                refs |= _references(part)[0]
    return out


def _claim_names(mod: Module, builders: set[str]) -> set[str]:
    return set().union(*(refs for callee, refs in mod.call_refs.items() if callee in builders))


def read_module(path: Path) -> Module:
    """Parse one paper module."""
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text)
    mod = Module(path.stem, text.count("\n"))
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module:
            if node.module == "navcore.papers":
                for a in node.names:
                    mod.aliases[a.asname or a.name] = a.name
            elif node.module.startswith("navcore.papers."):
                src = node.module.rsplit(".", 1)[1]
                for a in node.names:
                    mod.imported[a.asname or a.name] = (src, a.name)
        elif isinstance(node, ast.Import):
            for a in node.names:
                if a.name.startswith("navcore.papers.") and a.asname:
                    mod.aliases[a.asname] = a.name.rsplit(".", 1)[1]
    for node in tree.body:
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Call):
            if _call_name(node.value) == "InputSet":
                mod.input_sets |= {t.id for t in node.targets if isinstance(t, ast.Name)}
        elif isinstance(node, ast.Assign) and isinstance(node.value, ast.Name):
            if node.value.id in mod.input_sets:  # a second name of an input set (``MA = IN``)
                mod.input_sets |= {t.id for t in node.targets if isinstance(t, ast.Name)}
    defs: list[tuple[str, ast.AST]] = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            defs.append((node.name, node))
        elif isinstance(node, ast.ClassDef):
            defs += [
                (f"{node.name}.{m.name}", m)
                for m in node.body
                if isinstance(m, ast.FunctionDef | ast.AsyncFunctionDef)
            ]
    for name, node in defs:
        start = min([node.lineno, *(d.lineno for d in node.decorator_list)])
        fn = Function(mod.name, name, node.end_lineno - start + 1)
        fn.names, fn.attrs = _references(node)
        fn.builds = any(isinstance(s, ast.Call) and _call_name(s) == "Claim" for s in ast.walk(node))
        fn.in_claim = fn.builds
        mod.functions[name] = fn
    mod.call_refs = _call_refs(tree)
    return mod


def _mark_computes(mods: dict[str, Module]) -> None:
    """Mark the functions named in a claim builder's call, the builder local or imported from
    another paper module (a section module calls its chapter's ``_s``)."""
    for mod in mods.values():
        builders = BUILDERS | {n for n, f in mod.functions.items() if f.builds}
        builders |= {
            local
            for local, (src, orig) in mod.imported.items()
            if src in mods and orig in mods[src].functions and mods[src].functions[orig].builds
        }
        mod.claim_names = _claim_names(mod, builders)
        for fn in mod.functions.values():
            if fn.name in mod.claim_names:
                fn.in_claim = True


def audit(paths: list[Path]) -> dict[str, Module]:
    """Read the modules and decide, to a fixed point, which functions read a paper input."""
    mods = {p.stem: read_module(p) for p in paths}
    _mark_computes(mods)

    def resolve(mod: Module, name: str) -> Function | None:
        if name in mod.functions:
            return mod.functions[name]
        if name in mod.imported:
            src, orig = mod.imported[name]
            return mods[src].functions.get(orig) if src in mods else None
        return None

    def is_input_set(mod: Module, name: str) -> bool:
        if name in mod.input_sets:
            return True
        src = mod.imported.get(name)
        return bool(src) and src[0] in mods and src[1] in mods[src[0]].input_sets

    changed = True
    while changed:
        changed = False
        for mod in mods.values():
            for fn in mod.functions.values():
                if fn.reads:
                    continue
                hit = any(is_input_set(mod, n) for n in fn.names)
                hit = hit or any(a in mod.input_sets or (a in mod.aliases and t == "IN") for a, t in fn.attrs)
                fn.reads_directly = fn.reads_directly or hit
                hit = hit or any((f := resolve(mod, n)) is not None and f.reads for n in fn.names)
                for alias, attr in fn.attrs:
                    if hit:
                        break
                    if alias in mod.aliases and mod.aliases[alias] in mods:
                        other = mods[mod.aliases[alias]]
                        f = other.functions.get(attr)
                        hit = attr in other.input_sets or (f is not None and f.reads)
                    elif alias in mod.functions or alias in mod.imported:  # Class.method
                        f = resolve(mod, alias)
                        hit = f is not None and f.reads
                if hit:
                    fn.reads = changed = True
    return mods


def candidates(mod: Module) -> list[Function]:
    """Functions of ``mod`` that read no paper input and are not a claim's compute."""
    return [f for f in mod.functions.values() if not f.reads and not f.in_claim]


def main(argv: list[str] | None = None) -> int:
    """Print the table (and with ``--list`` the candidates); return 0."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", action="store_true", help="list the candidate functions")
    args = parser.parse_args(argv)
    mods = audit(sorted(p for p in PAPERS.glob("*.py") if p.name != "__init__.py"))
    rows = sorted(mods.values(), key=lambda m: -m.lines)
    total = [0, 0, 0, 0, 0]
    head = ("module", "lines", "funcs", "no-input", "their lines", "no direct read")
    print(f"{head[0]:32s} {head[1]:>6s} {head[2]:>6s} {head[3]:>8s} {head[4]:>11s} {head[5]:>14s}")
    for m in rows:
        cand = candidates(m)
        direct = sum(not f.reads_directly for f in m.functions.values())
        row = [m.lines, len(m.functions), len(cand), sum(f.lines for f in cand), direct]
        total = [a + b for a, b in zip(total, row, strict=True)]
        print(f"{m.name:32s} {row[0]:6d} {row[1]:6d} {row[2]:8d} {row[3]:11d} {row[4]:14d}")
        if args.list:
            for f in sorted(cand, key=lambda f: -f.lines):
                print(f"    {f.name} ({f.lines})")
    print(f"{'total':32s} {total[0]:6d} {total[1]:6d} {total[2]:8d} {total[3]:11d} {total[4]:14d}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
