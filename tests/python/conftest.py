"""The Python module's tests: the package comes from the build tree (PYTHONPATH, set by
ctest), the example files from the source tree."""
import os

SOURCE = os.environ.get("AIRSHAPE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("AIRSHAPE_BUILD_DIR", os.path.join(SOURCE, "build"))
AIRLINER = os.path.join(SOURCE, "examples", "generic-airliner.xml")
