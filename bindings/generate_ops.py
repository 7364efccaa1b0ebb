"""Writes the bindings' per-op functions from the query registry: one typed function per op of the
plugins built with Airshape, its parameters and documentation from the op's signature
(`airshape plugins --json`, core/include/airshape/query/op_signature.h). Run at build time:

    generate_ops.py python AIRSHAPE_BINARY OUTPUT.py        the Python package's Ops class
    generate_ops.py c AIRSHAPE_BINARY HEADER.h SOURCE.cpp   the C functions airshape_op_<name>

In Python, ops registered at run time by other plugins (AIRSHAPE_PLUGIN_PATH) become methods too,
through the class's __getattr__ (docs/python.md, "Every op as a method"); in C they stay reachable
through airshape_query (docs/c-api.md)."""
import json
import os
import subprocess
import sys

# Parameter types by argument name; any other argument is typed Any.
TYPES = {
    **dict.fromkeys(["eta", "xsi", "zeta", "x", "y", "z", "control_parameter", "deflection"], "float"),
    **dict.fromkeys(["index"], "int"),
    **dict.fromkeys(["on", "all", "mirrored", "other_mirrored"], "bool"),
    **dict.fromkeys(["uid", "uid1", "uid2", "other", "name", "plane", "component_segment"], "str"),
    **dict.fromkeys(["point", "normal"], "Sequence[float]"),
    **dict.fromkeys(["wing", "fuselage", "rotor", "segment"], "Selector"),
}

HEADER = '''"""Every query op as a method of `Configuration.ops`, generated from the query registry by
bindings/generate_ops.py at build time: do not edit. Ops of plugins loaded at run time
(AIRSHAPE_PLUGIN_PATH) are methods too (see Ops.__getattr__)."""
import json
from typing import Any, Callable, Dict, List, Optional, Sequence, Union

from . import _airshape

Selector = Union[int, str]  # a 1-based index or a uID


def _runtime_ops() -> List[Dict[str, Any]]:
    return json.loads(_airshape.ops_description())


class Ops:
    """Every query op of the loaded plugins as a method: `config.ops.wing_span(wing=1)` runs
    `config.query("wing_span", wing=1)`. Each method's docstring is the op's summary."""

    def __init__(self, query: Callable[..., Any]) -> None:
        self._query = query

    def __getattr__(self, name: str) -> Callable[..., Any]:
        for op in _runtime_ops():
            if op["name"] == name:
                query = self._query

                def method(**arguments: Any) -> Any:
                    return query(name, **arguments)

                method.__name__ = name
                method.__doc__ = f"{op['summary']} (op of plugin {op['owner']})"
                return method
        raise AttributeError(f"no query op '{name}' in the loaded plugins")


class ComponentOps:
    """Every query op that takes a component's `uid` as a method of that component, the uID filled
    in: `spar.ops.component_faces(mirrored=True)`. Ops of plugins loaded at run time too."""

    def __init__(self, query: Callable[..., Any], uid: str) -> None:
        self._query = query
        self._uid = uid

    def __getattr__(self, name: str) -> Callable[..., Any]:
        for op in _runtime_ops():
            if op["name"] == name and "uid" in op["arguments"]:
                query, uid = self._query, self._uid

                def method(**arguments: Any) -> Any:
                    return query(name, uid=uid, **arguments)

                method.__name__ = name
                method.__doc__ = f"{op['summary']} (op of plugin {op['owner']}; uid: this component)"
                return method
        raise AttributeError(f"no query op '{name}' taking a component's uid in the loaded plugins")
'''


def method(op, bound_uid=False):
    """A method of Ops, or with `bound_uid` of ComponentOps: the op's `uid` is the component's."""
    arguments = [name for name in op["arguments"] if not (bound_uid and name == "uid")]
    required = [f"{name}: {TYPES.get(name, 'Any')}" for name in arguments]
    optional = [f"{name}: Optional[{TYPES.get(name, 'Any')}] = None" for name in op["optional"]]
    parameters = ", ".join(["self", *(["*"] if required or optional else []), *required, *optional])
    passed = "".join(f", {name}={name}" for name in arguments) + (", uid=self._uid" if bound_uid else "")
    owner = f"op of plugin {op['owner']}" + ("; uid: this component" if bound_uid else "")
    lines = [f"    def {op['name']}({parameters}) -> Any:", f"        {json.dumps(op['summary'] + ' (' + owner + ')')}"]
    if op["optional"]:
        lines.append("        given = {k: v for k, v in {" + ", ".join(f'"{n}": {n}' for n in op["optional"]) +
                     "}.items() if v is not None}")
        lines.append(f"        return self._query({op['name']!r}{passed}, **given)")
    else:
        lines.append(f"        return self._query({op['name']!r}{passed})")
    return "\n".join(lines)

