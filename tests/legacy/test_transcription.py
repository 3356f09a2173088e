"""legacy/src is legacy/printed plus tagged edits only; tags and quirks are registered."""
import difflib
import re

import pytest

from linkrepro.port.ali1977 import Quirks
from linkrepro.port.rahman1996.quirks import CsspQuirks
from linkrepro.port.rahman1991.quirks import GscQuirks

TAG = re.compile(r"!\s*(D\d{3})\s*$")
PROGRAMS = ["ali1977_case1_source.f", "ali1977_case1_cognate.f", "ali1977_case2_source.f",
            "ali1977_case2_cognate.f", "ali1977_case3_source.f", "ali1977_case3_cognate.f",
            "rahman1996_cssp_main.f", "rahman1996_subroutines.f"]
#: our own code for a vanished library (IMSL), not a listing (D050)
STAND_INS = ["imsl_qprog.f"]
#: a program with no listing, reconstructed in src/ from a printed sibling (D037)
RECONSTRUCTED_FROM = {"ali1977_case3_cognate.f": "ali1977_case1_cognate.f"}


@pytest.mark.parametrize("name", PROGRAMS)
def test_src_differs_from_printed_only_on_tagged_lines(root, name, register):
    printed = (root / "legacy" / "printed" / RECONSTRUCTED_FROM.get(name, name)).read_text().splitlines()
    src = (root / "legacy" / "src" / name).read_text().splitlines()
    matcher = difflib.SequenceMatcher(a=printed, b=src, autojunk=False)
    untagged, deleted = [], []
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal":
            continue
        if op == "delete":
            deleted += printed[i1:i2]
        for line in src[j1:j2]:
            match = TAG.search(line)
            if not match:
                untagged.append(line)
            else:
                assert match.group(1) in register, f"{name}: tag {match.group(1)} has no register entry"
    assert not deleted, f"{name}: printed lines removed without a tagged replacement: {deleted}"
    assert not untagged, f"{name}: untagged edits in src: {untagged}"


def test_src_holds_only_edited_programs(root):
    """A listing that needs no edit (the SSP routines) is built from printed/ directly."""
    assert sorted(p.name for p in (root / "legacy" / "src").glob("*.f")) == sorted(PROGRAMS + STAND_INS)


def test_every_tag_in_src_is_registered(root, register):
    tags = {m.group(1) for path in (root / "legacy" / "src").glob("*.f")
            for line in path.read_text().splitlines() if (m := TAG.search(line))}
    assert tags, "no tags found: the src edits must be tagged"
    assert tags <= set(register), f"unregistered tags: {tags - set(register)}"


def test_every_quirk_has_one_register_entry_and_back(register):
    quirks_in_register = [e.quirk for e in register.values() if e.quirk]
    assert sorted(quirks_in_register) == sorted(Quirks.names() + CsspQuirks.names() + GscQuirks.names())
    for entry in register.values():
        if entry.quirk:
            assert entry.kind == "original-bug", f"{entry.id}: a quirk models a bug of the original"
