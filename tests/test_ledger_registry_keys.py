"""The ledger's stored evaluations are keyed on the files that compute them, not on those that
present them (issue 29: a change to the claim tables' HTML re-renders without re-evaluating)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from navcore.ledger import registry

ROOT = Path(__file__).resolve().parents[1]


def test_presentation_modules_are_not_in_a_claim_key_but_the_evaluation_is():
    """Oracle: the registry's own file list, read by hand: every claim's key holds the
    evaluating ledger modules and none of the presentation modules."""
    for c in registry.claims():
        deps = set(registry.claim_dependencies(c.id))
        assert {"claims/runs.py", "claims/inputs.py", "ledger/registry.py"} <= deps, c.id
        assert not {f"ledger/{name}" for name in registry._PRESENTATION} & deps, c.id


def test_evaluating_claims_imports_no_presentation_module():
    """Oracle: ``sys.modules`` of a fresh process that evaluates afresh (the disk cache off)
    every claim of WF and of ATC-10's jamming bounds (statements, bands, readings of
    conventions) and reads each stored field: no presentation module was imported, so none
    can have computed a stored field."""
    code = (
        "import json, sys\n"
        "from navcore.ledger import registry\n"
        "for c in registry.claims():\n"
        "    if c.paper == 'WF' or registry._CLAIM_MODULE[c.id] in ('navcore.papers.atc10_jamming',\n"
        "            'navcore.papers.atc10_single_pulse', 'navcore.papers.atc10_tracking_lists',\n"
        "            'navcore.papers.atc10_system_tables'):\n"
        "        ev = registry.evaluate_claim(c.id)\n"
        "        [getattr(ev, f) for f in registry._RECORD_FIELDS]\n"
        "ours = ('navcore.ledger', 'navcore.claims')\n"
        "print(json.dumps(sorted(m for m in sys.modules if m.startswith(ours))))\n"
    )
    env = dict(os.environ, NAVCORE_CACHE="off")
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, check=True
    )
    loaded = set(json.loads(out.stdout.strip().splitlines()[-1]))
    assert "navcore.claims.runs" in loaded
    assert not {f"navcore.ledger.{name.removesuffix('.py')}" for name in registry._PRESENTATION} & loaded


def test_every_paper_module_is_in_the_reading_order_and_the_ledger_follows_it():
    """Oracle: the files of navcore/papers, and the order the reading list gives by hand."""
    import navcore.papers as pkg

    files = {p.stem for p in Path(pkg.__file__).parent.glob("*.py") if not p.stem.startswith("_")}
    assert sorted(pkg.READING_ORDER) == sorted(files), "list each paper module once in READING_ORDER"
    assert [m.rsplit(".", 1)[1] for m in registry.paper_modules()] == list(pkg.READING_ORDER)
    papers = [registry._module_paper(m) for m in pkg.READING_ORDER]
    runs = [p for i, p in enumerate(papers) if i == 0 or p != papers[i - 1]]
    assert runs == ["WF", "SP", "ATC10", "KZL"], "each paper's modules together, in the papers' order"
