"""Airshape: CPACS aircraft descriptions as exact B-spline geometry.

    import airshape
    config = airshape.Configuration.open("examples/generic-airliner.xml")
    wing = config.wings["Wing"]
    wing.volume, wing.reference_area()
    wing.upper_point(segment=1, eta=0.5, xsi=0.3)
    wing.sections[2].elements[0].transformation.scaling.x = 1.4   # edit; rebuilt on next use
    config.export("airliner.step", mirror=True)

Every failure raises an `airshape.Error` subclass (airshape.errors) with the file and the
CPACS path it concerns.
"""
from __future__ import annotations

import json
from typing import Any, Dict, Iterator, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _airshape
from ._ops import ComponentOps, Ops
from .errors import (ArgumentError, Error, FileError, ModelError, NotBuiltYetError, PluginError,
                     WriteError)

__all__ = ["Configuration", "Wing", "Fuselage", "ControlSurface", "Component", "ComponentSegment", "Rotor", "Node", "NodeList", "Error", "FileError", "ModelError",
           "ArgumentError", "WriteError", "PluginError", "NotBuiltYetError", "Study", "sensitivities"]

Number = Union[int, float]


def _text(value: Any) -> str:
    """A value as CPACS text: numbers with every digit, booleans as true/false."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


class Node:
    """An element of the CPACS document, reached by attribute names and indices, for reading
    and editing values: `wing.sections[0].elements[0].transformation.scaling.x = 1.2`.

    An attribute name ending in "s" is a list of the elements named without it
    (`sections` -> `section`); others are single child elements. Setting an attribute sets
    that child's text. `float(node)`, `node.text` and `node.value` read it."""

    __slots__ = ("_config", "_xpath")

    def __init__(self, config: "Configuration", xpath: str) -> None:
        object.__setattr__(self, "_config", config)
        object.__setattr__(self, "_xpath", xpath)

    @property
    def xpath(self) -> str:
        return self._xpath

    @property
    def text(self) -> str:
        return self._config.value(self._xpath)

    @property
    def value(self) -> Union[float, str]:
        """The text as a number where it is one."""
        text = self.text
        try:
            return float(text)
        except ValueError:
            return text

    def __float__(self) -> float:
        return float(self.text)

    def __getattr__(self, name: str) -> Union["Node", "NodeList"]:
        if name.startswith("_"):
            raise AttributeError(name)
        if name.endswith("s") and len(name) > 1:
            return NodeList(self._config, f"{self._xpath}/{name}/{name[:-1]}")
        return Node(self._config, f"{self._xpath}/{name}")

    def __setattr__(self, name: str, value: Any) -> None:
        self._config.set(f"{self._xpath}/{name}", value)

    def attribute(self, name: str) -> str:
        """The value of an XML attribute of this element (uID, symmetry, ...)."""
        return self._config.value(f"{self._xpath}/@{name}")

    @property
    def xml(self) -> str:
        """The element with all it holds, as XML text (to copy it, say)."""
        return self._config._core.xml(self._xpath)

    def remove(self) -> None:
        """Removes the element; remove first what refers to it (a segment before its section)."""
        self._config.remove(self._xpath)

    def __repr__(self) -> str:
        return f"Node({self._xpath!r})"


class NodeList(Sequence[Node]):
    """The elements of one name under a parent, indexed from 0."""

    def __init__(self, config: "Configuration", xpath: str) -> None:
        self._config = config
        self._xpath = xpath

    def __len__(self) -> int:
        return self._config._core.count(self._xpath)

    def __iter__(self) -> Iterator[Node]:
        # Explicit: Sequence's own iteration stops at IndexError, and indices out of range
        # raise ArgumentError here.
        return (self[index] for index in range(len(self)))

    def __getitem__(self, index):  # type: ignore[override]
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        count = len(self)
        if index < 0:
            index += count
        if not 0 <= index < count:
            raise ArgumentError(f"index {index} is out of range ({count} elements at {self._xpath})")
        return Node(self._config, f"{self._xpath}[{index + 1}]")

    def append(self, xml: str) -> None:
        """Adds an element (XML text, e.g. a changed copy of another's .xml) after the last."""
        self.insert(len(self), xml)

    def insert(self, index: int, xml: str) -> None:
        """Adds an element before the index-th (0-based) of this list."""
        parent, _, name = self._xpath.rpartition("/")
        count = len(self)
        if not 0 <= index <= count:
            raise ArgumentError(f"index {index} is out of range ({count} elements at {self._xpath})")
        position = 0
        if index < count:  # the position of the index-th element among all the parent's children
            children = [node.tag for node in _children(self._config, parent)]
            seen = -1
            for position, tag in enumerate(children, start=1):
                seen += tag == name
                if seen == index:
                    break
        self._config.insert(parent, xml, position)

    def __repr__(self) -> str:
        return f"NodeList({self._xpath!r}, {len(self)} elements)"


