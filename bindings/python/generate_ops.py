"""Writes the Python binding's `Ops` class from the query registry: one typed method per op of the
plugins built with the package, its parameters and docstring from the op's signature
(`airshape plugins --json`, core/include/airshape/query/op_signature.h). Run at build time:

    generate_ops.py AIRSHAPE_BINARY OUTPUT.py

Ops registered at run time by other plugins (AIRSHAPE_PLUGIN_PATH) become methods too, through
the class's __getattr__ (docs/python.md, "Every op as a method")."""
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
bindings/python/generate_ops.py at build time: do not edit. Ops of plugins loaded at run time
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
'''


def method(op):
    required = [f"{name}: {TYPES.get(name, 'Any')}" for name in op["arguments"]]
    optional = [f"{name}: Optional[{TYPES.get(name, 'Any')}] = None" for name in op["optional"]]
    parameters = ", ".join(["self", *(["*"] if required or optional else []), *required, *optional])
    passed = ", ".join(f"{name}={name}" for name in op["arguments"])
    lines = [f"    def {op['name']}({parameters}) -> Any:",
             f"        {json.dumps(op['summary'] + ' (op of plugin ' + op['owner'] + ')')}"]
    if op["optional"]:
        lines.append("        given = {k: v for k, v in {" + ", ".join(f'"{n}": {n}' for n in op["optional"]) +
                     "}.items() if v is not None}")
        lines.append(f"        return self._query({op['name']!r}{', ' + passed if passed else ''}, **given)")
    else:
        lines.append(f"        return self._query({op['name']!r}{', ' + passed if passed else ''})")
    return "\n".join(lines)


def main(binary, output):
    env = {k: v for k, v in os.environ.items() if k != "AIRSHAPE_PLUGIN_PATH"}  # the package's plugins only
    listing = subprocess.run([binary, "plugins", "--json"], capture_output=True, text=True, env=env, check=True)
    ops = json.loads(listing.stdout)["ops"]
    text = HEADER + "".join("\n" + method(op) + "\n" for op in ops)
    temporary = output + ".tmp"
    with open(temporary, "w") as out:
        out.write(text)
    os.replace(temporary, output)


if __name__ == "__main__":
    main(*sys.argv[1:3])
