"""The progress of a study on stderr: one line, redrawn at most five times a second, with the
samples done and failed, the rate and the time left; a line of its own for each failure."""
from __future__ import annotations

import sys
import time
from typing import Any, Dict, Optional, TextIO


class Progress:
    def __init__(self, total: int, done_before: int, enabled: bool, stream: Optional[TextIO] = None) -> None:
        self.total = total
        self.done = done_before
        self.done_before = done_before
        self.failed = 0
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.start = time.monotonic()
        self.drawn = 0.0
        self.width = 0

    def _line(self) -> str:
        elapsed = time.monotonic() - self.start
        new = self.done - self.done_before
        rate = new / elapsed if elapsed > 0 else 0.0
        left = (self.total - self.done) / rate if rate > 0 else float("nan")
        filled = int(20 * self.done / self.total) if self.total else 20
        bar = "#" * filled + "." * (20 - filled)
        time_left = f", {left:.0f} s left" if left == left and self.done < self.total else ""
        return (f"study: [{bar}] {self.done}/{self.total} done, {self.failed} failed, {rate:.1f}/s"
                f"{time_left}")

    def _draw(self, line: str, end: str = "") -> None:
        self.stream.write("\r" + line.ljust(self.width) + end)
        self.width = 0 if end else len(line)
        self.stream.flush()

    def row(self, row: Dict[str, Any]) -> None:
        """Counts a finished sample; a failure is said on a line of its own."""
        self.done += 1
        if row.get("error"):
            self.failed += 1
            if self.enabled:
                where = f" ({row['cpacs_path']})" if row.get("cpacs_path") else ""
                self._draw(f"study: sample {row['id']} failed: {row['error']}{where}", "\n")
        if self.enabled and (time.monotonic() - self.drawn > 0.2 or self.done == self.total):
            self.drawn = time.monotonic()
            self._draw(self._line())

    def finish(self, interrupted: bool) -> None:
        if not self.enabled:
            return
        elapsed = time.monotonic() - self.start
        how = "interrupted: " if interrupted else ""
        self._draw(f"study: {how}{self.done}/{self.total} samples done, {self.failed} failed, {elapsed:.1f} s", "\n")
