"""`airshape mesh --structure` (docs/meshing.md): the structural model in shells, one node
where elements meet, an element and node set per structural element, and CalculiX (Debian's
calculix-ccx) solving on it: a rectangular wing box clamped at the root and loaded at the tip
bends as beam theory says, and the example airliner's wing solves without a singular matrix."""
import os
import re
import shutil
import subprocess
import sys

import numpy
import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli"))
from conftest import DATA, SOURCE, airshape, shared_path  # noqa: E402
from mesh_readers import free_edges  # noqa: E402

BOX = os.path.join(DATA, "wing-cst-structure.xml")  # chord 2, span 5, z = ±0.3 ξ(1-ξ), spars at ξ 0.2 and 0.6
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
E, NU, THICKNESS, LOAD = 70e9, 0.3, 0.002, 1000.0


def nodes_of(deck):
    """Node numbers and coordinates of an INP deck's *NODE block."""
    block = deck.split("*NODE\n")[1].split("*")[0]
    rows = numpy.array([[float(v) for v in line.split(",")] for line in block.strip().splitlines()])
    return rows[:, 0].astype(int), rows[:, 1:]


def element_set(deck, name):
    """The element numbers of an *ELSET of the deck."""
    block = deck.split(f"*ELSET, ELSET={name}\n")[1].split("*")[0]
    return {int(value) for value in block.replace("\n", ",").split(",") if value.strip()}


def node_set(deck, name):
    """The node numbers of an *NSET of the deck."""
    block = deck.split(f"*NSET, NSET={name}\n")[1].split("*")[0]
    return {int(value) for value in block.replace("\n", ",").split(",") if value.strip()}


def cantilever_deck(mesh_path, thickness):
    """The mesh with the analyst's cards: aluminium shells, the nodes at the smallest y clamped,
    LOAD newtons along z shared by the nodes at the largest y, the tip's displacements printed."""
    deck = open(mesh_path).read()
    numbers, points = nodes_of(deck)
    root = numbers[numpy.abs(points[:, 1] - points[:, 1].min()) < 1e-9]
    tip = numbers[numpy.abs(points[:, 1] - points[:, 1].max()) < 1e-9]
    models = re.findall(r"^\*ELSET, ELSET=(\S+_structure)$", deck, re.MULTILINE)
    cards = ["*NSET, NSET=ROOT", *map(str, root), "*NSET, NSET=TIP", *map(str, tip),
             "*MATERIAL, NAME=AL", "*ELASTIC", f"{E}, {NU}"]
    for model in models:
        cards += [f"*SHELL SECTION, ELSET={model}, MATERIAL=AL", str(thickness)]
    cards += ["*BOUNDARY", "ROOT, 1, 6", "*STEP", "*STATIC", "*CLOAD"]
    cards += [f"{node}, 3, {LOAD / len(tip)}" for node in tip]
    cards += ["*NODE PRINT, NSET=TIP", "U", "*END STEP"]
    return deck + "\n".join(cards) + "\n"


