"""Progress of long jobs on stderr: a bar redrawn in place where a terminal is
attached, one line per finished item otherwise (logs, pipes, CI).

Only stderr is written, so stdout stays clean for the results (``--json``);
``enabled=False`` (the CLI's ``--quiet``) silences it.

>>> import io
>>> out = io.StringIO()
>>> p = Progress(2, "checking", stream=out)
>>> p.start("Eq. (13)"); p.done("Eq. (13)", "holds", 0.25)
>>> p.start("Eq. (14)"); p.done("Eq. (14)", "holds", 1.5)
>>> p.close()
>>> print(out.getvalue(), end="")
[ 1/2] Eq. (13)   holds                      0.2 s
[ 2/2] Eq. (14)   holds                      1.5 s
"""
from __future__ import annotations

import sys
import time


class Progress:
    """Progress of ``total`` items.

    ``start(name)`` before an item (a terminal shows its name while it runs),
    ``done(name, status, seconds)`` after it, ``close()`` at the end.  On a
    terminal (``stream.isatty()``) one line is redrawn:
    ``checking [#####.....] 3/20 Eq. (10) 44 s``; otherwise each finished item
    prints one line ``[ 3/20] Eq. (10)   holds   44.8 s``.  ``min_total``:
    fewer items than this print nothing (a single claim needs no counter)."""

    def __init__(self, total: int, what: str = "", stream=None, enabled: bool = True, width: int = 24,
                 min_total: int = 1):
        self.total = int(total)
        self.what = what
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and self.total >= min_total
        self.width = width
        self.count = 0
        self.t0 = time.perf_counter()
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self._drawn = 0

    def _bar(self, name: str) -> str:
        filled = int(round(self.width * self.count / max(self.total, 1)))
        bar = "#" * filled + "." * (self.width - filled)
        head = f"{self.what} " if self.what else ""
        return f"{head}[{bar}] {self.count}/{self.total} {name} {time.perf_counter() - self.t0:.0f} s"

    def _draw(self, text: str):
        pad = max(0, self._drawn - len(text))
        self.stream.write("\r" + text + " " * pad)
        self.stream.flush()
        self._drawn = len(text)

    def start(self, name: str = ""):
        """An item begins (shown on a terminal only)."""
        if self.enabled and self.tty:
            self._draw(self._bar(name + " ..."))

    def done(self, name: str = "", status: str = "", seconds: float | None = None, detail: str = ""):
        """An item is finished: one line (or the bar advances)."""
        self.count += 1
        if not self.enabled:
            return
        if self.tty:
            self._draw(self._bar(f"{name} {status}".strip()))
            return
        w = len(str(self.total))
        secs = f" {seconds:6.1f} s" if seconds is not None else ""
        line = f"[{self.count:{w + 1}d}/{self.total}] {name:<10} {status:<24}{secs}"
        if detail:
            line += f" {detail}"
        print(line.rstrip(), file=self.stream, flush=True)

    def close(self):
        """End the bar's line (terminal) with the total time."""
        if self.enabled and self.tty and self._drawn:
            self._draw(self._bar("done"))
            self.stream.write("\n")
            self.stream.flush()
            self._drawn = 0


__all__ = ["Progress"]
