"""For the tests that need Exudyn: ``exudyn = needs_exudyn()`` at a test module's top skips
the module, saying how to install it, where Exudyn is missing (``harness/multibody.py``)."""
import pytest

from linkrepro.harness import multibody


def needs_exudyn():
    """The ``exudyn`` module, or the calling test module skipped with the install command."""
    try:
        return multibody.require()
    except multibody.ExudynMissing as exc:
        pytest.skip(str(exc), allow_module_level=True)
