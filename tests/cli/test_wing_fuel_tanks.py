"""Wing fuel tanks (docs/structure.md): the part of a component segment that spars and ribs
enclose, on the rectangular wing of parabolic arcs whose figures are known in closed form
(test_structure.py: chord 2 from x = 1 to 3, span 5, skins z = ±0.15·2·ξ(1−ξ))."""
import json
import re

import pytest

from conftest import airshape
from test_structure import ask, height, position, ribs, segment, skin_length, with_spars


def section_area(xi0, xi1):
    """The wing's cross section between two chord shares: ∫ 0.6 ξ(1−ξ) dx, x = 1 + 2ξ."""
    return 2 * 0.6 * ((xi1 ** 2 / 2 - xi1 ** 3 / 3) - (xi0 ** 2 / 2 - xi0 ** 3 / 3))


def border(spar=None, rib=None):
    if spar:
        return f"<border><sparUID>{spar}</sparUID></border>"
    return f"<border><ribDefinitionUID>Ribs</ribDefinitionUID><ribNumber>{rib}</ribNumber></border>"


def tank(uid, *borders):
    return f'<wingFuelTank uID="{uid}"><geometry>{"".join(borders)}</geometry></wingFuelTank>'


def wing_with_tanks(tmp_path, *tanks):
    """Spars at ξ 0.2 (Front), 0.4 (Mid) and 0.6 (Rear) over the whole span; three ribs along
    the front spar at 10, 50 and 90 % of its length: chordwise planes y = 0.5, 2.5 and 4.5."""
    positions = "".join(position(f"Pos{name}{end}", end, xsi)
                        for name, xsi in (("F", 0.2), ("M", 0.4), ("R", 0.6)) for end in (0, 1))
    spars = segment("Front", "PosF0", "PosF1") + segment("Mid", "PosM0", "PosM1") + segment("Rear", "PosR0", "PosR1")
    path = with_spars(tmp_path, positions, spars, ribs("Ribs", 0.1, 0.9, 3))
    text = path.read_text().replace("</controlSurfaces>",
                                    f"</controlSurfaces><wingFuelTanks>{''.join(tanks)}</wingFuelTanks>", 1)
    path.write_text(text)
    return path


def test_a_tank_between_two_spars_and_two_ribs_in_closed_form(tmp_path):
    path = wing_with_tanks(tmp_path, tank("Box", border("Front"), border(rib=1), border("Rear"), border(rib=3)))
    volume, area, box, kind = (a["ok"] for a in ask(
        path, {"op": "component_volume", "uid": "Box"}, {"op": "component_surface_area", "uid": "Box"},
        {"op": "bounding_box", "uid": "Box"}, {"op": "component_type", "uid": "Box"}))
    assert volume == pytest.approx(4.0 * section_area(0.2, 0.6), rel=1e-7)
    # Two rib walls, two spar walls and the upper and lower skin, 4 m long.
    walls = 2 * section_area(0.2, 0.6) + 4.0 * (height(0.2) + height(0.6))
    assert area == pytest.approx(walls + 2 * 4.0 * skin_length(0.2, 0.6), rel=1e-6)
    assert box["min"][:2] == pytest.approx([1.4, 0.5], abs=1e-6) and box["max"][:2] == pytest.approx([2.2, 4.5], abs=1e-6)
    assert box["max"][2] == pytest.approx(height(0.5) / 2, abs=1e-6)
    assert kind == "tank"
    # Walls are named by the spar or rib they stand in, skins by the wing face they are cut from.
    step = tmp_path / "box.step"
    airshape("export", str(path), "-o", str(step), "--components", "Box", "--quiet")
    names = set(re.findall(r"ADVANCED_FACE\('([^']+)'", step.read_text()))
    assert {"Box/Front", "Box/Rear", "Box/Ribs/rib 1", "Box/Ribs/rib 3"} <= names
    assert any(re.fullmatch(r"Box/.+/upper", name) for name in names), names


def test_an_open_list_of_borders_is_closed_by_the_nearer_end(tmp_path):
    # Two spars and one rib leave the tank open: the component segment's end nearer to the
    # rib closes it (a centre tank from the root to rib 1, an outer tank from rib 3 to the tip).
    path = wing_with_tanks(tmp_path, tank("Centre", border("Front"), border(rib=1), border("Rear")),
                           tank("Outer", border("Rear"), border(rib=3), border("Front")),
                           tank("Box", border("Front"), border(rib=1), border("Rear"), border(rib=3)))
    centre, outer, box = (a["ok"] for a in ask(path, *({"op": "component_volume", "uid": uid}
                                                       for uid in ("Centre", "Outer", "Box"))))
    assert centre == pytest.approx(0.5 * section_area(0.2, 0.6), rel=1e-7)
    assert outer == pytest.approx(0.5 * section_area(0.2, 0.6), rel=1e-7)
    assert centre + box + outer == pytest.approx(5.0 * section_area(0.2, 0.6), rel=1e-7)


def test_a_stepped_tank_follows_its_borders(tmp_path):
    # Front spar from rib 3 to rib 1, across to the rear spar, out to rib 2, forward to the mid
    # spar, out to rib 3 and back to the front spar: an L seen from above.
    path = wing_with_tanks(tmp_path, tank("Step", border("Front"), border(rib=1), border("Rear"), border(rib=2),
                                          border("Mid"), border(rib=3)))
    volume, = (a["ok"] for a in ask(path, {"op": "component_volume", "uid": "Step"}))
    assert volume == pytest.approx(2.0 * section_area(0.2, 0.6) + 2.0 * section_area(0.2, 0.4), rel=1e-7)


def test_borders_listed_out_of_order_are_taken_around_the_tank_with_a_warning(tmp_path):
    # Real files list "front spar, rib 1, rib 3, rear spar": the order that closes is taken.
    path = wing_with_tanks(tmp_path, tank("Listed", border("Front"), border(rib=1), border(rib=3), border("Rear")))
    result = airshape("query", str(path), stdin=json.dumps({"op": "component_volume", "uid": "Listed"}) + "\n")
    assert json.loads(result.stdout)["ok"] == pytest.approx(4.0 * section_area(0.2, 0.6), rel=1e-7)
    assert "wingFuelTank[1]/geometry: the borders are not listed in order around the tank; taken as border 1, 2, 4, 3" \
        in result.stderr


def test_tank_errors_name_the_cpacs_path(tmp_path):
    path = wing_with_tanks(tmp_path, tank("NoSpar", border("Nowhere"), border(rib=1), border("Rear"), border(rib=3)),
                           tank("NoRib", border("Front"), border(rib=7), border("Rear"), border(rib=3)),
                           tank("Apart", border(rib=1), border(rib=3), border("Front")),
                           tank("Good", border("Front"), border(rib=1), border("Rear"), border(rib=3)))
    no_spar, no_rib, apart, good = ask(path, *({"op": "component_volume", "uid": uid}
                                               for uid in ("NoSpar", "NoRib", "Apart", "Good")))
    assert "'Nowhere'" in no_spar["error"] and "wingFuelTank[1]/geometry/border[1]/sparUID" in no_spar["error"]
    assert "has no rib 7 (it has 3)" in no_rib["error"] and "wingFuelTank[2]/geometry/border[2]" in no_rib["error"]
    assert "border 1 and border 2 do not meet" in apart["error"] and "wingFuelTank[3]/geometry" in apart["error"]
    assert good["ok"] == pytest.approx(4.0 * section_area(0.2, 0.6), rel=1e-7), "one broken tank never stops another"
