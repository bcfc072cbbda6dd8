#!/usr/bin/env bash
# DDMP-MD over MPI ranks (VALIDATION.md P2): case H2 (400 points x 256 atoms, e0 = 5%,
# 0 K), the first END ps (default 2: 10 macro steps of 200 MD steps), on 1 rank and on
# 2 ranks of 1 thread each, in this one invocation: MD atom-steps per second and their
# ratio (target >= 1.8x), particles.csv identical; then the whole run to 40 ps on
# 2 ranks unless QUICK=1. Skipped when the build has no MPI.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX=$BUILD/mpmx
END=${END:-2.0}
if ! "$MPMX" --version | grep -q '^MPI: [^n]'; then
  echo "multiscale_mpi: $MPMX is built without MPI (MPI: none); skipped"
  exit 0
fi
launch=(mpirun --oversubscribe)
[ "$(id -u)" -ne 0 ] || launch+=(--allow-run-as-root)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -e "s/^end = 40.0/end = $END/" -e "s/^times = .*/times = [$END]/" -e '/^\[reference\]/,$d' \
  examples/H2_strong_0K_256.toml > "$tmp/h2_part.toml"
figures() { /usr/bin/python3 -c "import json;j=json.load(open('$1/run.json'));print(j['wall_seconds'], j['md_atom_steps'], j['rank_imbalance'])"; }
for n in 1 2; do
  "${launch[@]}" -np "$n" "$MPMX" run "$tmp/h2_part.toml" --out "$tmp/r$n" --threads 1 --quiet --no-plot >/dev/null
done
cmp -s "$tmp/r1/particles.csv" "$tmp/r2/particles.csv" && same=yes || same=NO
read -r w1 n1 i1 <<<"$(figures "$tmp/r1")"
read -r w2 n2 i2 <<<"$(figures "$tmp/r2")"
/usr/bin/python3 - "$w1" "$w2" "$n1" "$i2" "$same" "$END" <<'PY'
import sys
w1, w2, n, imb, same, end = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6]
print(f"H2 DDMP-MD over MPI ranks, first {end} ps (400 boxes of 256 atoms), 1 thread per rank")
print(f"  1 rank : {w1:8.2f} s  {n / w1:10.3e} atom-steps/s")
print(f"  2 ranks: {w2:8.2f} s  {n / w2:10.3e} atom-steps/s   scaling {w1 / w2:.2f}x (target >= 1.8x), "
      f"imbalance {imb:.3f}")
print(f"  per core at 2 ranks: {n / w2 / 2:.3e} atom-steps/s")
print(f"  particles.csv identical on 1 and 2 ranks: {same}")
PY
if [ "${QUICK:-0}" != 1 ]; then
  sed -e '/^\[reference\]/,$d' examples/H2_strong_0K_256.toml > "$tmp/h2.toml"
  "${launch[@]}" -np 2 "$MPMX" run "$tmp/h2.toml" --out "$tmp/full" --threads 1 --quiet --no-plot >/dev/null
  read -r w n i <<<"$(figures "$tmp/full")"
  /usr/bin/python3 - "$w" "$n" "$i" <<'PY'
import sys
w, n, imb = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
print(f"H2 DDMP-MD, whole run to 40 ps on 2 ranks x 1 thread: {w / 60:.2f} min, {n / w:.3e} atom-steps/s, "
      f"imbalance {imb:.3f}")
PY
fi
