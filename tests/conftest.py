"""Shared fixtures: the repository root (for legacy/printed, legacy/src) and the register."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def register():
    from linkrepro.harness import register as reg
    return reg.load()
