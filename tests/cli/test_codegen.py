"""The committed model is exactly what codegen makes of the schema."""
import filecmp
import os
import subprocess
import sys

from conftest import SOURCE, shared_path


def test_regenerating_changes_nothing(tmp_path):
    schema = shared_path("data", "schema", "cpacs_schema.xsd")
    subprocess.run([sys.executable, os.path.join(SOURCE, "codegen", "generate.py"), "--schema", schema,
                    "--out", str(tmp_path)], check=True, capture_output=True)
    pairs = [("include/airshape/schema/generated", "core/include/airshape/schema/generated"),
             ("src/schema/generated", "core/src/schema/generated")]
    for generated, committed in pairs:
        names = sorted(os.listdir(tmp_path / generated))
        committed_names = sorted(n for n in os.listdir(os.path.join(SOURCE, committed)) if not n.startswith("."))
        assert names == committed_names
        match, mismatch, errors = filecmp.cmpfiles(tmp_path / generated, os.path.join(SOURCE, committed), names,
                                                   shallow=False)
        assert not mismatch and not errors, f"regenerate with `cmake --build build --target codegen`: {mismatch}"
