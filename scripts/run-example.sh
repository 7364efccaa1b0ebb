#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs airshape on the example airliner:
# checks it, builds every element (wings, fuselage, flaps, slats, ailerons, spoiler, spars,
# ribs, frames, stringers, floor beams, a wall, engine, pylon, tank, duct) and says what became of each, writes the aircraft with its
# mirrored halves as STEP, STL, glTF and a page for any browser (open
# examples/generic-airliner.html) next to it with a summary (volumes, areas, time), and asks a
# few queries.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh airshape_tool_and_plugins  # the tests and benchmarks come with scripts/test.sh
example=examples/generic-airliner.xml
./build/bin/airshape validate "$example"
./build/bin/airshape build "$example"
./build/bin/airshape export "$example" --mirror --force \
  -o examples/generic-airliner.step -o examples/generic-airliner.stl -o examples/generic-airliner.glb \
  -o examples/generic-airliner.html
printf '%s\n' '{"op":"wing_reference_area","wing":"Wing","plane":"x-y"}' '{"op":"wing_span","wing":"Wing"}' \
  '{"op":"wing_mac","wing":"Wing"}' '{"op":"wing_upper_point","wing":"Wing","segment":1,"eta":0.5,"xsi":0.3}' \
  '{"op":"fuselage_point","fuselage":1,"segment":4,"eta":0.5,"zeta":0.25}' |
  ./build/bin/airshape query "$example"
