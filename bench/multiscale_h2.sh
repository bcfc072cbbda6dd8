#!/usr/bin/env bash
# DDMP-MD, case H2 (400 points x 256 atoms, e0 = 5%, 0 K, 200 macro steps of 200 MD
# steps): thread scaling on the first 4 ps (1 and 2 threads, the same numbers by
# construction), then the whole run to 40 ps on every core unless QUICK=1.
# Peer: the dissertation's DDMP-MD runs of this size, about 15 minutes each on a Tesla
# K20 GPU (sec. 6.3). Target: the whole run in <= 15 minutes on 2 cores, 1 -> 2
# threads >= 1.8x.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX=$BUILD/mpmx
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The first 4 ps, no reference needed.
sed -e 's/^end = 40.0/end = 4.0/' -e 's/^times = .*/times = [4.0]/' -e '/^\[reference\]/,$d' \
  examples/H2_strong_0K_256.toml > "$tmp/h2_4ps.toml"
wall() { /usr/bin/python3 -c "import json;j=json.load(open('$1/run.json'));print(j['wall_seconds'], j['md_atom_steps'])"; }
"$MPMX" run "$tmp/h2_4ps.toml" --out "$tmp/t1" --threads 1 --quiet --no-plot >/dev/null
"$MPMX" run "$tmp/h2_4ps.toml" --out "$tmp/t2" --threads 2 --quiet --no-plot >/dev/null
cmp -s "$tmp/t1/particles.csv" "$tmp/t2/particles.csv" && same=yes || same=NO
read -r w1 n1 <<<"$(wall "$tmp/t1")"
read -r w2 n2 <<<"$(wall "$tmp/t2")"
/usr/bin/python3 - "$w1" "$w2" "$n1" "$same" <<'PY'
import sys
w1, w2, n = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
print("H2 DDMP-MD, first 4 ps (20 macro steps, 400 boxes of 256 atoms, relaxation none)")
print(f"  1 thread : {w1:8.2f} s  {n / w1:10.3e} atom-steps/s")
print(f"  2 threads: {w2:8.2f} s  {n / w2:10.3e} atom-steps/s   scaling {w1 / w2:.2f}x (target >= 1.8x)")
print(f"  particles.csv identical on 1 and 2 threads: {sys.argv[4]}")
PY
if [ "${QUICK:-0}" != 1 ]; then
  sed -e '/^\[reference\]/,$d' examples/H2_strong_0K_256.toml > "$tmp/h2.toml"
  "$MPMX" run "$tmp/h2.toml" --out "$tmp/full" --quiet --no-plot >/dev/null
  read -r w n <<<"$(wall "$tmp/full")"
  /usr/bin/python3 - "$w" "$n" "$(nproc)" <<'PY'
import sys
w, n, cores = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
print(f"H2 DDMP-MD, whole run to 40 ps on {cores} cores: {w / 60:.2f} min, {n / w:.3e} atom-steps/s "
      f"(target <= 15 min on 2 cores; the dissertation: about 15 min on a Tesla K20)")
PY
fi
