"""A thesis's own command of ``linkrepro`` (beside reproduce, scenes, explain, bench).

A thesis lists its commands in ``COMMANDS`` of its ``harness/scenes/<thesis>/commands.py``; the
CLI finds them through the scene registry and gives each a subcommand with ``--out`` (checked
writable before the work, status 2), its own arguments, and the exit statuses of the others: a
failure in ``failures`` or a failed write, status 1; the markdown ``run`` returns printed.
"""
from __future__ import annotations

import argparse
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
    run: Callable[[argparse.Namespace], str]            # the work; returns the markdown to print
    failures: tuple[type[BaseException], ...] = ()      # a failed run (status 1, one line)
    add_arguments: Callable[[argparse.ArgumentParser], None] = lambda parser: None
    #: the report's section on what the command wrote: its title, and the markdown file of its
    #: ``outputs`` the report shows (``harness/report_folder.py``); none: not shown
    report_title: str = ""
    report_markdown: str = ""
