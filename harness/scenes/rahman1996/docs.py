"""Rahman (1996)'s generated blocks of the docs (``harness/docs.py``)."""
from __future__ import annotations

import contextlib
import io

from . import differential as cssp


def differential() -> str:
    """The CSSP's fixed sample of the port against legacy, as
    ``python -m linkrepro.harness.scenes.rahman1996.differential`` prints it."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        cssp.main([])
    return f"```text\n{out.getvalue().rstrip()}\n```\n"


BLOCKS = {"differential": differential}
