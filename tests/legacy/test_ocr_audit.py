"""legacy/printed against the scan's text: every difference is a registered OCR repair."""
from pathlib import Path

import pytest

from linkrepro.harness import ocr_audit

SEEDS = Path(__file__).resolve().parents[3] / "shared" / "seeds"


def _listings(root):
    return sorted(p.name for p in (root / "legacy" / "printed").glob("*.f"))


def test_every_printed_listing_has_a_scan(root):
    assert _listings(root) == ocr_audit.listings(root)


@pytest.mark.parametrize("listing", _listings(Path(__file__).resolve().parents[2]))
def test_every_difference_from_the_scan_is_a_registered_repair(root, register, listing):
    missing, stale = ocr_audit.unregistered(listing, root)
    assert not missing, (f"{listing}: {len(missing)} unregistered differences from the scan "
                         f"(python -m linkrepro.harness.ocr_audit {listing}), first: {missing[0]}")
    assert not stale, f"{listing}: repairs that no difference matches: {stale[:3]}"
    for item in ocr_audit.registered(listing, root):
        entry = register.get(item["deviation"])
        assert entry is not None, f"{listing}: repair {item} names no register entry"
        assert entry.kind == "ocr", f"{listing}: repair {item} names {entry.id}, a {entry.kind} entry"


def test_a_changed_printed_token_is_found(root, tmp_path):
    """The audit can fail: one token of a printed listing changed is an unregistered difference."""
    listing = _listings(root)[0]
    for sub in ("printed", "scan"):
        (tmp_path / "legacy" / sub).mkdir(parents=True)
    (tmp_path / "legacy" / "scan" / (Path(listing).stem + ".toml")).write_text(
        (root / "legacy" / "scan" / (Path(listing).stem + ".toml")).read_text())
    (tmp_path / "legacy" / "scan" / (Path(listing).stem + ".txt")).write_text(
        (root / "legacy" / "scan" / (Path(listing).stem + ".txt")).read_text())
    text = (root / "legacy" / "printed" / listing).read_text()
    (tmp_path / "legacy" / "printed" / listing).write_text(text.replace("END", "ENDX", 1))
    missing, _ = ocr_audit.unregistered(listing, tmp_path)
    assert any("ENDX" in diff.printed for diff in missing)


@pytest.mark.skipif(not SEEDS.is_dir(), reason="the seeds (../shared/seeds) are not at hand")
@pytest.mark.parametrize("listing", _listings(Path(__file__).resolve().parents[2]))
def test_the_scan_text_is_the_seed_verbatim(root, listing):
    stored = (root / "legacy" / "scan" / (Path(listing).stem + ".txt")).read_text()
    assert stored == ocr_audit.seed_excerpt(listing, SEEDS, root)
