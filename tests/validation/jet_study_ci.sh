#!/usr/bin/env bash
# The copper-jet study at CI size through the user's command (scripts/jet-study --scale
# tiny), in a copy of the study's files under WORK so that a user's runs/ is not touched:
#
#   tests/validation/jet_study_ci.sh SOURCE_DIR BUILD_DIR WORK
#
# Then its table: every row of Table 7.1 and both baselines there with an eq. 7.12 error,
# the DDMP-MD rows with fewer atom-steps than one box per point, and the figures written;
# and every row's eq. 7.12 recomputed from its particle output and the direct MD's bins by
# tools/check_eq712.py (not the run's code), agreeing with run.json to four digits; that
# check is shown to fail on a figure 1e-3 off and on bins 1% off. Last, the direct MD's
# reference pack (scripts/jet-reference-pack) at the rows' compared times gives every
# row the same figures as the whole run, and a time without a record is refused with
# nothing written.
set -euo pipefail
src=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work/scripts" "$work/tools"
cp -r "$src/examples" "$work/examples"
cp "$src/scripts/jet-study" "$src/scripts/jet-reference-pack" "$work/scripts/"
cp -r "$src/tools/plot" "$work/tools/plot"
cp "$src/tools/check_eq712.py" "$work/tools/"
"$work/scripts/jet-study" --scale tiny --threads 2 --build "$build"
/usr/bin/python3 - "$work/runs/jet_study_tiny" <<'PY'
import csv, math, os, sys
study = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(study, "table71.csv"))))
bad = []
if len(rows) != 7:
    bad.append(f"{len(rows)} rows, not 7")
for r in rows:
    e = float(r["error_percent"] or "nan")
    # A regression bound at this size (docs/jet.md has the figures): with MUSL the tiny
    # block's errors are 21-51% (the 10 x 5 x 16 row the largest), not the seed's (the
    # midpoint update gave up to 54%).
    if not (0.0 < e < 55.0):
        bad.append(f"{r['row']}: eq. 7.12 = {e}%")
    if r["row"].startswith("J4"):
        continue
    done, alone = float(r["atom_steps"]), float(r["atom_steps_unshared"])
    if not (0.0 < done < alone):
        bad.append(f"{r['row']}: {done:.4g} atom-steps shared, {alone:.4g} with one box per point")
    if float(r["peak_memory_bytes"]) <= 0:
        bad.append(f"{r['row']}: no peak memory")
for f in ("table71.png", "fig7_3.png", "fig7_4.png", "summary.md"):
    if not os.path.getsize(os.path.join(study, f)):
        bad.append(f"{f} empty")
for r in rows:
    print(f"{r['row']:32s} {r['error_percent']:>8s}%  {r['atom_steps']:>10s} / {r['atom_steps_unshared']:>10s} atom-steps")
if bad:
    print("jet_study_ci: " + "; ".join(bad), file=sys.stderr)
    sys.exit(1)
PY
study=$work/runs/jet_study_tiny md=$work/runs/J1_direct_md_tiny
check=$work/tools/check_eq712.py
for row in "$study"/J[234]_*/; do
  /usr/bin/python3 "$check" "${row%/}" --md "$md"
