"""``tests/python_c.py`` runs code as ``python -c`` does: the same exit status and output as a
fresh interpreter (run here beside it) for code that prints, fails, exits and looks at where it
runs."""
import subprocess
import sys

import pytest

from tests import python_c

CODES = [
    "print('out'); import sys; print('err', file=sys.stderr)",
    "import sys, os; print(__name__, sys.argv, sys.path[0], os.path.basename(os.getcwd()))",
    "raise ValueError('a failure')",
    "raise SystemExit(3)",
    "raise SystemExit('a message')",
    "import sys; sys.exit()",
    "x = undefined_name",
    "import dataclasses\n@dataclasses.dataclass\nclass A:\n    x: int\nprint(A(1))",
]


@pytest.mark.parametrize("code", CODES)
def test_as_python_c(code, tmp_path):
    fresh = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    ours = python_c.run(code, tmp_path, frozenset({"numpy"}))
    assert (ours.returncode, ours.stdout) == (fresh.returncode, fresh.stdout)
    assert ours.stderr.strip().splitlines()[-1:] == fresh.stderr.strip().splitlines()[-1:]


def test_imports():
    assert python_c.imports("import a.b, c\nfrom d.e import f\nfrom . import g\ndef h():\n    import i") == {
        "a.b", "c", "d.e", "i"}
