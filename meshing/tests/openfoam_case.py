"""An OpenFOAM case around a mesh written by `airshape mesh`, run with Debian's openfoam
package (its programs in /usr/bin, WM_PROJECT_DIR=/usr/share/openfoam): gmshToFoam, checkMesh
and potentialFoam with uniform flow at the far field and slip walls."""
import os
import shutil
import subprocess

import pytest

HEADER = "FoamFile {{ version 2.0; format ascii; class {kind}; object {name}; }}\n"
CONTROL = """application potentialFoam; startFrom startTime; startTime 0; stopAt endTime; endTime 1; deltaT 1;
writeControl timeStep; writeInterval 1; writeFormat ascii; writePrecision 10; writeCompression off;
timeFormat general; timePrecision 6; runTimeModifiable false;
"""
SCHEMES = """ddtSchemes { default steadyState; } gradSchemes { default Gauss linear; }
divSchemes { default none; div(div(phi,U)) Gauss linear; }
laplacianSchemes { default Gauss linear limited 0.5; } interpolationSchemes { default linear; }
snGradSchemes { default limited 0.5; }
"""
SOLUTION = """solvers { Phi { solver GAMG; smoother DIC; tolerance 1e-08; relTol 0; } p { $Phi; } }
potentialFlow { nNonOrthogonalCorrectors 3; }
"""


def field(name, kind, dimensions, internal, patches):
    """A field file: every patch a wall of the aircraft unless named in `patches`."""
    boundary = "".join(f"  {patch} {{ {condition} }}\n" for patch, condition in patches.items())
    return (HEADER.format(kind=kind, name=name) + f"dimensions {dimensions};\ninternalField uniform {internal};\n"
            f"boundaryField {{\n{boundary}  \".*\" {{ type slip; }}\n}}\n")


def run(program, case, *arguments):
    if shutil.which(program) is None:
        pytest.fail(f"{program} is missing (scripts/test.sh installs Debian's openfoam)")
    return subprocess.run([program, "-case", str(case), *arguments], capture_output=True, text=True, timeout=600,
                          env={**os.environ, "WM_PROJECT_DIR": "/usr/share/openfoam"})


def make_case(folder, mesh, patches, keep_orientation=False):
    """A case in `folder` holding the mesh (converted by gmshToFoam, with -keepOrientation when
    asked) and the fields; `patches` are the far-field patches (uniform flow along x), the rest
    slip walls. Returns gmshToFoam's run."""
    os.makedirs(folder / "system")
    os.makedirs(folder / "0")
    (folder / "system" / "controlDict").write_text(HEADER.format(kind="dictionary", name="controlDict") + CONTROL)
    (folder / "system" / "fvSchemes").write_text(HEADER.format(kind="dictionary", name="fvSchemes") + SCHEMES)
    (folder / "system" / "fvSolution").write_text(HEADER.format(kind="dictionary", name="fvSolution") + SOLUTION)
    velocity = {patch: "type fixedValue; value uniform (1 0 0);" for patch in patches}
    pressure = {patch: "type fixedValue; value uniform 0;" for patch in patches}
    (folder / "0" / "U").write_text(field("U", "volVectorField", "[0 1 -1 0 0 0 0]", "(1 0 0)", velocity))
    (folder / "0" / "p").write_text(field("p", "volScalarField", "[0 2 -2 0 0 0 0]", "0", pressure).replace(
        "type slip;", "type zeroGradient;"))
    return run("gmshToFoam", folder, str(mesh), *(["-keepOrientation"] if keep_orientation else []))


def boundary_patches(folder):
    """The patch names of constant/polyMesh/boundary with their face counts."""
    text = (folder / "constant" / "polyMesh" / "boundary").read_text()
    import re
    return {name: int(count) for name, count in re.findall(r"\n\s*(\S+)\s*\{[^}]*?nFaces\s+(\d+);", text)}
