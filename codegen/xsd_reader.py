"""Reads an XML schema (the CPACS XSD) into a small intermediate representation.

The representation keeps only what the C++ model needs: for each complex type its
base type, its attributes and child elements with their occurrence limits, the
choice groups they belong to, and for simple types their value base, enumeration
values and numeric range facets.
"""
from dataclasses import dataclass, field
import xml.etree.ElementTree as ET

XS = "{http://www.w3.org/2001/XMLSchema}"
UNBOUNDED = -1


@dataclass
class Facets:
    """Numeric range restrictions of a simple value."""
    min_inclusive: str | None = None
    max_inclusive: str | None = None
    min_exclusive: str | None = None
    max_exclusive: str | None = None

    def any(self):
        return any((self.min_inclusive, self.max_inclusive, self.min_exclusive, self.max_exclusive))


@dataclass
class Member:
    """An attribute or a child element of a complex type."""
    name: str
    type_name: str
    is_attribute: bool
    min_occurs: int = 1
    max_occurs: int = 1
    choice_group: int = -1
    choice_alternative: int = -1


@dataclass
class ChoiceGroup:
    """An xsd:choice: at most one alternative may be present; min_occurs=1 requires one."""
    min_occurs: int
    alternatives: list = field(default_factory=list)  # list of lists of element names


@dataclass
class SimpleType:
    """A named or anonymous simple type (or a complex type with simple content only)."""
    name: str
    base: str
    enumeration: list = field(default_factory=list)
    facets: Facets = field(default_factory=Facets)
    is_union: bool = False


@dataclass
class ComplexType:
    name: str
    base: str | None = None                 # complex base type (extension)
    simple_base: str | None = None          # simple content: the value's type
    members: list = field(default_factory=list)
    choices: list = field(default_factory=list)


@dataclass
class Schema:
    root_element: str
    root_type: str
    complex_types: dict = field(default_factory=dict)
    simple_types: dict = field(default_factory=dict)


def _occurs(node, attribute, default):
    value = node.get(attribute)
    if value is None:
        return default
    return UNBOUNDED if value == "unbounded" else int(value)


def _multiply(a, b):
    return UNBOUNDED if UNBOUNDED in (a, b) else a * b


