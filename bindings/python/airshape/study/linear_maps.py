"""Exact derivatives where an output depends linearly on a parameter: a wing's surface or chord
point (at fixed segment, eta, xsi) against a translation of the wing, of one of its sections or
of a section's element. CONVENTIONS §1.2: a profile point goes to P = C·Pos·Sec·Elem·p, and a
point at eta is the straight blend of the inner and outer profile points at xsi (§5.1), so a
translation t of the outer section moves it by eta·L_C·t (L_C the wing's rotation and
scaling), of the outer element by eta·L_C·L_Sec·t, of the wing by t. The matrices are read
from the document here, apart from the geometry code."""
from __future__ import annotations

import math
import re
from typing import Any, Dict, Optional

import numpy as np

from ..errors import Error
from .evaluation import sequence_of

_TRANSLATION = re.compile(r"^(?P<owner>.+)/transformation/translation/(?P<axis>[xyz])$")
_POINT_OPS = {"wing_upper_point", "wing_lower_point", "wing_chord_point"}


def _exists(config: Any, xpath: str) -> bool:
    return config._core.count(xpath) > 0


def _number(config: Any, xpath: str) -> float:
    """A child of a point: 0 when missing (CONVENTIONS §1.1.3)."""
    return float(config.value(xpath)) if _exists(config, xpath) else 0.0


def linear_part(config: Any, owner: str) -> np.ndarray:
    """Rx(a)·Ry(b)·Rz(c)·S of the transformation of the element at `owner` (CONVENTIONS §1.1)."""
    transformation = owner + "/transformation"
    scaling = np.eye(3)
    if _exists(config, transformation + "/scaling"):
        scaling = np.diag([_number(config, f"{transformation}/scaling/{axis}") for axis in "xyz"])
    a, b, c = (math.radians(_number(config, f"{transformation}/rotation/{axis}")) for axis in "xyz")
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    return rx @ ry @ rz @ scaling


def _point_query(output: Dict[str, Any]) -> Optional[Dict[str, Any]]:
    """The wing, segment and etas of an output of wing points, or None for other outputs."""
    if output.get("op") in _POINT_OPS:
        args = output["args"]
        return {"wing": args["wing"], "segment": args["segment"], "eta": np.atleast_1d(float(args["eta"]))}
    points = output.get("points")
    if points:
        etas = np.atleast_1d(np.asarray(sequence_of(points["eta"]), dtype=float))
        count = np.atleast_1d(sequence_of(points["xsi"])).size
        if etas.size != count and etas.size != 1 and count != 1:
            return None
        return {"wing": points["wing"], "segment": points.get("segment", 1), "eta": np.broadcast_to(etas, (max(
            etas.size, count),)).copy()}
    return None


def exact_derivative(config: Any, output: Dict[str, Any], xpath: str) -> Optional[np.ndarray]:
    """The exact derivative of a wing-point output with respect to the translation at `xpath`,
    shaped as the output's value; None where the output or the parameter is of another kind."""
    query = None if output.get("key") is not None else _point_query(output)
    match = _TRANSLATION.match(xpath or "")
    if query is None or match is None:
        return None
    owner, axis = match["owner"], "xyz".index(match["axis"])
    try:
        owner_uid = config.value(owner + "/@uID")
    except Error:
        return None  # an element without a uID: none this map knows
    wing = config.wings[query["wing"]]
    unit = np.eye(3)[axis]
    etas = query["eta"]
    wing_xpath = wing.node.xpath
    owning_component = owner.split("/sections/section[", 1)[0]
    if owning_component != owner and config.value(owning_component + "/@uID") != wing.uid:
        moved = np.zeros((etas.size, 3))  # another component's section or element: no part of this wing
    elif owner_uid == wing.uid:
        moved = np.tile(unit, (etas.size, 1))
    elif owning_component == owner and not _exists(config, wing_xpath + "/parentUID"):
        moved = np.zeros((etas.size, 3))  # another component, and this wing hangs on none
    else:
        segment = wing.segments[query["segment"] - 1] if isinstance(query["segment"], int) else \
            next(s for s in wing.segments if s.attribute("uID") == query["segment"])
        inner, outer = segment.fromElementUID.text, segment.toElementUID.text
        wing_linear = linear_part(config, wing_xpath)
        weights = None
        for section in wing.sections:
            elements = [element.attribute("uID") for element in section.elements]
            if owner_uid == section.attribute("uID"):
                direction = wing_linear @ unit
                weights = (1 - etas) * (inner in elements) + etas * (outer in elements)
            elif owner_uid in elements:
                direction = wing_linear @ linear_part(config, section.xpath) @ unit
                weights = (1 - etas) * (owner_uid == inner) + etas * (owner_uid == outer)
        if weights is None:
            return None  # the translation of something else than this wing's
        moved = np.outer(weights, direction)
    return moved[0] if output.get("op") in _POINT_OPS else moved
