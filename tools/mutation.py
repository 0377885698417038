"""Mutation testing with mutmut, one package at a time: the models, the ledger, the tools.

Usage: ``python tools/mutation.py [PACKAGE ...] [--budget-min M] [--max-children N] [--out PATH]``
(``nox -s mutation -- gnss`` runs it in the locked environment). PACKAGE is one of
:data:`PACKAGES` (default: all of them).

The packages (:data:`PACKAGES`): the model packages (estimation, inertial, gnss,
integration, detection, location, frames), the ledger engine (``ledger``: ``navcore/claims``,
``navcore/ledger`` and ``navcore/formatting.py``), ``units`` (``navcore/units.py`` and the
validation layer ``navcore/_validate.py``), ``figures``, the paper modules' functions
(``papers``: the claims are their tests), ``tools`` (``tools/*.py``) and the book's Sphinx
extensions (``book_ext``). Each is run with the tests that exercise it, never the whole
suite.

For each package a scratch project is laid out in ``_build/mutation/<package>/``: a copy of
``navcore/`` and ``tests/`` (and of ``tools/``, ``book/_ext`` or the book's pages where the
package needs them) and a ``pyproject.toml`` holding the repository's pytest options
and a ``[tool.mutmut]`` section that mutates only that package and selects only the test
files that exercise it (:data:`PACKAGES`; mutmut then narrows them per function, running for
each mutant only the tests that called the mutated function in its first, clean run). Each
run starts afresh (mutmut caches verdicts by mutated source, so a survivor would stay one
after a new test); ``--keep`` reuses the cache when only the code changed.
``--mutants PATTERN ...`` (one package) re-runs only the named mutants in the existing scratch
project, after refreshing its tests (mutmut finds the new tests and records what they reach):
the quick check that a new test kills the survivors it was written for, e.g.
``nox -s mutation -- gnss --mutants 'navcore.gnss.antijam.x_code_tracking*'``.

``--sample N`` (with ``--seed S``, default 0) runs a seeded random sample of N of a package's
mutants instead of all of them: the estimate for a package whose complete run takes hours (the
paper modules: each mutant's claim tests evaluate their claims afresh, 1-20 s). The mutants are
generated first (mutmut's own generation, no test run), their names sorted and sampled with
``random.Random(S)``, and only the sample is run; the row reports the sample's score with its
95 % Wilson interval, and the mutants outside the sample as not checked.

``mutmut run`` gets ``--budget-min`` minutes of wall-clock time per package (default 30; the
machine has 2 cores); a run cut short reports what it checked, and the unchecked mutants
are counted as such, never as killed. The score is ``killed / (killed + survived + no
tests)``: timeouts count as killed (the mutant made a test hang), mutants with no covering
test as survivors (the tests cannot see them). Equivalent mutants that were examined by hand
are described in ``tests/mutation_equivalents.md`` (function, change, reason); they are not
subtracted from the score. mutmut numbers a function's mutants in order, so a name such as
``x_rotvec_from_quat__mutmut_43`` is only stable while the function and the configuration
are.

The table is printed and written to ``_build/mutation.md``; the survivors' names go below it
(``cd _build/mutation/<package> && mutmut show NAME`` shows a diff). The aim of issue 21
(90 % killed per package) is reported, never asserted: this is a developer's session, not a
gate of ``.ci/run``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
WORK = ROOT / "_build" / "mutation"


@dataclass(frozen=True)
class Package:
    """What one mutation run mutates and which tests it runs.

    Attributes
    ----------
    mutate : list of str
        Globs of the files to mutate (mutmut's ``only_mutate``), relative to the repository.
    tests : list of str
        The test files that exercise them (under ``tests/``).
    deselect : str
        Tests of those files left out, as a pytest ``-k`` expression of what to leave out
        (``"a or b"`` runs ``-k "not (a or b)"``): tests that evaluate the whole ledger or
        build a book and check nothing of the package that a faster test does not.
    sources : tuple of str
        Folders copied into the scratch project as mutmut's ``source_paths``. Tools and book
        extensions are loaded by the tests from their files under their dotted names
        (``tools.check_book``), the names mutmut's trampolines recognise.
    copy : tuple of str
        Further folders or files the tests read (the book's pages, ``_config.yml``), copied as
        they are; ``tools`` always is, unmutated unless it is among ``sources``.
    not_mutated : list of str or None
        Lines not mutated (regular expressions); ``None`` for :data:`NOT_MUTATED`.
    import_time : bool
        The package runs code when imported that tests read (the paper modules build their
        claims at import): each mutant's run imports the tests afresh with the mutant active
        (mutmut's ``forkserver_warmup = "none"``, a few seconds more per mutant) instead of
        forking from a server that imported them unmutated, where a mutant of such code never
        runs and survives every test (the papers' claim helpers: a dropped tolerance, which
        fails the import, "survived").
    """

    mutate: list[str]
    tests: list[str]
    deselect: str = ""
    sources: tuple[str, ...] = ("navcore",)
    copy: tuple[str, ...] = ()
    not_mutated: list[str] | None = None
    import_time: bool = False


#: Lines not mutated (regular expressions): input validation, whose mutants only change an
#: error message's text or drop a check that ``tests/*::test_bad_input*`` exercise by name,
#: and which another issue is reworking across the library. Model code is all mutated; the
#: ``units`` run mutates the validation layer itself, every line.
NOT_MUTATED = [
    r"^\s*raise (ValueError|TypeError)\(",
    r"^\s*require_\w+\(",
    r"^\s*f?\"[^\"]*\"\)?,?$",
    r"^\s*\w+ = (as_finite_array|require_\w+|_\w+)\(\"\w+\", \w+\)$",
]

#: Package -> what it mutates and the tests that exercise it. Paper-level tests (the whole
#: ledger, the book builds, the long Monte Carlos) are left out of the model packages: they
#: take minutes and test the packages only through the papers' scenarios. For ``papers`` the
#: claims are the tests (each compares a paper module's function with the printed number):
#: mutmut runs, for each mutant, only the claims whose computation reached the mutated
#: function, so no mutant evaluates the whole ledger (the first, clean run does, once).
PACKAGES: dict[str, Package] = {
    "estimation": Package(
        ["navcore/estimation/*"],
        [
            "test_estimation.py",
            "test_estimation_kernel.py",
            "test_lmmse.py",
            "test_federated.py",
            "test_antijam.py",
            "test_covariance_analysis.py",
            "test_covariance_analysis_results.py",
            "test_ekf_ins_gnss.py",
            "test_ekf_ins_gnss_physics.py",
            "test_error_model17.py",
            "test_error_dynamics.py",
            "test_library_lifted.py",
        ],
    ),
    "inertial": Package(
        ["navcore/inertial/*"],
        [
            "test_strapdown.py",
            "test_trajectories.py",
            "test_error_dynamics.py",
            "test_inertial_imu.py",
            "test_residual_acceleration.py",
            "test_error_model17.py",
            "test_covariance_analysis.py",
            "test_ekf_ins_gnss.py",
        ],
    ),
    "gnss": Package(
        ["navcore/gnss/*"],
        [
            "test_acquisition.py",
            "test_antijam.py",
            "test_tracking.py",
            "test_jammer_flyby.py",
            "test_error_model17.py",
            "test_covariance_analysis.py",
            "test_sp_architectures.py",
            "test_constellation_geometry.py",
            "test_carrier_phase_geometry.py",
            "test_dop.py",
            "test_gnss_mutants.py",
        ],
    ),
    "integration": Package(
        ["navcore/integration/*"],
        [
            "test_covariance_analysis.py",
            "test_covariance_analysis_results.py",
            "test_ekf_ins_gnss.py",
            "test_ekf_ins_gnss_physics.py",
            "test_error_model17.py",
            "test_error_dynamics.py",
        ],
    ),
    "detection": Package(
        ["navcore/detection/*"],
        [
            "test_antenna.py",
            "test_detection_jamming.py",
            "test_jamming_monte_carlo.py",
            "test_multiple_access.py",
            "test_neyman_pearson.py",
            "test_roc_bounds.py",
            "test_zakai.py",
            "test_pulse_detection.py",
        ],
    ),
    "location": Package(
        ["navcore/location/*"],
        [
            "test_clock_model.py",
            "test_clock_tracking.py",
            "test_emitter.py",
            "test_multilateration.py",
            "test_sp_target_location.py",
            "test_library_lifted.py",
        ],
    ),
    "frames": Package(
        ["navcore/frames.py"],
        [
            "test_frames.py",
            "test_frames_bulk.py",
            "test_frames_edges.py",
            "test_strapdown.py",
            "test_error_model17.py",
        ],
    ),
    "gravity": Package(["navcore/gravity.py"], ["test_gravity.py"]),
    # the ledger engine on synthetic claims (one test evaluates a single registry claim: the
    # evaluation cache's round trip): the claims' types and verdict rule, the registry, the
    # rendering, and the text of units and numbers it prints with
    "ledger": Package(
        ["navcore/claims/*", "navcore/ledger/*", "navcore/formatting.py"],
        [
            "test_ledger.py",
            "test_ledger_inputs.py",
            "test_run_store.py",
            "test_claims_run_memo.py",
            "test_ledger_readings.py",
            "test_ledger_mechanisms.py",
            "test_ledger_printed.py",
            "test_ledger_compared_number.py",
            "test_claims_with_quotes.py",
            "test_render_claims.py",
            "test_errata_kinds.py",
            "test_ledger_mutation_verdict.py",
            "test_ledger_mutation_tolerance.py",
            "test_ledger_mutation_bands.py",
            "test_ledger_mutation_inputs.py",
            "test_ledger_mutation_evaluate.py",
            "test_ledger_mutation_summary.py",
            "test_ledger_mutation_render.py",
            "test_ledger_mutation_note.py",
            "test_ledger_mutation_registry.py",
            "test_ledger_css.py",
            "test_ledger_registry_keys.py",
            "test_ledger_render_quote_below.py",
            "test_ledger_trailing_zeros.py",
            "test_ledger_note_text.py",
            "test_plain_math.py",
            "test_ledger_sample_mutants.py",
            "test_book_format.py",
        ],
        deselect="each_published_input_moves or every_tolerance_has_a_policy or no_old_id_left",
        # the rendering tests read the book's LaTeX settings and its stylesheet
        copy=("_config.yml", "book"),
    ),
    "units": Package(
        ["navcore/units.py", "navcore/_validate.py"],
        ["test_units.py", "test_validate.py", "test_api_inputs.py"],
        not_mutated=[],
    ),
    "figures": Package(
        ["navcore/figures/*"], ["test_figures.py", "test_figure_data.py", "test_figures_mutants.py"]
    ),
    "papers": Package(
        ["navcore/papers/*"],
        [
            # first: mutmut gives the code that runs at import (the claims' helpers) to the first
            # test it runs, and this one checks every claim's declaration without evaluating it
            "test_claim_declarations.py",
            "test_atc10_jamming.py",
            "test_atc10_multiple_access.py",
            "test_atc10_tracking.py",
            "test_kzl_covariance.py",
            "test_sp_architectures.py",
            "test_sp_missions.py",
            "test_sp_target_location.py",
            "test_jammer_flyby.py",
            "test_wf_assessment.py",
            "test_glue_values.py",
            "test_atc10_oracles.py",
            "test_claims.py",
            "test_papers_mutants.py",
        ],
        copy=("book",),
        import_time=True,
    ),
    "tools": Package(
        ["tools/*"],
        [
            "test_book_tools.py",
            "test_book_tools_edges.py",
            "test_book_claim_selection.py",
            "test_book_format.py",
            "test_claim_values_tool.py",
            "test_input_gate.py",
            "test_input_gate_inprocess.py",
            "test_tools_inprocess.py",
            "test_bench_inprocess.py",
            "test_mutation_tool.py",
            "test_build_book_inprocess.py",
            "test_import_layers.py",
            "test_papers_audit.py",
        ],
        sources=("navcore", "tools"),
        copy=("book", "ARCHITECTURE.md"),  # the import-layer test reads the layer map
        deselect="errata_and_ledger_links or interactive_ledger_filters",
    ),
    "book_ext": Package(
        ["book/_ext/*"],
        [
            "test_book_ext.py",
            "test_book_errata_boxes.py",
            "test_book_tools.py",
            "test_book_tools_edges.py",
            "test_glossary_links.py",
        ],
        sources=("navcore", "book/_ext"),
        copy=("book",),
        deselect="errata_and_ledger_links or interactive_ledger_filters",
    ),
}

#: mutmut's exit-code classes (mutmut.stats.status_by_exit_code), grouped for the score.
KILLED = {"killed", "timeout", "segfault", "caught by type check"}
SURVIVED = {"survived", "no tests"}


def scratch_project(package: str, keep: bool = False) -> Path:
    """Lay out (or refresh) ``_build/mutation/<package>`` for one package."""
    spec = PACKAGES[package]
    work = WORK / package
    work.mkdir(parents=True, exist_ok=True)
    if not keep and (work / "mutants").exists():
        # mutmut keys its cached verdicts on the mutated source, not on the tests: a survivor
        # stays a survivor after a new test unless the cache goes
        shutil.rmtree(work / "mutants")
    for folder in dict.fromkeys(("navcore", "tests", "tools", *spec.sources, *spec.copy)):
        if (ROOT / folder).is_file():  # a file the tests read (the book's _config.yml)
            shutil.copy2(ROOT / folder, work / folder)
            continue
        if (work / folder).exists():
            shutil.rmtree(work / folder)
        shutil.copytree(ROOT / folder, work / folder, ignore=shutil.ignore_patterns("__pycache__", "_build"))
    pytest_options = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["pytest"]["ini_options"]
    pytest_options = {k: v for k, v in pytest_options.items() if k not in ("testpaths", "addopts")}
    selection = ["tests/" + t for t in spec.tests]
    if spec.deselect:
        selection += ["-k", f"not ({spec.deselect})"]
    not_mutated = NOT_MUTATED if spec.not_mutated is None else spec.not_mutated
    # the tools are read by some tests of every package (unmutated, unless they are the package)
    also_copy = [f for f in dict.fromkeys(("tools", *spec.copy)) if f not in spec.sources]
    lines = ["[tool.pytest.ini_options]"]
    lines += [f"{k} = {json.dumps(v)}" for k, v in pytest_options.items()]
    lines += [
        'addopts = "-p no:cacheprovider"',
        "",
        "[tool.mutmut]",
        f"source_paths = {json.dumps(list(spec.sources))}",
        f"also_copy = {json.dumps(also_copy)}",
        f"only_mutate = {json.dumps(spec.mutate)}",
        f"pytest_add_cli_args_test_selection = {json.dumps(selection)}",
        'pytest_add_cli_args = ["-x", "-q"]',
        f"do_not_mutate_patterns = {json.dumps(not_mutated)}",
        "use_git_change_detection = false",
        # each mutant's tests run in a child of a server that only collected the tests, never
        # of the process that ran them all: a claim's evaluation and the model runs memoised in
        # that clean run would otherwise be inherited, and a mutant's claim test would pass on
        # the unmutated result (the first papers run, 6 December: 836 of 1176 WF mutants "survived")
        'process_isolation = "forkserver"',
        f'forkserver_warmup = "{"none" if spec.import_time else "collect"}"',
        "timeout_multiplier = 5.0",
        "timeout_constant = 10.0",
        "",
    ]
    (work / "pyproject.toml").write_text("\n".join(lines))
    return work


#: mutmut's mutant generation alone (mutmut 3.8's ``run`` takes these steps, in this order,
#: before it runs any test): it writes every mutant's name, unchecked, in the ``.meta`` files.
_GENERATE = (
    "import os\n"
    "import mutmut.__main__ as m\n"
    "m.set_mutant_under_test('mutant_generation')\n"
    "os.makedirs('mutants', exist_ok=True)\n"
    "m.copy_src_dir()\n"
    "m.copy_also_copy_files()\n"
    "m.setup_source_paths()\n"
    "m.store_lines_covered_by_tests()\n"
    "m.create_mutants(1)\n"
)


def mutant_names(work: Path) -> list[str]:
    """Every mutant's name in a scratch project's ``.meta`` files, sorted."""
    names: list[str] = []
    for meta in (work / "mutants").rglob("*.py.meta"):
        names += json.loads(meta.read_text()).get("exit_code_by_key", {})
    return sorted(names)


def sample_mutants(names: list[str], size: int, seed: int) -> list[str]:
    """A seeded random sample of ``size`` of ``names`` (all of them if there are no more), sorted.

    The draw is ``random.Random(seed).sample`` of the sorted names, so the same names, size and
    seed give the same sample on any machine.
    """
    if isinstance(size, bool) or not isinstance(size, int) or size < 1:
        raise ValueError(f"size must be a positive integer, got {size!r}")
    population = sorted(names)
    if size >= len(population):
        return population
    return sorted(random.Random(seed).sample(population, size))


def wilson_interval(killed: int, judged: int, z: float = 1.959963984540054) -> tuple[float, float]:
    """The Wilson score interval (95 % by default) of a proportion ``killed / judged``.

    Used for a sampled run's score: the package's score lies in it with 95 % confidence (the
    sample is drawn without replacement from a finite population, so the interval is slightly
    conservative).
    """
    if judged < 1 or not 0 <= killed <= judged:
        raise ValueError(f"need 0 <= killed <= judged and judged >= 1, got killed={killed}, judged={judged}")
    p = killed / judged
    centre = (p + z * z / (2 * judged)) / (1 + z * z / judged)
    half = z / (1 + z * z / judged) * math.sqrt(p * (1 - p) / judged + z * z / (4 * judged * judged))
    return max(0.0, centre - half), min(1.0, centre + half)


def run_package(
    package: str,
    budget_min: float,
    max_children: int,
    keep: bool = False,
    mutants: list[str] | None = None,
    sample: int | None = None,
    seed: int = 0,
) -> dict:
    """Run mutmut on one package within the budget (only ``mutants``, if given, or a seeded sample
    of ``sample`` mutants); return its counts."""
    if sample is not None and mutants:
        raise ValueError("give mutants or sample, not both")
    work = scratch_project(package, keep or bool(mutants))
    # no ledger cache on disk: every mutant's file has the same contents (mutmut switches the
    # mutants at run time), so an evaluation a mutant's run stored would be read by the next
    # (NAVCORE_TEST_CACHE=off keeps tests/conftest.py from making a session folder)
    env = {
        **os.environ,
        "HYPOTHESIS_PROFILE": "ci",
        "NAVCORE_CACHE": "off",
        "NAVCORE_TEST_CACHE": "off",
        "NAVCORE_NO_DISK_CACHE": "1",
    }
    start = time.monotonic()
    cut = False
    population = 0
    if sample is not None:
        with (work / "mutmut-generate.log").open("w") as log:
            command = [sys.executable, "-c", _GENERATE]
            subprocess.run(command, cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT, check=True)
        names = mutant_names(work)
        population = len(names)
        mutants = sample_mutants(names, sample, seed)
    with (work / "mutmut-run.log").open("w") as log:
        proc = subprocess.Popen(
            [sys.executable, "-m", "mutmut", "run", "--max-children", str(max_children), *(mutants or [])],
            cwd=work,
            env=env,
            stdout=log,
            stderr=subprocess.STDOUT,
            start_new_session=True,
        )
        try:
            proc.wait(timeout=budget_min * 60)
        except subprocess.TimeoutExpired:
            cut = True
            os.killpg(proc.pid, 15)
            proc.wait()
    counts = count_results(work)
    minutes = (time.monotonic() - start) / 60
    counts.update(package=package, minutes=minutes, cut=cut, returncode=proc.returncode)
    if sample is not None:
        counts.update(sample=len(mutants or ()), seed=seed, population=population)
    return counts


def count_results(work: Path) -> dict:
    """Counts by class from the ``.meta`` files mutmut leaves beside each mutated module."""
    from mutmut.stats import status_by_exit_code

    counts: dict[str, Any] = {"killed": 0, "survived": 0, "not checked": 0, "other": 0, "total": 0}
    survivors: list[str] = []
    for meta in sorted((work / "mutants").rglob("*.py.meta")):
        data = json.loads(meta.read_text())
        for name, code in data.get("exit_code_by_key", {}).items():
            status = status_by_exit_code[code]
            counts["total"] += 1
            if status in KILLED:
                counts["killed"] += 1
            elif status in SURVIVED:
                counts["survived"] += 1
                survivors.append(f"{name} ({status})")
            elif status == "not checked":
                counts["not checked"] += 1
            else:
                counts["other"] += 1
    counts["survivors"] = survivors
    return counts


def _completeness(r: dict) -> str:
    """Whether a run judged every mutant, and if not why: mutmut failed (it exits non-zero only
    when it cannot run, e.g. the clean tests fail), the budget cut it, or it left no result;
    mutants mutmut reports as neither killed nor survived (skipped, suspicious, interrupted)
    are counted after it."""
    code = r.get("returncode") or 0  # a --report-only row has none
    if r.get("sample") is not None:
        judged = r["killed"] + r["survived"]
        unrun = r["not checked"] - (r["population"] - r["sample"])  # the rest are outside the sample
        low, high = wilson_interval(r["killed"], judged) if judged else (math.nan, math.nan)
        band = f"{100 * low:.1f}-{100 * high:.1f} %" if judged else "-"
        done = f"sample of {r['sample']} (seed {r['seed']}), 95 % interval {band}"
        if unrun > 0:
            done += f", {unrun} of the sample not checked"
    elif code and not r["cut"]:
        done = f"no (mutmut exited {code})"
    elif r["cut"] or r["not checked"]:
        done = "no (budget)"
    elif not r["total"]:
        done = "no (no results)"
    else:
        done = "yes"
    other = r.get("other", 0)
    return f"{done}; {other} other" if other else done


def table(rows: list[dict]) -> str:
    lines = [
        "| package | mutants | killed | survived | not checked | score | minutes | complete |",
        "|---|---:|---:|---:|---:|---:|---:|---|",
    ]
    for r in rows:
        judged = r["killed"] + r["survived"]
        score = f"{100 * r['killed'] / judged:.1f} %" if judged else "-"
        complete = _completeness(r)
        lines.append(
            f"| {r['package']} | {r['total']} | {r['killed']} | {r['survived']} | {r['not checked']} "
            f"| {score} | {r['minutes']:.1f} | {complete} |"
        )
    lines.append("")
    lines.append("Score = killed / (killed + survived); timeouts count as killed, mutants no test")
    lines.append("reaches as survived; unchecked mutants (budget) are excluded from the score.")
    if any(r.get("other") for r in rows):
        lines.append("'other': mutants mutmut reports as skipped, suspicious or interrupted (in no column).")
    lines.append("Survivors examined and found equivalent are described in tests/mutation_equivalents.md.")
    for r in rows:
        if r["survivors"]:
            lines.append("")
            lines.append(f"Survivors in {r['package']}:")
            lines.append("")
            lines += [f"- `{s}`" for s in r["survivors"]]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "packages", nargs="*", metavar="PACKAGE", help=f"packages to run (default all): {', '.join(PACKAGES)}"
    )
    parser.add_argument("--budget-min", type=float, default=30.0, help="wall-clock minutes per package")
    parser.add_argument("--max-children", type=int, default=2)
    parser.add_argument("--out", type=Path, default=ROOT / "_build" / "mutation.md")
    parser.add_argument("--report-only", action="store_true", help="tabulate the last runs, run nothing")
    parser.add_argument(
        "--keep", action="store_true", help="reuse mutmut's cached verdicts (if the tests did not change)"
    )
    parser.add_argument(
        "--mutants", nargs="+", metavar="PATTERN", help="re-run only these mutants (globs), one package"
    )
    parser.add_argument(
        "--sample", type=int, metavar="N", help="run a seeded random sample of N mutants of each package"
    )
    parser.add_argument("--seed", type=int, default=0, help="the sample's seed (default 0)")
    args = parser.parse_args(argv)
    if args.sample is not None and args.sample < 1:
        parser.error(f"--sample must be a positive number of mutants, got {args.sample}")
    if args.sample is not None and (args.mutants or args.keep or args.report_only):
        parser.error("--sample runs afresh: it takes no --mutants, --keep or --report-only")
    unknown = [p for p in args.packages if p not in PACKAGES]
    if unknown:
        parser.error(f"unknown package {unknown[0]!r}; choose from {', '.join(PACKAGES)}")
    packages = args.packages or list(PACKAGES)
    if args.mutants and len(packages) != 1:
        parser.error("--mutants needs exactly one package")
    rows = []
    for package in packages:
        if args.report_only:
            r = count_results(WORK / package)
            r.update(package=package, minutes=0.0, cut=False)
        else:
            print(f"mutation testing navcore.{package} ({args.budget_min:g} min budget)", flush=True)
            extra = {} if args.sample is None else {"sample": args.sample, "seed": args.seed}
            r = run_package(package, args.budget_min, args.max_children, args.keep, args.mutants, **extra)
        rows.append(r)
    text = table(rows)
    print(text)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
