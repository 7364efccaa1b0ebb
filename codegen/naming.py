"""C++ names for schema names: classes, enumerators and members."""
import re

CPP_KEYWORDS = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break",
    "case", "catch", "char", "class", "compl", "const", "constexpr", "const_cast", "continue",
    "decltype", "default", "delete", "do", "double", "dynamic_cast", "else", "enum", "explicit",
    "export", "extern", "false", "float", "for", "friend", "goto", "if", "inline", "int", "long",
    "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or",
    "or_eq", "private", "protected", "public", "register", "reinterpret_cast", "return", "short",
    "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch", "template",
    "this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union",
    "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while",
}
# Names the Node base class uses; a schema member of the same name gets a trailing underscore.
NODE_MEMBERS = {"visit", "schemaType", "binding", "xpath", "absentOnRead"}


def class_name(schema_name):
    """wingType -> WingType, doubleConstraintBaseType_relationalOperator -> DoubleConstraintBaseTypeRelationalOperator."""
    return "".join(part[:1].upper() + part[1:] for part in schema_name.split("_"))


def member_name(schema_name):
    name = re.sub(r"[^A-Za-z0-9_]", "_", schema_name)
    if name in CPP_KEYWORDS or name in NODE_MEMBERS:
        name += "_"
    return name


def enumerator_names(values):
    """x-z-plane -> XZPlane, 'C1 from previous' -> C1FromPrevious, 1-cos -> V1Cos; unique."""
    names = []
    for value in values:
        parts = [p for p in re.split(r"[^A-Za-z0-9]+", value) if p]
        name = "".join(p[:1].upper() + p[1:] for p in parts) or "Empty"
        if name[0].isdigit():
            name = "V" + name
        base, suffix = name, 2
        while name in names:
            name = f"{base}{suffix}"
            suffix += 1
        names.append(name)
    return names
