"""reproduce's worker processes (harness/run.py) and its progress line (harness/progress.py)."""
import io
import multiprocessing

import pytest

from linkrepro.harness import progress, run


def _fake_item(name, out_dir, options, partial):
    if name == "boom":
        raise ZeroDivisionError("a failure inside a worker")
    return f"{name} from {out_dir}"


@pytest.fixture
def fake_items(monkeypatch):
    monkeypatch.delenv(run.IN_POOL_ENV, raising=False)
    monkeypatch.setattr(run, "_run_item", _fake_item)        # forked workers inherit it
    monkeypatch.setattr(run.os, "cpu_count", lambda: 2)


@pytest.mark.skipif("fork" not in multiprocessing.get_all_start_methods(), reason="workers inherit the fake by fork")
def test_groups_in_workers_give_what_they_give_in_turn(fake_items, tmp_path):
    groups = [["a", "b"], ["c"], ["d", "e"]]
    in_workers = run._run_groups(groups, tmp_path, False, tmp_path)
    run.os.environ[run.IN_POOL_ENV] = "1"                    # the serial path
    try:
        in_turn = run._run_groups(groups, tmp_path, False, tmp_path)
    finally:
        del run.os.environ[run.IN_POOL_ENV]
    assert in_workers == in_turn == {n: f"{n} from {tmp_path}" for n in "abcde"}
    assert multiprocessing.active_children() == []


@pytest.mark.skipif("fork" not in multiprocessing.get_all_start_methods(), reason="workers inherit the fake by fork")
def test_a_worker_error_is_raised_here_and_no_worker_is_left(fake_items, tmp_path):
    with pytest.raises(ZeroDivisionError, match="inside a worker"):
        run._run_groups([["a", "boom"], ["c"], ["d"]], tmp_path, False, tmp_path)
    assert multiprocessing.active_children() == []


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_line_on_a_terminal_and_nothing_otherwise():
    quiet, terminal = io.StringIO(), _Terminal()
    for stream in (quiet, terminal):
        with progress.Bar(4, stream=stream):
            progress.note("rahman1991-example", "figures")
            progress.done("rahman1991-example")
            progress.handle(("done", "ali1977-table1", ""))
    assert quiet.getvalue() == ""
    last = terminal.getvalue().split("\r\033[K")[-2]
    assert last.startswith("[##########..........] 2/4")
    assert "rahman1991-example: figures" in terminal.getvalue()
    assert terminal.getvalue().endswith("\r\033[K")           # the line is cleared at the end
