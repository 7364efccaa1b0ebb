"""Decides how each schema type is represented in C++ and which types the model keeps.

A type becomes either a *value* (a codec over a plain C++ value: text, number, enum, ...)
or a *class* (a generated Node subclass). The prune list removes elements; the kept
types are those reachable from the root type through elements that are not pruned.
"""
from dataclasses import dataclass

import naming
from xsd_reader import Facets

CODECS = {
    "string": ("StringCodec", "std::string"),
    "uid": ("UidCodec", "std::string"),
    "uidref": ("UidRefCodec", "std::string"),
    "double": ("DoubleCodec", "double"),
    "integer": ("IntegerCodec", "long long"),
    "boolean": ("BooleanCodec", "bool"),
    "doubleVector": ("DoubleVectorCodec", "std::vector<double>"),
}


@dataclass
class ValueType:
    codec: str
    cpp_type: str
    facets: Facets
    enum_type: str | None = None  # schema name of the enumeration, if any


@dataclass
class ClassType:
    schema_name: str
    cpp_name: str


def read_custom_types(path):
    mapping = {}
    for line in open(path, encoding="utf-8"):
        line = line.split("#", 1)[0].strip()
        if line:
            schema_type, kind = line.split()
            if kind not in CODECS:
                raise ValueError(f"{path}: unknown value kind '{kind}' for {schema_type}")
            mapping[schema_type] = kind
    return mapping


def read_prune_list(path):
    pruned = set()
    for line in open(path, encoding="utf-8"):
        line = line.split("#", 1)[0].strip()
        if line:
            owner, element = line.split("/")
            pruned.add((owner, element))
    return pruned


class TypeResolver:
    def __init__(self, schema, custom_types, pruned):
        self.schema = schema
        self.custom_types = custom_types
        self.pruned = pruned
        unknown = {o for o, _ in pruned} - set(schema.complex_types)
        if unknown:
            raise ValueError(f"prune list names unknown types: {sorted(unknown)}")

    def resolve(self, type_name):
        if type_name in self.custom_types:
            codec, cpp = CODECS[self.custom_types[type_name]]
            return ValueType(codec, cpp, Facets())
        simple = self.schema.simple_types.get(type_name)
        if simple is not None:
            if simple.enumeration:
                cpp = naming.class_name(type_name)
                return ValueType(f"EnumCodec<{cpp}>", cpp, Facets(), enum_type=type_name)
            if simple.is_union:
                return self.resolve("xsd:string")
            base = self.resolve(simple.base)
            if not isinstance(base, ValueType):
                raise ValueError(f"simple type {type_name} restricts a class type {simple.base}")
            return ValueType(base.codec, base.cpp_type, simple.facets if simple.facets.any() else base.facets,
                             base.enum_type)
        if type_name in self.schema.complex_types:
            return ClassType(type_name, naming.class_name(type_name))
        raise ValueError(f"unknown schema type {type_name}")

    def is_pruned(self, owner, member):
        return (owner, member.name) in self.pruned

    def kept_members(self, complex_type):
        return [m for m in complex_type.members
                if m.is_attribute or not self.is_pruned(complex_type.name, m)]

    def class_base(self, complex_type):
        """The generated base class (schema name) of a class type, or None for Node."""
        base = complex_type.base or complex_type.simple_base
        if base and isinstance(self.resolve(base), ClassType):
            return base
        return None

    def text_value(self, complex_type):
        """For a class with simple content over a plain value: the value's type; else None."""
        if complex_type.simple_base and self.class_base(complex_type) is None:
            return self.resolve(complex_type.simple_base)
        return None

    def reachable(self):
        """Schema names of the class types and enumerations the model keeps."""
        classes, enums = [], set()
        seen = set()
        stack = [self.schema.root_type]
        while stack:
            name = stack.pop()
            if name in seen:
                continue
            seen.add(name)
            classes.append(name)
            complex_type = self.schema.complex_types[name]
            base = self.class_base(complex_type)
            if base:
                stack.append(base)
            text = self.text_value(complex_type)
            if text is not None and text.enum_type:
                enums.add(text.enum_type)
            for member in self.kept_members(complex_type):
                resolved = self.resolve(member.type_name)
                if isinstance(resolved, ClassType):
                    stack.append(resolved.schema_name)
                elif resolved.enum_type:
                    enums.add(resolved.enum_type)
        return sorted(classes), sorted(enums)
