"""The fuzz tool (issue 11, item 3): its runner and classification on calls whose outcome is
known, and a fast slice of the full run (`make fuzz` runs 20,000 calls a seed).

Sizes (``tests/sizes.py``): in ``make test`` the known calls run in two workers with the
smallest context (``fuzz_known.py``: a worker starts in a fraction of a second, and three are
replaced), and the slice in one worker with the fuzz's own context; ``make fuzz``
(``LINKREPRO_FULL_TESTS=1``) runs the known calls in workers with the fuzz's own context and
the slice in two workers, as the command does.

No verdict here depends on how busy the machine is: a call counts as a hang only after
PATIENCE seconds (the first call in a worker may compile kernels, slowly on a loaded
2-core machine), except the one call that must hang, which sleeps far longer than its own
short deadline."""
import pytest

from linkrepro.harness import fuzz, fuzz_runner
from linkrepro.harness.fuzz_calls import Job
from linkrepro.harness.fuzz_runner import run as run_calls
from tests.harness import fuzz_known
from tests.patience import CHILD_SECONDS as PATIENCE
from tests.sizes import FULL

#: call texts whose outcome the runner must report, and that outcome
KNOWN = [
    ("1.0 + 1.0", False, "ok"),
    ("float('nan')", False, "nan"),
    ("int('x')", False, "typed"),
    ("1 / 0", False, "untyped"),
    ("np.linalg.inv(np.zeros((2, 2)))", False, "untyped"),          # LinAlgError is a ValueError
    ("(_ for _ in ()).throw(AssemblyError('open', 20.0))", True, "typed"),
    ("(_ for _ in ()).throw(AssemblyError('open'))", True, "angle"),
    ("(_ for _ in ()).throw(SingularPositionError('pivot'))", False, "typed"),
    ("__import__('os')._exit(0)", False, "crash"),                    # what a FORTRAN STOP does
    ("__import__('os').kill(__import__('os').getpid(), 11)", False, "crash"),
    ("__import__('time').sleep(3600)", False, "hang"),
    ("1.0 + 2.0", False, "ok"),                                       # the replaced worker runs on
]


def test_runner_classifies_known_outcomes():
    jobs = [Job(i, "known", text, angles=angles, timeout=1.0 if outcome == "hang" else None)
            for i, (text, angles, outcome) in enumerate(KNOWN)]
    context = fuzz.CONTEXT if FULL else fuzz_known.REFERENCE
    results = run_calls(jobs, context, timeout=PATIENCE, workers=2)
    assert [r["outcome"] for r in results] == [outcome for _, _, outcome in KNOWN]
    assert "SIGSEGV" in results[9]["detail"]


def test_same_seed_same_calls():
    first, again, other = fuzz.generate(120, 7), fuzz.generate(120, 7), fuzz.generate(120, 8)
    assert [j.text for j in first] == [j.text for j in again]
    assert [j.text for j in first] != [j.text for j in other]
    assert {j.entry for j in first} == {e.name for e in fuzz.entries()}


def test_fuzz_slice_has_no_findings():
    report = fuzz.fuzz(calls=200, seed=0, timeout=PATIENCE, workers=2 if FULL else 1)
    assert len(report.results) == 200
    if report.findings:
        pytest.fail(fuzz_runner.format_findings(report), pytrace=False)


def test_checks_flag_results_that_break_their_promise():
    """A returned QP solution outside its constraints and a corrected cognate off the source's
    coupler point are findings ('violated'), not 'ok'."""
    import numpy as np
    from linkrepro.port.ali1977.quirks import CORRECTED, PRINTED
    checks = fuzz.context().checks
    qp = checks["qp"]
    bound = {"diag": 0.0, "active": np.array([0]), "multipliers": np.array([0.5])}    # as QPROG returns it
    missed = {**bound, "sol": np.ones(2)}
    assert "inequality" in qp(([np.eye(2), -np.ones(2)], {"a": [[1.0, 1.0]], "b": [3.0]}), missed)
    assert qp(([np.eye(2), -np.ones(2)], {"a": [[1.0, 1.0]], "b": [3.0]}), {**bound, "sol": np.full(2, 1.5)}) is None
    assert "equality" in qp(([np.eye(2), -np.ones(2), [[1.0, 1.0]], [3.0], 1], {}), missed)
    near = {**bound, "sol": np.array([1.5, 1.5 - 3e-13])}             # within 1e3 eps, not 1e-15 short
    assert qp(([np.eye(2), -np.ones(2)], {"a": [[1.0, 1.0]], "b": [3.0]}), near) is None
    apart = {"xp": np.array([1.0]), "yp": np.array([2.0]), "cxp": np.array([1.5]), "cyp": np.array([2.0])}
    assert "off the source's" in checks["cognate"](([], {"quirks": CORRECTED}), apart)
    assert checks["cognate"](([], {"quirks": PRINTED}), apart) is None     # the listing's D141 may do that
    ns = fuzz.namespace()
    assert fuzz_runner.arguments_of("port.ali1977.case2.case2_cognate(np.array([1.0]), quirks=port.ali1977.case2.LISTING)",
                             ns)[1]["quirks"] is ns["port"].ali1977.case2.LISTING


def test_the_damaged_folder_check_flags_a_pass_a_traceback_and_a_report_that_shows_it():
    """A damaged run folder (harness/fuzz_folders.py) is a finding where verify passes a damage
    it must see, fails an undamaged folder, ends in a traceback, or the report shows the damaged
    scene as run; not where verify fails it and the report says so."""
    check = fuzz.context().checks["run_folder"]
    seen = {"damage": "truncate", "target": "s/legacy.csv", "must_fail": True, "scene": "s", "raised": "",
            "verify": 1, "verify_said": "FAILED", "report_shows": []}
    assert check(None, seen) is None
    assert "verify passed" in check(None, {**seen, "verify": 0})
    assert "undamaged" in check(None, {**seen, "damage": "none", "must_fail": False, "scene": ""})
    assert "IsADirectoryError" in check(None, {**seen, "raised": "verify: IsADirectoryError: x at verify.py:1"})
    assert "report shows s" in check(None, {**seen, "report_shows": ["s"]})
