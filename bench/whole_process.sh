#!/usr/bin/env bash
# The whole-process workloads of issue 22, timed as a user meets them: one airshape process
# each, wall time and peak memory, the median of three runs (this machine is noisy: compare
# instruction counts with callgrind too). Needs ../shared/data and a built build/bin/airshape.
#
#   bench/whole_process.sh [RUNS]        (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
AIRSHAPE=build/bin/airshape
DATA=../shared/data
RUNS=${1:-3}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# One query's answer.
ask() { printf '%s\n' "$2" | "$AIRSHAPE" query "$1" 2>/dev/null | sed -n 's/.*"ok":\(.*\)}/\1/p'; }

# The volume of every wing and fuselage, then 4,000 point queries spread over them (issue 54's
# point-query workload).
point_queries() {
  local file=$1 wings fuselages
  wings=$(ask "$file" '{"op":"wing_count"}')
  fuselages=$(ask "$file" '{"op":"fuselage_count"}')
  awk -v wings="$wings" -v fuselages="$fuselages" 'BEGIN {
    for (w = 1; w <= wings; ++w) printf "{\"op\":\"wing_volume\",\"wing\":%d}\n", w
    for (f = 1; f <= fuselages; ++f) printf "{\"op\":\"fuselage_volume\",\"fuselage\":%d}\n", f
    srand(22)
    for (i = 0; i < 4000; ++i) {
      if (i % 2 == 0 && wings > 0)
        printf "{\"op\":\"wing_upper_point\",\"wing\":%d,\"segment\":1,\"eta\":%.4f,\"xsi\":%.4f}\n", 1 + i % wings, rand(), rand()
      else
        printf "{\"op\":\"fuselage_point\",\"fuselage\":%d,\"segment\":1,\"eta\":%.4f,\"zeta\":%.4f}\n", 1 + i % fuselages, rand(), rand()
    }
  }'
}

# The uIDs of the wings and fuselages: the lofts the reference library writes.
lofts() {
  local file=$1 uids=() n
  n=$(ask "$file" '{"op":"wing_count"}')
  for ((i = 1; i <= n; ++i)); do uids+=("$(ask "$file" "{\"op\":\"wing_uid\",\"wing\":$i}" | tr -d '"')"); done
  n=$(ask "$file" '{"op":"fuselage_count"}')
  for ((i = 1; i <= n; ++i)); do uids+=("$(ask "$file" "{\"op\":\"fuselage_uid\",\"fuselage\":$i}" | tr -d '"')"); done
  (IFS=,; echo "${uids[*]}")
}

# Runs a command RUNS times; prints the median wall time and the largest peak memory.
measure() {
  local name=$1; shift
  local times=() memory=0
  for ((run = 0; run < RUNS; ++run)); do
    /usr/bin/time -f '%e %M' -o "$scratch/time" "$@" >/dev/null 2>&1 || true
    read -r seconds kilobytes < "$scratch/time"
    times+=("$seconds")
    ((kilobytes > memory)) && memory=$kilobytes
  done
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(( (RUNS + 1) / 2 ))p")
  printf '%-56s %8s s %8d MB\n' "$name" "$median" $((memory / 1024))
}

printf '%-56s %10s %11s\n' "workload (median of $RUNS)" "wall" "peak"
for file in CPACS_30_D150.xml D150WithGuides.xml; do
  point_queries "$DATA/cpacs/$file" > "$scratch/queries-$file"
  [ -z "${KEEP_QUERIES:-}" ] || cp "$scratch/queries-$file" "$KEEP_QUERIES-$file"  # to check the answers
  measure "$file: open, volumes, 4,000 point queries" sh -c "$AIRSHAPE query $DATA/cpacs/$file < $scratch/queries-$file"
done
for file in CPACS_30_D150.xml D150WithGuides.xml crm.xml; do
  components=$(lofts "$DATA/cpacs/$file")
  measure "$file: build, write STEP" "$AIRSHAPE" export "$DATA/cpacs/$file" --components "$components" \
    -o "$scratch/out.step" --force --quiet
done
network=$DATA/curve-networks/helibody
measure "gordon helibody" "$AIRSHAPE" gordon "$network/profiles.brep" "$network/guides.brep" -o "$scratch/s.brep"
measure "gordon helibody --report" "$AIRSHAPE" gordon "$network/profiles.brep" "$network/guides.brep" \
  -o "$scratch/s.brep" --report