def _children(config: "Configuration", xpath: str):
    """The child elements of an element (for positions among them)."""
    import xml.etree.ElementTree as ElementTree
    return list(ElementTree.fromstring(config._core.xml(xpath)))


class _ByUid:
    """What every component object holds: its configuration and its uID, and through them every
    query op that takes a component's uid, as methods generated from the query registry:
    spar.ops.component_faces(mirrored=True) (docs/python.md, "Every op as a method")."""

    def __init__(self, config: "Configuration", uid: str) -> None:
        self._config = config
        self.uid = uid

    @property
    def ops(self) -> ComponentOps:
        return ComponentOps(self._config.query, self.uid)


class _Component(_ByUid):
    """What wings and fuselages share: a uID, the node of its element, the ops."""

    _kind = ""

    def _op(self, name: str, **arguments: Any) -> Any:
        return self._config.query(f"{self._kind}_{name}", **{self._kind: self.uid}, **arguments)

    @property
    def node(self) -> Node:
        """The component's element, for reading and editing its values."""
        kind = self._kind
        return Node(self._config, f"/cpacs/vehicles/aircraft/model/{kind}s/{kind}[@uID='{self.uid}']")

    def __getattr__(self, name: str) -> Union[Node, NodeList]:
        if name.startswith("_"):
            raise AttributeError(name)
        return getattr(self.node, name)

    def _points(self, op: str, segment: Union[int, str], first: str, a: Any, second: str, b: Any) -> np.ndarray:
        """A point op over two parameter arrays (scalars broadcast), in one call."""
        a, b = np.broadcast_arrays(np.asarray(a, dtype=float).ravel(), np.asarray(b, dtype=float).ravel())
        return self._config._core.points(op, {self._kind: self.uid, "segment": segment}, first,
                                         np.ascontiguousarray(a), second, np.ascontiguousarray(b))

    @property
    def segment_count(self) -> int:
        return self._op("segment_count")

    @property
    def volume(self) -> float:
        return self._op("volume")

    @property
    def surface_area(self) -> float:
        return self._op("surface_area")

    def segment_volume(self, segment: Union[int, str]) -> float:
        return self._op("segment_volume", segment=segment)

    def segment_surface_area(self, segment: Union[int, str]) -> float:
        return self._op("segment_surface_area", segment=segment)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.uid!r})"


class Wing(_Component):
    """A wing: points on its skins by segment, eta and xsi, and its measures."""

    _kind = "wing"

    def upper_point(self, segment: Union[int, str], eta: float, xsi: float) -> np.ndarray:
        return np.array(self._op("upper_point", segment=segment, eta=eta, xsi=xsi))

    def lower_point(self, segment: Union[int, str], eta: float, xsi: float) -> np.ndarray:
        return np.array(self._op("lower_point", segment=segment, eta=eta, xsi=xsi))

    def chord_point(self, segment: Union[int, str], eta: float, xsi: float) -> np.ndarray:
        return np.array(self._op("chord_point", segment=segment, eta=eta, xsi=xsi))

    def points(self, side: str, segment: Union[int, str], eta: Any, xsi: Any) -> np.ndarray:
        """Points of one side ("upper", "lower" or "chord") for arrays of eta and xsi
        (scalars broadcast): an (n, 3) array, computed in one call."""
        return self._points(f"wing_{side}_point", segment, "eta", eta, "xsi", xsi)

    @property
    def section_count(self) -> int:
        return self._op("section_count")

    @property
    def symmetry(self) -> str:
        return self._op("symmetry")

    def reference_area(self, plane: str = "x-y") -> float:
        return self._op("reference_area", plane=plane)

    @property
    def wetted_area(self) -> float:
        return self._op("wetted_area")

    @property
    def span(self) -> float:
        return self._op("span")

    @property
    def mac(self) -> dict:
        """{"mac": length, "point": [x, y, z]}"""
        return self._op("mac")

    @property
    def component_segments(self) -> List[ComponentSegment]:
        """Its component segments, with their spars, ribs, cells and fuel tanks."""
        return [ComponentSegment(self._config, child["uid"])
                for child in self._config.query("component_children", uid=self.uid)
                if child["type"] == "wing_component_segment"]

    @property
    def control_surfaces(self) -> "_Devices":
        """Its trailing- and leading-edge devices (no spoilers), by index or uID."""
        return _Devices(self, "control_surface")

    @property
    def spoilers(self) -> "_Devices":
        """Its spoilers, by index or uID."""
        return _Devices(self, "spoiler")


