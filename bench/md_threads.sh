#!/usr/bin/env bash
# One large MD system on one thread and on two (`mpmx md --threads N`: the tiled force
# loop, the same bits for any count): the direct-MD copper jet at s = 0.1
# (examples/J1_direct_md_s0p1.toml, 28,200 atoms, 3,000 steps; the shock, the notch and
# the surfaces make the tiles uneven) and the 32,000-atom crystal of
# bench/md_cu32000.toml run 1,000 steps. Prints atom-steps/s, the two-thread speed-up and
# whether the two runs wrote the same bytes (every output but run.json, which holds the
# timings). QUICK=1: the jet's tiny deck instead.
# Usage: bench/md_threads.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: md_threads.sh BUILD_DIR}" && pwd)
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3

jet=$src/examples/J1_direct_md_s0p1.toml
[ "${QUICK:-0}" = 1 ] && jet=$src/examples/J1_direct_md_tiny.toml
sed 's/^steps = 200$/steps = 1000/' "$src/bench/md_cu32000.toml" > "$work/cu32000.toml"
grep -q '^steps = 1000$' "$work/cu32000.toml" || { echo "bench/md_cu32000.toml: no 'steps = 200' to lengthen" >&2; exit 1; }

printf '%-34s %14s %14s %9s %s\n' case "1 thread" "2 threads" speed-up "same bytes"
for deck in "$jet" "$work/cu32000.toml"; do
  name=$(basename "$deck" .toml)
  for n in 1 2; do
    (cd "$work" && "$build/mpmx" md "$deck" --out "$work/$name.$n" --threads "$n" --quiet > /dev/null)
  done
  same=yes
  diff -rq -x run.json "$work/$name.1" "$work/$name.2" > /dev/null || same=no
  "$py" -c '
import json, sys
name, a, b, same = sys.argv[1:]
one, two = (json.load(open(f))["atom_steps_per_second"] for f in (a, b))
print(f"{name:<34} {one:14.4g} {two:14.4g} {two / one:8.2f}x {same}")
' "$name" "$work/$name.1/run.json" "$work/$name.2/run.json" "$same"
done
echo "(atom-steps per second of wall time; the speed-up is the issue's 1.8x target)"
