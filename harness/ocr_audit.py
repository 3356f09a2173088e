"""The printed listings against the scan's text: every repair of OCR damage, found and registered.

``legacy/printed/`` holds each listing as printed, OCR damage repaired.  ``legacy/scan/`` holds,
per listing, the scan's own text (``<listing>.txt``: the seed's lines, verbatim) and the list
of every difference between the two (``<listing>.toml``: the seed lines it comes from and
``[[repair]]`` items, each naming the register entry that explains it).  The comparison is by tokens, not by lines (the OCR broke and
joined lines and moved some), so a repair is a pair of token runs:

    printed = "DO 10 I = 2 , 9"     scan = "DJ 10 I = 2 , 9"

Tokens are runs of letters and digits or single other characters, upper-cased, blanks and line
breaks dropped.  The WATFIV statement numbers the 1977 scans print before each statement, and
blank and Markdown fence lines, are not part of the listing and are dropped from the scan.

``python -m linkrepro.harness.ocr_audit [LISTING]`` prints the unregistered differences (the
audit's to-do list) and exits 1 if there are any; ``--extract`` rewrites the ``.txt`` files
from the seeds when they are at hand (``../shared/seeds``).
"""
from __future__ import annotations

import argparse
import difflib
import json
import re
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

#: the source tree (an installed package lacks legacy/scan: pass the tree as ``root``)
ROOT = Path(__file__).resolve().parent.parent
#: context tokens shown around a difference (not part of its key)
CONTEXT = 4

_TOKEN = re.compile(r"[A-Z0-9_]+|\S")
_WATFIV_NUMBER = re.compile(r"^\s*\d+\s+(?=\S)")
_FENCE = re.compile(r"^\s*```")
_WORD = re.compile(r"[A-Z0-9]+")
#: a comment card: C or * in column 1 (the scan: C, or the Cyrillic letter the OCR read, first)
_PRINTED_COMMENT = re.compile(r"^[Cc*]")
_SCAN_COMMENT = re.compile(r"^\s*[CcС](?=\s|\*|\.|$)")


@dataclass(frozen=True)
class Difference:
    """One run of printed tokens where the scan has another run (either may be empty)."""
    printed: str
    scan: str
    context: str           # the printed text around it, for a reader

    @property
    def key(self) -> tuple[str, str]:
        return self.printed, self.scan


def tokens(lines: list[str], comment: re.Pattern) -> list[str]:
    """The listing's tokens: upper-cased runs of letters/digits and single other characters;
    on comment cards only the words (their rows of stars and dots are decoration), marked by
    a leading ``C``."""
    found = []
    for line in lines:
        mark = comment.match(line)
        if mark:
            words = _WORD.findall(line[mark.end():].upper())
            found += ["C", *words] if words else []
        else:
            found += _TOKEN.findall(line.upper())
    return found


def printed_lines(listing: str, root: Path = ROOT) -> list[str]:
    return (root / "legacy" / "printed" / listing).read_text().splitlines()


def _scan(listing: str, root: Path, suffix: str) -> Path:
    return root / "legacy" / "scan" / (Path(listing).stem + suffix)


def scan_config(listing: str, root: Path = ROOT) -> dict:
    """``legacy/scan/<listing minus .f>.toml``: seed, line ranges, numbered, repairs."""
    with open(_scan(listing, root, ".toml"), "rb") as fh:
        return tomllib.load(fh)


def scan_lines(listing: str, root: Path = ROOT) -> list[str]:
    """The scan's text of the listing with what is not the listing's dropped (module docstring)."""
    return [line for _, line in numbered_scan_lines(listing, root)]


