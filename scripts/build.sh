#!/usr/bin/env bash
# Installs the Debian packages Airshape needs that are missing, then configures and builds
# it (Release, ccache when present) in ./build. Run as root on Debian 12.
#
#   scripts/build.sh            everything: the library, the plugins, the tools, the bindings,
#                               the tests and the benchmarks
#   scripts/build.sh TARGET...  only those targets and what they need (the main job builds
#                               airshape_tool_and_plugins)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build ccache python3 python3-pytest
          libxerces-c-dev libboost-dev libboost-filesystem-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
          libeigen3-dev libtbb-dev libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
          libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev pybind11-dev python3-dev python3-numpy libgmsh-dev)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
# npm fetches three.js for the browser viewer at build time (without it the viewer is left out).
command -v npm >/dev/null || missing+=(nodejs npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j "$(nproc)" ${1:+--target "$@"}
