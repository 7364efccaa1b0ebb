#!/usr/bin/env bash
# The meshing workloads of issue 56, timed as a user meets them: one process each, wall time and
# peak memory (/usr/bin/time), the median of RUNS runs. Needs ../shared/data, a built
# build/bin/airshape and Debian's python3-gmsh for the STEP route.
#
#   bench/mesh_workloads.sh [RUNS]        (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
AIRSHAPE=build/bin/airshape
D150=../shared/data/cpacs/CPACS_30_D150.xml
RUNS=${1:-3}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# "median seconds, peak MB" of a command run RUNS times.
timed() {
  local runs=() memory=0
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%e %M" -o "$scratch/time" "$@" >"$scratch/out" 2>/dev/null
    read -r seconds kilobytes <"$scratch/time"
    runs+=("$seconds")
    memory=$kilobytes
  done
  printf '%s s, %d MB' "$(printf '%s\n' "${runs[@]}" | sort -n | sed -n "$(((RUNS + 1) / 2))p")" $((memory / 1024))
}

# The same surface mesh by the usual route: the fused aircraft written to STEP by `export`, then
# read by Gmsh's Python module and meshed with the sizes `airshape mesh` uses by default
# (length / 50, size / 50, 40 elements per turn), no refinement at trailing edges.
step_route() {
  "$AIRSHAPE" export "$D150" --fused --mirror -o "$scratch/d150.step" --force -q
  /usr/bin/python3 - "$scratch/d150.step" "$scratch/d150-step.msh" <<'PY'
import sys, gmsh
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
gmsh.model.occ.importShapes(sys.argv[1]); gmsh.model.occ.synchronize()
low = gmsh.model.getBoundingBox(-1, -1)
length = max(low[3] - low[0], low[4] - low[1], low[5] - low[2])
gmsh.option.setNumber("Mesh.MeshSizeMax", length / 50)
gmsh.option.setNumber("Mesh.MeshSizeMin", length / 2500)
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 40)
gmsh.model.mesh.generate(2)
gmsh.write(sys.argv[2])
PY
}

echo "D150 surface (fused, mirrored, default size):   $(timed "$AIRSHAPE" mesh "$D150" --mirror -o "$scratch/s.msh" --force -q)"
grep -o 'surface: .*' "$scratch/out" || true
echo "the same through STEP and Gmsh's Python module:  $(timed bash -c "$(declare -f step_route); AIRSHAPE=$AIRSHAPE D150=$D150 scratch=$scratch step_route")"
echo "D150 half CFD volume, far field 20L, size 0.5:   $(timed "$AIRSHAPE" mesh "$D150" --farfield 20L --symmetry --size 0.5 -o "$scratch/v.msh" --force -q)"
grep -o 'fluid: .*' "$scratch/out" || true
echo "D150 wing structure in S4 shells:                $(timed "$AIRSHAPE" mesh "$D150" --structure --components D150_VAMP_W1 -o "$scratch/w.inp" --force -q)"
grep -o 'structure: .*' "$scratch/out" || true
