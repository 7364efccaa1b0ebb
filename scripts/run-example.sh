#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs airshape on the example aircraft.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
example=examples/example-aircraft.xml
./build/bin/airshape info "$example"
./build/bin/airshape validate "$example"
./build/bin/airshape build "$example"
printf '%s\n' '{"op":"wing_count"}' '{"op":"wing_uid","wing":1}' '{"op":"wing_symmetry","wing":"MainWing"}' \
  '{"op":"wing_segment_count","wing":1}' '{"op":"fuselage_segment_count","fuselage":1}' \
  '{"op":"wing_upper_point","wing":1,"segment":1,"eta":0.5,"xsi":0.3}' '{"op":"wing_volume","wing":1}' \
  '{"op":"wing_surface_area","wing":1}' '{"op":"wing_reference_area","wing":1,"plane":"x-y"}' \
  '{"op":"wing_span","wing":1}' '{"op":"wing_mac","wing":1}' |
  ./build/bin/airshape query "$example"