class _Reader:
    def __init__(self, root):
        self.schema = Schema(root_element="", root_type="")
        self.root = root

    def read(self):
        for node in self.root:
            if node.tag == XS + "element":
                self.schema.root_element = node.get("name")
                self.schema.root_type = node.get("type")
            elif node.tag == XS + "complexType":
                self._complex_type(node.get("name"), node)
            elif node.tag == XS + "simpleType":
                self._simple_type(node.get("name"), node)
        return self.schema

    # -- simple types ---------------------------------------------------
    def _simple_type(self, name, node):
        restriction = node.find(XS + "restriction")
        union = node.find(XS + "union")
        if union is not None:
            self.schema.simple_types[name] = SimpleType(name, "xsd:string", is_union=True)
        elif restriction is not None:
            self.schema.simple_types[name] = self._restriction(name, restriction)
        else:
            raise ValueError(f"simple type {name}: neither restriction nor union")
        return name

    def _restriction(self, name, restriction):
        simple = SimpleType(name, restriction.get("base"))
        for facet in restriction:
            tag = facet.tag[len(XS):]
            if tag == "enumeration":
                simple.enumeration.append(facet.get("value"))
            elif tag in ("minInclusive", "maxInclusive", "minExclusive", "maxExclusive"):
                attr = {"minInclusive": "min_inclusive", "maxInclusive": "max_inclusive",
                        "minExclusive": "min_exclusive", "maxExclusive": "max_exclusive"}[tag]
                setattr(simple.facets, attr, facet.get("value"))
        return simple

    # -- complex types --------------------------------------------------
    def _complex_type(self, name, node):
        simple_content = node.find(XS + "simpleContent")
        if simple_content is not None:
            return self._simple_content(name, simple_content)
        complex_type = ComplexType(name)
        content = node
        complex_content = node.find(XS + "complexContent")
        if complex_content is not None:
            content = complex_content.find(XS + "extension")
            if content is None:
                raise ValueError(f"complex type {name}: only extension is supported")
            complex_type.base = content.get("base")
        self.schema.complex_types[name] = complex_type
        for child in content:
            tag = child.tag[len(XS):]
            if tag in ("sequence", "all", "choice"):
                self._particle(complex_type, child, 1, -1, -1)
            elif tag == "attribute":
                complex_type.members.append(self._attribute(name, child))
        return name

    def _simple_content(self, name, simple_content):
        derivation = simple_content[0] if simple_content[0].tag != XS + "annotation" else simple_content[1]
        if derivation.tag == XS + "restriction":
            self.schema.simple_types[name] = self._restriction(name, derivation)
            return name
        complex_type = ComplexType(name)
        complex_type.simple_base = derivation.get("base")
        for child in derivation:
            if child.tag == XS + "attribute":
                complex_type.members.append(self._attribute(name, child))
        self.schema.complex_types[name] = complex_type
        return name

    def _attribute(self, owner, node):
        name = node.get("name")
        type_name = node.get("type")
        inline = node.find(XS + "simpleType")
        if inline is not None:
            type_name = self._simple_type(f"{owner}_{name}", inline)
        required = node.get("use") == "required"
        return Member(name, type_name or "xsd:string", True, 1 if required else 0, 1)

    def _particle(self, owner, node, outer_max, group, alternative):
        """Flattens sequence/all/choice into members; nested occurrence limits multiply."""
        tag = node.tag[len(XS):]
        min_occurs = _occurs(node, "minOccurs", 1)
        max_occurs = _multiply(outer_max, _occurs(node, "maxOccurs", 1))
        if tag == "choice":
            nested = group >= 0
            choice = ChoiceGroup(0 if nested or min_occurs == 0 else 1)
            owner.choices.append(choice)
            group = len(owner.choices) - 1
            for index, child in enumerate(c for c in node if c.tag != XS + "annotation"):
                choice.alternatives.append([])
                self._choice_alternative(owner, child, max_occurs, group, index)
            return
        for child in node:
            child_tag = child.tag[len(XS):]
            if child_tag == "element":
                self._element(owner, child, max_occurs, group, alternative, min_occurs)
            elif child_tag in ("sequence", "all", "choice"):
                self._particle(owner, child, max_occurs, group, alternative)

    def _choice_alternative(self, owner, node, outer_max, group, alternative):
        before = len(owner.members)
        if node.tag == XS + "element":
            self._element(owner, node, outer_max, group, alternative, 1)
        else:
            self._particle(owner, node, outer_max, group, alternative)
        names = [m.name for m in owner.members[before:] if not m.is_attribute]
        owner.choices[group].alternatives[alternative].extend(names)

    def _element(self, owner, node, outer_max, group, alternative, outer_min):
        name = node.get("name")
        type_name = node.get("type")
        inline_complex = node.find(XS + "complexType")
        inline_simple = node.find(XS + "simpleType")
        if inline_complex is not None:
            type_name = self._complex_type(f"{owner.name}_{name}", inline_complex)
        elif inline_simple is not None:
            type_name = self._simple_type(f"{owner.name}_{name}", inline_simple)
        min_occurs = _occurs(node, "minOccurs", 1) * min(outer_min, 1)
        if group >= 0:
            min_occurs = 0  # presence inside a choice is checked by the choice group
        max_occurs = _multiply(outer_max, _occurs(node, "maxOccurs", 1))
        existing = next((m for m in owner.members if m.name == name and not m.is_attribute), None)
        if existing is not None:
            # The same element in two alternatives of a choice: one member serves both.
            existing.min_occurs = min(existing.min_occurs, min_occurs)
            existing.max_occurs = UNBOUNDED if UNBOUNDED in (existing.max_occurs, max_occurs) \
                else max(existing.max_occurs, max_occurs)
            return
        owner.members.append(Member(name, type_name, False, min_occurs, max_occurs, group, alternative))


def read_schema(path):
    return _Reader(ET.parse(path).getroot()).read()
