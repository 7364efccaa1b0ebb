"""What a study is: its parameters (where in the CPACS document each goes, and the values it
takes or the relation it follows), its design of experiments, its outputs (query ops, component
measures, surface points) and the files it exports per sample. Read from TOML
(`Study.from_toml`) or given in Python (`Study(...)`); docs/studies.md."""
from __future__ import annotations

import hashlib
import os
import re
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import design as designs
from .relation import Relation, evaluation_order


class StudyError(ValueError):
    """A study that cannot be run as written: the message names the study and the item."""


@dataclass
class Parameter:
    """One parameter: where its value goes (`xpath`, or `path`: an element path from the
    configuration such as `wings["Wing"].positionings[2].length`; neither for a design variable
    that others relate to) and the values it takes: `values`, a `range` (with `steps` for a
    grid; 5 when not given), or a `relation` to other parameters ("2 * span")."""

    name: str
    xpath: Optional[str] = None
    path: Optional[str] = None
    range: Optional[Tuple[float, float]] = None
    steps: Optional[int] = None
    values: Optional[List[float]] = None
    relation: Optional[str] = None


@dataclass
class Output:
    """One output per sample: a query op with its arguments (`op`, `args`; docs/query.md), a
    component's measure (`measure`: "UID.attribute", e.g. "Wing.mac"), or surface points
    (`points`: {wing, side: upper|lower, segment, eta, xsi}, eta or xsi a number, a list, or
    [start, stop, count] as {"linspace": [...]}). `key` picks one item of an answer that is a
    dict or a list ("mac" of the answer {"mac", "point"} of Wing.mac)."""

    name: str
    op: Optional[str] = None
    args: Dict[str, Any] = field(default_factory=dict)
    measure: Optional[str] = None
    points: Optional[Dict[str, Any]] = None
    key: Optional[Any] = None


@dataclass
class Export:
    """A file written per sample: `path` holds "{id}" (the sample's id); `options` as
    Configuration.export takes them (components, mirror, ...)."""

    path: str
    options: Dict[str, Any] = field(default_factory=dict)


@dataclass
class Sample:
    """One sample: its id (from 0, in design order) and every parameter's value."""

    id: int
    values: Dict[str, float]


# Values of a range in a grid when its steps are not given.
DEFAULT_STEPS = 5
_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_DESIGNS = ("grid", "latin_hypercube", "table")
_RESERVED = {"id", "seconds", "error", "cpacs_path"}


