"""A thesis's own command of ``linkrepro`` (beside reproduce, scenes, explain, bench).

A thesis lists its commands in ``COMMANDS`` of its ``harness/scenes/<thesis>/commands.py``; the
CLI finds them through the scene registry and gives each a subcommand with ``--out`` (checked
writable before the work, status 2), its own arguments, and the exit statuses of the others: a
failure in ``failures`` or a failed write, status 1; the markdown ``run`` returns printed.

A command is declared apart from its work: the parser reads every thesis's commands for
``linkrepro --help``, and the work imports the engines (a second or more), so the module that
does it is named (``work``) and imported only when the command runs.
"""
from __future__ import annotations

import argparse
import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Callable


@dataclass(frozen=True)
class Command:
    name: str
    help: str
    default_out: Path                                   # --out's default
    out_help: str                                       # --out's help
    outputs: tuple[str, ...]                            # the files ``run`` writes into --out
    #: the module that does the work, by its full name: its ``run(args)`` returns the markdown to
    #: print; its ``FAILURES``, where it has them, are the errors of a failed run (status 1, one line)
    work: str
    add_arguments: Callable[[argparse.ArgumentParser], None] = lambda parser: None
    #: the report's section on what the command wrote: its title, and the markdown file of its
    #: ``outputs`` the report shows (``harness/report_folder.py``); none: not shown
    report_title: str = ""
    report_markdown: str = ""

    @property
    def run(self) -> Callable[[argparse.Namespace], str]:
        """The work (its module imported now)."""
        return importlib.import_module(self.work).run

    @property
    def failures(self) -> tuple[type[BaseException], ...]:
        """The errors of a failed run (its module imported now)."""
        return getattr(importlib.import_module(self.work), "FAILURES", ())