def solve(folder, deck):
    """Runs ccx on the deck; returns its output and the tip nodes' z displacements."""
    if shutil.which("ccx") is None:
        pytest.fail("ccx is missing (scripts/test.sh installs Debian's calculix-ccx)")
    (folder / "job.inp").write_text(deck)
    run = subprocess.run(["ccx", "job"], cwd=folder, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0 and "*ERROR" not in run.stdout, run.stdout[-3000:]
    printed = (folder / "job.dat").read_text().split("displacements")[1].strip().splitlines()[1:]
    return run.stdout, numpy.array([float(line.split()[3]) for line in printed if line.strip()])


def box_bending_stiffness():
    """E I of the box's section from its closed form (no code of Airshape): the whole skin
    z = ±0.3 ξ(1-ξ), x = 2ξ, as a thin wall, and the two spar webs; symmetric about z = 0."""
    xi = numpy.linspace(0, 1, 200001)
    z = 0.3 * xi * (1 - xi)
    ds = numpy.sqrt(1 + (0.15 * (1 - 2 * xi)) ** 2) * 2  # ds/dξ of the skin
    skin = 2 * THICKNESS * numpy.trapz(z ** 2 * ds, xi)
    webs = sum(THICKNESS * (2 * 0.3 * s * (1 - s)) ** 3 / 12 for s in (0.2, 0.6))
    return E * (skin + webs)


@pytest.fixture(scope="module")
def box_mesh(tmp_path_factory):
    folder = tmp_path_factory.mktemp("box")
    result = airshape("mesh", BOX, "--structure", "--order", "2", "--size", "0.1", "-o", str(folder / "box.inp"),
                      "-o", str(folder / "box.vtu"))
    assert result.returncode == 0, result.stderr
    return folder, result


def test_sets_per_structural_element_and_one_node_where_elements_meet(box_mesh):
    folder, result = box_mesh
    assert re.match(r"structure: [\d,]+ nodes, [\d,]+ quadrilaterals \(8 nodes\)", result.stdout), result.stdout
    deck = (folder / "box.inp").read_text()
    for uid in ("RectCS_structure", "Front", "Rear", "Ribs", "RS"):
        assert f"*ELSET, ELSET={uid}\n" in deck and f"*NSET, NSET={uid}\n" in deck, uid
    assert "TYPE=S8" in deck and "TYPE=S4R" not in deck
    _, points = nodes_of(deck)
    rounded = numpy.round(points / 1e-7).astype(numpy.int64)
    assert len(numpy.unique(rounded, axis=0)) == len(points)  # never two nodes in one place
    front, ribs = (node_set(deck, uid) for uid in ("Front", "Ribs"))
    assert len(front & ribs) >= 3 * 3  # each of the three ribs shares its edge's nodes with the front spar


def test_wing_box_tip_deflection_agrees_with_beam_theory(box_mesh, tmp_path):
    folder, _ = box_mesh
    _, tip = solve(tmp_path, cantilever_deck(folder / "box.inp", THICKNESS))
    span = 5.0
    webs = THICKNESS * sum(2 * 0.3 * s * (1 - s) for s in (0.2, 0.6))
    beam = LOAD * span ** 3 / (3 * box_bending_stiffness()) + LOAD * span / (E / (2 * (1 + NU)) * webs)
    assert tip.mean() == pytest.approx(beam, rel=0.03)
    assert numpy.ptp(tip) < 0.02 * tip.mean()  # the tip plate moves as one


@pytest.mark.parametrize("source, wing, size", [(AIRLINER, "Wing", "0.3"), (None, "D250_wing_CS", "0.6")])
def test_wings_solve_without_a_singular_matrix(tmp_path, source, wing, size):
    # D250's mid web lies on the wall of a flap's cut-out: joined as one face, not two with
    # opposite normals (CalculiX: "size of estimated shell normal ... smaller than 1.e-10").
    source = source or shared_path("data", "cpacs", "CPACS_30_D250_10.xml")
    mesh = tmp_path / "wing.inp"
    result = airshape("mesh", source, "--structure", "--components", wing, "--size", size, "-o", str(mesh))
    assert result.returncode in (0, 1) and mesh.exists(), result.stderr  # D250: four spoiler spars fail, said
    output, tip = solve(tmp_path, cantilever_deck(mesh, 0.003))
    assert "singular" not in output.lower()
    assert numpy.isfinite(tip).all() and tip.mean() > 0


@pytest.mark.parametrize("name", ["CPACS_30_D150.xml", "cell_rib_spar_test.xml"])
def test_structural_models_are_conformal_where_spars_kink(name, tmp_path):
    # A spar's webs on either side of a kink share their kink edge and their edges on the skins:
    # the shells have no free edge (31 mesh edges of D150's wing, 2 of cell_rib_spar_test's, before).
    path = tmp_path / "structure.vtu"
    result = airshape("mesh", shared_path("data", "cpacs", name), "--structure", "--size", "0.3", "-o", str(path))
    assert result.returncode == 0, result.stderr
    assert free_edges(path) == 0


def test_frames_and_stringers_are_beams_on_the_shells_nodes(tmp_path):
    mesh = tmp_path / "fuselage.inp"
    result = airshape("mesh", AIRLINER, "--structure", "--components", "Fuselage", "--size", "1", "-o", str(mesh))
    assert result.returncode == 0, result.stderr
    deck = mesh.read_text()
    elements = {}
    for kind, body in re.findall(r"\*ELEMENT, TYPE=(\w+)\n((?:\d.*\n)+)", deck):
        for line in body.strip().splitlines():
            numbers = [int(value) for value in line.split(",")]
            elements[numbers[0]] = (kind, numbers[1:])
    shell_nodes = {node for kind, nodes in elements.values() if kind.startswith("S") for node in nodes}
    beams = element_set(deck, "Fuselage_structure_beams")
    assert beams and all(elements[number][0] == "B31" for number in beams)
    assert not beams & element_set(deck, "Fuselage_structure")  # shells and beams take sections apart
    for uid in ("Stringer_Side", "Frame_Door_Front"):
        nodes = {node for number in element_set(deck, uid) for node in elements[number][1]}
        assert nodes and nodes <= shell_nodes, uid  # on the skin, on its nodes
