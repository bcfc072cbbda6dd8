#!/usr/bin/env bash
# ADMPM sec. 10.3, run 3 (201 nodes, 4 ppc, moving particles, 10^6 steps, a record every
# 5,000 steps) with the plain scheme, DDMP, and DDMP with 8 sub-points, one thread, on
# every vector path of the 1-D kernels this machine has (MPMX_ISA; `mpmx --version` lists
# them), the paths interleaved so that a busy spell of the host falls on all of them.
# Peer: ADMPM's C code, gcc -O3: 25.7 s for this run on a Zen 4 machine of this kind,
# 36.8 s on a Zen 3 one (docs/performance.md; ADMPM's own table lists 82.7 s on its 2021
# machine). ADMPM_SECONDS=... gives the figure measured on the machine at hand;
# ISAS="avx2 sse4" times only those paths.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX=$BUILD/mpmx
ADMPM_SECONDS=${ADMPM_SECONDS:-25.7}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
version=$("$MPMX" --version)
chosen=$(sed -n 's/^1-D kernels: .*; chosen: \([a-z0-9_]*\).*/\1/p' <<<"$version")
ISAS=${ISAS:-$(sed -n 's/^1-D kernels: .*; this machine: \([^;]*\);.*/\1/p' <<<"$version")}
wall() {  # wall time of one run from run.json
  MPMX_ISA=$2 OMP_NUM_THREADS=1 "$MPMX" run "$1" --out "$tmp/r" --quiet --no-plot >/dev/null
  /usr/bin/python3 -c "import json;print(json.load(open('$tmp/r/run.json'))['wall_seconds'])"
}
sed 's/^name = "mpm"/name = "ddmp"/' bench/admpm_run3.toml > "$tmp/ddmp.toml"
sed 's/^name = "mpm"/name = "ddmp_subpoints"\nsubpoints = 8/' bench/admpm_run3.toml > "$tmp/sub8.toml"
: > "$tmp/times"
for deck in bench/admpm_run3.toml "$tmp/ddmp.toml" "$tmp/sub8.toml"; do
  for i in 1 2 3; do
    for isa in $ISAS; do echo "$(basename "$deck" .toml) $isa $(wall "$deck" "$isa")" >> "$tmp/times"; done
  done
done
/usr/bin/python3 - "$tmp/times" "$ADMPM_SECONDS" "$chosen" $ISAS <<'PY'
import sys
times, admpm, chosen, isas = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4:]
chosen = chosen if chosen in isas else isas[0]
best = {}
for line in open(times):
    deck, isa, t = line.split()
    best[deck, isa] = min(best.get((deck, isa), float("inf")), float(t))
decks = (("mpm", "admpm_run3"), ("ddmp", "ddmp"), ("ddmp_subpoints (8)", "sub8"))
ps = 800 * 1_000_000
print(f"ADMPM run 3 (800 particles x 10^6 steps), best of 3, one thread; vector paths {' '.join(isas)}"
      f" (the default takes {chosen})")
print(f"  {'scheme':<22}{'path':<8}{'wall s':>9}{'particle-steps/s':>20}{'vs ADMPM C -O3':>16}{'vs mpm':>9}")
for name, deck in decks:
    for isa in isas:
        t, t_mpm = best[deck, isa], best["admpm_run3", isa]
        print(f"  {name:<22}{isa:<8}{t:9.3f}{ps / t:20.3e}{admpm / t:15.1f}x{t / t_mpm:8.2f}x")
# Each path against the next narrower one: below 1 the wider path is faster.
for wide, narrow in zip(isas, isas[1:]):
    ratios = ", ".join(f"{name} {best[deck, wide] / best[deck, narrow]:.2f}" for name, deck in decks)
    print(f"  time {wide}/{narrow}: {ratios}")
t_mpm, t_sub = best["admpm_run3", chosen], best["sub8", chosen]
print(f"  targets ({chosen}): mpm <= {admpm / 10:.2f} s (10x ADMPM's {admpm} s): {t_mpm:.2f} s; "
      f"ddmp_subpoints(8) <= 3x mpm: {t_sub / t_mpm:.2f}x")
PY
