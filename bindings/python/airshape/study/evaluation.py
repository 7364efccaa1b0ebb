"""One sample evaluated where it runs (a local worker process or a Dask worker): the CPACS
document is opened once per process and kept; each sample sets every parameter's value in it
(only what depends on the edits is rebuilt) and measures the outputs."""
from __future__ import annotations

import dataclasses
import re
import time
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from .. import Configuration
from ..errors import ArgumentError, Error
from .definition import StudyError

# The documents this process has opened, by study key (a worker keeps its configuration).
_OPEN: Dict[str, Configuration] = {}
_TOKEN = re.compile(r"""\s*(?:(?P<name>[A-Za-z_][A-Za-z0-9_]*)|\[\s*(?P<index>-?\d+)\s*\]|"""
                    r"""\[\s*(?P<quote>["'])(?P<key>[^"']*)(?P=quote)\s*\]|(?P<dot>\.))""")


def xpath_of_path(config: Configuration, path: str) -> str:
    """The XPath of an element path from the configuration: `wings["Wing"].positionings[2].length`
    (attribute names and indices as Python reaches elements, docs/python.md)."""
    target: Any = config
    position = 0
    while position < len(path):
        match = _TOKEN.match(path, position)
        if not match:
            raise ValueError(f"path '{path}': cannot read it at '{path[position:]}'")
        position = match.end()
        if match.group("name"):
            target = getattr(target, match.group("name"))
        elif match.group("index") is not None:
            target = target[int(match.group("index"))]
        elif match.group("quote"):
            target = target[match.group("key")]
    xpath = getattr(target, "xpath", None)
    if not isinstance(xpath, str):
        raise ValueError(f"path '{path}' leads to no element of the document")
    return xpath


@dataclasses.dataclass
class Plan:
    """What a worker needs for any sample of a study, small enough to send: the document's
    text, where each parameter goes, the outputs and exports."""

    key: str
    file: str
    document: str
    setters: List[Tuple[str, str]]  # (parameter name, XPath)
    outputs: List[Dict[str, Any]]
    exports: List[Dict[str, Any]]


def plan_of(study: Any) -> Plan:
    """The plan of a study, its element paths turned into XPaths on the document (which is
    opened here once, so that a file that cannot be read fails before any worker starts)."""
    config = Configuration.open(study.file)
    setters = []
    for parameter in study.parameters:
        if parameter.path:
            try:
                setters.append((parameter.name, xpath_of_path(config, parameter.path)))
            except (ValueError, AttributeError, IndexError, KeyError, Error) as error:
                raise StudyError(f"{study.name}: parameter {parameter.name}: {error}") from None
        elif parameter.xpath:
            setters.append((parameter.name, parameter.xpath))
    for name, xpath in setters:  # a place no sample could set fails the study, not every sample
        try:
            _missing_steps(config, xpath)
        except Error as error:
            raise StudyError(f"{study.name}: parameter {name}: {error}") from None
    with open(study.file, encoding="utf-8") as file:
        document = file.read()
    return Plan(study.key(), study.file, document, setters, [dataclasses.asdict(o) for o in study.outputs],
                [dataclasses.asdict(e) for e in study.exports])


def open_document(plan: Plan) -> Configuration:
    """The plan's document opened, with the places of its parameters that it lacks made."""
    config = Configuration.from_string(plan.document, plan.file)
    for _, xpath in plan.setters:
        if config._core.count(xpath) == 0:
            make_place(config, xpath)
    return config


def configuration_of(plan: Plan) -> Configuration:
    """The process's configuration of the plan's document, opened on first use."""
    if plan.key not in _OPEN:
        _OPEN.clear()  # one study at a time per process
        _OPEN[plan.key] = open_document(plan)
    return _OPEN[plan.key]


def sequence_of(value: Any) -> Any:
    """An eta or xsi of a points output: a number, a list, or {"linspace": [start, stop, count]}."""
    if isinstance(value, dict) and "linspace" in value:
        start, stop, count = value["linspace"]
        return np.linspace(float(start), float(stop), int(count))
    return value


