#!/usr/bin/env bash
# MD boxes inside material points against the engine alone and against LAMMPS, in one
# invocation (docs/performance.md, "MD boxes"):
#  - the closure: examples/J3_ddmp_md_50x25_1ppc_s0p1.toml cut to its first 50 continuum
#    steps (relax_steps = 100, no reference), on 1 and 2 threads, double and mixed;
#  - the engine: one 500-atom box (bench/md_cu500.toml cut to 10,000 steps), 1 thread,
#    double and mixed, and at its default thread count;
#  - LAMMPS on the same box: steady (the better of lmp and lmp -sf opt), and driven as
#    heterogeneous multiscale codes drive it, a box per call (fix deform, `run 10 pre yes
#    post no` 500 times);
#  - one core kept busy by another program (`yes`): the closure and the engine at their
#    default thread counts against --threads 1, and the closure at twice the cores.
# Prints atom-steps per second and the ratios. Usage: bench/multiscale_boxes.sh BUILD_DIR [REPEATS]
# With REPEATS (default 1) every run is made that many times, one after another, and the
# best kept: on a shared or virtual machine one run's figure can be 10-20% off its best.
set -euo pipefail
build=$(cd "${1:?usage: multiscale_boxes.sh BUILD_DIR [REPEATS]}" && pwd)
repeats=${2:-1}
[[ "$repeats" =~ ^[1-9][0-9]*$ ]] || { echo "REPEATS: '$repeats' is not a whole number >= 1" >&2; exit 2; }
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
busy=
trap '[ -n "$busy" ] && kill "$busy" 2>/dev/null; rm -rf "$work"' EXIT
pot=/usr/share/lammps/potentials/Cu_mishin1.eam.alloy
cores=$(nproc)

sed -e 's/^relax_steps = 1000/relax_steps = 100/' -e 's/^end = 2 .*/end = 0.5/' -e 's/^times = \[1, 2\]/times = [0.5]/' \
  -e '/^\[reference\]/,$d' "$src/examples/J3_ddmp_md_50x25_1ppc_s0p1.toml" > "$work/jet_double.toml"
grep -q '^end = 0.5$' "$work/jet_double.toml" || { echo "J3 deck: no 'end = 2' line to cut" >&2; exit 1; }
sed 's/^relax_steps = 100$/relax_steps = 100\nprecision = "mixed"/' "$work/jet_double.toml" > "$work/jet_mixed.toml"
for p in double mixed; do
  sed -e "s/^\[run\]/[run]\nprecision = \"$p\"/" -e 's/^steps = 20000/steps = 10000/' "$src/bench/md_cu500.toml" \
    > "$work/box_$p.toml"
done

jet() {  # label precision threads ("" for the default)
  for r in $(seq "$repeats"); do
    "$build/mpmx" run "$work/jet_$2.toml" --out "$work/$1.r$r" ${3:+--threads $3} --quiet --no-plot > /dev/null
  done
}
box() {  # label precision threads ("" for the default)
  for r in $(seq "$repeats"); do
    "$build/mpmx" md "$work/box_$2.toml" --out "$work/$1.r$r" ${3:+--threads $3} --quiet > /dev/null
  done
}

lammps() {  # label suffix driven(0|1): prints atom-steps/s
  local dir="$work/$1"
  mkdir -p "$dir"
  {
    cat <<EOF
units metal
atom_style atomic
lattice fcc 3.615
region box block 0 5 0 5 0 5
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
thermo 0
EOF
    if [ "$3" = 1 ]; then
      cat <<EOF
fix 2 all deform 1 x erate 0.01 y erate -0.005 remap v
run 0
variable i loop 500
label again
run 10 pre yes post no
next i
jump SELF again
EOF
    else
      echo "run 10000"
    fi
  } > "$dir/in.cu"
  local t0 t1
  t0=$(date +%s.%N)
  (cd "$dir" && lmp ${2:+-sf $2} -in in.cu -log log.lammps -screen none > /dev/null)
  t1=$(date +%s.%N)
  if [ "$3" = 1 ]; then  # the whole loop of calls: what a multiscale code waits for
    /usr/bin/python3 -c "import sys; print(500 * 10 * 500 / (float(sys.argv[2]) - float(sys.argv[1])))" "$t0" "$t1"
  else  # the run's own loop time
    awk '/^Loop time of/ {printf "%.6g\n", 500 * $9 / $4}' "$dir/log.lammps"
  fi
}

