"""The core knows no component kind by name (docs/plugins.md, "What the core knows"): outside the
generated schema model, no source or header of the core names a component element. Plugins declare
their node types (where they live, what they are) and offer what others need through services."""
import os
import re

from conftest import SOURCE

CORE = os.path.join(SOURCE, "core")
# Component kinds of CPACS and of the plugins that build them, singular and plural, any case.
KINDS = re.compile(
    r"\b(wings?|fuselages?|spars?|ribs?|frames?|flaps?|slats?|spoilers?|ailerons?|tanks?|ducts?|decks?|"
    r"engines?|nacelles?|pylons?|rotors?|blades?|stringers?|bulkheads?|doors?|landing ?gears?)\b",
    re.IGNORECASE)

def core_sources():
    for base in (os.path.join(CORE, "src"), os.path.join(CORE, "include", "airshape")):
        for folder, _, names in os.walk(base):
            if os.sep + "generated" in folder:
                continue
            for name in sorted(names):
                if name.endswith((".cpp", ".h")):
                    yield os.path.relpath(os.path.join(folder, name), CORE)


def kinds_named_in(path):
    with open(os.path.join(CORE, path), encoding="utf-8") as source:
        return sorted({match.lower() for match in KINDS.findall(source.read())})


def test_the_core_names_no_component_kind():
    naming = {path: kinds_named_in(path) for path in core_sources()}
    offending = {path: kinds for path, kinds in naming.items() if kinds}
    assert not offending, offending


def test_the_check_sees_the_core_and_finds_kinds():
    # The scan must cover the core's sources, and the pattern must catch a kind written as code
    # or prose (else the test above passes on nothing).
    assert len(list(core_sources())) > 100
    assert KINDS.findall('select("wings/wing"); // a Fuselage frame') == ["wings", "wing", "Fuselage", "frame"]
