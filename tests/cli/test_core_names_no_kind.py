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

# Files that still name kinds, to be emptied as their code moves into the plugins that own the
# kinds (issue 55): the wing and fuselage lists of a model and the selections and exports built
# on them. A file leaves this list once it is clean; none may join it.
STILL_TO_MOVE = {
    "src/component_shapes.cpp",
    "src/fused_shape.cpp",
    "src/schema/value_codec.cpp",
    "src/model/placement.cpp",
    "src/model/primary_model.cpp",
    "src/export/export_scene.cpp",
    "src/export/exporter.cpp",
    "src/export/gltf_lines.cpp",
    "src/export/gltf_lines.h",
    "src/export/mesh_lines.h",
    "src/export/obj_lines.cpp",
    "src/export/obj_lines.h",
    "src/export/posed_components.cpp",
    "src/export/posed_components.h",
    "src/export/scene_mesh.cpp",
    "src/export/scene_mesh.h",
    "src/export/step_brep_writer.cpp",
    "src/export/structural_model.cpp",
    "src/export/structural_model.h",
    "src/export/viewer_content.cpp",
    "src/export/vtp_writer.cpp",
    "src/query/box_answer.cpp",
    "src/query/component_queries.cpp",
    "src/query/intersection_curves.cpp",
    "src/query/intersection_curves.h",
    "src/geometry/brep_measures.cpp",
    "src/geometry/coons_patches.cpp",
    "src/geometry/curve_network.cpp",
    "src/geometry/ruled_crossing.cpp",
    "src/geometry/ruled_loft.cpp",
    "src/geometry/ruled_sections.cpp",
    "src/geometry/ruled_sections_module.cpp",
    "src/geometry/traced_section.cpp",
    "include/airshape/component_cache.h",
    "include/airshape/component_shapes.h",
    "include/airshape/error.h",
    "include/airshape/named_shape.h",
    "include/airshape/schema/element_reading.h",
    "include/airshape/schema/node.h",
    "include/airshape/model/approximation_settings.h",
    "include/airshape/model/component_fingerprints.h",
    "include/airshape/model/cst_airfoil.h",
    "include/airshape/model/guide_curves.h",
    "include/airshape/model/placed_elements.h",
    "include/airshape/model/placement.h",
    "include/airshape/model/primary_model.h",
    "include/airshape/model/segment_chain.h",
    "include/airshape/xml/xpath.h",
    "include/airshape/export/export_options.h",
    "include/airshape/export/export_scene.h",
    "include/airshape/export/exporter.h",
    "include/airshape/export/viewer_content.h",
    "include/airshape/query/arguments.h",
    "include/airshape/query/model_selection.h",
    "include/airshape/geometry/curve_approximation.h",
    "include/airshape/geometry/faces_near.h",
    "include/airshape/geometry/loft_piece.h",
    "include/airshape/geometry/loft_shell.h",
    "include/airshape/geometry/plane_face_within.h",
    "include/airshape/geometry/ruled_crossing.h",
    "include/airshape/geometry/ruled_side.h",
    "include/airshape/geometry/skin_split.h",
    "include/airshape/geometry/tangent_contact.h",
    "include/airshape/geometry/traced_section.h",
    "include/airshape/plugin/services.h",
}


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
    offending = {path: kinds for path, kinds in naming.items() if kinds and path not in STILL_TO_MOVE}
    assert not offending, offending


def test_the_list_of_files_still_to_move_only_shrinks():
    cleaned = sorted(path for path in STILL_TO_MOVE if not kinds_named_in(path))
    assert not cleaned, f"these files name no kind any more: remove them from STILL_TO_MOVE: {cleaned}"
