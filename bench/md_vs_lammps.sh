#!/usr/bin/env bash
# MD speed against LAMMPS, same invocation, one thread each: Cu_mishin1 fcc a = 3.615,
# 600 K initial, NVE, dt = 1 fs; 500 atoms x 20,000 steps and 32,000 atoms x 200 steps
# (bench/md_cu500.toml, bench/md_cu32000.toml). Prints atom-steps/s and the ratios of
# mpmx (double and mixed precision) to LAMMPS's better figure (lmp or lmp -sf opt).
# Usage: bench/md_vs_lammps.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:?usage: md_vs_lammps.sh BUILD_DIR}" && pwd)
src=$(cd "$(dirname "$0")/.." && pwd)
export OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pot=/usr/share/lammps/potentials/Cu_mishin1.eam.alloy

json_field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

mpmx_rate() {  # deck precision
  local deck=$1 prec=$2 out="$work/mpmx_$(basename "$1" .toml)_$2"
  sed "s/^\[run\]/[run]\nprecision = \"$prec\"/" "$deck" > "$work/deck_$prec.toml"
  "$build/mpmx" md "$work/deck_$prec.toml" --out "$out" --quiet > /dev/null
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
echo "md_vs_lammps: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(date -u +%FT%TZ), OMP_NUM_THREADS=1"
printf "%-8s %14s %14s %14s %14s %14s %10s %10s\n" case mpmx_double mpmx_mixed lmp lmp_opt best_lammps x_double x_mixed
for spec in "500 5 20000 md_cu500.toml" "32000 20 200 md_cu32000.toml"; do
  set -- $spec
  d=$(mpmx_rate "$src/bench/$4" double)
  m=$(mpmx_rate "$src/bench/$4" mixed)
  l=$(lammps_rate "$2" "$3")
  o=$(lammps_rate "$2" "$3" opt)
  python3 - "$1" "$d" "$m" "$l" "$o" <<'EOF3'
import sys
name, d, m, l, o = sys.argv[1], *map(float, sys.argv[2:])
best = max(l, o)
print(f"{name:<8} {d:14.4g} {m:14.4g} {l:14.4g} {o:14.4g} {best:14.4g} {d/best:10.2f} {m/best:10.2f}")
EOF3
done
echo "(atom-steps per second, one thread; x_* = mpmx / best LAMMPS)"