class Component(_ByUid):
    """Any component by uID (QUERY-components §1): a spar, a rib set, a cell, a component
    segment, a device, ...: its type, its measures, the components inside it, its shape."""

    @property
    def type(self) -> str:
        return self._config.query("component_type", uid=self.uid)

    @property
    def volume(self) -> float:
        """The volume of its solids (0 for surfaces such as spars, ribs and cells)."""
        return self._config.query("component_volume", uid=self.uid)

    @property
    def surface_area(self) -> float:
        return self._config.query("component_surface_area", uid=self.uid)

    @property
    def bounding_box(self) -> dict:
        """{"min": [x, y, z], "max": [x, y, z]}"""
        return self._config.query("bounding_box", uid=self.uid)

    @property
    def children(self) -> List["Component"]:
        """The components directly inside it."""
        return [_component(self._config, child["uid"], child["type"])
                for child in self._config.query("component_children", uid=self.uid)]

    def _children_of_type(self, kind: str) -> List["Component"]:
        return [child for child in self.children if child.type == kind]

    def export(self, path: str) -> None:
        """Writes its shape in the format the extension names (docs/export.md)."""
        self._config.export(path, components=[self.uid])

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.uid!r})"


class ComponentSegment(Component):
    """A wing's component segment with its structure (docs/structure.md)."""

    @property
    def spars(self) -> List[Component]:
        return self._children_of_type("wing_spar")

    @property
    def ribs(self) -> List[Component]:
        """Its ribs definitions (each one component with all its ribs)."""
        return self._children_of_type("wing_rib")

    @property
    def cells(self) -> List[Component]:
        return self._children_of_type("wing_cell")

    @property
    def fuel_tanks(self) -> List[Component]:
        """Its wing fuel tanks: the solids its spars and ribs enclose."""
        return self._children_of_type("tank")


class Rotor(Component):
    """A rotor of a rotorcraft: its attached blades as one shape, and its figures
    (QUERY-components §5, docs/rotor.md)."""

    def _figure(self, what: str) -> Any:
        return self._config.query(f"rotor_{what}", rotor=self.uid)

    @property
    def blade_count(self) -> int:
        return self._figure("blade_count")

    @property
    def radius(self) -> float:
        return self._figure("radius")

    @property
    def reference_area(self) -> float:
        """pi radius^2"""
        return self._figure("reference_area")

    @property
    def total_blade_planform_area(self) -> float:
        return self._figure("total_blade_planform_area")

    @property
    def solidity(self) -> float:
        return self._figure("solidity")

    @property
    def tip_speed(self) -> float:
        """In m/s; negative for a negative rotation speed, 0 without one."""
        return self._figure("tip_speed")


def _component(config: "Configuration", uid: str, kind: str) -> Component:
    classes = {"wing_component_segment": ComponentSegment, "rotor": Rotor}
    return classes.get(kind, Component)(config, uid)


