"""The papers audit (tools/papers_audit.py) classifies paper-module functions as it says.

Oracle: two small synthetic paper modules written here, whose input reads, claim computes and
leftovers are known by construction.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _load_tool():
    spec = importlib.util.spec_from_file_location("papers_audit", ROOT / "tools" / "papers_audit.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["papers_audit"] = module
    spec.loader.exec_module(module)
    return module


audit_tool = _load_tool()

CHAPTER = """
from navcore.claims import Claim, InputSet

IN = InputSet("ATC10", "chapter")

CH = IN


def reads_input():
    return IN.x


def through_a_reader():
    return reads_input() + 1


def plain_helper():
    return 2


def reads_second_name():
    return CH.z


def _s(cid, compute):
    return Claim(id=cid, compute=compute)


def local_compute():
    return plain_helper()


CLAIMS = [_s("ATC10-a", local_compute)]
"""

SECTION = """
from navcore.claims import Claim
from navcore.papers.atc10_chapter import CH, IN, _s


def imported_builder_compute():
    return 3


def reads_imported_set():
    return IN.y


def leftover():
    return 4


def reads_imported_second_name():
    return CH.w


def statement_compute():
    return 5


CLAIMS = [
    _s("ATC10-b", imported_builder_compute),
    Claim.statement(id="ATC10-c", compute=statement_compute),
]
"""


def test_reads_computes_and_leftovers_across_two_modules(tmp_path: Path):
    (tmp_path / "atc10_chapter.py").write_text(CHAPTER)
    (tmp_path / "atc10_section.py").write_text(SECTION)
    mods = audit_tool.audit(sorted(tmp_path.glob("*.py")))
    left = {m: sorted(f.name for f in audit_tool.candidates(mod)) for m, mod in mods.items()}
    # plain_helper reads no input and is named in no claim call (local_compute is); a compute
    # passed to a builder imported from the chapter module is a claim's compute too, and so is
    # one passed to Claim.statement
    assert left == {"atc10_chapter": ["plain_helper"], "atc10_section": ["leftover"]}
    chapter, section = mods["atc10_chapter"].functions, mods["atc10_section"].functions
    assert chapter["through_a_reader"].reads and not chapter["through_a_reader"].reads_directly
    assert section["reads_imported_set"].reads_directly
    # a second name of an input set (CH = IN) is an input set, here and where it is imported
    assert chapter["reads_second_name"].reads_directly
    assert section["reads_imported_second_name"].reads_directly
    assert chapter["_s"].builds and not chapter["local_compute"].builds
