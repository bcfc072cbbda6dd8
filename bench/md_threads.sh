#!/usr/bin/env bash
# One large MD system on one thread and on two (`mpmx md --threads N`: the tiled force
# loop, the same bits for any count): the direct-MD copper jet at s = 0.1
# (examples/J1_direct_md_s0p1.toml, 28,200 atoms, 3,000 steps; the shock, the notch and
# the surfaces make the tiles uneven) and the 32,000-atom crystal of
# bench/md_cu32000.toml run 1,000 steps. Prints atom-steps/s, the two-thread speed-up and
# whether the two runs wrote the same numbers. QUICK=1: the jet's tiny deck instead.
# Usage: bench/md_threads.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: md_threads.sh BUILD_DIR}" && pwd)
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3
json_field() { "$py" -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

jet=$src/examples/J1_direct_md_s0p1.toml
[ "${QUICK:-0}" = 1 ] && jet=$src/examples/J1_direct_md_tiny.toml
sed 's/^steps = 200$/steps = 1000/' "$src/bench/md_cu32000.toml" > "$work/cu32000.toml"

printf '%-34s %14s %14s %9s %s\n' case "1 thread" "2 threads" speed-up "same numbers"
for deck in "$jet" "$work/cu32000.toml"; do
  name=$(basename "$deck" .toml)
  declare -A rate=()
  for n in 1 2; do
    (cd "$work" && "$build/mpmx" md "$deck" --out "$work/$name.$n" --threads "$n" --quiet > /dev/null)
    rate[$n]=$(json_field "$work/$name.$n/run.json" atom_steps_per_second)
  done
  same=yes
  for f in "$work/$name.1"/*.csv "$work/$name.1"/*.lammpstrj; do
    [ -f "$f" ] || continue
    cmp -s "$f" "$work/$name.2/$(basename "$f")" || same=no
  done
  "$py" - "$name" "${rate[1]}" "${rate[2]}" "$same" <<'EOF'
import sys
name, one, two, same = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
print(f"{name:<34} {one:14.4g} {two:14.4g} {two / one:8.2f}x {same}")
EOF
  unset rate
done
echo "(atom-steps per second of wall time; the speed-up is the issue's 1.8x target)"