# C types by the Python type of an argument: required, and optional (a pointer, NULL for absent).
C_TYPES = {"float": ("double", "const double*"), "int": ("int", "const int*"), "bool": ("int", "const int*"),
           "str": ("const char*", "const char*"), "Sequence[float]": ("const double*", "const double*"),
           "Selector": ("int", "const int*"), "Any": ("const char*", "const char*")}

C_HEADER = """/* Every query op of the plugins built with Airshape as a C function, generated from the query
 * registry by bindings/generate_ops.py when the library is built: do not edit (docs/c-api.md).
 * airshape_op_<name>(configuration, arguments..., result_json) runs op <name> as airshape_query
 * does and returns its result as JSON in *result_json (free it with airshape_free). Wings,
 * fuselages, rotors and segments are 1-based indices (uIDs through airshape_query); points are
 * three doubles; an optional argument is a pointer, NULL leaving it out; an argument of no
 * known type is JSON text. */
#ifndef AIRSHAPE_OPS_H
#define AIRSHAPE_OPS_H

#include "airshape.h"

#ifdef __cplusplus
extern "C" {
#endif
"""

C_FOOTER = """
#ifdef __cplusplus
}
#endif

#endif
"""


def c_parameters(op):
    parameters = ["airshape_configuration* configuration"]
    for name in op["arguments"]:
        parameters.append(f"{C_TYPES[TYPES.get(name, 'Any')][0]} {name}")
    for name in op["optional"]:
        parameters.append(f"{C_TYPES[TYPES.get(name, 'Any')][1]} {name}")
    return ", ".join(parameters + ["char** result_json"])


def c_argument(name, optional):
    kind = TYPES.get(name, "Any")
    value = f"*{name}" if optional and kind not in ("str", "Any", "Sequence[float]") else name
    if kind == "bool":
        value = f"({value} != 0)"
    elif kind == "Sequence[float]":
        value = f"{name} ? Json::array({{{name}[0], {name}[1], {name}[2]}}) : Json()"
    elif kind == "Any":
        value = f"{name} ? Json::parse({name}, nullptr, false) : Json()"
    elif kind == "str":
        value = f"{name} ? Json({name}) : Json()"
    line = f'  query["{name}"] = {value};'
    return f"  if ({name}) {line.strip()}" if optional else line


def c_function(op):
    summary = op["summary"].replace("*/", "* /")
    declaration = f"airshape_status airshape_op_{op['name']}({c_parameters(op)})"
    body = [f'  Json query{{{{"op", "{op["name"]}"}}}};']
    body += [c_argument(name, False) for name in op["arguments"]]
    body += [c_argument(name, True) for name in op["optional"]]
    body.append("  return airshape_query(configuration, query.dump().c_str(), result_json);")
    return f"/* {summary} (op of plugin {op['owner']}) */\n{declaration};\n", \
        f"{declaration} {{\n" + "\n".join(body) + "\n}\n"


def registry(binary):
    env = {k: v for k, v in os.environ.items() if k != "AIRSHAPE_PLUGIN_PATH"}  # the built plugins only
    listing = subprocess.run([binary, "plugins", "--json"], capture_output=True, text=True, env=env, check=True)
    return json.loads(listing.stdout)["ops"]


def write(path, text):
    temporary = path + ".tmp"
    with open(temporary, "w") as out:
        out.write(text)
    os.replace(temporary, path)


def main(language, binary, *outputs):
    ops = registry(binary)
    if language == "python":
        ops_class, component_class = HEADER.split("\n\nclass ComponentOps:")
        write(outputs[0], ops_class + "".join("\n" + method(op) + "\n" for op in ops) +
              "\n\nclass ComponentOps:" + component_class +
              "".join("\n" + method(op, bound_uid=True) + "\n" for op in ops if "uid" in op["arguments"]))
    elif language == "c":
        functions = [c_function(op) for op in ops]
        write(outputs[0], C_HEADER + "".join("\n" + declaration for declaration, _ in functions) + C_FOOTER)
        write(outputs[1], "// Generated by bindings/generate_ops.py from the query registry: do not edit.\n"
                          "#include <nlohmann/json.hpp>\n\n#include \"airshape_ops.h\"\n\n"
                          "using Json = nlohmann::json;\n\nextern \"C\" {\n"
                          + "".join("\n" + definition for _, definition in functions) + "\n}  // extern \"C\"\n")
    else:
        sys.exit(f"generate_ops.py: unknown language '{language}' (python or c)")


if __name__ == "__main__":
    main(*sys.argv[1:])
