#!/usr/bin/env bash
# Every test: installs what is missing (the build's packages, the independent readers the
# export tests reopen files with: gmsh, VTK, admesh from Debian, gltf-validator from npm, and
# headless Chromium with Pillow and websocket-client for the viewer's tests, mypy for the Python
# binding's types, meshio, OpenFOAM and CalculiX for the meshes' tests, Dask distributed and
# matplotlib for the design studies' tests),
# builds, and runs the unit, CLI, round-trip, codegen, plugin, export and conformance tests
# with ctest. Tests that need ../shared skip when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh

readers=(python3-gmsh python3-vtk9 admesh chromium python3-pil python3-websocket mypy python3-meshio openfoam
         calculix-ccx python3-distributed python3-matplotlib)
missing=()
for package in "${readers[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
# Node.js may come from elsewhere than Debian (with its own npm); Debian's only when none is there.
command -v npm >/dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ ! -d build/tools/node_modules/gltf-validator ]; then
  npm install --prefix build/tools --no-audit --no-fund --silent gltf-validator@2.0.0-dev.3.10 >/dev/null
fi

ctest --test-dir build --output-on-failure -j "$(nproc)"
