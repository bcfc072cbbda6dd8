#!/usr/bin/env bash
# The copper-jet study at CI size through the user's command (scripts/jet-study --scale
# tiny), in a copy of the study's files under WORK so that a user's runs/ is not touched:
#
#   tests/validation/jet_study_ci.sh SOURCE_DIR BUILD_DIR WORK
#
# Then its table: every row of Table 7.1 and both baselines there with an eq. 7.12 error,
# the DDMP-MD rows with fewer atom-steps than one box per point, and the figures written.
set -euo pipefail
src=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work/scripts" "$work/tools"
cp -r "$src/examples" "$work/examples"
cp "$src/scripts/jet-study" "$work/scripts/"
cp -r "$src/tools/plot" "$work/tools/plot"
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
    # block's errors are 21-47%, not the seed's (the midpoint update gave up to 54%).
    if not (0.0 < e < 50.0):
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