class ControlSurface(_ByUid):
    """A control device of a wing (trailing-edge device, leading-edge device or spoiler): its
    kind, its control parameter range, its rigid motion and its measures at rest or deflected
    (docs/controlsurfaces.md)."""

    @property
    def type(self) -> str:
        """"trailing_edge_device", "leading_edge_device" or "spoiler"."""
        return self._config.query("control_surface_type", uid=self.uid)

    @property
    def parameter_range(self) -> Tuple[float, float]:
        """The control parameters of its first and last step, in document order."""
        found = self._config.query("control_surface_parameter_range", uid=self.uid)
        return found["min"], found["max"]

    def deflection(self, p: float) -> dict:
        """Its rigid motion at control parameter p: {"control_parameter", "rotation" (degrees),
        "matrix": a 3x4 array [R | t]}; p outside the range raises ArgumentError."""
        found = self._config.query("control_surface_deflection", uid=self.uid, control_parameter=p)
        found["matrix"] = np.array(found["matrix"])
        return found

    def _own(self, kind: str) -> List["Component"]:
        return [_component(self._config, child["uid"], child["type"])
                for child in self._config.query("component_children", uid=self.uid) if child["type"] == kind]

    @property
    def spars(self) -> List["Component"]:
        """Its own spars (its structure, in its own coordinates: docs/structure.md)."""
        return self._own("wing_spar")

    @property
    def ribs(self) -> List["Component"]:
        """Its own ribs definitions."""
        return self._own("wing_rib")

    @property
    def cells(self) -> List["Component"]:
        """Its own cells."""
        return self._own("wing_cell")

    def _measure(self, what: str, p: Optional[float]) -> Any:
        if p is None:
            return self._config.query(f"component_{what}" if what != "bounding_box" else what, uid=self.uid)
        return self._config.query(f"control_surface_{what}", uid=self.uid, control_parameter=p)

    def volume(self, p: Optional[float] = None) -> float:
        """Its volume at rest, or deflected to control parameter p."""
        return self._measure("volume", p)

    def surface_area(self, p: Optional[float] = None) -> float:
        """Its surface area at rest, or deflected to control parameter p."""
        return self._measure("surface_area", p)

    def bounding_box(self, p: Optional[float] = None) -> dict:
        """{"min": [x, y, z], "max": [x, y, z]} at rest, or deflected to control parameter p."""
        return self._measure("bounding_box", p)

    def __repr__(self) -> str:
        return f"ControlSurface({self.uid!r})"


class _Devices(Sequence):
    """The control surfaces (or the spoilers) of one wing, by 0-based index or by uID, in the
    order of the query protocol."""

    def __init__(self, wing: "Wing", kind: str) -> None:
        self._wing, self._kind = wing, kind

    def _uids(self) -> List[str]:
        config, wing = self._wing._config, self._wing.uid
        count = config.query(f"{self._kind}_count", wing=wing)
        return [config.query(f"{self._kind}_uid", wing=wing, index=i) for i in range(1, count + 1)]

    def __len__(self) -> int:
        return self._wing._config.query(f"{self._kind}_count", wing=self._wing.uid)

    def __getitem__(self, key):  # type: ignore[override]
        uids = self._uids()
        if isinstance(key, str):
            if key not in uids:
                raise ArgumentError(f"wing '{self._wing.uid}' has no {self._kind.replace('_', ' ')} '{key}'")
            return ControlSurface(self._wing._config, key)
        if key < 0:
            key += len(uids)
        if not 0 <= key < len(uids):
            raise ArgumentError(f"{self._kind.replace('_', ' ')} index {key} is out of range ({len(uids)} on "
                                f"wing '{self._wing.uid}')")
        return ControlSurface(self._wing._config, uids[key])

    def __iter__(self) -> Iterator:
        return (ControlSurface(self._wing._config, uid) for uid in self._uids())


class Fuselage(_Component):
    """A fuselage: points by segment, eta and zeta, and its measures."""

    _kind = "fuselage"

    def point(self, segment: Union[int, str], eta: float, zeta: float) -> np.ndarray:
        return np.array(self._op("point", segment=segment, eta=eta, zeta=zeta))

    def points(self, segment: Union[int, str], eta: Any, zeta: Any) -> np.ndarray:
        """Points for arrays of eta and zeta (scalars broadcast): an (n, 3) array."""
        return self._points("fuselage_point", segment, "eta", eta, "zeta", zeta)

    def circumference(self, segment: Union[int, str], eta: float) -> float:
        return self._op("circumference", segment=segment, eta=eta)

    @property
    def structure(self) -> List["Component"]:
        """Its structure elements (frames, stringers, pressure bulkheads, doors, walls, cross
        beams, ...) as components, in document order (docs/structure.md)."""
        return [_component(self._config, child["uid"], child["type"])
                for child in self._config.query("component_children", uid=self.uid)
                if child["type"] != "fuselage_segment"]


class _Components(Sequence):
    """Wings, fuselages or rotors, by 0-based index or by uID."""

    def __init__(self, config: "Configuration", kind: str, cls: type) -> None:
        self._config, self._kind, self._cls = config, kind, cls

    def __len__(self) -> int:
        return self._config.query(f"{self._kind}_count")

    def __getitem__(self, key):  # type: ignore[override]
        if isinstance(key, str):
            return self._cls(self._config, self._config.query(f"{self._kind}_uid", **{self._kind: key}))
        count = len(self)
        if key < 0:
            key += count
        if not 0 <= key < count:
            raise ArgumentError(f"{self._kind} index {key} is out of range ({count} {self._kind}s)")
        return self._cls(self._config, self._config.query(f"{self._kind}_uid", **{self._kind: key + 1}))

    def __iter__(self) -> Iterator:
        return (self[i] for i in range(len(self)))