def numbered_scan_lines(listing: str, root: Path = ROOT) -> list[tuple[int, str]]:
    """``scan_lines`` with the seed line number each line comes from (the ``.txt`` holds the
    seed lines of the ``.toml``'s ranges, one after another)."""
    config = scan_config(listing, root)
    numbers = [n for first, last in config["lines"] for n in range(first, last + 1)]
    lines = []
    for number, line in zip(numbers, _scan(listing, root, ".txt").read_text().splitlines()):
        if _FENCE.match(line) or not line.strip():
            continue
        lines.append((number, _WATFIV_NUMBER.sub("", line) if config.get("numbered", False) else line))
    return lines


def differences(listing: str, root: Path = ROOT) -> list[Difference]:
    """Every run where printed/ and the scan's text differ, in the printed listing's order."""
    ours = tokens(printed_lines(listing, root), _PRINTED_COMMENT)
    theirs = tokens(scan_lines(listing, root), _SCAN_COMMENT)
    matcher = difflib.SequenceMatcher(a=ours, b=theirs, autojunk=False)
    found = []
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal":
            continue
        context = " ".join(ours[max(0, i1 - CONTEXT):i1] + ["[", *ours[i1:i2], "]"] + ours[i2:i2 + CONTEXT])
        found.append(Difference(" ".join(ours[i1:i2]), " ".join(theirs[j1:j2]), context))
    return found


def registered(listing: str, root: Path = ROOT) -> list[dict]:
    """The ``[[repair]]`` items of the listing: ``printed`` and ``scan`` (token runs as
    ``differences`` gives them), ``deviation`` (the register entry), optional ``count`` (how
    many times the same repair occurs, default 1) and ``note``."""
    return scan_config(listing, root).get("repair", [])


def unregistered(listing: str, root: Path = ROOT) -> tuple[list[Difference], list[dict]]:
    """(differences no repair item names, repair items no difference matches)."""
    found = differences(listing, root)
    pending = {}
    for item in registered(listing, root):
        pending.setdefault((item["printed"], item["scan"]), []).extend([item] * int(item.get("count", 1)))
    missing = []
    for diff in found:
        items = pending.get(diff.key)
        if items:
            items.pop()
        else:
            missing.append(diff)
    stale = [item for items in pending.values() for item in items]
    return missing, stale


def listings(root: Path = ROOT) -> list[str]:
    """The printed listings that have a scan (every file of legacy/printed should)."""
    return sorted(p.stem + ".f" for p in (root / "legacy" / "scan").glob("*.toml"))


def seed_excerpt(listing: str, seeds: Path, root: Path = ROOT) -> str:
    """The seed lines (``seeds``: the folder of the OCR'd theses) the scan's ``.toml`` names."""
    config = scan_config(listing, root)
    seed = (seeds / config["seed"]).read_text().splitlines()
    text = []
    for first, last in config["lines"]:
        text += seed[first - 1:last]
    return "\n".join(text) + "\n"


def extract(listing: str, seeds: Path = ROOT.parent / "shared" / "seeds", root: Path = ROOT) -> None:
    """Write ``legacy/scan/<listing>.txt`` from the seed lines its ``.toml`` names."""
    _scan(listing, root, ".txt").write_text(seed_excerpt(listing, seeds, root))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m linkrepro.harness.ocr_audit", description=__doc__.split("\n")[0])
    parser.add_argument("listing", nargs="*", help="e.g. ali1977_case1_source.f (default: every one)")
    parser.add_argument("--extract", action="store_true", help="rewrite the scan texts from the seeds")
    args = parser.parse_args(argv)
    names = args.listing or listings()
    status = 0
    for name in names:
        if args.extract:
            extract(name)
        missing, stale = unregistered(name)
        print(f"# {name}: {len(differences(name))} differences, {len(missing)} unregistered, {len(stale)} stale")
        for diff in missing:
            status = 1
            print(f"[[repair]]  # at: {diff.context}\nprinted = {json.dumps(diff.printed)}\n"
                  f"scan = {json.dumps(diff.scan)}\ndeviation = \"D???\"")
        for item in stale:
            status = 1
            print(f"# stale: {item}")
    return status


if __name__ == "__main__":
    sys.exit(main())
