"""harness/blas_threads.py: every linkrepro command runs with one BLAS thread, set before numpy loads."""
import os
import subprocess
import sys

from linkrepro.harness import blas_threads, cli

PROBE = ("import os, sys; from linkrepro.harness import blas_threads; {before}"
         "print(blas_threads.use_one(), os.environ.get('OPENBLAS_NUM_THREADS'))")


def _probe(before: str) -> str:
    env = {k: v for k, v in os.environ.items() if k != blas_threads.VARIABLE}
    return subprocess.run([sys.executable, "-c", PROBE.format(before=before)], env=env, capture_output=True,
                          text=True, check=True).stdout.split()


def test_set_before_numpy_loads_and_not_after():
    assert _probe("") == ["True", "1"]
    assert _probe("import numpy; ") == ["False", "None"]


def test_the_command_sets_it_first(monkeypatch, capsys):
    called = []
    monkeypatch.setattr(blas_threads, "use_one", lambda: called.append(True) or True)
    assert cli.main(["scenes"]) == 0
    assert called == [True]