class Configuration:
    """A CPACS 3 file opened for geometry. Geometry is built on first use and cached; an
    edit rebuilds only the components it can change (see cache_statistics())."""

    def __init__(self, core: "_airshape.Configuration") -> None:
        self._core = core

    @classmethod
    def open(cls, path: str) -> "Configuration":
        """Opens a CPACS 3 file; raises FileError naming it when it cannot."""
        return cls(_airshape.Configuration.open(str(path)))

    @classmethod
    def from_string(cls, xml: str, name: str = "<string>") -> "Configuration":
        """Opens a CPACS 3 document held in a string."""
        return cls(_airshape.Configuration.from_string(xml, name))

    @property
    def source(self) -> str:
        return self._core.source

    @property
    def wings(self) -> _Components:
        return _Components(self, "wing", Wing)

    @property
    def fuselages(self) -> _Components:
        return _Components(self, "fuselage", Fuselage)

    def _components_of_type(self, kind: str) -> List[Component]:
        return [_component(self, entry["uid"], entry["type"]) for entry in self.query("component_list", all=True)
                if entry["type"] == kind]

    @property
    def engines(self) -> List[Component]:
        """The engine placements of the model, each with its nacelle as shape (docs/nacelle.md)."""
        return self._components_of_type("engine_nacelle")

    @property
    def pylons(self) -> List[Component]:
        """The engine pylons of the model (docs/nacelle.md)."""
        return self._components_of_type("engine_pylon")

    @property
    def tanks(self) -> List[Component]:
        """The fuel tanks, each the compound of its vessels (docs/tank.md), and the wing fuel
        tanks of the component segments (docs/structure.md)."""
        return self._components_of_type("tank")

    @property
    def ducts(self) -> List[Component]:
        """The ducts and duct assemblies (docs/fuselage.md)."""
        return self._components_of_type("duct")

    @property
    def systems(self) -> List[Component]:
        """The generic systems, each the compound of its components (docs/generic.md)."""
        return self._components_of_type("generic_system")

    @property
    def decks(self) -> List[Component]:
        """The decks, each the compound of its seats, galleys, ... (docs/generic.md)."""
        return self._components_of_type("deck")

    @property
    def external_objects(self) -> List[Component]:
        """The external CAD objects placed in the aircraft (docs/generic.md)."""
        return self._components_of_type("external_object")

    @property
    def rotors(self) -> _Components:
        """The rotors of the model the queries address (a rotorcraft model's)."""
        return _Components(self, "rotor", Rotor)

    @property
    def ops(self) -> Ops:
        """Every query op of the loaded plugins as a method, its parameters and docstring from
        the op's signature: config.ops.wing_span(wing=1) (docs/python.md)."""
        return Ops(self.query)

    def component(self, uid: str) -> Component:
        """Any component by uID (spars, ribs, cells, devices, segments, ...)."""
        return _component(self, uid, self.query("component_type", uid=uid))

    def query(self, op: str, **arguments: Any) -> Any:
        """Runs any op of the query protocol (docs/query.md): query("wing_span", wing=1)."""
        return self._core.query(op, arguments)

    def value(self, xpath: str) -> str:
        """The text (or attribute value) an XPath addresses."""
        return self._core.value(xpath)

    def set(self, xpath: str, value: Any) -> None:
        """Sets a value by XPath; raises ArgumentError (and changes nothing) for a value the
        schema refuses there or a path that addresses nothing."""
        self._core.set(xpath, _text(value))

    def insert(self, parent_xpath: str, xml: str, position: int = 0) -> None:
        """Inserts XML elements under the element at parent_xpath, before its position-th
        child element (1-based; 0 appends). Raises (and changes nothing) when the result
        would not be a usable model: a repeated uID, a reference to nothing, a cycle."""
        self._core.insert(parent_xpath, xml, position)

    def remove(self, xpath: str) -> None:
        """Removes the element at an XPath with all it holds (same checks as insert)."""
        self._core.remove(xpath)

    def node(self, xpath: str) -> Node:
        """The element at an XPath, for reading and editing by attribute names."""
        return Node(self, xpath)

    def save(self, path: str) -> None:
        """Writes the document, edits included (complete or not at all)."""
        self._core.save(str(path))

    def mesh(self, path: str, *, components: Optional[List[str]] = None, mirror: bool = False,
             deflect: Optional[Dict[str, Union[float, str]]] = None, size: Optional[float] = None,
             sizes: Optional[Dict[str, float]] = None, min_size: Optional[float] = None,
             curvature: Optional[float] = None, farfield: Optional[str] = None, symmetry: bool = False,
             boundary_layer: Optional[Sequence[float]] = None, structure: bool = False,
             order: int = 1) -> Dict[str, Any]:
        """Meshes through Gmsh and writes the mesh in the format the extension names (.msh, .su2,
        .vtu, .inp, .stl; docs/meshing.md). `size`/`min_size` in metres, `sizes` per component
        uID, `curvature` elements per turn, `farfield` "20L" or "sphere:100" for a CFD domain,
        `symmetry` for the half domain y >= 0, `boundary_layer` (count, first height[, growth])
        for prism layers on the walls under the tetrahedra, `structure` for the FEM shell model (`order` 2:
        8-node shells). Returns the report: {"meshes": [{"name", "nodes", "elements",
        "worst_quality", "seconds"}], "failures": [...], "notes": [...]}."""
        arguments: List[str] = []
        if components:
            arguments += ["--components", ",".join(components)]
        if mirror:
            arguments.append("--mirror")
        if deflect:
            arguments += ["--deflect", ",".join(f"{uid}={_text(p)}" for uid, p in deflect.items())]
        if size is not None:
            arguments += ["--size", repr(float(size))]
        if sizes:
            arguments += ["--size", ",".join(f"{uid}={float(s)!r}" for uid, s in sizes.items())]
        if min_size is not None:
            arguments += ["--min-size", repr(float(min_size))]
        if curvature is not None:
            arguments += ["--curvature", repr(float(curvature))]
        if farfield is not None:
            arguments += ["--farfield", farfield]
        if symmetry:
            arguments.append("--symmetry")
        if boundary_layer is not None:
            arguments += ["--boundary-layer", ",".join(repr(v) for v in boundary_layer)]
        if structure:
            arguments.append("--structure")
        if order != 1:
            arguments += ["--order", str(order)]
        report: Dict[str, Any] = json.loads(self._core.mesh(str(path), arguments))
        return report

    def export(self, path: str, components: Optional[List[str]] = None, mirror: bool = False, fused: bool = False,
               linear_deflection: float = 0.0, angular_deflection: float = 0.0,
               deflect: Optional[Dict[str, Union[float, str]]] = None, structure: bool = False,
               profiles: bool = False) -> None:
        """Writes the geometry in the format the extension names (docs/export.md). `deflect`
        maps device uIDs (or "all") to control parameters (a number, "min" or "max"): those
        devices are written deflected, their wings with the cut-outs (docs/controlsurfaces.md).
        `structure` writes the structural model instead (docs/structure.md); `profiles` writes
        frames and stringers with their structural profiles swept along them."""
        poses = ",".join(f"{uid}={_text(p)}" for uid, p in (deflect or {}).items())
        self._core.export(str(path), components or [], mirror, fused, linear_deflection, angular_deflection, poses,
                          structure, profiles)

    @property
    def duct_cutouts(self) -> bool:
        """Whether the duct assemblies are cut out of the wings and fuselages they pass through
        (off when a file is opened, as in the reference library; docs/fuselage.md#duct-cut-outs).
        Setting it rebuilds what it changes on next use."""
        return self._core.option("duct_cutouts")

    @duct_cutouts.setter
    def duct_cutouts(self, on: bool) -> None:
        self._core.set_option("duct_cutouts", bool(on))

    def set_option(self, name: str, on: bool) -> None:
        """Turns a build option the loaded plugins declare on or off (see options())."""
        self._core.set_option(name, bool(on))

    def options(self) -> Dict[str, bool]:
        """Every build option the loaded plugins declare, and whether it is on."""
        return {name: self._core.option(name) for name in self._core.options()}

    def cache_statistics(self) -> dict:
        """{"built", "reused", "invalidated", "builds_by_key"}: what the geometry cache did."""
        return self._core.cache_statistics()

    def __repr__(self) -> str:
        return f"Configuration({self.source!r})"


# Design studies (docs/studies.md), after Configuration: they open configurations.
from .study import Study, sensitivities  # noqa: E402
