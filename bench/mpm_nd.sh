#!/usr/bin/env bash
# The 2-D and 3-D continuum against the peer: the two-disk case (160 x 160 cells) and the
# two-sphere case (40^3 cells) of issue 13, with mpm, ddmp and ddmp_subpoints (2 per
# axis), on one thread and two; and a shock step, bench/copper_2d.toml (N6 widened:
# ddmp, mie_gruneisen, the tensor viscosity; 200 steps), which has no peer figure.
# Prints million particle-steps per second and the ratios against Karamelo's figures for the same case measured on this machine kind
# (docs/performance.md: 2-D 1.50-2.05, 3-D 0.85-0.93 million particle-steps/s, one rank),
# and two threads against one. The runs end at t = 1 (BENCH_FULL=1: at 3.5, the whole run),
# before the bodies touch: 800 steps in 2-D, 200 in 3-D, long enough for steady figures.
# Each run on one thread and on two alternates REPEAT times (default 2) and the best of each
# counts: on a shared machine whose speed drifts by tens of percent over minutes, a pair
# of runs side by side sees the same conditions more nearly than single runs. With the
# rates, the two-thread ratio of each phase of the step (run.json "phases") of those runs,
# and, as the machine's own ceiling, two one-thread runs at once: their summed rate is
# what the two cores deliver together in those minutes (2x one on an idle machine with
# two free cores, less where the second core is shared or slower), and the two-thread
# run's rate over it is the code's share of that ceiling.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX="$BUILD/mpmx"
REPEAT=${REPEAT:-2}
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for case in disks_2d:1.50:2.05:mpm,ddmp,ddmp_subpoints spheres_3d:0.85:0.93:mpm,ddmp,ddmp_subpoints copper_2d:-:-:ddmp; do
  IFS=: read -r name klo khi schemes <<<"$case"
  for scheme in ${schemes//,/ }; do
    deck="$tmp/$name-$scheme.toml"
    sed "s/^name = \"[a-z_]*\"/name = \"$scheme\"$([ "$scheme" = ddmp_subpoints ] && echo '\nsubpoints = 2')/" "bench/$name.toml" > "$deck"
    [ "${BENCH_FULL:-0}" = 1 ] || sed -i 's/^end = 3.5/end = 1.0/' "$deck"
    for r in $(seq "$REPEAT"); do
      for t in 1 2; do
        # Exit 3: the physics stopped the run (BENCH_FULL: ddmp_subpoints keeps the disks'
        # energy, so one reaches the grid's edge before t = 3.5); the rate of the steps run
        # is in its partial run.json.
        rc=0
        "$MPMX" run "$deck" --out "$tmp/$name-$scheme-$t-$r" --threads "$t" --quiet --no-plot > /dev/null 2> "$tmp/err" || rc=$?
        if [ "$rc" = 3 ] && [ "$r" = 1 ]; then echo "   ($name $scheme, $t thread(s): $(tail -n 1 "$tmp/err"); rate of the steps run)"
        elif [ "$rc" != 0 ] && [ "$rc" != 3 ]; then cat "$tmp/err" >&2; exit "$rc"; fi
      done
      # The ceiling: two one-thread runs side by side (exit 3 as above).
      for k in a b; do
        "$MPMX" run "$deck" --out "$tmp/$name-$scheme-pair$k-$r" --threads 1 --quiet --no-plot > /dev/null 2>&1 &
      done
      for k in a b; do wait -n || [ $? = 3 ] || { echo "$name $scheme: a side-by-side run failed" >&2; exit 1; }; done
    done
    /usr/bin/python3 - "$tmp" "$name" "$scheme" "$REPEAT" "$klo" "$khi" <<'PY'
import json, sys
tmp, name, scheme, repeat = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
# copper_2d ("-"): no Karamelo figure (it has no Mie-Gruneisen law)
karamelo = lambda r: "" if sys.argv[5] == "-" else f" ({r / float(sys.argv[6]):4.1f}-{r / float(sys.argv[5]):4.1f}x Karamelo)"
def best(t):
    runs = [json.load(open(f"{tmp}/{name}-{scheme}-{t}-{r}/run.json")) for r in range(1, repeat + 1)]
    return max(runs, key=lambda j: j["particle_steps_per_second"])
one, two = best(1), best(2)
r1, r2 = one["particle_steps_per_second"] / 1e6, two["particle_steps_per_second"] / 1e6
pair = max(sum(json.load(open(f"{tmp}/{name}-{scheme}-pair{k}-{r}/run.json"))["particle_steps_per_second"]
               for k in "ab") for r in range(1, repeat + 1)) / 1e6
print(f"{name:>11} {scheme:<15} 1 thread {r1:6.2f} M/s{karamelo(r1)}, "
      f"2 threads {r2:6.2f} M/s ({r2/r1:4.2f}x one); two one-thread runs at once {pair:6.2f} M/s together "
      f"({pair/r1:4.2f}x one): two threads reach {r2/pair:4.2f} of it")
phases = one.get("phases", {})
print(" " * 28 + "two threads by phase: " + ", ".join(
    f"{k} {phases[k] / two['phases'][k]:.2f}x ({100 * phases[k] / one['wall_seconds']:.0f}%)" for k in phases))
PY
  done
done
