"""Designs of experiments: which values a study's free parameters take in each sample. A full
grid of every parameter's values, a Latin hypercube of a given size drawn with a seed, or a
table of samples the user wrote (CSV, a column per parameter)."""
from __future__ import annotations

import csv
import itertools
from typing import Dict, List, Sequence

import numpy as np


def full_grid(values: Dict[str, Sequence[float]]) -> List[Dict[str, float]]:
    """Every combination of the parameters' values, the last parameter varying fastest."""
    names = list(values)
    return [dict(zip(names, map(float, combination))) for combination in itertools.product(*values.values())]


def latin_hypercube(ranges: Dict[str, Sequence[float]], samples: int, seed: int) -> List[Dict[str, float]]:
    """`samples` points of the parameters' ranges, each range cut into `samples` equal strata
    and each stratum used once per parameter, at a random place within it. The same seed gives
    the same points on any machine (NumPy's PCG64)."""
    generator = np.random.Generator(np.random.PCG64(seed))
    columns = {}
    for name, (low, high) in ranges.items():
        strata = (generator.permutation(samples) + generator.random(samples)) / samples
        columns[name] = low + strata * (high - low)
    return [{name: float(column[i]) for name, column in columns.items()} for i in range(samples)]


def table_of_samples(path: str, names: Sequence[str]) -> List[Dict[str, float]]:
    """The samples of a CSV file with a header naming the parameters (other columns ignored)."""
    with open(path, newline="") as file:
        reader = csv.DictReader(file)
        missing = [name for name in names if name not in (reader.fieldnames or [])]
        if missing:
            raise ValueError(f"{path}: no column for parameter {', '.join(missing)}")
        samples = []
        for line, row in enumerate(reader, start=2):
            try:
                samples.append({name: float(row[name]) for name in names})
            except (TypeError, ValueError):
                raise ValueError(f"{path}:{line}: a parameter's value is not a number") from None
    return samples
