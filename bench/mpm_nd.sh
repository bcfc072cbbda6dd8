#!/usr/bin/env bash
# The 2-D and 3-D continuum against the peer: the two-disk case (160 x 160 cells) and the
# two-sphere case (40^3 cells) of issue 13, with mpm, ddmp and ddmp_subpoints (2 per
# axis), on one thread and two. Prints million particle-steps per second and the ratios
# against Karamelo's figures for the same case measured on this machine kind
# (docs/performance.md: 2-D 1.50-2.05, 3-D 0.85-0.93 million particle-steps/s, one rank),
# and two threads against one. The runs end at t = 1 (BENCH_FULL=1: at 3.5, the whole run),
# before the bodies touch: 800 steps in 2-D, 200 in 3-D, long enough for steady figures.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX="$BUILD/mpmx"
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rate() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['particle_steps_per_second'] / 1e6)" "$1"; }
for case in disks_2d:1.50:2.05 spheres_3d:0.85:0.93; do
  IFS=: read -r name klo khi <<<"$case"
  for scheme in mpm ddmp ddmp_subpoints; do
    deck="$tmp/$name-$scheme.toml"
    sed "s/^name = \"mpm\"/name = \"$scheme\"$([ "$scheme" = ddmp_subpoints ] && echo '\nsubpoints = 2')/" "bench/$name.toml" > "$deck"
    [ "${BENCH_FULL:-0}" = 1 ] || sed -i 's/^end = 3.5/end = 1.0/' "$deck"
    for t in 1 2; do
      # Exit 3: the physics stopped the run (BENCH_FULL: ddmp_subpoints keeps the disks'
      # energy, so one reaches the grid's edge before t = 3.5); the rate of the steps run
      # is in its partial run.json.
      rc=0
      "$MPMX" run "$deck" --out "$tmp/$name-$scheme-$t" --threads "$t" --quiet --no-plot > /dev/null 2> "$tmp/err" || rc=$?
      if [ "$rc" = 3 ]; then echo "   ($name $scheme, $t thread(s): $(tail -n 1 "$tmp/err"); rate of the steps run)"
      elif [ "$rc" != 0 ]; then cat "$tmp/err" >&2; exit "$rc"; fi
    done
    r1=$(rate "$tmp/$name-$scheme-1/run.json")
    r2=$(rate "$tmp/$name-$scheme-2/run.json")
    /usr/bin/python3 -c "
import sys
r1, r2, lo, hi = map(float, sys.argv[1:5])
print(f'{sys.argv[5]:>11} {sys.argv[6]:<15} 1 thread {r1:6.2f} M/s ({r1/hi:4.1f}-{r1/lo:4.1f}x Karamelo), 2 threads {r2:6.2f} M/s ({r2/r1:4.2f}x one)')
" "$r1" "$r2" "$klo" "$khi" "$name" "$scheme"
  done
done
