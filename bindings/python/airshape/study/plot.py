"""A picture of a sweep beside its results: each output named in the study's [plot] against
one parameter, a line for each combination of the other free parameters (matplotlib, Agg)."""
from __future__ import annotations

import os
from collections import defaultdict
from typing import Any, Dict, List


def plot_sweep(study: Any, rows: List[Dict[str, Any]], path: str) -> str:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = study.plot["x"]
    outputs = list(study.plot.get("y", []))
    others = [p.name for p in study.free_parameters if p.name != x]
    figure, axes = plt.subplots(len(outputs), 1, figsize=(7, 2.8 * len(outputs)), squeeze=False)
    for axis, output in zip(axes[:, 0], outputs):
        lines: Dict[tuple, List[tuple]] = defaultdict(list)
        for row in rows:
            if not row.get("error") and isinstance(row.get(output), (int, float)):
                lines[tuple(row[name] for name in others)].append((row[x], row[output]))
        for key, points in sorted(lines.items()):
            points.sort()
            label = ", ".join(f"{name} = {value:g}" for name, value in zip(others, key)) or None
            axis.plot([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3, label=label)
        axis.set_xlabel(x)
        axis.set_ylabel(output)
        axis.grid(True, alpha=0.3)
        if others and 0 < len(lines) <= 12:
            axis.legend(fontsize=7)
    figure.suptitle(f"{os.path.basename(study.name)}: {len(rows)} samples", fontsize=9)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path
