"""Runs of ``linkrepro reproduce`` stopped by a signal at chosen points (tests/harness/test_run_folder.py).

Run as a script, in a fresh process (``python kill_trials.py PLAN.json``): it imports linkrepro,
runs the plan's scenes once into ``base`` (its folder before the trials; the engines' results
are then cached in this process), then runs each trial in a forked child, which counts the
run's changes to its folder (a file opened for writing, a rename, a folder made, a file or
folder removed, two folders swapped) and sends itself the trial's signal just before the ``at``-th
(0-based; a fraction in [0, 1) of the events the first trial counted, or from the end where
negative).  The first trial has no signal: it counts them.  ``from_worker``: the
signal is sent to the run's main process by the worker that has just put its first scene in
place (the workers' pids are written into ``pids``).  ``again``: the run goes into the folder an
earlier trial left (not a copy of ``base``).  Prints one JSON object per trial: its
folder, exit status or signal, the events counted and the one it stopped before.
"""
from __future__ import annotations

import builtins
import io
import json
import os
import shutil
import signal
import sys


def _hooks(trial: dict) -> list:
    """Wrap the file system's changing calls to count them, and stop the run at ``at``."""
    from linkrepro.harness import run, run_folder
    seen = []
    at, signum = trial.get("at"), getattr(signal, trial["signal"]) if trial.get("signal") else None

    inside = os.path.abspath(trial["folder"])

    def counted(name, real, writes=lambda *a, **k: True):
        def call(*args, **kwargs):
            if writes(*args, **kwargs) and isinstance(args[0], (str, os.PathLike)) \
                    and os.path.abspath(args[0]).startswith(inside):
                if at is not None and len(seen) == at and not trial.get("from_worker"):
                    seen.append(f"{name} {args[0]} (stopped before)")
                    _report(trial, seen)
                    os.kill(os.getpid(), signum)
                seen.append(f"{name} {args[0]}")
            return real(*args, **kwargs)
        return call

    def writing(file, mode="r", *args, **kwargs):
        return any(c in mode for c in "wax+")
    for module, name in ((os, "replace"), (os, "rename"), (os, "mkdir"), (os, "unlink"), (os, "rmdir"),
                         (run_folder, "_exchange")):
        setattr(module, name, counted(name, getattr(module, name)))
    opened = counted("open", builtins.open, writing)
    builtins.open = io.open = opened

    if trial.get("from_worker"):
        real_place, real_die = run_folder.place, run._die_with

        def place(new, target):
            real_place(new, target)
            os.kill(os.getppid(), signum)          # the run's main process, from its worker

        def die_with(parent):
            real_die(parent)
            with open(os.path.join(trial["pids"], str(os.getpid())), "w"):
                pass
        run_folder.place, run._die_with = place, die_with
    return seen


def _report(trial: dict, seen: list) -> None:
    with open(trial["events"], "w") as handle:
        json.dump(seen, handle)


def _trial(trial: dict, base: str) -> dict:
    """Copy ``base`` into the trial's folder, run the trial in a forked child, wait for it."""
    from linkrepro.harness import cli
    if not trial.get("again"):                      # else: a run into what an earlier trial left
        shutil.copytree(base, trial["folder"])
    if trial.get("pids"):
        os.makedirs(trial["pids"])
    pid = os.fork()
    if pid == 0:                                   # the child: the run
        status = 3
        try:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 1)
            os.dup2(null, 2)
            if trial.get("pool"):
                os.environ.pop("LINKREPRO_IN_POOL", None)
            seen = _hooks(trial)
            status = cli.main(["reproduce", *trial["scenes"], "--skip-readings", "--out", trial["folder"]])
            if not trial.get("from_worker"):
                _report(trial, seen)
        finally:
            os._exit(status)
    _, code = os.waitpid(pid, 0)
    done = {"folder": trial["folder"], "signal": trial.get("signal"), "at": trial.get("at")}
    if os.WIFSIGNALED(code):
        done["killed_by"] = signal.Signals(os.WTERMSIG(code)).name
    else:
        done["exit"] = os.WEXITSTATUS(code)
    if os.path.exists(trial["events"]):
        with open(trial["events"]) as handle:
            done["events"] = json.load(handle)
    return done


def main(plan_path: str) -> int:
    with open(plan_path) as handle:
        plan = json.load(handle)
    # Ctrl-C as at a terminal, even where this process was started with SIGINT ignored (by a
    # shell's background job: the trials' SIGINT then did nothing and the run exited 0)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    os.environ["LINKREPRO_IN_POOL"] = "1"          # in this process, in turn: the events in one order
    from linkrepro.harness import cli
    null = os.open(os.devnull, os.O_WRONLY)
    saved = os.dup(1)
    os.dup2(null, 1)
    try:
        status = cli.main(["reproduce", *plan["base_scenes"], "--skip-readings", "--out", plan["base"]])
    finally:
        os.dup2(saved, 1)
    if status != 0:
        return status
    events = None
    for trial in plan["trials"]:
        at = trial.get("at")
        if events is not None and at is not None:
            trial["at"] = int(at * events) if isinstance(at, float) else at % events
        done = _trial(trial, plan["base"])
        events = len(done["events"]) if events is None else events
        print(json.dumps(done), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
