#!/usr/bin/env bash
# MD speed against LAMMPS, same invocation, one thread each: Cu_mishin1 fcc a = 3.615,
# 600 K initial, NVE, dt = 1 fs; 500 atoms x 20,000 steps and 32,000 atoms x 200 steps
# (bench/md_cu500.toml, bench/md_cu32000.toml). Prints atom-steps/s of mpmx (double and
# mixed precision) on every vector path of the MD kernel this machine has (MPMX_ISA;
# `mpmx --version` lists them), and the ratios to LAMMPS's better figure (lmp or lmp -sf
# opt). Best of REPS (3) rounds, each timing every path and LAMMPS in turn, so that a
# busy spell of the host falls on all of them; the spread (worst/best - 1) is printed.
# Other builds may be timed alongside as peers, on their default path: LABEL=BUILD_DIR.
# ISAS="avx2 sse4" times only those paths.
# Usage: bench/md_vs_lammps.sh BUILD_DIR [LABEL=BUILD_DIR ...]
set -euo pipefail
build=$(cd "${1:?usage: md_vs_lammps.sh BUILD_DIR [LABEL=BUILD_DIR ...]}" && pwd)
shift
src=$(cd "$(dirname "$0")/.." && pwd)
export OMP_NUM_THREADS=1
REPS=${REPS:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pot=/usr/share/lammps/potentials/Cu_mishin1.eam.alloy

json_field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

mpmx_rate() {  # mpmx deck precision isa ("" for the default)
  local exe=$1 deck=$2 prec=$3 isa=$4 out="$work/mpmx_$(basename "$2" .toml)_$3"
  sed "s/^\[run\]/[run]\nprecision = \"$prec\"/" "$deck" > "$work/deck_$prec.toml"
  if [ -n "$isa" ]; then
    MPMX_ISA=$isa "$exe" md "$work/deck_$prec.toml" --out "$out" --quiet > /dev/null
  else
    env -u MPMX_ISA "$exe" md "$work/deck_$prec.toml" --out "$out" --quiet > /dev/null
  fi
  json_field "$out/run.json" atom_steps_per_second
}

lammps_rate() {  # cells steps [suffix]
  local n=$1 steps=$2 sf=${3:-} dir="$work/lmp_$1_${3:-plain}"
  mkdir -p "$dir"
  cat > "$dir/in.cu" <<EOF2
units metal
atom_style atomic
lattice fcc 3.615
region box block 0 $n 0 $n 0 $n
create_box 1 box
create_atoms 1 box
mass 1 63.55
pair_style eam/alloy
pair_coeff * * $pot Cu
velocity all create 600.0 12345 mom yes rot no dist gaussian
neighbor 1.0 bin
neigh_modify every 1 delay 0 check yes
timestep 0.001
fix 1 all nve
thermo $steps
run $steps
EOF2
  (cd "$dir" && lmp ${sf:+-sf $sf} -in in.cu -log log.lammps -screen none > /dev/null)
  awk -v n=$((4 * n * n * n)) '/^Loop time of/ {printf "%.6g\n", n * $9 / $4}' "$dir/log.lammps"
}

if ! command -v lmp > /dev/null; then echo "md_vs_lammps: lmp not installed"; exit 0; fi
version=$("$build/mpmx" --version)
isas=${ISAS:-$(sed -n 's/^MD kernels: .*; this machine: \([^;]*\);.*/\1/p' <<<"$version")}
chosen=$(sed -n 's/^MD kernels: .*; chosen: \([a-z0-9_]*\).*/\1/p' <<<"$version")
# label exe isa, one runner a line: the paths of BUILD, then the peers.
runners=""
if [ -z "$isas" ]; then
  runners="default $build/mpmx -"  # a build without run-time paths
else
  for isa in $isas; do runners+="$isa $build/mpmx $isa"$'\n'; done
fi
for peer in "$@"; do
  runners+="${peer%%=*} $(cd "${peer#*=}" && pwd)/mpmx -"$'\n'
done
echo "md_vs_lammps: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(date -u +%FT%TZ), OMP_NUM_THREADS=1," \
  "best of $REPS; the default path: ${chosen:-none}"
: > "$work/rates"
for spec in "500 5 20000 md_cu500.toml" "32000 20 200 md_cu32000.toml"; do
  set -- $spec
  for rep in $(seq "$REPS"); do
    while read -r label exe isa; do
      [ -n "$label" ] || continue
      [ "$isa" = - ] && isa=""
      for prec in double mixed; do
        echo "$1 $label $prec $(mpmx_rate "$exe" "$src/bench/$4" "$prec" "$isa")" >> "$work/rates"
      done
    done <<< "$runners"
    echo "$1 lmp - $(lammps_rate "$2" "$3")" >> "$work/rates"
    echo "$1 lmp_opt - $(lammps_rate "$2" "$3" opt)" >> "$work/rates"
  done
done
python3 - "$work/rates" $(awk '{print $1}' <<< "$runners") <<'EOF3'
import sys
path, labels = sys.argv[1], sys.argv[2:]
rates = {}
for line in open(path):
    case, label, prec, r = line.split()
    rates.setdefault((case, label, prec), []).append(float(r))
best = {k: max(v) for k, v in rates.items()}
spread = {k: max(v) / min(v) - 1 for k, v in rates.items()}
print(f"{'case':<7}{'mpmx':<14}{'double':>11}{'spread':>8}{'mixed':>11}{'spread':>8}{'x_double':>10}{'x_mixed':>9}")
for case in ("500", "32000"):
    lmp = best[case, "lmp", "-"], best[case, "lmp_opt", "-"]
    top = max(lmp)
    for label in labels:
        d, m = best[case, label, "double"], best[case, label, "mixed"]
        sd, sm = spread[case, label, "double"], spread[case, label, "mixed"]
        print(f"{case:<7}{label:<14}{d:11.4g}{sd:8.0%}{m:11.4g}{sm:8.0%}{d / top:10.2f}{m / top:9.2f}")
    print(f"{case:<7}{'lmp, lmp opt':<14}{lmp[0]:11.4g}{spread[case, 'lmp', '-']:8.0%}"
          f"{lmp[1]:11.4g}{spread[case, 'lmp_opt', '-']:8.0%}")
print("(atom-steps per second, one thread; x_* = mpmx / best LAMMPS)")
EOF3