echo "multiscale_boxes: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $cores cores; $("$build/mpmx" --version | sed -n 's/.*chosen: //p' | sort -u | paste -sd, -)" >&2
jet jet_d1 double 1
jet jet_d2 double 2
jet jet_m1 mixed 1
jet jet_m2 mixed 2
jet jet_over mixed $((2 * cores))
box box_d1 double 1
box box_m1 mixed 1
box box_dd double
lmp_plain=0 lmp_opt=0 lmp_driven=0
if command -v lmp > /dev/null; then
  best() {  # label suffix driven: the best of the repeats
    for r in $(seq "$repeats"); do lammps "$1.r$r" "$2" "$3"; done | sort -g | tail -1
  }
  lmp_plain=$(best lmp_plain "" 0)
  lmp_opt=$(best lmp_opt opt 0)
  lmp_driven=$(best lmp_driven "" 1)
fi
# One core busy with another program for the rest.
yes > /dev/null &
busy=$!
jet busy_jet_1 mixed 1
jet busy_jet_default mixed
box busy_box_1 double 1
box busy_box_default double
kill "$busy"
busy=

/usr/bin/python3 - "$work" "$lmp_plain" "$lmp_opt" "$lmp_driven" "$cores" "$repeats" <<'PY'
import glob, json, sys
work, plain, opt, driven, cores = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
def recs(d): return [json.load(open(f)) for f in sorted(glob.glob(f"{work}/{d}.r*/run.json"))]
def rec(d): return recs(d)[0]
def jet(d): return max(j["md_atom_steps"] / j["wall_seconds"] for j in recs(d))
def box(d): return max(j["atom_steps_per_second"] for j in recs(d))
lmp = max(plain, opt)
rows = [
    ("closure, J3 50x25x1 s=0.1, first 50 steps, double, 1 thread", jet("jet_d1")),
    ("closure, double, 2 threads", jet("jet_d2")),
    ("closure, mixed, 1 thread", jet("jet_m1")),
    ("closure, mixed, 2 threads", jet("jet_m2")),
    (f"closure, mixed, {2 * cores} threads (twice the cores)", jet("jet_over")),
    ("engine, one 500-atom box, double, 1 thread", box("box_d1")),
    ("engine, one 500-atom box, mixed, 1 thread", box("box_m1")),
    ("engine, one 500-atom box, double, default threads", box("box_dd")),
]
if lmp > 0:
    rows += [("LAMMPS steady, same box (lmp)", plain), ("LAMMPS steady, same box (lmp -sf opt)", opt),
             ("LAMMPS driven per box (fix deform, run 10 pre yes post no, x500)", driven)]
rows += [
    ("one core busy: closure, mixed, 1 thread", jet("busy_jet_1")),
    ("one core busy: closure, mixed, default threads", jet("busy_jet_default")),
    ("one core busy: engine, double, 1 thread", box("busy_box_1")),
    ("one core busy: engine, double, default threads", box("busy_box_default")),
]
w = max(len(r[0]) for r in rows)
for name, v in rows:
    extra = f"  {v / lmp:5.2f}x LAMMPS steady" if lmp > 0 else ""
    if lmp > 0 and driven > 0: extra += f", {v / driven:5.2f}x driven"
    print(f"{name:<{w}}  {v:10.3e} atom-steps/s{extra}")
print(f"closure / engine, 1 thread: double {jet('jet_d1') / box('box_d1'):.2f}, mixed {jet('jet_m1') / box('box_m1'):.2f}")
print(f"closure 2 threads / 1: double {jet('jet_d2') / jet('jet_d1'):.2f}x, mixed {jet('jet_m2') / jet('jet_m1'):.2f}x"
      f"; {2 * cores} threads / 2: {jet('jet_over') / jet('jet_m2'):.2f}")
print(f"one core busy, default threads / 1 thread: closure {jet('busy_jet_default') / jet('busy_jet_1'):.2f}, "
      f"engine {box('busy_box_default') / box('busy_box_1'):.2f}")
builds = rec("jet_d1")["md"]
steps = rec("jet_d1")["md_atom_steps"] / builds["atoms_per_point"]
if int(sys.argv[6]) > 1: print(f"each figure the best of {sys.argv[6]} runs")
print(f"closure list builds: {100 * builds['neighbor_builds'] / steps:.1f}% of the boxes' MD steps")
PY