def _component(config: Configuration, uid: str) -> Any:
    for collection in (config.wings, config.fuselages, config.rotors):
        try:
            return collection[uid]
        except (KeyError, IndexError, Error):
            continue
    return config.component(uid)


def _plain(value: Any) -> Any:
    """A value as JSON holds it: arrays as lists, NumPy numbers as Python's."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return [_plain(item) for item in value]
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    return value


def output_value(config: Configuration, output: Dict[str, Any]) -> Any:
    """One output's value on the configuration as it is (its `key`'s item, when it has one)."""
    value = _whole_output(config, output)
    return value if output.get("key") is None else value[output["key"]]


def _whole_output(config: Configuration, output: Dict[str, Any]) -> Any:
    if output["op"] is not None:
        return _plain(config.query(output["op"], **output["args"]))
    if output["measure"] is not None:
        uid, _, attribute = output["measure"].rpartition(".")
        value = getattr(_component(config, uid), attribute)
        return _plain(value() if callable(value) else value)
    points = output["points"]
    wing = config.wings[points["wing"]]
    return _plain(wing.points(points.get("side", "upper"), points.get("segment", 1),
                              eta=sequence_of(points["eta"]), xsi=sequence_of(points["xsi"])))


def _missing_steps(config: Configuration, xpath: str) -> Tuple[str, List[str]]:
    """The deepest element of an XPath the document has, and the steps below it that it lacks.
    Raises ArgumentError when those steps are not plain element names (nothing to make)."""
    steps = xpath.split("/")
    cut = len(steps) if config._core.count(xpath) > 0 else len(steps) - 1
    while cut > 1 and config._core.count("/".join(steps[:cut])) == 0:
        cut -= 1
    missing = steps[cut:]
    if any(not re.fullmatch(r"[A-Za-z_][\w.-]*", step) for step in missing):
        raise ArgumentError(f"XPath {xpath}: no element there, and '{'/'.join(missing)}' names no element to make")
    return "/".join(steps[:cut]), missing


def make_place(config: Configuration, xpath: str) -> None:
    """Makes the elements an XPath names but the document lacks (a section's translation where
    it has none: its other coordinates are then 0, as CPACS reads a missing one). Only plain
    element names can be made; raises ArgumentError otherwise."""
    parent, missing = _missing_steps(config, xpath)
    config.insert(parent, "".join(f"<{step}>" for step in missing) + "0" +
                  "".join(f"</{step}>" for step in reversed(missing)))


def apply(config: Configuration, plan: Plan, values: Dict[str, float]) -> None:
    """Sets every parameter that has a place in the document to its value (the document opened
    by open_document, which makes the places it lacks)."""
    for name, xpath in plan.setters:
        config.set(xpath, values[name])


def evaluate(plan: Plan, sample_id: int, values: Dict[str, float]) -> Dict[str, Any]:
    """The sample's row: its id, the parameters' values, every output, the exports written,
    the time it took; on failure the error's line and CPACS path, outputs left empty."""
    start = time.perf_counter()
    row: Dict[str, Any] = {"id": sample_id, **values}
    outputs: Dict[str, Any] = {output["name"]: None for output in plan.outputs}
    error: Optional[str] = None
    cpacs_path: Optional[str] = None
    try:
        config = configuration_of(plan)
        apply(config, plan, values)
        for output in plan.outputs:
            outputs[output["name"]] = output_value(config, output)
        for export in plan.exports:
            config.export(export["path"].format(id=sample_id), **export["options"])
    except Error as failure:
        outputs = dict.fromkeys(outputs)
        error, cpacs_path = str(failure).splitlines()[0] if str(failure) else type(failure).__name__, \
            failure.cpacs_path or None
    except Exception as failure:  # noqa: BLE001 - a sample's failure is its row's, never the study's
        outputs = dict.fromkeys(outputs)
        error = f"{type(failure).__name__}: {failure}".splitlines()[0]
    row.update(outputs)
    row.update(seconds=time.perf_counter() - start, error=error, cpacs_path=cpacs_path)
    return row
