"""How large a test runs: ``make test`` runs each property at the size that shows it; ``make fuzz``
sets ``LINKREPRO_FULL_TESTS=1`` and runs the whole version (docs/reliability.md, "The tests: two
sizes").  A test that has two sizes says in its docstring what each runs.
"""
import os

FULL_ENV = "LINKREPRO_FULL_TESTS"
FULL = os.environ.get(FULL_ENV) == "1"
