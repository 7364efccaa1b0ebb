"""The results table of a study, a row per sample, as CSV or JSON lines (by the file's
extension): rows are appended as samples finish, so that an interrupted study keeps what it
did, and the file is rewritten in sample order when the study completes. Numbers are written
so that they read back to the same bits (Python's repr); lists and dicts as JSON in a cell."""
from __future__ import annotations

import csv
import io
import json
import math
import os
from typing import Any, Dict, List, Sequence


def table_format(path: str) -> str:
    """"csv" or "jsonl" by the extension; raises ValueError on another."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in (".csv", ".jsonl"):
        raise ValueError(f"{path}: the results are written as .csv or .jsonl, not '{extension or 'no extension'}'")
    return extension[1:]


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else str(value)
    if isinstance(value, (list, dict)):
        return json.dumps(value)
    return str(value)


def _from_cell(text: str) -> Any:
    if text == "":
        return None
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        pass
    if text[:1] in "[{":
        try:
            return json.loads(text)
        except ValueError:
            pass
    return text


class ResultsTable:
    """The results file of one study: `columns` in order (id, parameters, outputs, seconds,
    error, cpacs_path)."""

    def __init__(self, path: str, columns: Sequence[str]) -> None:
        self.path = path
        self.format = table_format(path)
        self.columns = list(columns)

    def read(self) -> List[Dict[str, Any]]:
        """The rows the file holds (none if it does not exist). Raises ValueError when its
        columns are not this study's."""
        if not os.path.exists(self.path):
            return []
        with open(self.path, newline="", encoding="utf-8") as file:
            text = file.read()
        if self.format == "jsonl":
            rows = []
            for number, line in enumerate(text.splitlines(), start=1):
                if not line.strip():
                    continue
                try:
                    rows.append(json.loads(line))
                except ValueError:
                    if number == len(text.splitlines()):
                        break  # the last line cut short by an interruption: that sample runs again
                    raise ValueError(f"{self.path}:{number}: not a JSON line") from None
            if rows and list(rows[0]) != self.columns:
                raise ValueError(f"{self.path}: holds the rows of another study (other columns)")
            return rows
        reader = csv.reader(io.StringIO(text))
        header = next(reader, None)
        if header is None:
            return []
        if header != self.columns:
            raise ValueError(f"{self.path}: holds the rows of another study (other columns)")
        return [dict(zip(header, map(_from_cell, cells))) for cells in reader if len(cells) == len(header)]

    def _line(self, row: Dict[str, Any]) -> str:
        if self.format == "jsonl":
            return json.dumps({column: row.get(column) for column in self.columns}) + "\n"
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerow([_cell(row.get(column)) for column in self.columns])
        return out.getvalue()

    def _header(self) -> str:
        if self.format == "jsonl":
            return ""
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerow(self.columns)
        return out.getvalue()

    def start(self, keep: bool) -> None:
        """Begins the file: kept as it is to resume (`keep`), else written anew with the header."""
        if keep and os.path.exists(self.path):
            with open(self.path, "rb+") as file:  # an interrupted last line is dropped
                content = file.read()
                if content and not content.endswith(b"\n"):
                    file.truncate(content.rfind(b"\n") + 1)
            return
        with open(self.path, "w", encoding="utf-8") as file:
            file.write(self._header())

    def append(self, row: Dict[str, Any]) -> None:
        with open(self.path, "a", encoding="utf-8") as file:
            file.write(self._line(row))
            file.flush()

    def rewrite(self, rows: List[Dict[str, Any]]) -> None:
        """Writes the rows in sample order, through a file beside it renamed over it."""
        temporary = self.path + ".writing"
        with open(temporary, "w", encoding="utf-8") as file:
            file.write(self._header())
            for row in sorted(rows, key=lambda row: row["id"]):
                file.write(self._line(row))
        os.replace(temporary, self.path)