class Study:
    """A parameter study of one CPACS file: `Study(file, parameters, outputs, design="grid")`,
    then `study.run("results.csv")`. `design`: "grid" (every combination), "latin_hypercube"
    (`samples` points, `seed`), or "table" (`table`: a CSV file with a column per parameter)."""

    def __init__(self, file: str, parameters: Sequence[Any], outputs: Sequence[Any], *, design: str = "grid",
                 samples: Optional[int] = None, seed: int = 0, table: Optional[str] = None,
                 exports: Sequence[Any] = (), plot: Optional[Dict[str, Any]] = None, name: str = "study") -> None:
        self.name = name
        self.file = str(file)
        self.parameters = [item if isinstance(item, Parameter) else _parameter(item, name) for item in parameters]
        self.outputs = [item if isinstance(item, Output) else _output(item, name) for item in outputs]
        self.exports = [item if isinstance(item, Export) else _export(item, name) for item in exports]
        self.design = design
        self.sample_count = samples
        self.seed = seed
        self.table = table
        self.plot = plot
        self._check()

    @classmethod
    def from_toml(cls, path: str) -> "Study":
        """The study a TOML file describes (docs/studies.md); relative paths in it are taken
        from the file's folder."""
        import tomllib
        try:
            with open(path, "rb") as file:
                data = tomllib.load(file)
        except OSError as error:
            raise StudyError(f"{path}: cannot be read ({error.strerror})") from None
        except tomllib.TOMLDecodeError as error:
            raise StudyError(f"{path}: not TOML ({error})") from None
        return cls.from_dict(data, os.path.dirname(os.path.abspath(path)), name=path)

    @classmethod
    def from_dict(cls, data: Dict[str, Any], folder: str = ".", name: str = "study") -> "Study":
        """The study a dict in the TOML file's layout describes; relative paths from `folder`."""
        known = {"file", "parameter", "output", "export", "design", "plot"}
        unknown = set(data) - known
        if unknown:
            raise StudyError(f"{name}: unknown key {', '.join(sorted(unknown))} (known: {', '.join(sorted(known))})")
        if "file" not in data:
            raise StudyError(f"{name}: 'file' (the CPACS file) is missing")
        design = dict(data.get("design", {}))
        table = design.get("table")
        exports = [dict(item, path=os.path.join(folder, item["path"])) if "path" in item else item
                   for item in data.get("export", [])]
        return cls(os.path.join(folder, data["file"]), data.get("parameter", []), data.get("output", []),
                   design=design.get("kind", "grid"), samples=design.get("samples"), seed=design.get("seed", 0),
                   table=os.path.join(folder, table) if table else None, exports=exports, plot=data.get("plot"),
                   name=name)

    def _fail(self, message: str) -> StudyError:
        return StudyError(f"{self.name}: {message}")

    def _check(self) -> None:
        if not self.parameters:
            raise self._fail("no [[parameter]]")
        if not self.outputs and not self.exports:
            raise self._fail("no [[output]] nor [[export]]")
        names = [item.name for item in self.parameters] + [item.name for item in self.outputs]
        for item in names:
            if not _NAME.match(item) or item in _RESERVED:
                raise self._fail(f"'{item}' cannot name a parameter or output (letters, digits, _; not "
                                 f"{', '.join(sorted(_RESERVED))})")
        repeated = {item for item in names if names.count(item) > 1}
        if repeated:
            raise self._fail(f"the name {', '.join(sorted(repeated))} is used twice")
        if self.design not in _DESIGNS:
            raise self._fail(f"design kind '{self.design}' is none of {', '.join(_DESIGNS)}")
        for parameter in self.parameters:
            given = [parameter.values is not None, parameter.range is not None, parameter.relation is not None]
            if sum(given) != 1 and not (self.design == "table" and sum(given) == 0):
                raise self._fail(f"parameter {parameter.name}: give one of values, range, relation")
            if parameter.xpath and parameter.path:
                raise self._fail(f"parameter {parameter.name}: give xpath or path, not both")
        self._evaluation_order()
        for export in self.exports:
            if "{id}" not in export.path:
                raise self._fail(f"export {export.path}: the path must hold {{id}}, or every sample overwrites it")
        if self.plot is not None:
            wanted = [self.plot.get("x")] + list(self.plot.get("y", []))
            if None in wanted or not set(wanted) <= set(names):
                raise self._fail("plot: x and y must name parameters and outputs")
        self.samples()  # the design itself can fail (a missing range, a bad table)

    def _evaluation_order(self) -> List[str]:
        try:
            return evaluation_order(self._relations(), {p.name for p in self.free_parameters})
        except ValueError as error:
            raise self._fail(str(error)) from None

    def _relations(self) -> Dict[str, Relation]:
        try:
            return {p.name: Relation(p.relation, p.name) for p in self.parameters if p.relation is not None}
        except ValueError as error:
            raise self._fail(str(error)) from None

    @property
    def free_parameters(self) -> List[Parameter]:
        """The parameters the design gives values to (those without a relation)."""
        return [parameter for parameter in self.parameters if parameter.relation is None]

    def samples(self) -> List[Sample]:
        """Every sample of the design, in order, with the related parameters' values."""
        free = self.free_parameters
        try:
            if self.design == "grid":
                points = designs.full_grid({p.name: self._grid_values(p) for p in free})
            elif self.design == "latin_hypercube":
                if not self.sample_count or self.sample_count < 1:
                    raise ValueError("a latin_hypercube needs design.samples, a positive number")
                missing = [p.name for p in free if p.range is None]
                if missing:
                    raise ValueError(f"a latin_hypercube needs a range for {', '.join(missing)}")
                points = designs.latin_hypercube({p.name: p.range for p in free}, int(self.sample_count),
                                                 int(self.seed))
            else:
                if not self.table:
                    raise ValueError("a table design needs design.table, a CSV file")
                points = designs.table_of_samples(self.table, [p.name for p in free])
        except (ValueError, OSError) as error:
            raise self._fail(str(error)) from None
        return [Sample(index, self.values_of(point)) for index, point in enumerate(points)]

    def values_of(self, free: Dict[str, float]) -> Dict[str, float]:
        """Every parameter's value, given the free parameters' (the related ones follow)."""
        relations = self._relations()
        values = dict(free)
        for name in self._evaluation_order():
            values[name] = relations[name](values)
        return {p.name: values[p.name] for p in self.parameters}

    def _grid_values(self, parameter: Parameter) -> List[float]:
        if parameter.values is not None:
            return [float(value) for value in parameter.values]
        if parameter.range is None or (parameter.steps is not None and parameter.steps < 1):
            raise ValueError(f"parameter {parameter.name}: a grid needs values, or a range (with steps, "
                             "a positive number)")
        low, high = parameter.range
        return [float(value) for value in np.linspace(low, high, int(parameter.steps or DEFAULT_STEPS))]

    def key(self) -> str:
        """What makes the study's samples what they are: the file's bytes, the parameters, the
        outputs and exports (a results file of another study is not resumed)."""
        with open(self.file, "rb") as file:
            digest = hashlib.sha256(file.read())
        digest.update(repr((self.parameters, self.outputs, self.exports)).encode())
        return digest.hexdigest()[:16]

    def run(self, results: str, **options: Any) -> "Any":
        """Runs every sample not yet in `results` (.csv or .jsonl) and returns the outcome (its
        rows by id, how many failed, whether it was interrupted); docs/studies.md. Options:
        `workers` (local processes, default one per core), `client` (a dask.distributed Client)
        or `scheduler` ("tcp://host:port"), `progress` (a bar on stderr, default on),
        `restart` (discard what `results` holds), `on_row` (called with each row as it comes)."""
        from .runner import run_study
        return run_study(self, results, **options)


