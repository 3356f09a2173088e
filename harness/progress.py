"""Progress of a long run: one line on a terminal, rewritten in place; nothing otherwise.

``Bar(total)`` draws ``[#####.....] 7/17 12.3 s  rahman1991-example: figures`` on standard
error when it is a terminal.  Work running in another process reports through ``note`` and
``done`` over a queue that ``attach`` gives that process; in this process they go to the
current bar directly.  Neither ever raises for a closed terminal.
"""
from __future__ import annotations

import sys
import time

_queue = None          # in a worker process: where notes go
_bar = None            # in the main process: the bar drawn now


def attach(queue) -> None:
    """In a worker process: send notes to ``queue`` (a multiprocessing queue)."""
    global _queue
    _queue = queue


def note(job: str, what: str) -> None:
    """``job`` is now doing ``what`` (a few words)."""
    if _queue is not None:
        _queue.put(("note", job, what))
    elif _bar is not None:
        _bar.note(job, what)


def done(job: str) -> None:
    """One of the bar's ``total`` items, ``job``, is finished."""
    if _queue is not None:
        _queue.put(("done", job, ""))
    elif _bar is not None:
        _bar.done(job)


def handle(message: tuple) -> None:
    """In the main process: a message a worker sent (``note`` or ``done``)."""
    if _bar is not None:
        _bar.handle(message)


class Bar:
    """A progress line over ``total`` items (a context manager; the line is cleared at exit)."""

    def __init__(self, total: int, stream=None):
        self.total, self.count, self.start = total, 0, time.perf_counter()
        self.stream = stream or sys.stderr
        self.active = bool(getattr(self.stream, "isatty", lambda: False)())
        self.doing: dict[str, str] = {}

    def __enter__(self) -> Bar:
        global _bar
        _bar = self
        self.draw()
        return self

    def __exit__(self, *exc) -> None:
        global _bar
        _bar = None
        self._write("\r\033[K")

    def note(self, job: str, what: str) -> None:
        self.doing[job] = what
        self.draw()

    def done(self, job: str) -> None:
        self.count += 1
        self.doing.pop(job, None)
        self.draw()

    def handle(self, message: tuple) -> None:
        """A message from a worker's queue."""
        kind, job, what = message
        self.done(job) if kind == "done" else self.note(job, what)

    def draw(self) -> None:
        filled = int(20 * self.count / max(self.total, 1))
        doing = "; ".join(f"{job}: {what}" if what else job for job, what in self.doing.items())
        line = (f"[{'#' * filled}{'.' * (20 - filled)}] {self.count}/{self.total} "
                f"{time.perf_counter() - self.start:5.1f} s  {doing}")
        self._write("\r\033[K" + line[:160])

    def _write(self, text: str) -> None:
        if not self.active:
            return
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):
            self.active = False
