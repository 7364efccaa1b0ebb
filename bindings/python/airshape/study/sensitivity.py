"""Sensitivities of a study's outputs to its free parameters: central differences on
incremental rebuilds of one configuration, each checked by a second step half as long, and
exact derivatives where an output depends linearly on a parameter (linear_maps)."""
from __future__ import annotations

from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from .. import Configuration
from .definition import Study, StudyError
from .evaluation import apply, open_document, output_value, plan_of
from .linear_maps import exact_derivative
from .relation import Relation


def _base_values(study: Study, config: Configuration, setters: Dict[str, str],
                 at: Optional[Dict[str, float]]) -> Dict[str, float]:
    """Where the derivatives are taken: `at`, else each free parameter's value in the document,
    else the middle of its range or its first value."""
    values: Dict[str, float] = {}
    for parameter in study.free_parameters:
        if at and parameter.name in at:
            values[parameter.name] = float(at[parameter.name])
        elif parameter.name in setters:
            values[parameter.name] = float(config.value(setters[parameter.name]))
        elif parameter.range is not None:
            values[parameter.name] = (parameter.range[0] + parameter.range[1]) / 2
        elif parameter.values:
            values[parameter.name] = float(parameter.values[0])
        else:
            raise StudyError(f"{study.name}: parameter {parameter.name}: give its value in `at`")
    return values


def _step(study: Study, name: str, value: float, step: Optional[float]) -> float:
    """1e-4 of the parameter's scale: its range's width, else its size (at least 1)."""
    if step is not None:
        return step
    parameter = next(p for p in study.parameters if p.name == name)
    scale = abs(parameter.range[1] - parameter.range[0]) if parameter.range else max(abs(value), 1.0)
    return 1e-4 * scale


def sensitivities(study: Study, *, at: Optional[Dict[str, float]] = None,
                  parameters: Optional[Sequence[str]] = None, outputs: Optional[Sequence[str]] = None,
                  step: Optional[float] = None, tolerance: float = 1e-3) -> List[Dict[str, Any]]:
    """The derivative of each numeric output with respect to each free parameter at `at` (by
    default the document's values): one entry per pair, {"output", "parameter", "derivative"
    (a number, or a list shaped as the output), "method" ("central difference" or "exact"),
    "step", "check" (the central difference with half the step), "agrees" (whether the two
    differences agree within `tolerance`, relatively; false at a kink or a jump), and with
    "exact" the central difference as "finite_difference"}. The document is left as it was."""
    plan = plan_of(study)
    setters = dict(plan.setters)
    config = open_document(plan)
    base = _base_values(study, config, setters, at)
    chosen_outputs = [o for o in plan.outputs if outputs is None or o["name"] in outputs]
    chosen = [p.name for p in study.free_parameters if parameters is None or p.name in parameters]

    def measure(free: Dict[str, float]) -> Dict[str, np.ndarray]:
        apply(config, plan, study.values_of(free))
        return {o["name"]: np.asarray(output_value(config, o), dtype=float) for o in chosen_outputs}

    at_base = measure(base)
    answers = []
    for name in chosen:
        # Exact maps hold for a parameter set directly, not through a relation of others.
        xpath = setters.get(name)
        related = any(p.relation and name in Relation(p.relation, p.name).names for p in study.parameters)
        h = _step(study, name, base[name], step)
        values = {}
        for factor in (1.0, -1.0, 0.5, -0.5):
            values[factor] = measure({**base, name: base[name] + factor * h})
        for output in chosen_outputs:
            key = output["name"]
            long = (values[1.0][key] - values[-1.0][key]) / (2 * h)
            short = (values[0.5][key] - values[-0.5][key]) / h
            # Rebuilds agree to about 1e-9 of a value: differences below that noise, over the
            # step, are not told apart.
            noise = 1e-9 * (np.abs(at_base[key]) + 1) / h
            agrees = bool(np.all(np.abs(long - short) <= tolerance * np.maximum(np.abs(long), np.abs(short)) + noise))
            answer = {"output": key, "parameter": name, "derivative": long.tolist(), "method": "central difference",
                      "step": h, "check": short.tolist(), "agrees": agrees}
            exact = None if related or xpath is None else exact_derivative(config, output, xpath)
            if exact is not None:
                answer.update(derivative=exact.tolist(), method="exact", finite_difference=long.tolist())
            answers.append(answer)
    apply(config, plan, study.values_of(base))
    return answers
