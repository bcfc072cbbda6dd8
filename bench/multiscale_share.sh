#!/usr/bin/env bash
# Boxes shared by history ([material.md.share]) against one box per point, in one
# invocation: the H2 bar's first 8 ps (400 points x 256 atoms; the whole 40 ps with
# FULL=1) and the J2 tiny jet (160 points x 108 atoms, against J1 tiny's direct MD, run
# first when it is missing). For each: atom-steps run (audits included), one box per
# point's, their ratio, the rate, the peak memory, and eq. 7.12 where there is a
# reference. Peer: the unshared run of the same deck.
set -euo pipefail
BUILD=${1:-build-bench}
MPMX=$BUILD/mpmx
THREADS=${THREADS:-$(nproc)}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
unshared() { awk '/^\[material.md\]/{print; print "share = { enabled = false }"; next}1' "$1"; }
if [ "${FULL:-0}" = 1 ]; then
  sed -e '/^\[reference\]/,$d' examples/H2_strong_0K_256.toml > "$tmp/h2.toml"
else
  sed -e 's/^end = 40.0/end = 8.0/' -e 's/^times = .*/times = [8.0]/' -e '/^\[reference\]/,$d' \
    examples/H2_strong_0K_256.toml > "$tmp/h2.toml"
fi
unshared "$tmp/h2.toml" > "$tmp/h2_unshared.toml"
j1=runs/J1_direct_md_tiny
[ -f "$j1/run.json" ] || "$MPMX" md examples/J1_direct_md_tiny.toml --out "$j1" --threads "$THREADS" --quiet >/dev/null
sed "s|\"../runs/|\"$PWD/runs/|" examples/J2_ddmp_md_20x10_1ppc_tiny.toml > "$tmp/j2.toml"
unshared "$tmp/j2.toml" > "$tmp/j2_unshared.toml"
for d in h2 h2_unshared j2 j2_unshared; do
  "$MPMX" run "$tmp/$d.toml" --out "$tmp/$d" --threads "$THREADS" --quiet --no-plot >/dev/null
done
/usr/bin/python3 - "$tmp" "$THREADS" <<'PY'
import json, sys
tmp, threads = sys.argv[1], sys.argv[2]
def row(name, d):
    j = json.load(open(f"{tmp}/{d}/run.json"))
    md = j["md"]
    run, alone = md["atom_steps"], md["atom_steps_unshared"]
    eq = j.get("errors", {}).get("stress_vs_direct_md")
    audit = md.get("share", {})
    print(f"  {name:18s} {run:10.3e} {alone:10.3e} {alone / run:6.2f}x {run / j['wall_seconds']:10.3e} "
          f"{j['peak_memory_bytes'] / 2**20:8.1f} MiB {md['boxes']['max']:6d}"
          + (f"   eq. 7.12 {100 * eq:.2f}%" if eq is not None else "")
          + (f"   audit {100 * audit['audit_rel_rms']:.3f}% rms, {audit['audit_max_gpa']:.3g} GPa max" if audit else ""))
print(f"Boxes shared by history against one box per point, {threads} thread(s)")
print("  deck                atom-steps  unshared   saving  atom-steps/s  peak memory  boxes")
for case, label in (("h2", "H2"), ("j2", "J2 tiny")):
    row(label + ", shared", case)
    row(label + ", one per point", case + "_unshared")
PY