def _fields(item: Dict[str, Any], kind: str, allowed: Sequence[str], study: str) -> Dict[str, Any]:
    if not isinstance(item, dict) or "name" not in item and kind != "export":
        raise StudyError(f"{study}: each [[{kind}]] needs a name")
    unknown = set(item) - set(allowed)
    if unknown:
        raise StudyError(f"{study}: {kind} {item.get('name', item.get('path'))}: unknown key "
                         f"{', '.join(sorted(unknown))} (known: {', '.join(allowed)})")
    return item


def _parameter(item: Dict[str, Any], study: str) -> Parameter:
    item = _fields(item, "parameter", ("name", "xpath", "path", "range", "steps", "values", "relation"), study)
    return Parameter(**{**item, "range": tuple(map(float, item["range"])) if "range" in item else None})


def _output(item: Dict[str, Any], study: str) -> Output:
    item = _fields(item, "output", ("name", "op", "args", "measure", "points", "key"), study)
    output = Output(**item)
    if sum(x is not None for x in (output.op, output.measure, output.points)) != 1:
        raise StudyError(f"{study}: output {output.name}: give one of op, measure, points")
    return output


def _export(item: Dict[str, Any], study: str) -> Export:
    if isinstance(item, dict) and "path" in item:
        return Export(item["path"], {key: value for key, value in item.items() if key != "path"})
    raise StudyError(f"{study}: each [[export]] needs a path")