done
# The check must be able to fail: a copy of the J2 row whose run.json's pooled figure is
# off by 1e-3 (beyond four digits), and a copy of the direct MD with every sxx 1% larger.
row=$(ls -d "$study"/J2_*/ | head -1)
row=${row%/}
bad=$work/check_eq712_bad
rm -rf "$bad" && mkdir -p "$bad/run" "$bad/md/bins"
ln -s "$row/particles.pvd" "$row/vtk" "$bad/run/"
/usr/bin/python3 - "$row/run.json" "$bad/run/run.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
r["errors"]["stress_vs_direct_md"] *= 1 + 1e-3
json.dump(r, open(sys.argv[2], "w"))
PY
expect_fail() {
  local rc=0
  /usr/bin/python3 "$check" "$1" --md "$2" >/dev/null 2>&1 || rc=$?
  [ "$rc" = 1 ] || { echo "jet_study_ci: check_eq712.py on $3 exited $rc, not 1" >&2; exit 1; }
}
expect_fail "$bad/run" "$md" "a pooled figure 1e-3 off"
cp "$md/run.json" "$md/md_bins.pvd" "$bad/md/"
for f in "$md"/bins/*.csv; do
  awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "sxx_GPa") c = i; print; next }
                    { $c = $c * 1.01; print }' "$f" >"$bad/md/bins/$(basename "$f")"
done
expect_fail "$row" "$bad/md" "bins with sxx 1% larger"
echo "jet_study_ci: eq. 7.12 recomputed for every row; the check catches a perturbed figure and perturbed bins"
pack=$work/data/J1_direct_md_tiny
times=$(sed -n 's/^times = \[\(.*\)\]/\1/p' "$work"/examples/*_tiny.toml | tr ',' '\n' | tr -d ' ' | sort -gu)
# shellcheck disable=SC2086
"$work/scripts/jet-reference-pack" "$md" "$pack" $times
[ "$(ls "$pack/bins" | wc -l)" = "$(wc -w <<<"$times")" ] || { echo "jet_study_ci: the pack's records" >&2; exit 1; }
[ "$(head -1 "$(ls -d "$pack"/bins/*.csv | head -1)")" = "ix,iy,x_A,y_A,atoms,density_g_cm3,temperature_K,vx_km_s,vy_km_s,sxx_GPa" ] ||
  { echo "jet_study_ci: the pack's columns" >&2; exit 1; }
for row in "$study"/J[234]_*/; do
  /usr/bin/python3 "$check" "${row%/}" --md "$pack" >/dev/null
done
rc=0
"$work/scripts/jet-reference-pack" "$md" "$work/data/bad_pack" 0.5 0.77 2>/dev/null || rc=$?
[ "$rc" = 2 ] && [ ! -e "$work/data/bad_pack" ] && [ -z "$(ls -d "$work"/data/bad_pack.staging.* 2>/dev/null)" ] ||
  { echo "jet_study_ci: a pack at a time without a record: exit $rc, or something left" >&2; exit 1; }
echo "jet_study_ci: the reference pack at $(echo $times) ps gives every row's eq. 7.12"
# The scale study's tool (tools/plot/jet_scale.py) on the two 10 x 5 rows: a line each,
# each front within 30% of the direct MD's at the scaled 10 ps (measured: +4.7% and
# -16.9%), the figure, and the figure again from the table alone.
scale=$work/jet_scale
/usr/bin/python3 "$work/tools/plot/jet_scale.py" --out "$scale" "$study/J3_ddmp_md_10x5_1ppc:$md" \
  "$study/J3_ddmp_md_10x5_4ppc:$md"
/usr/bin/python3 - "$scale.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [int(float(r["per_cell"])) for r in rows] == [1, 4], rows
for r in rows:
    ratio = float(r["front_row_nm"]) / float(r["front_md_nm"])
    assert 0.7 < ratio < 1.3 and float(r["scale"]) == 0.05, r
PY
# The front on hand-made profiles: a wall column at rest before a noisy plateau (the front
# read after it, at the half-plateau crossing between the columns at 4.75 and 5.25 nm),
# and one shocked to its end (refused, not read at its last column).
/usr/bin/python3 - "$work/tools/plot" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
import jet_scale
x = np.arange(0.25, 10.0, 0.5)
rng = np.random.default_rng(7)
sxx = np.where(x < 5.2, -170.0 + rng.normal(0.0, 8.0, x.size), -0.5)
sxx[0] = 1.0
front, plateau = jet_scale.front_of(x, sxx)
assert 4.75 < front < 5.25 and abs(plateau + 170.0) < 10.0, (front, plateau)
try:
    jet_scale.front_of(x, np.full(x.size, -170.0))
    sys.exit("jet_study_ci: a profile shocked to its end gave a front")
except jet_scale.Bad:
    pass
PY
rm "$scale.png"
/usr/bin/python3 "$work/tools/plot/jet_scale.py" --out "$scale" --replot "$scale.csv" >/dev/null
[ -s "$scale.png" ] || { echo "jet_study_ci: jet_scale.py --replot wrote no figure" >&2; exit 1; }
